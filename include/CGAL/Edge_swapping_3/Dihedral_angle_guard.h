// SPDX-License-Identifier: GPL-3.0-or-later
// The guard that keeps a run's extreme dihedral angles: a measure adaptor
// that scores as the worst possible value every tetrahedron whose smallest
// dihedral angle is below a bound or whose largest is above one. Under a
// criterion of the guarded measure, every operation refuses to make such a
// tetrahedron, so a one-sided criterion (MinMax sees only the largest angle,
// MaxMin only the smallest) cannot trade one end for the other.

#ifndef CGAL_EDGE_SWAPPING_3_DIHEDRAL_ANGLE_GUARD_H
#define CGAL_EDGE_SWAPPING_3_DIHEDRAL_ANGLE_GUARD_H

#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {

// The four points in lexicographic order: the same four points give the
// same values whatever their order in a cell, so a tetrahedron that passed
// the guard when it was made passes it whenever it is measured again.
template <class P>
std::array<const P*, 4> in_lexicographic_order(const P& a, const P& b, const P& c, const P& d)
{
  std::array<const P*, 4> p = {&a, &b, &c, &d};
  auto order = [](const P*& u, const P*& v) {
    const double ux = CGAL::to_double(u->x()), vx = CGAL::to_double(v->x());
    bool swap = vx < ux;
    if(ux == vx)
    {
      const double uy = CGAL::to_double(u->y()), vy = CGAL::to_double(v->y());
      swap = vy < uy || (uy == vy && CGAL::to_double(v->z()) < CGAL::to_double(u->z()));
    }
    if(swap) std::swap(u, v);
  };
  // A sorting network of five comparisons (the points of a cell are distinct,
  // so any correct sort gives this order).
  order(p[0], p[1]);
  order(p[2], p[3]);
  order(p[0], p[2]);
  order(p[1], p[3]);
  order(p[1], p[2]);
  return p;
}

// The smallest and largest cosine of the dihedral angles of `abcd`,
// computed on the four points in lexicographic order.
template <class P>
std::pair<double, double> dihedral_cosine_extremes(const P& a, const P& b, const P& c, const P& d)
{
  const auto p = in_lexicographic_order(a, b, c, d);
  const auto cosines = dihedral_cosines(*p[0], *p[1], *p[2], *p[3]);
  const auto [lo, hi] = std::minmax_element(cosines.begin(), cosines.end());
  return {*lo, *hi};
}

// The same extremes, and `minimum_dihedral_sine` of the points in that
// order, from the same face normals: the guarded dihedral sine at the cost
// of one measure.
template <class P>
std::array<double, 3> dihedral_cosine_extremes_and_minimum_sine(const P& a, const P& b, const P& c, const P& d)
{
  const auto p = in_lexicographic_order(a, b, c, d);
  const auto v = to_vecs(*p[0], *p[1], *p[2], *p[3]);
  // The normals of minimum_dihedral_sine (the face opposite vertex k); the
  // cosines want them outward, and their sign changes no sine.
  std::array<Vec, 4> n;
  std::array<double, 4> lengths, outward;
  for(int k = 0; k < 4; ++k)
  {
    const Vec& o = v[(k + 1) & 3];
    n[k] = cross(sub(v[(k + 2) & 3], o), sub(v[(k + 3) & 3], o));
    lengths[k] = norm(n[k]);
    outward[k] = dot(n[k], sub(v[k], o)) > 0 ? -1.0 : 1.0;
  }
  double lo = 1, hi = -1, smallest = HUGE_VAL;
  for(int k = 0; k < 4; ++k)
    for(int l = k + 1; l < 4; ++l)
    {
      const double length = lengths[k] * lengths[l];
      const double c = length > 0 ? -(outward[k] * outward[l]) * dot(n[k], n[l]) / length : 1.0;
      const double cosine = std::isfinite(c) ? (std::max)(-1.0, (std::min)(1.0, c)) : 1.0;
      lo = (std::min)(lo, cosine);
      hi = (std::max)(hi, cosine);
      const double s = length > 0 ? norm(cross(n[k], n[l])) / length : 0.0;
      smallest = (std::min)(smallest, std::isfinite(s) ? s : 0.0);
    }
  return {lo, hi, smallest / (2 * std::sqrt(2.0) / 3)};
}

} // namespace internal

/// The range of dihedral angles allowed, as cosines (no `acos` per cell): a
/// tetrahedron is inside when the cosine of its smallest angle is at most
/// `smallest_angle_cosine` and that of its largest at least
/// `largest_angle_cosine`. The default allows every tetrahedron.
struct Dihedral_angle_range
{
  double smallest_angle_cosine = 1;  ///< cosine of the smallest angle allowed
  double largest_angle_cosine = -1;  ///< cosine of the largest angle allowed

  /// Widens the range to hold the tetrahedron `abcd`.
  template <class P>
  void extend(const P& a, const P& b, const P& c, const P& d)
  {
    const auto [lo, hi] = internal::dihedral_cosine_extremes(a, b, c, d);
    smallest_angle_cosine = (std::max)(smallest_angle_cosine, hi);
    largest_angle_cosine = (std::min)(largest_angle_cosine, lo);
  }

  /// Whether a tetrahedron whose dihedral angles have the cosines from
  /// `lo` to `hi` (`internal::dihedral_cosine_extremes`) is inside the range.
  bool contains_cosines(double lo, double hi) const
  {
    return hi <= smallest_angle_cosine && lo >= largest_angle_cosine;
  }

  /// Whether every dihedral angle of `abcd` is inside the range.
  template <class P>
  bool contains(const P& a, const P& b, const P& c, const P& d) const
  {
    const auto [lo, hi] = internal::dihedral_cosine_extremes(a, b, c, d);
    return contains_cosines(lo, hi);
  }
};

/// The smallest range that holds the finite cells of `tr` that `counted(c)` accepts.
/// Empty (every cosine out) when there is none.
template <class Tr, class Counted>
Dihedral_angle_range dihedral_angle_range(const Tr& tr, const Counted& counted)
{
  Dihedral_angle_range range{-1, 1};
  for(auto c : tr.finite_cell_handles())
    if(counted(c))
      range.extend(internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()),
                   internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point()));
  return range;
}

/// Model of `TetrahedronMeasure_3`: `measure`, except that a tetrahedron with
/// a dihedral angle outside `range` scores the worst value there is
/// (`+inf` when larger is worse, `-inf` otherwise).
template <class Measure, bool larger_is_worse>
struct Dihedral_angle_guarded
{
  Measure measure;             ///< the measure the criterion climbs
  Dihedral_angle_range range;  ///< the angles every tetrahedron keeps

  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    if constexpr(std::is_same<Measure, Minimum_dihedral_sine>::value)
    {
      const auto [lo, hi, sine] = internal::dihedral_cosine_extremes_and_minimum_sine(a, b, c, d);
      return range.contains_cosines(lo, hi) ? sine : -HUGE_VAL;
    }
    const auto [lo, hi] = internal::dihedral_cosine_extremes(a, b, c, d);
    if(!range.contains_cosines(lo, hi)) return larger_is_worse ? HUGE_VAL : -HUGE_VAL;
    // The extreme angles from the cosines just computed.
    if constexpr(std::is_same<Measure, Largest_dihedral_angle>::value) return internal::degrees_of_cosine(lo);
    else if constexpr(std::is_same<Measure, Smallest_dihedral_angle>::value) return internal::degrees_of_cosine(hi);
    else return measure(a, b, c, d);
  }
};

/// `criterion`, guarded: no operation under it makes a tetrahedron with a
/// dihedral angle outside `range`.
template <class Measure, bool larger_is_worse>
Worst_tetrahedron_criterion<Dihedral_angle_guarded<Measure, larger_is_worse>, larger_is_worse>
guarded_by_dihedral_angles(const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                           const Dihedral_angle_range& range)
{
  Worst_tetrahedron_criterion<Dihedral_angle_guarded<Measure, larger_is_worse>, larger_is_worse> guarded;
  guarded.relative_tolerance = criterion.relative_tolerance;
  guarded.measure.measure = criterion.measure;
  guarded.measure.range = range;
  return guarded;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DIHEDRAL_ANGLE_GUARD_H
