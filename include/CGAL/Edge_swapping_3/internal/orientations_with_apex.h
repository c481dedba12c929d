// SPDX-License-Identifier: GPL-3.0-or-later
// The three orientation tests of a link flip at once: for a cell c and its
// vertex i (the new vertex), the orientation of c with each other vertex k
// replaced by a point e. All three share the translation by c's vertex i, so
// they are computed from four translated vectors instead of nine, under the
// semi-static error bound of CGAL's own Orientation_3 filter (which holds for
// any choice of the point translated to the origin). Any sign the bound
// leaves open is decided by the kernel's exact Orientation_3.
//
// Only for kernels whose coordinates are doubles (Epick); the caller falls
// back to the kernel's predicate otherwise.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_ORIENTATIONS_WITH_APEX_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_ORIENTATIONS_WITH_APEX_H

#include <CGAL/determinant.h>
#include <CGAL/enum.h>
#include <array>
#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Gt>
constexpr bool has_double_coordinates()
{
  return std::is_same<typename Gt::FT, double>::value;
}

// `orientation[k]` for k != i: the orientation of (p[0], p[1], p[2], p[3])
// with p[k] replaced by e. p are the vertices of a positively oriented cell.
template <class Gt>
std::array<Orientation, 4> orientations_with_apex(const Gt& gt,
                                                  const std::array<const typename Gt::Point_3*, 4>& p,
                                                  int i, const typename Gt::Point_3& e)
{
  std::array<Orientation, 4> result{};
  const auto& o = *p[i];
  std::array<std::array<double, 3>, 4> d; // p[m] - o, and e - o in slot i
  for(int m = 0; m < 4; ++m)
  {
    const auto& q = (m == i) ? e : *p[m];
    d[m] = {q.x() - o.x(), q.y() - o.y(), q.z() - o.z()};
  }
  // Moving p[i] to the front of the four points is i transpositions.
  const bool odd = (i & 1) != 0;
  for(int k = 0; k < 4; ++k)
  {
    if(k == i) continue;
    std::array<const std::array<double, 3>*, 3> r;
    for(int m = 0, j = 0; m < 4; ++m)
      if(m != i) r[j++] = (m == k) ? &d[i] : &d[m];
    double maxx = 0, maxy = 0, maxz = 0;
    for(const auto* row : r)
    {
      maxx = (std::max)(maxx, std::fabs((*row)[0]));
      maxy = (std::max)(maxy, std::fabs((*row)[1]));
      maxz = (std::max)(maxz, std::fabs((*row)[2]));
    }
    const double det = CGAL::determinant((*r[0])[0], (*r[0])[1], (*r[0])[2], (*r[1])[0], (*r[1])[1],
                                         (*r[1])[2], (*r[2])[0], (*r[2])[1], (*r[2])[2]);
    const double eps = 5.1107127829973299e-15 * maxx * maxy * maxz;
    const double lo = (std::min)({maxx, maxy, maxz}), hi = (std::max)({maxx, maxy, maxz});
    Orientation s = ZERO;
    bool decided = false;
    if(lo >= 1e-97 && hi < 1e102) // no underflow in eps, no overflow in det
    {
      if(det > eps) { s = POSITIVE; decided = true; }
      else if(det < -eps) { s = NEGATIVE; decided = true; }
    }
    if(decided)
      result[k] = odd ? Orientation(-s) : s;
    else
    {
      std::array<const typename Gt::Point_3*, 4> q = p;
      q[k] = &e;
      result[k] = gt.orientation_3_object()(*q[0], *q[1], *q[2], *q[3]);
    }
  }
  return result;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_ORIENTATIONS_WITH_APEX_H
