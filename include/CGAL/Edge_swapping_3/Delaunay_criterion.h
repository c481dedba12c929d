// SPDX-License-Identifier: GPL-3.0-or-later
// The Delaunay (InSphere) swap criterion and the local Delaunay test of a facet.

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_CRITERION_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_CRITERION_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/perturbed_predicates.h>
#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {

/// How cospherical (and, on the hull, cocircular) ties are broken.
enum Perturbation
{
  CGAL_PERTURBATION, ///< CGAL's symbolic perturbation: the result equals Delaunay_triangulation_3
  NO_PERTURBATION    ///< a point on the sphere does not violate it: any of the tied triangulations
};

namespace internal {

// `is_locally_delaunay` with its tie-breaking spelled out.
template <class Tr>
bool is_locally_delaunay(const Tr& tr, typename Tr::Cell_handle c, int i, Perturbation perturbation)
{
  internal::require_exact_predicates<typename Tr::Geom_traits>();
  const bool perturb = (perturbation == CGAL_PERTURBATION);
  const auto n = c->neighbor(i);
  const auto m = n->vertex(n->index(c));
  if(tr.is_infinite(m))
    return internal::side_of_sphere(tr, n, internal::bare_point(c->vertex(i)->point()), perturb) != ON_BOUNDED_SIDE;
  return internal::side_of_sphere(tr, c, internal::bare_point(m->point()), perturb) != ON_BOUNDED_SIDE;
}

// `number_of_non_delaunay_facets` with its tie-breaking spelled out.
template <class Tr>
std::size_t number_of_non_delaunay_facets(const Tr& tr, Perturbation perturbation)
{
  std::size_t n = 0;
  // Each facet once, from its cell of smaller address, as CGAL's facet
  // iterator does, in storage order with the cells ahead prefetched.
  internal::for_each_cell_prefetching(tr.tds().cells(), [&](typename Tr::Cell_handle c) {
    for(int i = 0; i < 4; ++i)
      if(internal::address_of(c) < internal::address_of(c->neighbor(i)) && !is_locally_delaunay(tr, c, i, perturbation))
        ++n;
  });
  return n;
}

} // namespace internal

/// Whether facet `(c, i)` is locally Delaunay: the vertex across it is not in
/// conflict with `c` under the test CGAL's Delaunay insertion uses (sphere of
/// a finite cell; for a cell outside a hull facet, the points beyond the facet
/// and the coplanar ones inside its circle). Facets on the hull always pass.
/// Named parameter: `perturbation` (default `CGAL_PERTURBATION`).
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_locally_delaunay(const Tr& tr, typename Tr::Cell_handle c, int i,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return internal::is_locally_delaunay(tr, c, i,
                                       choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION));
}

/// The number of facets (finite or not) of `tr` that are not locally Delaunay.
/// Named parameter: `perturbation` (default `CGAL_PERTURBATION`).
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t number_of_non_delaunay_facets(const Tr& tr, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return internal::number_of_non_delaunay_facets(
      tr, choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION));
}

/// \ingroup PkgEdgeSwapping3Criteria
/// Model of `SwapCriterion_3`: swap when the inspected facet is not locally
/// Delaunay. For five points with two triangulations exactly one is Delaunay
/// (with the perturbation), so a swap always moves toward the Delaunay triangulation.
///
/// It declares `is_delaunay_criterion`, so the drivers decide its visits with
/// the exact in-sphere test under their `perturbation` parameter (the one home
/// of the tie-breaking) and end on the Delaunay triangulation. Called on its
/// own, it breaks ties as CGAL does.
struct Delaunay_criterion
{
  static constexpr bool is_delaunay_criterion = true; ///< see `Is_delaunay_criterion`

  /// Whether the facet `conf` inspects is not locally Delaunay.
  template <class Tr>
  bool operator()(const Tr& tr, const Five_point_configuration<Tr>& conf) const
  {
    return !internal::is_locally_delaunay(tr, conf.cell(), conf.index(), CGAL_PERTURBATION);
  }
};

/// \ingroup PkgEdgeSwapping3Criteria
/// Whether the drivers treat `Criterion` as the Delaunay criterion (its fast
/// path, its endings, its repair): true when the criterion declares
/// `static constexpr bool is_delaunay_criterion = true`. The dispatch is on
/// this declaration, never on the type, so a user's wrapper that declares it
/// keeps every fast path and ending.
template <class Criterion, class = void>
struct Is_delaunay_criterion : std::false_type {};
template <class Criterion>
struct Is_delaunay_criterion<Criterion, std::enable_if_t<Criterion::is_delaunay_criterion>> : std::true_type {};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_CRITERION_H
