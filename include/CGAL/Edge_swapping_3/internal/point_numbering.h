// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers distinct points by their lexicographic rank, to compare cells of
// two triangulations of the same points.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_POINT_NUMBERING_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_POINT_NUMBERING_H

#include <CGAL/assertions.h>
#include <algorithm>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Gt>
class Point_numbering
{
public:
  typedef typename Gt::Point_3 Point;

  Point_numbering(std::vector<Point> points, const Gt& gt) : sorted_(std::move(points)), gt_(gt)
  {
    std::sort(sorted_.begin(), sorted_.end(), [this](const Point& p, const Point& q) { return less(p, q); });
  }

  std::size_t index(const Point& p) const
  {
    auto it = std::lower_bound(sorted_.begin(), sorted_.end(), p,
                               [this](const Point& a, const Point& b) { return less(a, b); });
    CGAL_assertion(it != sorted_.end() && !less(p, *it));
    return std::size_t(it - sorted_.begin());
  }

private:
  bool less(const Point& p, const Point& q) const
  {
    return gt_.compare_xyz_3_object()(p, q) == SMALLER;
  }
  std::vector<Point> sorted_;
  Gt gt_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_POINT_NUMBERING_H
