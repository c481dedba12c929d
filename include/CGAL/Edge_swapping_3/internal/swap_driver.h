// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule and the ending shared by the swap drivers; the rule (what a
// visit of a facet decides) is the caller's. Two schedules:
//  - the paper's cycles: each round lists every interior facet and visits those
//    that still exist when their turn comes;
//  - a work queue: the first round visits every interior facet, later rounds
//    only the facets whose configuration or tags changed since their last
//    visit, so a round costs what the flips before it changed.
// Driver state (the helper's tags, the queue) is kept in arrays indexed by
// the cells' slot numbers, never in the TDS marks that CGAL's own
// traversals clear. Both name a facet by a cell slot and an index; the
// paper's cycles follow a listed facet across the flips that replace its cell,
// so that it is visited whenever a facet with its three vertices exists.
//
// The driver is made of layers, each a header: the state by cell slot
// (driver_slot_state.h), the visits and their tracing (driver_visits.h),
// loop detection (loop_detection.h), the schedules (paper_cycles.h,
// same_cycle_sweeps.h, work_queue.h); a flip tells each through its hooks.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H

#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Flip_visitor.h>
#include <CGAL/Edge_swapping_3/internal/work_queue.h>
#include <array>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// A swap driver: a schedule (the work queue, the paper's cycles or same-cycle
/// sweeps, as `Driver_settings` says), a rule the caller gives (what a visit of a
/// facet decides) and an ending. The rule calls `flip`, `keep`, `tag` and
/// `is_tagged`; a flip tells each layer before and after (its hooks), the
/// flip visitor sees the plan before and the new cells after.
template <class Tr, class Constraints, class Visitor, class VisitVisitor = No_visit_visitor>
class Swap_driver
  : public Work_queue<Swap_driver<Tr, Constraints, Visitor, VisitVisitor>,
                      Same_cycle_sweeps<Swap_driver<Tr, Constraints, Visitor, VisitVisitor>,
                                        Paper_cycles<Swap_driver<Tr, Constraints, Visitor, VisitVisitor>,
                                                     Loop_detection<Driver_visits<Swap_driver<Tr, Constraints, Visitor, VisitVisitor>,
                                                                                  Driver_slot_state<Tr>, VisitVisitor>>>>>
{
  typedef Work_queue<Swap_driver, Same_cycle_sweeps<Swap_driver, Paper_cycles<Swap_driver,
          Loop_detection<Driver_visits<Swap_driver, Driver_slot_state<Tr>, VisitVisitor>>>>> Base;

public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Five_point_configuration<Tr> Configuration;

  Swap_driver(Tr& tr, const Driver_settings& settings, const Constraints& constraints, Visitor& visitor)
    : Base(tr, settings), constraints_(constraints), visitor_(visitor)
  {}

  Swap_driver(Tr& tr, const Driver_settings& settings, const Constraints& constraints, Visitor& visitor,
              VisitVisitor& visit_visitor)
    : Swap_driver(tr, settings, constraints, visitor)
  {
    this->visit_visitor_ = &visit_visitor;
  }

  const Constraints& constraints() const { return constraints_; }
  using Base::is_tagged;

  // ---- what a rule calls (with `is_tagged` and `keep`) ----

  /// Tags `c` (the helper); a new tag queues the facets whose visit it may change.
  void tag(Cell_handle c)
  {
    if(!this->set_tag(c)) return;
    this->trace_new_tag(c);
    this->queue_after_tag(c);
  }

  /// Makes the flip of a swappable, fresh configuration; returns its kind.
  int flip(const Configuration& conf)
  {
    const auto& plan = conf.flip_plan();
    this->current_cell_ = Cell_handle(); // the flip destroys the facet under visit, and may reuse its cell
    unwrap(visitor_).before_flip(this->tr_, plan);
    // The old cells' state goes with them (their slots may be reused at
    // once); in round 1 they stay marked, so that a list of cells skips them.
    // In a cycle, their listed facets move to the cells across first.
    this->cycles_before_flip(plan);
    for(int k = 0; k < plan.number_of_old_cells; ++k)
    {
      if(this->state_.empty()) break;
      auto& s = this->state(plan.old_cells[k]);
      this->forget_queued_facets(plan.old_cells[k], s);
      s = this->first_round_ ? Base::TOUCHED : 0;
    }
    std::array<Cell_handle, 4> created;
    const int n = execute_flip(this->tr_, plan, created, constraints_);
    for(int k = 0; k < n; ++k) this->tag_if_remembered(created[k]); // made again on tagged vertices
    this->sweeps_after_flip(created, n);
    unwrap(visitor_).after_flip(this->tr_, plan, created, n);
    this->trace_flip(plan, created, n);
    this->cycles_after_flip(created, n);
    this->queue_after_flip(created, n);
    ++this->record_.swaps[plan.kind];
    return int(plan.kind);
  }

  // ---- the schedules ----

  /// `visit(driver, c, i)` decides one interior facet.
  template <class Rule>
  Swap_report run(Rule& visit)
  {
    CGAL_precondition(this->tr_.dimension() == 3);
    CGAL::Real_timer timer;
    timer.start();
    constexpr bool plain_visitor =
      std::is_same<std::decay_t<decltype(unwrap(std::declval<Visitor&>()))>, Default_flip_visitor>::value;
    const auto& settings = this->settings_;
    this->start_loop_detection(settings.skip_repeated_cycles && settings.face_order == PRIORITY_ORDER &&
                               Reads_only_cells_and_tags<Rule>::value && plain_visitor && !Base::tracing);
    this->round_rule_ = Round_rule_of<Rule>::value;
    Swap_report report = (settings.schedule == WORK_QUEUE)                         ? this->run_work_queue(visit)
                         : (settings.reading.made_facets == MADE_FACETS_SAME_CYCLE) ? this->run_sweeps(visit)
                                                                                     : this->run_cycles(visit);
    report.seconds = timer.time();
    return report;
  }


private:
  const Constraints& constraints_;
  Visitor& visitor_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
