// The problems that keep a point set from having a 3-D triangulation, named
// for the user: too few points, duplicates, all coplanar. Exact predicates.

#ifndef CGAL_EDGE_SWAPPING_3_POINT_SET_CHECKS_H
#define CGAL_EDGE_SWAPPING_3_POINT_SET_CHECKS_H

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// An empty string if `points` (finite coordinates) span 3-D space with no
/// point repeated; otherwise what is wrong, with 0-based point numbers.
template <class Gt>
std::string point_set_problem(const std::vector<typename Gt::Point_3>& points, const Gt& gt = Gt())
{
  const std::size_t n = points.size();
  if(n < 4) return "fewer than four points (" + std::to_string(n) + ")";

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  auto compare = gt.compare_xyz_3_object();
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return compare(points[a], points[b]) == SMALLER; });
  for(std::size_t k = 1; k < n; ++k)
    if(compare(points[order[k - 1]], points[order[k]]) == EQUAL)
    {
      const std::size_t a = (std::min)(order[k - 1], order[k]), b = (std::max)(order[k - 1], order[k]);
      return "duplicate points: point " + std::to_string(a) + " and point " + std::to_string(b);
    }

  // Find a non-degenerate tetrahedron: the first point, a second one, a
  // third not collinear with them, a fourth not coplanar with the three.
  auto collinear = gt.collinear_3_object();
  auto orientation = gt.orientation_3_object();
  std::size_t k = 2;
  while(k < n && collinear(points[0], points[1], points[k])) ++k;
  if(k == n) return "all points are collinear";
  std::size_t m = 2;
  while(m < n && (m == k || orientation(points[0], points[1], points[k], points[m]) == COPLANAR)) ++m;
  if(m == n) return "all points are coplanar";
  return std::string();
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_POINT_SET_CHECKS_H
