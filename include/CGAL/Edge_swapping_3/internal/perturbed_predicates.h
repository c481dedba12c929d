// SPDX-License-Identifier: GPL-3.0-or-later
// Exact in-sphere and coplanar in-circle tests, optionally with the symbolic
// perturbation of Devillers and Teillaud that CGAL's Delaunay_triangulation_3
// uses, so that a flip algorithm reaches the same triangulation as CGAL, cell
// for cell, on cospherical and cocircular input.
//
// The perturbation lifts point p to |p|^2 + eps^(rank of p), the rank being the
// position of p in lexicographic (x, y, z) order, the largest point perturbed
// most. A degenerate determinant is then decided by its leading monomial in eps.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_PERTURBED_PREDICATES_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_PERTURBED_PREDICATES_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/enum.h>
#include <algorithm>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Gt>
struct Lexicographic_point_order
{
  const Gt& gt;
  template <class Point>
  bool operator()(const Point* p, const Point* q) const
  {
    return gt.compare_xyz_3_object()(*p, *q) == SMALLER;
  }
};

// A degenerate (power) sphere test of p against the positively oriented
// p0..p3, decided by the symbolic perturbation: the points in lexicographic
// order of their bare points, the coefficient of the leading monomial is the
// orientation of the four points left once the largest is removed (with the
// sign of its slot); `monomials` of them are looked at.
template <class Gt, class Point>
Oriented_side perturbed_sphere_side(const Gt& gt, const Point& p0, const Point& p1, const Point& p2,
                                    const Point& p3, const Point& p, int monomials)
{
  const Point* points[5] = {&p0, &p1, &p2, &p3, &p};
  std::sort(points, points + 5, [&](const Point* a, const Point* b) {
    return gt.compare_xyz_3_object()(bare_point(*a), bare_point(*b)) == SMALLER;
  });
  auto orientation = [&](const Point& a, const Point& b, const Point& c, const Point& d) {
    return gt.orientation_3_object()(bare_point(a), bare_point(b), bare_point(c), bare_point(d));
  };
  for(int i = 4; i > 4 - monomials; --i)
  {
    if(points[i] == &p)
      return ON_NEGATIVE_SIDE; // p0..p3 is positively oriented
    Orientation o = COPLANAR;
    if(points[i] == &p3) o = orientation(p0, p1, p2, p);
    else if(points[i] == &p2) o = orientation(p0, p1, p, p3);
    else if(points[i] == &p1) o = orientation(p0, p, p2, p3);
    else o = orientation(p, p1, p2, p3);
    if(o != COPLANAR)
      return Oriented_side(o);
  }
  CGAL_assertion(false);
  return ON_NEGATIVE_SIDE;
}

// Side of `p` with respect to the sphere through the positively oriented
// tetrahedron (p0, p1, p2, p3): ON_POSITIVE_SIDE means inside.
template <class Gt, class Point>
Oriented_side side_of_oriented_sphere(const Gt& gt,
                                      const Point& p0, const Point& p1,
                                      const Point& p2, const Point& p3,
                                      const Point& p, bool perturb)
{
  const Oriented_side os = gt.side_of_oriented_sphere_3_object()(p0, p1, p2, p3, p);
  if(os != ON_ORIENTED_BOUNDARY || !perturb)
    return os;

  // Two monomials always suffice: five points cannot have two disjoint
  // coplanar quadruples among the three largest.
  return perturbed_sphere_side(gt, p0, p1, p2, p3, p, 2);
}

// Side of `p` with respect to the circle through the non collinear p0, p1, p2,
// all four points coplanar.
template <class Gt, class Point>
Bounded_side coplanar_side_of_bounded_circle(const Gt& gt,
                                             const Point& p0, const Point& p1,
                                             const Point& p2, const Point& p,
                                             bool perturb)
{
  const Bounded_side bs = gt.coplanar_side_of_bounded_circle_3_object()(p0, p1, p2, p);
  if(bs != ON_BOUNDARY || !perturb)
    return bs;

  const Point* points[4] = {&p0, &p1, &p2, &p};
  std::sort(points, points + 4, Lexicographic_point_order<Gt>{gt});
  auto coplanar_orientation = gt.coplanar_orientation_3_object();
  const Orientation local = coplanar_orientation(p0, p1, p2);

  for(int i = 3; i > 0; --i)
  {
    if(points[i] == &p)
      return ON_UNBOUNDED_SIDE;
    Orientation o = COLLINEAR;
    if(points[i] == &p2) o = coplanar_orientation(p0, p1, p);
    else if(points[i] == &p1) o = coplanar_orientation(p0, p, p2);
    else o = coplanar_orientation(p, p1, p2);
    if(o != COLLINEAR)
      return Bounded_side(o * local);
  }
  // Only the monomial of p is left; its coefficient has the sign of `local`.
  return Bounded_side(-local);
}

// Whether `p` conflicts with cell `c` of `tr` (the test CGAL's Delaunay
// insertion uses). An infinite cell conflicts with the points beyond its hull
// facet, and with the coplanar points inside the facet's circumcircle.
template <class Tr>
Bounded_side side_of_sphere(const Tr& tr, typename Tr::Cell_handle c,
                            const typename Tr::Geom_traits::Point_3& p, bool perturb)
{
  const auto& gt = tr.geom_traits();
  int inf = -1;
  if(!c->has_vertex(tr.infinite_vertex(), inf))
    return Bounded_side(side_of_oriented_sphere(gt, internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()),
                                                internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point()),
                                                p, perturb));

  // The finite facet, ordered so that replacing the infinite vertex by p keeps
  // the cell's orientation (the same orders as CGAL, which matters for the
  // last case of the coplanar perturbation).
  static const int order[4][3] = {{2, 1, 3}, {2, 3, 0}, {1, 0, 3}, {0, 1, 2}};
  const auto& q0 = internal::bare_point(c->vertex(order[inf][0])->point());
  const auto& q1 = internal::bare_point(c->vertex(order[inf][1])->point());
  const auto& q2 = internal::bare_point(c->vertex(order[inf][2])->point());
  const Orientation o = gt.orientation_3_object()(q0, q1, q2, p);
  if(o != COPLANAR)
    return Bounded_side(o);
  return coplanar_side_of_bounded_circle(gt, q0, q1, q2, p, perturb);
}


// The power tests of a regular triangulation (weighted points), perturbed as
// Regular_triangulation_3 perturbs them: the same lexicographic ranks, more
// monomials (the weights can make more determinants vanish).
template <class Gt, class Weighted_point>
Oriented_side side_of_oriented_power_sphere(const Gt& gt,
                                            const Weighted_point& p0, const Weighted_point& p1,
                                            const Weighted_point& p2, const Weighted_point& p3,
                                            const Weighted_point& p, bool perturb)
{
  const Oriented_side os = gt.power_side_of_oriented_power_sphere_3_object()(p0, p1, p2, p3, p);
  if(os != ON_ORIENTED_BOUNDARY || !perturb)
    return os;

  // Three monomials, as Regular_triangulation_3 looks at.
  return perturbed_sphere_side(gt, p0, p1, p2, p3, p, 3);
}

// The coplanar power test of p against the positively oriented (in their
// plane) p0, p1, p2, perturbed as Regular_triangulation_3 does.
template <class Gt, class Weighted_point>
Oriented_side side_of_oriented_power_circle(const Gt& gt,
                                            const Weighted_point& p0, const Weighted_point& p1,
                                            const Weighted_point& p2, const Weighted_point& p, bool perturb)
{
  const Oriented_side os = gt.power_side_of_oriented_power_sphere_3_object()(p0, p1, p2, p);
  if(os != ON_ORIENTED_BOUNDARY || !perturb)
    return os;

  const Weighted_point* points[4] = {&p0, &p1, &p2, &p};
  std::sort(points, points + 4, [&](const Weighted_point* a, const Weighted_point* b) {
    return gt.compare_xyz_3_object()(bare_point(*a), bare_point(*b)) == SMALLER;
  });
  auto coplanar_orientation = [&](const Weighted_point& a, const Weighted_point& b, const Weighted_point& c) {
    return gt.coplanar_orientation_3_object()(bare_point(a), bare_point(b), bare_point(c));
  };
  for(int i = 3; i > 1; --i)
  {
    if(points[i] == &p)
      return ON_NEGATIVE_SIDE;
    Orientation o = COLLINEAR;
    if(points[i] == &p2) o = coplanar_orientation(p0, p1, p);
    else if(points[i] == &p1) o = coplanar_orientation(p0, p, p2);
    else o = coplanar_orientation(p, p1, p2);
    if(o != COLLINEAR)
      return Oriented_side(o);
  }
  CGAL_assertion(false);
  return ON_NEGATIVE_SIDE;
}

// Whether the weighted point `p` conflicts with cell `c` of `tr`, as
// Regular_triangulation_3 decides it (`in_conflict_3`).
template <class Tr>
Bounded_side side_of_power_sphere(const Tr& tr, typename Tr::Cell_handle c, const typename Tr::Point& p,
                                  bool perturb)
{
  const auto& gt = tr.geom_traits();
  int i3 = -1;
  if(!c->has_vertex(tr.infinite_vertex(), i3))
    return Bounded_side(side_of_oriented_power_sphere(gt, c->vertex(0)->point(), c->vertex(1)->point(),
                                                      c->vertex(2)->point(), c->vertex(3)->point(), p, perturb));
  const int i0 = (i3 % 2 == 1) ? (i3 + 1) & 3 : (i3 + 2) & 3;
  const int i1 = (i3 % 2 == 1) ? (i3 + 2) & 3 : (i3 + 1) & 3;
  const int i2 = (i3 + 3) & 3;
  const auto& q0 = c->vertex(i0)->point();
  const auto& q1 = c->vertex(i1)->point();
  const auto& q2 = c->vertex(i2)->point();
  const Orientation o = gt.orientation_3_object()(bare_point(q0), bare_point(q1), bare_point(q2), bare_point(p));
  if(o != ZERO)
    return Bounded_side(o);
  // Coplanar with the hull facet: the power circle, oriented in its plane.
  if(gt.coplanar_orientation_3_object()(bare_point(q0), bare_point(q1), bare_point(q2)) == POSITIVE)
    return Bounded_side(side_of_oriented_power_circle(gt, q0, q1, q2, p, perturb));
  return Bounded_side(side_of_oriented_power_circle(gt, q0, q2, q1, p, perturb));
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_PERTURBED_PREDICATES_H
