// SPDX-License-Identifier: GPL-3.0-or-later
// The swap drivers: Algorithm 3 of the paper for any criterion (with, for
// the Delaunay criterion, the repair of delaunay_repair.h, which ends on the
// Delaunay triangulation) and Algorithm 4, the helper strategy.
//
// A driver (internal/swap_driver.h) is a schedule (a work queue, or the
// paper's cycles), a rule (internal/swap_rules.h: what a visit of a facet
// decides) and an ending (converged, stuck, limit reached).

#ifndef CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H
#define CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/delaunay_repair.h>
#include <CGAL/Edge_swapping_3/internal/facet_scan.h>
#include <CGAL/Edge_swapping_3/internal/lawson_flips.h>
#include <CGAL/Edge_swapping_3/internal/swap_rules.h>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// `swap_edges` with its domain constraints made.
template <class Tr, class Criterion, class Constraints, class NamedParameters>
Swap_report swap_edges(Tr& tr, const Criterion& criterion, const Constraints& constraints, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  constexpr bool delaunay = Is_delaunay_criterion<Criterion>::value;
  static_assert(!delaunay || !Is_weighted_point<typename Tr::Point>::value,
                "a regular triangulation needs the power criterion, not the Delaunay one (not in the package yet)");

  CGAL::Real_timer total; // the report's time: the whole call
  total.start();
  const Driver_settings s = driver_settings(np, STORAGE_ORDER);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);
  const bool repair = choose_parameter(get_parameter(np, internal_np::delaunay_repair), true);
  typedef std::vector<std::pair<typename Tr::Cell_handle, int>> Facets;
  // The repair in storage order, where no visitor watches the visits or the
  // flips and no constraint or cell data must follow them, makes the common
  // plain flips itself (internal/lawson_flips.h) before the driver's.
  typedef decltype(choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_flip_visitor()))
      Flip_visitor_type;
  typedef decltype(choose_parameter(get_parameter(np, internal_np::visit_visitor), No_visit_visitor()))
      Visit_visitor_type;
  constexpr bool unwatched = delaunay && std::is_same<Constraints, No_constraints>::value &&
                             std::is_same<std::decay_t<Flip_visitor_type>, Default_flip_visitor>::value &&
                             std::is_same<std::decay_t<Visit_visitor_type>, No_visit_visitor>::value;
  const bool lawson = unwatched && repair && s.schedule == WORK_QUEUE && s.face_order == STORAGE_ORDER &&
                      s.perturbation == CGAL_PERTURBATION && tr.dimension() == 3;

  // Plain flips from `seeds` (the facets that need a visit; `scanned` facets
  // were tested to find them), or from every facet without `seeds`. Returns
  // the facets left not locally Delaunay in `stuck`.
  auto plain_flips = [&](Facets* seeds, std::size_t scanned, std::vector<Facet_key<Tr>>& stuck) {
    Cycle_record first_flips; // made before the driver, in its first round
    if constexpr(unwatched)
      if(seeds && lawson)
      {
        auto flips = lawson_flips(tr, *seeds, s.perturbation);
        *seeds = std::move(flips.left);
        first_flips.visits = flips.visits;
        first_flips.swaps = flips.swaps;
      }
    return with_driver(tr, s, constraints, np, [&](auto& driver) {
      Criterion_rule<Criterion> rule{criterion, s.perturbation};
      if(seeds) driver.seed_scanned(*seeds, scanned, first_flips);
      Swap_report r = driver.run(rule);
      if constexpr(delaunay)
      {
        decide_delaunay_ending(r, driver, s);
        if(r.ending != CONVERGED && s.schedule == WORK_QUEUE) stuck = driver.non_delaunay_facets_kept();
      }
      return r;
    });
  };

  // Delaunay: the rule decides nothing on a locally Delaunay facet, so the
  // first round is a scan of every facet with the in-sphere test alone (on
  // `number_of_threads` threads), and the driver visits the facets that
  // failed it, in the same order whatever the number of threads.
  std::vector<Facet_key<Tr>> stuck; // where plain flips are stuck: the facets left
  Swap_report report;
  bool scanned = false;
  if constexpr(delaunay)
    if(s.schedule == WORK_QUEUE && tr.dimension() == 3)
    {
      auto scan = failing_interior_facets(
          tr, [&](typename Tr::Cell_handle c, int i) { return !is_locally_delaunay(tr, c, i, s.perturbation); },
          threads);
      report = plain_flips(&scan.first, scan.second, stuck); // the scan is round 1's first part
      scanned = true;
    }
  if(!scanned) report = plain_flips(nullptr, 0, stuck);
  if constexpr(delaunay)
    if(report.ending != CONVERGED && repair) repair_to_delaunay(tr, report, stuck, plain_flips, lawson, s, constraints, np);
  report.seconds = total.time();
  return report;
}

} // namespace internal
} // namespace Edge_swapping_3

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Algorithm 3 of the paper: swaps every swappable configuration that
/// `criterion` prefers in its alternative form, until none is left.
///
/// With a Delaunay criterion (one whose `Is_delaunay_criterion` is true, such
/// as `Edge_swapping_3::Delaunay_criterion`) the result is the Delaunay
/// triangulation (CGAL's, cell for cell, with `CGAL_PERTURBATION`) from any
/// valid start: plain flips first; where they are stuck (Joe's local optima),
/// the helper strategy for at most `helper_rounds_before_rebuild` rounds; where
/// that has not converged, the cells are rebuilt by flip insertion of the
/// vertices (`delaunay_by_insertion()`; the vertices stay, every cell is
/// new). `report.repair_path` names the step that finished the work (or
/// the last one taken, when the ending is not `CONVERGED`), and each round's
/// `Cycle_record::rule` says whether it was a round of plain flips or of the
/// helper. Should the rebuild leave a facet not locally Delaunay (a defect:
/// not seen in any test or benchmark), the ending is `STUCK` with that count; no other
/// triangulator stands in. `delaunay_repair(false)` gives the paper's Algorithm 3 alone,
/// whose ending is then `CONVERGED` or `STUCK`. A domain mesh is never
/// rebuilt: its repair ends after the helper step.
///
/// The repair of an unconstrained triangulation on the work queue in storage
/// order, with no `visitor` or `visit_visitor` and `CGAL_PERTURBATION` (the
/// defaults), makes the common plain flips (2-3 and 3-2) itself in round 1,
/// in place, from each facet the scan found not locally Delaunay in turn, and
/// leaves the rest to the driver; where plain flips are stuck, it alternates
/// runs of the helper strategy (2 rounds, then 4, 8, ..., each in a new
/// random order) with plain flips until they are stuck again. Every swap is
/// still one the plain rule or the helper rule makes.
/// `report.helper_rounds` counts the helper's rounds, and
/// `report.first_helper_round` is the number of its first round.
///
/// \tparam Tr a `CGAL::Triangulation_3` (or a class derived from one, such as the
///   triangulation of a `Mesh_complex_3_in_triangulation_3`)
/// \tparam Criterion a model of `SwapCriterion_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
///
/// \param tr the triangulation, of dimension 3; changed in place
/// \param criterion decides whether the alternative triangulation of five points is better
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \pre `tr.dimension() == 3` and `tr.is_valid()`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{schedule}
///     \cgalParamDescription{how facets are visited: the work queue (only what changed) or the paper's cycles}
///     \cgalParamType{`Edge_swapping_3::Schedule`}
///     \cgalParamDefault{`Edge_swapping_3::WORK_QUEUE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_order}
///     \cgalParamDescription{the order of visits within a round; the helper step of the repair is in random
///       order unless this is given}
///     \cgalParamType{`Edge_swapping_3::Face_order`}
///     \cgalParamDefault{`Edge_swapping_3::STORAGE_ORDER` (memory locality)}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed of every random choice}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the round (cycle) limit}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{perturbation}
///     \cgalParamDescription{how a Delaunay criterion breaks cospherical ties}
///     \cgalParamType{`Edge_swapping_3::Perturbation`}
///     \cgalParamDefault{`Edge_swapping_3::CGAL_PERTURBATION` (the result equals CGAL's)}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{told before and after every flip}
///     \cgalParamType{a model of `FlipVisitor_3`}
///     \cgalParamDefault{`Edge_swapping_3::Default_flip_visitor`}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_is_constrained_map}
///     \cgalParamDescription{the facets that no swap may remove (boundaries, interfaces)}
///     \cgalParamType{a `ReadablePropertyMap` with `Tr::Facet` as key and `bool` as value; written back at the
///       end if it is also writable}
///     \cgalParamDefault{none, or the facets of the complex for a C3T3's triangulation}
///   \cgalParamNEnd
///   \cgalParamNBegin{cell_is_selected_map}
///     \cgalParamDescription{the cells that may change; a swap never joins a selected cell with another}
///     \cgalParamType{a `ReadablePropertyMap` with `Tr::Cell_handle` as key and `bool` as value}
///     \cgalParamDefault{every cell}
///   \cgalParamNEnd
///   \cgalParamNBegin{mesh_constraints}
///     \cgalParamDescription{a domain given as a model of the package's concept, instead of the two maps}
///     \cgalParamType{a model of `MeshConstraints_3`}
///     \cgalParamDefault{from the maps and the cells' subdomain indices}
///   \cgalParamNEnd
///   \cgalParamNBegin{cycle_visitor}
///     \cgalParamDescription{called after each round}
///     \cgalParamType{a callable `void(const Edge_swapping_3::Cycle_record&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{record_non_delaunay_facets}
///     \cgalParamDescription{count the non-Delaunay facets after each round (a full pass)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{with a Delaunay criterion on the work queue, the threads of the first round's scan (the in-sphere test of every facet), TBB's (`CGAL_LINKED_WITH_TBB`; without TBB, one); the run is the same whatever the number}
///     \cgalParamType{`unsigned`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{delaunay_repair}
///     \cgalParamDescription{with a Delaunay criterion, go on from a stuck state to the helper and the rebuild}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{helper_rounds_before_rebuild}
///     \cgalParamDescription{the rounds the helper step of the repair may take}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{100}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report: swaps per round by kind, the ending, the repair path
template <class Tr, class Criterion, class NamedParameters = parameters::Default_named_parameters>
Edge_swapping_3::Swap_report swap_edges(Tr& tr, const Criterion& criterion,
                                        const NamedParameters& np = parameters::default_values())
{
  return Edge_swapping_3::internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    return Edge_swapping_3::internal::swap_edges(tr, criterion, constraints, np);
  });
}

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Algorithm 4 of the paper, the helper strategy, for the Delaunay
/// criterion: a configuration that is not Delaunay tags its tetrahedra; a
/// swappable configuration with a tagged tetrahedron is swapped, Delaunay or
/// not, which lets a non-Delaunay concave configuration out of a local optimum.
/// A tag lives on its cell until a flip replaces the cell; tags are kept by
/// the driver, not in the cells. Its termination is not proved: the ending
/// is `CONVERGED`, `STUCK` or `CYCLE_LIMIT_REACHED`, never repaired.
///
/// \tparam Tr as for `swap_edges()`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr the triangulation, of dimension 3; changed in place
/// \param np the named parameters of `swap_edges()` but `delaunay_repair` and
///   `helper_rounds_before_rebuild`; `face_order` defaults to `RANDOM_ORDER`
///   (in storage order the helper can loop: laboratory/doc/findings.md)
/// \pre `tr.dimension() == 3` and `tr.is_valid()`
/// \return the report, as for `swap_edges()`
template <class Tr, class NamedParameters = parameters::Default_named_parameters>
Edge_swapping_3::Swap_report swap_edges_with_helper(Tr& tr, const NamedParameters& np = parameters::default_values())
{
  namespace ES = Edge_swapping_3;
  return ES::internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    return ES::internal::run_helper(tr, ES::internal::driver_settings(np, ES::RANDOM_ORDER), constraints, np);
  });
}

} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H
