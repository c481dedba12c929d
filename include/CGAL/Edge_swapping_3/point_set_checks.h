// SPDX-License-Identifier: GPL-3.0-or-later
// The problems that keep a point set from having a 3-D triangulation, named
// for the user: coordinates not finite, an extent outside the supported range, too few points,
// duplicates, all coplanar. Exact predicates.

#ifndef CGAL_EDGE_SWAPPING_3_POINT_SET_CHECKS_H
#define CGAL_EDGE_SWAPPING_3_POINT_SET_CHECKS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>
#include <algorithm>
#include <cmath>
#include <charconv>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// The supported extent of a point set: along each axis, the largest
/// coordinate minus the smallest is at most `max_extent`, and along the
/// longest axis at least `min_extent`. Any finite coordinate is accepted
/// (1e-32 beside 1, a mesh placed at 1e20): the exact predicates have no
/// limit, and every construction the package makes (circumcenters, squared
/// distances, barycentric weights, the quality measures) works on coordinate
/// differences, which in this range stay finite and clear of underflow.
constexpr double max_extent = 1e30;
constexpr double min_extent = 1e-30; ///< the smallest extent along the longest axis

/// An empty string if `x` is a supported coordinate (a finite number); otherwise why not.
inline std::string coordinate_problem(double x)
{
  if(std::isnan(x)) return "a coordinate is not a number (nan)";
  if(std::isinf(x)) return "a coordinate is not finite";
  return std::string();
}

/// The shortest text that reads back as `x`.
inline std::string shortest_text(double x)
{
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  return std::string(text, end);
}

namespace internal {
/// How a message names point `k`: as `(*numbers)[k]` when given (the
/// numbering of the file, whose points that no tetrahedron uses were left
/// out before `k` was counted), otherwise as `k`.
struct Point_names
{
  const std::vector<std::size_t>* numbers = nullptr;
  std::string operator()(std::size_t k) const
  {
    return std::to_string(numbers != nullptr && k < numbers->size() ? (*numbers)[k] : k);
  }
};
} // namespace internal

/// An empty string if `points` (finite coordinates, within the supported extent) span 3-D
/// space with no point repeated; otherwise what is wrong, with 0-based point numbers. Named parameter:
/// `geom_traits` (CGAL's; default: the kernel of the points).
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::string point_set_problem(const std::vector<Point>& points,
                              const NamedParameters& np = CGAL::parameters::default_values(),
                              const internal::Point_names& name = internal::Point_names())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  const auto gt = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Kernel());
  const std::size_t n = points.size();
  double low[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, high[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(std::size_t k = 0; k < n; ++k)
    for(int c = 0; c < 3; ++c)
    {
      const double x = CGAL::to_double(points[k][c]);
      const std::string problem = coordinate_problem(x);
      if(!problem.empty()) return "point " + name(k) + ": " + problem;
      low[c] = (std::min)(low[c], x);
      high[c] = (std::max)(high[c], x);
    }
  if(n < 4) return "fewer than four points (" + std::to_string(n) + ")";
  double longest = 0;
  for(int c = 0; c < 3; ++c)
  {
    const double extent = high[c] - low[c]; // inf when the difference overflows
    if(!(extent <= max_extent))
      return std::string("the points span ") + (std::isinf(extent) ? "more than the largest double" : shortest_text(extent)) +
             " along " + "xyz"[c] + " (from " + shortest_text(low[c]) + " to " + shortest_text(high[c]) +
             "), more than 1e30, the largest extent supported: scale the coordinates";
    longest = (std::max)(longest, extent);
  }
  if(longest < min_extent)
    return "the points span only " + shortest_text(longest) +
           " along their longest axis, less than 1e-30, the smallest extent supported: scale the coordinates";

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  auto compare = gt.compare_xyz_3_object();
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return compare(points[a], points[b]) == SMALLER; });
  for(std::size_t k = 1; k < n; ++k)
    if(compare(points[order[k - 1]], points[order[k]]) == EQUAL)
    {
      const std::size_t a = (std::min)(order[k - 1], order[k]), b = (std::max)(order[k - 1], order[k]);
      return "duplicate points: point " + name(a) + " and point " + name(b);
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
