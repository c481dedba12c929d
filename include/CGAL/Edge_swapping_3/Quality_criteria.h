// SPDX-License-Identifier: GPL-3.0-or-later
// Swap criteria that compare the worst tetrahedron of the current and the
// alternative triangulation of a configuration: MinMax and MaxMin dihedral
// angle, and aspect ratio (both of the paper's definitions).
//
// The measures are computed in double precision, so a swap needs an
// improvement beyond a relative tolerance: otherwise rounding could make two
// triangulations each look better than the other, and a run could cycle.

#ifndef CGAL_EDGE_SWAPPING_3_QUALITY_CRITERIA_H
#define CGAL_EDGE_SWAPPING_3_QUALITY_CRITERIA_H

#include <type_traits>

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>

namespace CGAL {
namespace Edge_swapping_3 {

/// The worst value of `measure` (a function of four points) over the finite
/// tetrahedra of the current and of the alternative triangulation.
/// `larger_is_worse`: worst means largest; otherwise smallest.
template <class Tr, class Measure>
std::pair<double, double> worst_current_and_alternative(const Tr& tr,
                                                        const Five_point_configuration<Tr>& conf,
                                                        const Measure& measure,
                                                        bool larger_is_worse)
{
  const auto& plan = conf.flip_plan();
  auto worse = [&](double a, double b) { return larger_is_worse ? (std::max)(a, b) : (std::min)(a, b); };
  const double start = larger_is_worse ? -HUGE_VAL : HUGE_VAL;
  double current = start, alternative = start;
  for(int k = 0; k < plan.number_of_old_cells; ++k)
  {
    const auto c = plan.old_cells[k];
    if(tr.is_infinite(c)) continue;
    current = worse(current, measure(internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()),
                                     internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point())));
  }
  for(int k = 0; k < plan.number_of_new_cells; ++k)
  {
    const auto& t = plan.new_cells[k];
    if(tr.is_infinite(t[0]) || tr.is_infinite(t[1]) || tr.is_infinite(t[2]) || tr.is_infinite(t[3]))
      continue;
    alternative = worse(alternative, measure(internal::bare_point(t[0]->point()), internal::bare_point(t[1]->point()), internal::bare_point(t[2]->point()), internal::bare_point(t[3]->point())));
  }
  return {current, alternative};
}

/// Base of the criteria that improve the worst tetrahedron of a configuration.
template <class Measure, bool larger_is_worse>
struct Worst_tetrahedron_criterion
{
  /// A swap must improve the worst value by more than this fraction.
  double relative_tolerance = 1e-9;
  Measure measure; ///< the measure of one tetrahedron (a model of `TetrahedronMeasure_3`)

  /// Whether the worst tetrahedron of the alternative triangulation of `conf`
  /// is better than the worst of the current one, beyond the tolerance.
  template <class Tr>
  bool operator()(const Tr& tr, const Five_point_configuration<Tr>& conf) const
  {
    const auto [current, alternative] = worst_current_and_alternative(tr, conf, measure, larger_is_worse);
    if(larger_is_worse)
      return alternative < current * (1 - relative_tolerance);
    return alternative > current * (1 + relative_tolerance);
  }
};

namespace internal {
template <class Measure, bool larger_is_worse>
std::true_type is_worst_tetrahedron_criterion(const Worst_tetrahedron_criterion<Measure, larger_is_worse>*);
std::false_type is_worst_tetrahedron_criterion(...);
} // namespace internal

/// Whether `Criterion` is (or derives from) a `Worst_tetrahedron_criterion`,
/// the criteria that the quality operations (`remove_edge`,
/// `improve_worst_tetrahedra`, ...) take.
template <class Criterion>
struct Is_worst_tetrahedron_criterion
  : decltype(internal::is_worst_tetrahedron_criterion(static_cast<const Criterion*>(nullptr)))
{};

/// Model of `TetrahedronMeasure_3`: the largest dihedral angle, in degrees.
struct Largest_dihedral_angle
{
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return largest_dihedral_angle(a, b, c, d);
  }
};

/// Model of `TetrahedronMeasure_3`: the smallest dihedral angle, in degrees.
struct Smallest_dihedral_angle
{
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return smallest_dihedral_angle(a, b, c, d);
  }
};

/// Which of the paper's aspect ratios.
enum Aspect_ratio_definition
{
  EDGE_LENGTH_RATIO,          ///< longest over shortest edge
  CIRCUMRADIUS_OVER_INRADIUS  ///< circumradius over inradius R/r (the radius ratio 3r/R is 3 over it)
};

/// The aspect ratio, by default circumradius over inradius: the edge length
/// ratio is blind to slivers (four well-spaced points nearly coplanar), so
/// minimizing it can make the worst dihedral angles worse (on the two-spheres
/// mesh the worst went from 178.97 to 180.0 degrees).
struct Aspect_ratio
{
  Aspect_ratio_definition definition = CIRCUMRADIUS_OVER_INRADIUS; ///< which of the paper's two ratios
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return definition == EDGE_LENGTH_RATIO ? edge_length_ratio(a, b, c, d) : circumradius_over_inradius(a, b, c, d);
  }
};

/// 3 r / R, the inradius over the circumradius normalized: 1 for a regular
/// tetrahedron, 0 for a flat one (larger is better). A sliver, flat with
/// well-shaped faces, scores near 0, which the edge length ratio misses.
struct Normalized_radius_ratio
{
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return 3 / circumradius_over_inradius(a, b, c, d);
  }
};

/// The smallest dihedral sine, normalized (`minimum_dihedral_sine`; larger is better).
struct Minimum_dihedral_sine
{
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return minimum_dihedral_sine(a, b, c, d);
  }
};

/// The volume-length ratio (`volume_length_ratio`; larger is better).
struct Volume_length_ratio
{
  /// The measure of the tetrahedron `abcd`.
  template <class P>
  double operator()(const P& a, const P& b, const P& c, const P& d) const
  {
    return volume_length_ratio(a, b, c, d);
  }
};

/// Model of `SwapCriterion_3`: maximize the smallest normalized radius ratio 3 r / R.
typedef Worst_tetrahedron_criterion<Normalized_radius_ratio, false> Max_min_radius_ratio_criterion;

/// Model of `SwapCriterion_3`: maximize the smallest dihedral sine (both small and large angles are poor).
typedef Worst_tetrahedron_criterion<Minimum_dihedral_sine, false> Max_min_dihedral_sine_criterion;

/// Model of `SwapCriterion_3`: maximize the smallest volume-length ratio.
typedef Worst_tetrahedron_criterion<Volume_length_ratio, false> Max_min_volume_length_criterion;

/// Model of `SwapCriterion_3`: minimize the largest dihedral angle (MinMax).
typedef Worst_tetrahedron_criterion<Largest_dihedral_angle, true> Min_max_dihedral_angle_criterion;

/// Model of `SwapCriterion_3`: maximize the smallest dihedral angle (MaxMin).
typedef Worst_tetrahedron_criterion<Smallest_dihedral_angle, false> Max_min_dihedral_angle_criterion;

/// Model of `SwapCriterion_3`: minimize the largest aspect ratio (by default
/// the radius ratio; `EDGE_LENGTH_RATIO` for the paper's other one).
struct Aspect_ratio_criterion : Worst_tetrahedron_criterion<Aspect_ratio, true>
{
  Aspect_ratio_criterion() = default;
  /// The criterion of the ratio `d`.
  explicit Aspect_ratio_criterion(Aspect_ratio_definition d) { measure.definition = d; }
};

/// Model of `SwapCriterion_3`: the configuration with fewer tetrahedra (paper
/// section 4). Only 3-2 flips reduce the count; each removes an edge, a face
/// and a tetrahedron.
struct Min_edges_criterion
{
  /// Whether the alternative has fewer edges (a 2-3 flip adds one, a 3-2 flip removes one).
  template <class Tr>
  bool operator()(const Tr&, const Five_point_configuration<Tr>& conf) const
  {
    return conf.flip_kind() == FLIP_3_2;
  }
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_QUALITY_CRITERIA_H
