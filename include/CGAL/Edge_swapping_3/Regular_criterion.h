// SPDX-License-Identifier: GPL-3.0-or-later
// The regular (power) swap criterion of a triangulation of weighted points
// (a CGAL::Regular_triangulation_3, Mesh_3's triangulations among them), and
// the local regularity test of a facet.

#ifndef CGAL_EDGE_SWAPPING_3_REGULAR_CRITERION_H
#define CGAL_EDGE_SWAPPING_3_REGULAR_CRITERION_H

#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/internal/perturbed_predicates.h>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {

// `is_locally_regular` with its tie-breaking spelled out.
template <class Tr>
bool is_locally_regular(const Tr& tr, typename Tr::Cell_handle c, int i, Perturbation perturbation)
{
  const bool perturb = (perturbation == CGAL_PERTURBATION);
  const auto n = c->neighbor(i);
  const auto m = n->vertex(n->index(c));
  if(tr.is_infinite(m))
    return internal::side_of_power_sphere(tr, n, c->vertex(i)->point(), perturb) != ON_BOUNDED_SIDE;
  return internal::side_of_power_sphere(tr, c, m->point(), perturb) != ON_BOUNDED_SIDE;
}

} // namespace internal

/// Whether facet `(c, i)` of a triangulation of weighted points is locally
/// regular: the vertex across it is not in conflict with `c` under the power
/// test that CGAL's `Regular_triangulation_3` uses (with its symbolic
/// perturbation under `CGAL_PERTURBATION`). Facets on the hull always pass.
/// Named parameter: `perturbation` (default `CGAL_PERTURBATION`).
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_locally_regular(const Tr& tr, typename Tr::Cell_handle c, int i,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return internal::is_locally_regular(tr, c, i,
                                      choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION));
}

/// \ingroup PkgEdgeSwapping3Criteria
/// Model of `SwapCriterion_3` for weighted points: swap when the inspected
/// facet is not locally regular (the power criterion of Edelsbrunner and
/// Shah). It declares `is_regular_criterion`: `insert_by_swapping` then makes
/// the regular triangulation, removing the vertices a heavier point makes
/// redundant (4-1 flips), and hides a point that is redundant itself, as
/// `Regular_triangulation_3` does.
struct Regular_criterion
{
  static constexpr bool is_regular_criterion = true; ///< see `Is_regular_criterion`

  /// Whether the facet `conf` inspects is not locally regular.
  template <class Tr>
  bool operator()(const Tr& tr, const Five_point_configuration<Tr>& conf) const
  {
    return !internal::is_locally_regular(tr, conf.cell(), conf.index(), CGAL_PERTURBATION);
  }
};

/// \ingroup PkgEdgeSwapping3Criteria
/// Whether `Criterion` is the regular (power) criterion: true when it
/// declares `static constexpr bool is_regular_criterion = true`.
template <class Criterion, class = void>
struct Is_regular_criterion : std::false_type {};
template <class Criterion>
struct Is_regular_criterion<Criterion, std::enable_if_t<Criterion::is_regular_criterion>> : std::true_type {};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_REGULAR_CRITERION_H
