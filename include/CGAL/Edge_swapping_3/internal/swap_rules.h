// SPDX-License-Identifier: GPL-3.0-or-later
// The two rules of the swap drivers, Algorithm 3's (a criterion) and
// Algorithm 4's (the helper), the settings a run takes from its named
// parameters, and a run of the driver with them.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_RULES_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_RULES_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Flip_visitor.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/swap_driver.h>
#include <functional>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

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
  s.reading = choose_parameter(get_parameter(np, internal_np::helper_reading), Helper_reading());
  return s;
}

/// Algorithm 2 with a criterion: swap a swappable configuration the criterion prefers.
template <class Criterion>
struct Criterion_rule
{
  static constexpr Round_rule round_rule = PLAIN_RULE;
  const Criterion& criterion;
  Perturbation perturbation; // the tie-breaking of a Delaunay criterion's test

  bool sees_facet_from_either_side() const
  {
    if constexpr(Is_delaunay_criterion<Criterion>::value) return perturbation == CGAL_PERTURBATION;
    else return false;
  }

  template <class Driver, class Cell_handle>
  void operator()(Driver& d, Cell_handle c, int i) const
  {
    constexpr bool delaunay = Is_delaunay_criterion<Criterion>::value;
    auto& tr = d.triangulation();
    // The exact in-sphere test is cheaper than the classification, and most
    // facets pass it: for Delaunay, only a failing facet is classified, and
    // the criterion is not asked again (the test under `perturbation` is it).
    if constexpr(delaunay)
      if(is_locally_delaunay(tr, c, i, perturbation)) return;
    const auto conf = classify_facet(tr, c, i);
    if(conf.is_swappable() && flip_respects_constraints(tr, conf.flip_plan(), d.constraints()) &&
       (delaunay || criterion(tr, conf)))
      d.flip(conf);
    else
      d.keep(conf, delaunay, false);
  }
};

/// Algorithm 4: a non-Delaunay configuration tags its tetrahedra; a swappable
/// configuration with a tagged tetrahedron is swapped, Delaunay or not.
struct Helper_rule
{
  Helper_swap_condition condition = PASS_OVER_UNTAGGED_DELAUNAY_FACETS; // Helper_reading::swap_condition
  static constexpr bool reads_only_cells_and_tags = true; // a fixed-order run that comes back to a state loops
  static constexpr Round_rule round_rule = HELPER_RULE;

  template <class Driver, class Cell_handle>
  void operator()(Driver& d, Cell_handle c, int i) const
  {
    auto& tr = d.triangulation();
    // A Delaunay facet between two untagged cells is skipped unclassified: a
    // swappable configuration with a tagged cell is also reached through a
    // facet of that cell, so no help is lost, only deferred.
    const bool delaunay = is_locally_delaunay(tr, c, i, d.perturbation());
    // (With a tag needed on the facet's cells, such a visit swaps nothing either.)
    const bool pass_over = condition != TAG_ON_ANY_TETRAHEDRON;
    if(pass_over && delaunay && !d.is_tagged(c) && !d.is_tagged(c->neighbor(i))) return;
    const auto conf = classify_facet(tr, c, i);
    if(!delaunay)
      for(int k = 0; k < conf.number_of_tetrahedra(); ++k) d.tag(conf.tetrahedron(k));
    if(conf.is_swappable() && flip_respects_constraints(tr, conf.flip_plan(), d.constraints()))
    {
      const auto& plan = conf.flip_plan();
      bool tagged = false;
      if(condition == TAG_ON_FACET_CELLS)
        tagged = d.is_tagged(c) || d.is_tagged(c->neighbor(i));
      else
        for(int k = 0; k < plan.number_of_old_cells; ++k) tagged = tagged || d.is_tagged(plan.old_cells[k]);
      if(tagged)
      {
        d.flip(conf); // the new cells are untagged (unless the reading remembers their vertices)
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

/// Calls `f(driver)` with the driver of `np`. The visitor is a copy, as in
/// CGAL: a visitor keeps its state behind a pointer or std::ref.
template <class Tr, class Constraints, class NamedParameters, class F>
auto with_driver(Tr& tr, const Driver_settings& s, const Constraints& constraints, const NamedParameters& np, F f)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_flip_visitor());
  auto visit_visitor = choose_parameter(get_parameter(np, internal_np::visit_visitor), No_visit_visitor());
  Swap_driver<Tr, Constraints, decltype(visitor), decltype(visit_visitor)> driver(tr, s, constraints, visitor,
                                                                                  visit_visitor);
  return f(driver);
}

/// The helper; its first round visits `seeds` only when there are any.
template <class Tr, class Constraints, class NamedParameters>
Swap_report run_helper(Tr& tr, const Driver_settings& s, const Constraints& constraints, const NamedParameters& np,
                       const std::vector<Facet_key<Tr>>& seeds = {}, std::vector<Facet_key<Tr>>* left = nullptr)
{
  static_assert(!Is_weighted_point<typename Tr::Point>::value,
                "the helper strategy is for Delaunay triangulations of bare points");
  return with_driver(tr, s, constraints, np, [&](auto& driver) {
    if(s.schedule == WORK_QUEUE) driver.seed(seeds);
    if(s.schedule == WORK_QUEUE && !s.reading.is_default())
      throw std::invalid_argument("Edge_swapping_3: the readings of Algorithm 4 other than the package's run on the "
                                  "paper's cycles (schedule PAPER_CYCLES)");
    Helper_rule rule{s.reading.swap_condition};
    Swap_report report = driver.run(rule);
    decide_delaunay_ending(report, driver, s);
    if(left && report.ending != CONVERGED && s.schedule == WORK_QUEUE) *left = driver.non_delaunay_facets_kept();
    return report;
  });
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_RULES_H
