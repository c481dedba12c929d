// SPDX-License-Identifier: GPL-3.0-or-later
// How a vertex on the boundary of a domain may move without changing the
// boundary's shape: within the plane of a flat boundary patch, along the
// line of a straight boundary edge, or not at all. Every decision is exact
// (orientation and collinearity predicates, equal coordinates). A position
// is kept only if it lies exactly on the plane or the line: a plane
// parallel to a coordinate plane, or a line parallel to an axis, keeps the
// fixed coordinates exactly; on another plane or line a rounded position
// rarely lies on it, so such vertices seldom move.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_BOUNDARY_MOTION_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_BOUNDARY_MOTION_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>
#include <array>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class T, class = void>
struct Is_equality_comparable : std::false_type {};
template <class T>
struct Is_equality_comparable<T, std::void_t<decltype(std::declval<const T&>() == std::declval<const T&>())>>
    : std::true_type {};

// Whether two facets carry the same data (a boundary reference); data with
// no comparison (No_constraints) is all alike.
template <class Data>
bool same_facet_data(const Data& a, const Data& b)
{
  if constexpr(Is_equality_comparable<Data>::value) return a == b;
  else return true;
}

/// Where a vertex may go.
template <class Point>
struct Boundary_motion
{
  enum Kind
  {
    FIXED, ///< a corner, a curved or folded boundary, a junction
    PLANE, ///< within the plane of `p[0], p[1], p[2]`
    LINE   ///< along the line of `p[0], p[1]`
  };
  Kind kind = FIXED;
  std::array<Point, 3> p;               ///< the plane's or the line's points
  std::array<bool, 3> kept{{false, false, false}}; ///< the coordinates every position keeps exactly
  Vec origin{0, 0, 0}, axis{0, 0, 0};   ///< the vertex, and the plane's normal or the line's direction

  /// `x` moved onto the plane or the line (the kept coordinates copied).
  Vec project(const Vec& x) const
  {
    Vec y = x;
    const double t = dot(sub(x, origin), axis) / dot(axis, axis);
    if(kind == PLANE) y = Vec{x.x - t * axis.x, x.y - t * axis.y, x.z - t * axis.z};
    else if(kind == LINE) y = Vec{origin.x + t * axis.x, origin.y + t * axis.y, origin.z + t * axis.z};
    const double* from[3] = {&origin.x, &origin.y, &origin.z};
    double* to[3] = {&y.x, &y.y, &y.z};
    for(int a = 0; a < 3; ++a)
      if(kept[a]) *to[a] = *from[a];
    return y;
  }

  /// The direction `d` within the plane or along the line.
  Vec project_direction(const Vec& d) const
  {
    const double t = dot(d, axis) / dot(axis, axis);
    if(kind == PLANE) return Vec{d.x - t * axis.x, d.y - t * axis.y, d.z - t * axis.z};
    return Vec{t * axis.x, t * axis.y, t * axis.z};
  }

  /// Whether `q` lies exactly on the plane or the line.
  template <class Traits>
  bool holds(const Traits& traits, const Point& q) const
  {
    if(kind == PLANE) return traits.orientation_3_object()(p[0], p[1], p[2], q) == CGAL::COPLANAR;
    return traits.collinear_3_object()(p[0], p[1], q);
  }
};

/// How the vertex `v` with the cells `star` around it may move: the facets
/// through `v` between a cell of the domain and one outside it, between two
/// subdomains, constrained, or on the hull, are its boundary facets; `FIXED`
/// when there is none. A plane when they all lie in one plane and carry the same
/// data; a line when the edges through `v` where the boundary bends, the
/// data changes or more than two boundary facets meet are two, on a line
/// through `v` that the plane of every boundary facet holds.
template <class Tr, class Constraints>
Boundary_motion<typename Tr::Geom_traits::Point_3>
boundary_motion(const Tr& tr, const std::vector<typename Tr::Cell_handle>& star, typename Tr::Vertex_handle v,
                const Constraints& constraints)
{
  typedef typename Tr::Geom_traits::Point_3 Point;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  Boundary_motion<Point> motion;
  auto inside = [&](Cell_handle c) { return !tr.is_infinite(c) && constraints.is_in_domain(tr, c); };
  struct Facet
  {
    std::array<Vertex_handle, 2> others; // the facet's vertices besides v
    typename Constraints::Facet_data data;
  };
  std::vector<Facet> facets;
  for(Cell_handle c : star)
  {
    if(tr.is_infinite(c)) continue;
    const int iv = c->index(v);
    for(int i = 0; i < 4; ++i)
    {
      if(i == iv) continue;
      const Cell_handle n = c->neighbor(i);
      // The hull counts too, from whichever side: the infinite cells stay
      // valid only while the vertex stays on its hull facets' planes.
      const bool boundary =
          tr.is_infinite(n) ||
          (inside(c) && !(inside(n) && constraints.same_subdomain(c, n) && !constraints.is_facet_constrained(c, i)));
      // A facet between two subdomains is seen from both: once is enough.
      if(!boundary || (inside(c) && inside(n) && !(n < c))) continue;
      Facet f;
      for(int j = 0, k = 0; j < 4; ++j)
        if(j != i && j != iv) f.others[k++] = c->vertex(j);
      f.data = constraints.facet_data(c, i);
      facets.push_back(f);
    }
  }
  if(facets.empty()) return motion;
  const auto& traits = tr.geom_traits();
  auto at = [](Vertex_handle w) -> const Point& { return internal::bare_point(w->point()); };
  const Point& o = at(v);
  auto coplanar = [&](const Facet& f, const Point& q) {
    return traits.orientation_3_object()(o, at(f.others[0]), at(f.others[1]), q) == CGAL::COPLANAR;
  };
  auto to_vec = [](const Point& q) { return Vec{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}; };
  auto coordinate = [](const Point& q, int a) { return CGAL::to_double(a == 0 ? q.x() : a == 1 ? q.y() : q.z()); };
  motion.origin = to_vec(o);

  // The edges through v and their boundary facets.
  std::vector<std::pair<Vertex_handle, std::vector<std::size_t>>> edges;
  for(std::size_t k = 0; k < facets.size(); ++k)
    for(Vertex_handle w : facets[k].others)
    {
      auto e = edges.begin();
      while(e != edges.end() && e->first != w) ++e;
      if(e == edges.end())
      {
        edges.push_back({w, {}});
        e = edges.end() - 1;
      }
      e->second.push_back(k);
    }
  std::vector<Vertex_handle> bends;
  for(const auto& [w, around] : edges)
  {
    const bool bend = around.size() != 2 || !same_facet_data(facets[around[0]].data, facets[around[1]].data) ||
                      !coplanar(facets[around[0]], at(facets[around[1]].others[0] == w ? facets[around[1]].others[1]
                                                                                       : facets[around[1]].others[0]));
    if(bend) bends.push_back(w);
  }

  if(bends.empty())
  {
    // One flat patch (a single fan of facets, or several in one plane).
    for(const Facet& f : facets)
      if(!same_facet_data(f.data, facets.front().data) || !coplanar(facets.front(), at(f.others[0])) ||
         !coplanar(facets.front(), at(f.others[1])))
        return motion;
    motion.kind = Boundary_motion<Point>::PLANE;
    motion.p = {o, at(facets.front().others[0]), at(facets.front().others[1])};
    motion.axis = cross(sub(to_vec(motion.p[1]), motion.origin), sub(to_vec(motion.p[2]), motion.origin));
    for(int a = 0; a < 3; ++a)
    {
      bool same = true;
      for(const Facet& f : facets)
        for(Vertex_handle w : f.others) same = same && coordinate(at(w), a) == coordinate(o, a);
      motion.kept[a] = same;
    }
    return motion;
  }
  if(bends.size() != 2 || !traits.collinear_3_object()(at(bends[0]), o, at(bends[1])) ||
     !traits.collinear_are_strictly_ordered_along_line_3_object()(at(bends[0]), o, at(bends[1])))
    return motion;
  for(const Facet& f : facets)
    if(!coplanar(f, at(bends[0])) || !coplanar(f, at(bends[1]))) return motion;
  motion.kind = Boundary_motion<Point>::LINE;
  motion.p = {at(bends[0]), at(bends[1]), o};
  motion.axis = sub(to_vec(motion.p[1]), to_vec(motion.p[0]));
  for(int a = 0; a < 3; ++a)
    motion.kept[a] = coordinate(motion.p[0], a) == coordinate(o, a) && coordinate(motion.p[1], a) == coordinate(o, a);
  return motion;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_BOUNDARY_MOTION_H
