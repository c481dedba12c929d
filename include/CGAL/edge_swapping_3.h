// Edge_swapping_3: the 3-D edge-swapping method of Gandhi and Barth (1993) on
// CGAL::Triangulation_3. This header is the public entry: it brings in the
// criteria and defines the two drivers users call.
//
//   CGAL::swap_edges(tr, criterion, options)        Algorithm 3, any criterion
//   CGAL::swap_edges_with_helper(tr, options)       Algorithm 4, the helper strategy

#ifndef CGAL_EDGE_SWAPPING_3_H
#define CGAL_EDGE_SWAPPING_3_H

#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Swap_options.h>
#include <CGAL/Edge_swapping_3/internal/cycle_driver.h>
#include <type_traits>

namespace CGAL {

/// Algorithm 3 of the paper: cycles over all interior facets and swaps every
/// swappable configuration that `criterion` (a model of `SwapCriterion_3`)
/// prefers in its alternative form, until a cycle makes no swap.
/// With `Edge_swapping_3::Delaunay_criterion` the ending is CONVERGED only if
/// every facet is then locally Delaunay, else STUCK (Joe's local optima).
/// In a domain mesh, `constraints` (a model of `MeshConstraints_3`) keeps the
/// constrained facets and the subdomains: a flip that would remove the one or
/// join the other is not made.
template <class Tr, class Criterion, class Constraints = Edge_swapping_3::No_constraints>
Edge_swapping_3::Swap_report swap_edges(Tr& tr, const Criterion& criterion,
                                        const Edge_swapping_3::Swap_options& options = {},
                                        const Constraints& constraints = Constraints())
{
  using namespace Edge_swapping_3;
  std::array<typename Tr::Cell_handle, 4> created;
  auto report = Edge_swapping_3::internal::run_cycles(tr, options, [&](typename Tr::Cell_handle c, int i) {
    // The exact in-sphere test is cheaper than the classification, and most
    // facets pass it: for Delaunay, only a failing facet is classified.
    if constexpr(std::is_same<Criterion, Delaunay_criterion>::value)
      if(is_locally_delaunay(tr, c, i, criterion.perturbation)) return -1;
    const auto conf = classify_facet(tr, c, i);
    if(!conf.is_swappable() || !flip_respects_constraints(tr, conf.flip_plan(), constraints) ||
       !criterion(tr, conf))
      return -1;
    flip(tr, conf, created, constraints);
    return int(conf.flip_kind());
  });
  if constexpr(std::is_same<Criterion, Delaunay_criterion>::value)
  {
    report.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr, criterion.perturbation);
    if(report.ending == CONVERGED && report.non_delaunay_facets > 0) report.ending = STUCK;
  }
  return report;
}

/// Algorithm 4 of the paper, the helper strategy, for the Delaunay criterion:
/// a configuration that is not Delaunay tags its tetrahedra; a swappable
/// configuration with a tagged tetrahedron is swapped, Delaunay or not, which
/// lets a non-Delaunay concave configuration out of a local optimum.
/// A tag lives on its cell until a flip replaces the cell. Tags are kept in the
/// cells' TDS mark (`tds_data()`, which CGAL's own operations clear after use),
/// and all marks are clear again when the function returns.
/// `constraints` as for `swap_edges`.
template <class Tr, class Constraints = Edge_swapping_3::No_constraints>
Edge_swapping_3::Swap_report swap_edges_with_helper(Tr& tr,
                                                    const Edge_swapping_3::Swap_options& options = {},
                                                    const Constraints& constraints = Constraints())
{
  using namespace Edge_swapping_3;
  typedef typename Tr::Cell_handle Cell_handle;
  auto tagged = [](Cell_handle c) { return c->tds_data().is_in_conflict(); };
  std::array<Cell_handle, 4> created;

  auto report = Edge_swapping_3::internal::run_cycles(tr, options, [&](Cell_handle c, int i) {
    // A Delaunay facet between two untagged cells is skipped unclassified: a
    // swappable configuration with a tagged cell is also reached through a
    // facet of that cell, so no help is lost, only deferred.
    const bool delaunay = is_locally_delaunay(tr, c, i, options.perturbation);
    if(delaunay && !tagged(c) && !tagged(c->neighbor(i)))
      return -1;
    const auto conf = classify_facet(tr, c, i);
    if(!delaunay)
      for(int k = 0; k < conf.number_of_tetrahedra(); ++k) conf.tetrahedron(k)->tds_data().mark_in_conflict();
    if(!conf.is_swappable()) return -1;
    const auto& plan = conf.flip_plan();
    if(!flip_respects_constraints(tr, plan, constraints)) return -1;
    bool any_tagged = false;
    for(int k = 0; k < plan.number_of_old_cells; ++k) any_tagged = any_tagged || tagged(plan.old_cells[k]);
    if(!any_tagged) return -1;
    flip(tr, conf, created, constraints); // the new cells are untagged
    return int(conf.flip_kind());
  });
  for(auto c : tr.all_cell_handles()) c->tds_data().clear();
  report.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr, options.perturbation);
  if(report.ending == CONVERGED && report.non_delaunay_facets > 0) report.ending = STUCK;
  return report;
}

} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_H
