// SPDX-License-Identifier: GPL-3.0-or-later
// The tetrahedra that fill the outside of a domain mesh up to a box around
// it, made by TetGen's library with the domain's boundary kept as it is: no
// point is added on it, and added points lie strictly outside the domain.
// The domain's cells and these make a triangulation of a convex region (the
// box), which the package's algorithms need; the added cells are marked as
// outside the domain and never written back.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_EXTERIOR_FILL_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_EXTERIOR_FILL_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/enum.h>
#include <CGAL/intersections.h>
#include <CGAL/number_utils.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#ifdef CGAL_EDGE_SWAPPING_3_HAS_TETGEN
#ifndef TETLIBRARY
#define TETLIBRARY // TetGen's library throws its exit code instead of ending the process
#endif
#include <tetgen.h>
#endif

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The outside of a domain, filled: points added (after the mesh's own) and
/// tetrahedra by point number (the mesh's points first, then these).
struct Exterior_fill
{
  std::vector<std::array<double, 3>> added_points;
  std::vector<std::array<std::size_t, 4>> cells;
  std::size_t boundary_facets = 0;        ///< facets of one tetrahedron of the domain
  std::size_t components = 0;             ///< parts of the domain joined through facets
  std::string problem;                    ///< empty when the fill was made
};

struct Point_triple_hash
{
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const
  {
    const std::uint64_t h = (std::uint64_t(k[0]) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(k[1]) * 0xC2B2AE3D27D4EB4Full) ^
                            (std::uint64_t(k[2]) * 0x165667B19E3779F9ull);
    return std::size_t(h ^ (h >> 29));
  }
};

/// The boundary facets of `cells` (facets of exactly one tetrahedron), as
/// sorted point triples, and the parts of the mesh joined through shared
/// facets (`part[k]` for tetrahedron `k`). Returns what is wrong, or an empty string.
inline std::string boundary_and_parts(const std::vector<std::array<std::size_t, 4>>& cells,
                                      std::vector<std::array<std::uint32_t, 3>>& boundary,
                                      std::vector<std::uint32_t>& part, std::size_t& parts,
                                      const Point_names& name = Point_names())
{
  // Per sorted facet: the first tetrahedron that has it, and how many do.
  struct Seen { std::uint32_t cell; std::uint32_t count; };
  Flat_hash_map<std::array<std::uint32_t, 3>, Seen, Point_triple_hash> facets;
  std::vector<std::uint32_t> parent(cells.size());
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  auto root = [&](std::uint32_t k) {
    while(parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for(std::size_t k = 0; k < cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      std::array<std::uint32_t, 3> key = {std::uint32_t(cells[k][(i + 1) & 3]), std::uint32_t(cells[k][(i + 2) & 3]),
                                         std::uint32_t(cells[k][(i + 3) & 3])};
      std::sort(key.begin(), key.end());
      const auto slot = facets.emplace(key, Seen{std::uint32_t(k), 1});
      if(slot.second) continue;
      if(++slot.first->count > 2)
        return "the facet of points " + name(key[0]) + " " + name(key[1]) + " " + name(key[2]) +
               " is shared by more than two tetrahedra (tetrahedra overlap)";
      parent[root(std::uint32_t(k))] = root(slot.first->cell);
    }
  facets.for_each([&](const std::array<std::uint32_t, 3>& key, const Seen& s) {
    if(s.count == 1) boundary.push_back(key);
  });
  std::sort(boundary.begin(), boundary.end()); // independent of the table's layout
  part.assign(cells.size(), 0);
  std::vector<std::uint32_t> number(cells.size(), std::uint32_t(-1));
  parts = 0;
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    const std::uint32_t r = root(std::uint32_t(k));
    if(number[r] == std::uint32_t(-1)) number[r] = std::uint32_t(parts++);
    part[k] = number[r];
  }
  return std::string();
}

/// Whether the triangles `a` and `b` of `points` (sorted point numbers, of a
/// closed boundary) meet in more than the points and edge they share: exact.
template <class Point>
bool triangles_overlap(const std::vector<Point>& points, const std::array<std::uint32_t, 3>& a,
                       const std::array<std::uint32_t, 3>& b)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Triangle_3 Triangle;
  typedef typename K::Segment_3 Segment;
  const K kernel;
  const auto orientation = kernel.orientation_3_object();
  const auto coplanar_orientation = kernel.coplanar_orientation_3_object();
  const auto do_intersect = kernel.do_intersect_3_object();
  std::vector<std::uint32_t> shared, only_a, only_b;
  for(auto v : a) (std::find(b.begin(), b.end(), v) != b.end() ? shared : only_a).push_back(v);
  for(auto v : b)
    if(std::find(a.begin(), a.end(), v) == a.end()) only_b.push_back(v);
  const Triangle ta(points[a[0]], points[a[1]], points[a[2]]), tb(points[b[0]], points[b[1]], points[b[2]]);
  if(shared.empty()) return do_intersect(ta, tb);
  if(shared.size() == 2)
  {
    // Across their common edge: only a fold (coplanar, on one side) overlaps.
    const Point &u = points[shared[0]], &v = points[shared[1]], &p = points[only_a[0]], &q = points[only_b[0]];
    return orientation(u, v, p, q) == CGAL::COPLANAR && coplanar_orientation(u, v, p, q) == CGAL::POSITIVE;
  }
  if(shared.size() == 3) return true;
  // One common point w: an opposite edge meets the other triangle, or an
  // edge from w runs into the other triangle's angle at w (in its plane).
  const Point& w = points[shared[0]];
  auto enters = [&](const Point& x, const Point& r, const Point& s) { // w->x into the angle r w s
    if(orientation(w, r, s, x) != CGAL::COPLANAR) return false;
    const CGAL::Orientation by_r = coplanar_orientation(w, r, s, x), by_s = coplanar_orientation(w, s, r, x);
    return (by_r == CGAL::POSITIVE && by_s == CGAL::POSITIVE) || (by_r == CGAL::COLLINEAR && by_s == CGAL::POSITIVE) ||
           (by_s == CGAL::COLLINEAR && by_r == CGAL::POSITIVE);
  };
  const Point &a1 = points[only_a[0]], &a2 = points[only_a[1]], &b1 = points[only_b[0]], &b2 = points[only_b[1]];
  return do_intersect(Segment(a1, a2), tb) || do_intersect(Segment(b1, b2), ta) || enters(a1, b1, b2) ||
         enters(a2, b1, b2) || enters(b1, a1, a2) || enters(b2, a1, a2);
}

/// An empty string if the boundary triangles `boundary` of `points` meet
/// only at their common points and edges; else the first two that overlap.
/// Exact; candidate pairs by CGAL's intersection of boxes.
template <class Point>
std::string boundary_overlap(const std::vector<Point>& points, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                             const Point_names& point_name = Point_names())
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t> Box;
  std::vector<Box> boxes;
  boxes.reserve(boundary.size());
  for(std::size_t k = 0; k < boundary.size(); ++k)
  {
    const auto& t = boundary[k];
    boxes.emplace_back(points[t[0]].bbox() + points[t[1]].bbox() + points[t[2]].bbox(), k);
  }
  std::string found;
  try
  {
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
      const auto &a = boundary[x.info()], &b = boundary[y.info()];
      if(!triangles_overlap(points, a, b)) return;
      auto name = [&](const std::array<std::uint32_t, 3>& t) {
        return point_name(t[0]) + " " + point_name(t[1]) + " " + point_name(t[2]);
      };
      found = "the boundary intersects itself: its triangles of points " + name((std::min)(a, b)) + " and " +
              name((std::max)(a, b)) + " overlap (tetrahedra overlap, or the mesh is not conforming)";
      throw 0; // one is enough
    });
  }
  catch(int)
  {
  }
  return found;
}

/// 6 V / L^3 of tetrahedron `t` of `points` (L its longest edge): 0 flat,
/// 0.94 at most (regular), in double precision on the edge vectors scaled
/// as the quality measures scale them (`to_vecs`: no overflow or underflow).
template <class Point>
double relative_volume(const std::vector<Point>& points, const std::array<std::size_t, 4>& t)
{
  const auto v = to_vecs(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
  double longest = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) longest = (std::max)(longest, norm(sub(v[i], v[j])));
  if(!(longest > 0)) return 0;
  return std::abs(dot(v[1], cross(v[2], v[3]))) / (longest * longest * longest);
}

/// Fills the outside of the domain that the tetrahedra `cells` of `points`
/// mesh, up to a box around the points (its corners are the first added
/// points), keeping the domain's boundary: the returned tetrahedra and
/// `cells` together cover the box once, if TetGen succeeded. Their
/// orientation is TetGen's; the caller orients them and checks the whole exactly.
template <class Point>
Exterior_fill fill_exterior(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 4>>& cells,
                            const Point_names& point_name = Point_names())
{
  Exterior_fill fill;
  std::vector<std::array<std::uint32_t, 3>> boundary;
  std::vector<std::uint32_t> part;
  fill.problem = boundary_and_parts(cells, boundary, part, fill.components, point_name);
  if(!fill.problem.empty()) return fill;
  fill.boundary_facets = boundary.size();
  // TetGen's library crashes when it gives up (its error path frees its
  // memory twice), and its recovery of a boundary can run without end near a
  // tetrahedron too flat for double precision (seen under fuzzing): such
  // input is refused here first.
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    const double flatness = relative_volume(points, cells[k]);
    if(!(flatness >= 1e-12))
      return fill.problem = "tetrahedron " + std::to_string(k) + " is too flat for double precision (6 V / L^3 = " +
                            shortest_text(flatness) + ", L its longest edge) to complete the domain around it: "
                            "repair or remove it in the mesher",
             fill;
  }
  fill.problem = boundary_overlap(points, boundary, point_name);
  if(!fill.problem.empty()) return fill;
#ifndef CGAL_EDGE_SWAPPING_3_HAS_TETGEN
  fill.problem = "the mesh is not a triangulation of the convex hull of its points (a non-convex domain, cavities "
                 "or several parts), and completing it needs TetGen's library: build with libtet1.5-dev";
  return fill;
#else
  auto xyz = [&](std::size_t v) {
    const Point& p = points[v];
    return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  // TetGen sees the boundary's points only, then the box's corners.
  std::vector<std::uint32_t> local(points.size(), std::uint32_t(-1));
  std::vector<std::size_t> global;
  for(const auto& f : boundary)
    for(auto v : f)
      if(local[v] == std::uint32_t(-1))
      {
        local[v] = std::uint32_t(global.size());
        global.push_back(v);
      }
  std::array<double, 3> low, high;
  low.fill(HUGE_VAL);
  high.fill(-HUGE_VAL);
  for(std::size_t v : global)
  {
    const auto p = xyz(v);
    for(int a = 0; a < 3; ++a)
    {
      low[a] = (std::min)(low[a], p[a]);
      high[a] = (std::max)(high[a], p[a]);
    }
  }
  // A margin of half the largest extent on every side: the box is well
  // shaped even around a flat domain, and its corners are far from it.
  double extent = 0;
  for(int a = 0; a < 3; ++a) extent = (std::max)(extent, high[a] - low[a]);
  for(int a = 0; a < 3; ++a)
  {
    low[a] -= extent / 2;
    high[a] += extent / 2;
  }
  for(int corner = 0; corner < 8; ++corner)
    fill.added_points.push_back({(corner & 1) ? high[0] : low[0], (corner & 2) ? high[1] : low[1],
                                 (corner & 4) ? high[2] : low[2]});

  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(global.size() + 8);
  in.pointlist = new REAL[3 * std::size_t(in.numberofpoints)];
  for(std::size_t k = 0; k < global.size(); ++k)
  {
    const auto p = xyz(global[k]);
    for(int a = 0; a < 3; ++a) in.pointlist[3 * k + a] = p[a];
  }
  for(int corner = 0; corner < 8; ++corner)
    for(int a = 0; a < 3; ++a) in.pointlist[3 * (global.size() + corner) + a] = fill.added_points[corner][a];
  // The box's six sides (corner bits: x, y, z), then the domain's boundary triangles.
  static const int sides[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  in.numberoffacets = int(6 + boundary.size());
  in.facetlist = new tetgenio::facet[std::size_t(in.numberoffacets)];
  in.facetmarkerlist = new int[std::size_t(in.numberoffacets)];
  for(int f = 0; f < in.numberoffacets; ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::polygon& polygon = facet.polygonlist[0];
    tetgenio::init(&polygon);
    polygon.numberofvertices = f < 6 ? 4 : 3;
    polygon.vertexlist = new int[std::size_t(polygon.numberofvertices)];
    for(int j = 0; j < polygon.numberofvertices; ++j)
      polygon.vertexlist[j] = f < 6 ? int(global.size()) + sides[f][j] : int(local[boundary[std::size_t(f - 6)][j]]);
    in.facetmarkerlist[f] = f < 6 ? 1 : 2;
  }
  // A hole inside each part of the domain: the centroid of its roundest
  // tetrahedron (the test of the whole, after, catches a centroid misplaced).
  std::vector<double> best(fill.components, -1.0);
  std::vector<std::array<double, 3>> hole(fill.components);
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    std::array<std::array<double, 3>, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = xyz(cells[k][i]);
    std::array<std::array<double, 3>, 3> e;
    double lengths = 0;
    for(int i = 0; i < 3; ++i)
      for(int a = 0; a < 3; ++a)
      {
        e[i][a] = p[i + 1][a] - p[0][a];
        lengths += e[i][a] * e[i][a];
      }
    const double volume = std::abs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                   e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                   e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]));
    const double roundness = lengths > 0 ? volume / std::pow(lengths, 1.5) : 0;
    if(roundness > best[part[k]])
    {
      best[part[k]] = roundness;
      for(int a = 0; a < 3; ++a) hole[part[k]][a] = (p[0][a] + p[1][a] + p[2][a] + p[3][a]) / 4;
    }
  }
  in.numberofholes = int(fill.components);
  in.holelist = new REAL[3 * fill.components];
  for(std::size_t h = 0; h < fill.components; ++h)
    for(int a = 0; a < 3; ++a) in.holelist[3 * h + a] = hole[h][a];

  // p: a piecewise linear complex; Y: its facets as they are, points added
  // only inside the volume; M: no merging of coplanar facets; z: numbers
  // from 0; Q: quiet.
  char switches[] = "pYMzQ";
  try
  {
    tetrahedralize(switches, &in, &out);
  }
  catch(int code)
  {
    fill.problem = code == 3   ? "its boundary intersects itself (tetrahedra overlap, or the mesh is not conforming)"
                   : code == 1 ? "out of memory while completing the domain to its convex hull"
                               : "TetGen could not fill the outside of the domain (its code " + std::to_string(code) +
                                     "): the boundary may not be a closed, non-intersecting surface";
    return fill;
  }
  for(int k = int(global.size()) + 8; k < out.numberofpoints; ++k)
    fill.added_points.push_back({out.pointlist[3 * k], out.pointlist[3 * k + 1], out.pointlist[3 * k + 2]});
  auto number = [&](int v) {
    if(v < int(global.size())) return global[std::size_t(v)];
    return points.size() + std::size_t(v - int(global.size()));
  };
  fill.cells.reserve(std::size_t(out.numberoftetrahedra));
  for(int k = 0; k < out.numberoftetrahedra; ++k)
  {
    const int* t = out.tetrahedronlist + std::size_t(k) * std::size_t(out.numberofcorners);
    fill.cells.push_back({number(t[0]), number(t[1]), number(t[2]), number(t[3])});
  }
  return fill;
#endif
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_EXTERIOR_FILL_H
