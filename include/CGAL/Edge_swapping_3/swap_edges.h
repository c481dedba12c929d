// SPDX-License-Identifier: GPL-3.0-or-later
// The swap drivers: Algorithm 3 of the paper for any criterion (with, for
// the Delaunay criterion, a repair that ends on the Delaunay triangulation)
// and Algorithm 4, the helper strategy.
//
// A driver is a schedule (a work queue, or the paper's cycles), a rule (what a
// visit of a facet decides) and an ending (converged, stuck, limit reached).

#ifndef CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H
#define CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Flip_visitor.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/rebuild_delaunay.h>
#include <CGAL/Edge_swapping_3/internal/swap_driver.h>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// A criterion that declares `static constexpr bool is_delaunay_criterion = true`
/// (and has a `perturbation`) gets the Delaunay fast path and endings.
template <class C, class = void>
struct Is_delaunay_criterion : std::false_type {};
template <class C>
struct Is_delaunay_criterion<C, std::enable_if_t<C::is_delaunay_criterion>> : std::true_type {};

/// The settings from `np`; `default_order` when it names no face order.
template <class NamedParameters>
Driver_settings driver_settings(const NamedParameters& np, Face_order default_order)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Driver_settings s;
  s.schedule = choose_parameter(get_parameter(np, internal_np::schedule), WORK_QUEUE);
  s.face_order = choose_parameter(get_parameter(np, internal_np::face_order), default_order);
  s.random_seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  s.max_rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(1000));
  s.record_non_delaunay_facets = choose_parameter(get_parameter(np, internal_np::record_non_delaunay_facets), false);
  s.perturbation = choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION);
  s.cycle_visitor = choose_parameter(get_parameter(np, internal_np::cycle_visitor),
                                     std::function<void(const Cycle_record&)>());
  return s;
}

/// Algorithm 2 with a criterion: swap a swappable configuration the criterion prefers.
template <class Criterion>
struct Criterion_rule
{
  const Criterion& criterion;

  bool sees_facet_from_either_side() const
  {
    if constexpr(Is_delaunay_criterion<Criterion>::value) return criterion.perturbation == CGAL_PERTURBATION;
    else return false;
  }

  template <class Driver, class Cell_handle>
  void operator()(Driver& d, Cell_handle c, int i) const
  {
    constexpr bool delaunay = Is_delaunay_criterion<Criterion>::value;
    auto& tr = d.triangulation();
    // The exact in-sphere test is cheaper than the classification, and most
    // facets pass it: for Delaunay, only a failing facet is classified.
    if constexpr(delaunay)
      if(is_locally_delaunay(tr, c, i, criterion.perturbation)) return;
    const auto conf = classify_facet(tr, c, i);
    if(conf.is_swappable() && flip_respects_constraints(tr, conf.flip_plan(), d.constraints()) &&
       criterion(tr, conf))
      d.flip(conf);
    else
      d.keep(conf, delaunay, false);
  }
};

/// Algorithm 4: a non-Delaunay configuration tags its tetrahedra; a swappable
/// configuration with a tagged tetrahedron is swapped, Delaunay or not.
struct Helper_rule
{
  template <class Driver, class Cell_handle>
  void operator()(Driver& d, Cell_handle c, int i) const
  {
    auto& tr = d.triangulation();
    // A Delaunay facet between two untagged cells is skipped unclassified: a
    // swappable configuration with a tagged cell is also reached through a
    // facet of that cell, so no help is lost, only deferred.
    const bool delaunay = is_locally_delaunay(tr, c, i, d.perturbation());
    if(delaunay && !d.is_tagged(c) && !d.is_tagged(c->neighbor(i))) return;
    const auto conf = classify_facet(tr, c, i);
    if(!delaunay)
      for(int k = 0; k < conf.number_of_tetrahedra(); ++k) d.tag(conf.tetrahedron(k));
    if(conf.is_swappable() && flip_respects_constraints(tr, conf.flip_plan(), d.constraints()))
    {
      const auto& plan = conf.flip_plan();
      for(int k = 0; k < plan.number_of_old_cells; ++k)
        if(d.is_tagged(plan.old_cells[k]))
        {
          d.flip(conf); // the new cells are untagged
          return;
        }
    }
    // A non-Delaunay facet is visited again in the next round, as in a cycle.
    d.keep(conf, !delaunay, !delaunay);
  }
};

template <class Driver>
void decide_delaunay_ending(Swap_report& report, Driver& driver, const Driver_settings& s)
{
  report.non_delaunay_facets =
    (long long)((s.schedule == WORK_QUEUE) ? driver.number_of_non_delaunay_facets_left()
                                           : number_of_non_delaunay_facets(driver.triangulation(), s.perturbation));
  if(report.ending == CONVERGED && report.non_delaunay_facets > 0) report.ending = STUCK;
}

/// Calls `f(driver)` with the driver of `np`. The constraints and the visitor
/// are copies, as in CGAL: a visitor keeps its state behind a pointer or std::ref.
template <class Tr, class NamedParameters, class F>
auto with_driver(Tr& tr, const Driver_settings& s, const NamedParameters& np, F f)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto constraints = choose_parameter(get_parameter(np, internal_np::mesh_constraints), No_constraints());
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_flip_visitor());
  Swap_driver<Tr, std::remove_const_t<decltype(constraints)>, decltype(visitor)> driver(tr, s, constraints, visitor);
  return f(driver);
}

/// The helper; its first round visits `seeds` only when there are any.
template <class Tr, class NamedParameters>
Swap_report run_helper(Tr& tr, const Driver_settings& s, const NamedParameters& np,
                       const std::vector<Facet_key<Tr>>& seeds = {})
{
  return with_driver(tr, s, np, [&](auto& driver) {
    if(s.schedule == WORK_QUEUE) driver.seed(seeds);
    Helper_rule rule;
    Swap_report report = driver.run(rule);
    decide_delaunay_ending(report, driver, s);
    return report;
  });
}

} // namespace internal
} // namespace Edge_swapping_3

/// \brief Algorithm 3 of the paper: swaps every swappable configuration that
/// `criterion` (a model of `SwapCriterion_3`) prefers in its alternative form,
/// until none is left.
///
/// With `Edge_swapping_3::Delaunay_criterion` the result is the Delaunay
/// triangulation (CGAL's, cell for cell, with `CGAL_PERTURBATION`) from any
/// valid start: plain flips first; where they are stuck (Joe's local optima),
/// the helper strategy for at most `helper_rounds_before_rebuild` rounds; where
/// that has not converged, the cells are rebuilt from CGAL's Delaunay
/// triangulation of the vertices. `report.repair_path` says which step ended
/// the work. `delaunay_repair(false)` gives the paper's Algorithm 3 alone,
/// whose ending is then CONVERGED or STUCK. A mesh with constraints is never
/// rebuilt: its repair ends after the helper step.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{schedule} `WORK_QUEUE` (default) or `PAPER_CYCLES` \cgalParamNEnd
///   \cgalParamNBegin{face_order} `STORAGE_ORDER` (default: keeps memory locality) or `RANDOM_ORDER`;
///     the helper step of the repair is in `RANDOM_ORDER` unless this is given \cgalParamNEnd
///   \cgalParamNBegin{random_seed} `unsigned int`, default 0 \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} the round limit, default 1000 \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `FlipVisitor_3`, default `Default_flip_visitor` \cgalParamNEnd
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{cycle_visitor} called after each round \cgalParamNEnd
///   \cgalParamNBegin{record_non_delaunay_facets} `bool`, default false \cgalParamNEnd
///   \cgalParamNBegin{delaunay_repair} `bool`, default true \cgalParamNEnd
///   \cgalParamNBegin{helper_rounds_before_rebuild} `std::size_t`, default 100 \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Criterion, class NamedParameters = parameters::Default_named_parameters>
Edge_swapping_3::Swap_report swap_edges(Tr& tr, const Criterion& criterion,
                                        const NamedParameters& np = parameters::default_values())
{
  namespace ES = Edge_swapping_3;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  constexpr bool delaunay = ES::internal::Is_delaunay_criterion<Criterion>::value;

  ES::internal::Driver_settings s = ES::internal::driver_settings(np, ES::STORAGE_ORDER);
  if constexpr(delaunay) s.perturbation = criterion.perturbation; // the criterion's tie-breaking decides the ending
  typedef std::decay_t<decltype(choose_parameter(get_parameter(np, ES::internal_np::mesh_constraints),
                                                  ES::No_constraints()))> Constraints;
  // Where plain flips are stuck: the facets left, for the helper's first round.
  std::vector<ES::internal::Facet_key<Tr>> stuck;
  ES::Swap_report report = ES::internal::with_driver(tr, s, np, [&](auto& driver) {
    ES::internal::Criterion_rule<Criterion> rule{criterion};
    ES::Swap_report r = driver.run(rule);
    if constexpr(delaunay)
    {
      ES::internal::decide_delaunay_ending(r, driver, s);
      if(r.ending != ES::CONVERGED && s.schedule == ES::WORK_QUEUE) stuck = driver.non_delaunay_facets_kept();
    }
    return r;
  });
  if constexpr(delaunay)
  {
    if(report.ending == ES::CONVERGED || !choose_parameter(get_parameter(np, ES::internal_np::delaunay_repair), true))
      return report;

    // Stuck (or out of rounds): the helper, then the rebuild.
    report.stuck_after_plain_flips = report.non_delaunay_facets;
    ES::internal::Driver_settings hs = ES::internal::driver_settings(np, ES::RANDOM_ORDER);
    hs.perturbation = criterion.perturbation;
    hs.max_rounds = choose_parameter(get_parameter(np, ES::internal_np::helper_rounds_before_rebuild), std::size_t(100));
    // Without tags the helper does nothing on a Delaunay facet: its first
    // round needs only the facets plain flips left.
    ES::Swap_report helper = ES::internal::run_helper(tr, hs, np, stuck);
    report.repair_path = ES::HELPER_FLIPS;
    report.helper_rounds = helper.number_of_cycles();
    for(ES::Cycle_record r : helper.cycles)
    {
      r.cycle += report.cycles.size();
      report.cycles.push_back(r);
    }
    report.seconds += helper.seconds;
    report.ending = helper.ending;
    report.non_delaunay_facets = helper.non_delaunay_facets;
    if(report.ending != ES::CONVERGED && std::is_same<Constraints, ES::No_constraints>::value)
    {
      CGAL::Real_timer timer;
      timer.start();
      report.repair_path = ES::REBUILT;
      report.rebuilt_cells = ES::internal::rebuild_as_delaunay(tr);
      report.ending = ES::CONVERGED;
      report.non_delaunay_facets = 0;
      report.seconds += timer.time();
    }
  }
  return report;
}

/// \brief Algorithm 4 of the paper, the helper strategy, for the Delaunay
/// criterion: a configuration that is not Delaunay tags its tetrahedra; a
/// swappable configuration with a tagged tetrahedron is swapped, Delaunay or
/// not, which lets a non-Delaunay concave configuration out of a local optimum.
/// A tag lives on its cell until a flip replaces the cell; tags are kept by
/// the driver, not in the cells. Its termination is not proved: the ending
/// is CONVERGED, STUCK or CYCLE_LIMIT_REACHED, never repaired.
///
/// Named parameters as `swap_edges`, plus `perturbation` (the tie-breaking of
/// its Delaunay tests, default `CGAL_PERTURBATION`); no `delaunay_repair`.
/// Its default face order is `RANDOM_ORDER`: in storage order it can loop
/// (doc/Edge_swapping_3/findings.md).
template <class Tr, class NamedParameters = parameters::Default_named_parameters>
Edge_swapping_3::Swap_report swap_edges_with_helper(Tr& tr, const NamedParameters& np = parameters::default_values())
{
  return Edge_swapping_3::internal::run_helper(tr, Edge_swapping_3::internal::driver_settings(np, Edge_swapping_3::RANDOM_ORDER), np);
}

} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_SWAP_EDGES_H
