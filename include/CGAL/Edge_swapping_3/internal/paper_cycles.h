// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's cycles as a schedule of the swap driver.
//
// A cycle lists every interior facet once, as slot and index (4 bytes), and
// visits each at its turn if it still exists, whatever flips happened in
// between: a flip that destroys the cell a facet was listed from moves its
// entry to the cell across (`move_listed_facets`), and a facet destroyed and
// made again later in the cycle is found again (`relist_made_again`).
// Unvisited listed facets carry the LISTED bit where they are now; an entry
// that moved is forwarded through `moved_`, keyed by the entry.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_PAPER_CYCLES_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_PAPER_CYCLES_H

#include <CGAL/Edge_swapping_3/internal/loop_detection.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <queue>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The paper's cycles: each round lists every interior facet and visits
/// those that still exist when their turn comes.
template <class Derived, class Base>
class Paper_cycles : public Base
{
protected:
  CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES
  CGAL_EDGE_SWAPPING_3_DRIVER_VISITS_NAMES
  CGAL_EDGE_SWAPPING_3_LOOP_DETECTION_NAMES

  Paper_cycles(Tr& tr, const Driver_settings& settings) : Base(tr, settings) {}

  /// Before a flip: the listed facets of the cells it destroys move to the cells across.
  void cycles_before_flip(const Flip_plan<Tr>& plan)
  {
    if(!queueing_)
      for(int k = 0; k < plan.number_of_old_cells; ++k) move_listed_facets(plan, plan.old_cells[k]);
  }

  /// After a flip: the listed facets it made again are found again.
  void cycles_after_flip(const std::array<Cell_handle, 4>& created, int n)
  {
    if(!queueing_) relist_made_again(created, n);
  }

  /// The listed facets of `c`, a cell the flip of `plan` destroys.
  void move_listed_facets(const Flip_plan<Tr>& plan, Cell_handle c)
  {
    const std::size_t k = index_(c);
    const State s = state_at(k); // a copy: state_at may resize
    if((s & (0xF * LISTED)) == 0) return;
    for(int i = 0; i < 4; ++i)
    {
      if(!(s & (LISTED << i))) continue;
      const std::uint32_t here = facet_slot(k, i);
      std::uint32_t entry = here;
      if(!(s & (MOVED_IN << i)))
      {
        if(settings_.face_order == STORAGE_ORDER) displaced_.push(entry); // it leaves its slot
      }
      else
      {
        const std::uint32_t* listed_as = entry_of_.find(here);
        CGAL_assertion(listed_as != nullptr);
        entry = *listed_as;
        entry_of_.erase(here);
      }
      const Cell_handle n = c->neighbor(i);
      if(is_old_cell(plan, n))
      {
        // Destroyed with the cavity (no longer found: not where it was
        // listed, not moved); a later flip may make it again.
        moved_.erase(entry);
        made_again_.emplace(vertex_slots(c, i), entry);
      }
      else
        list_at(n, n->index(c), entry); // on the cavity's boundary: n keeps it
    }
  }

  /// The listed facets that the flip destroyed and made again: interior
  /// facets of the new cells, found by their vertices.
  void relist_made_again(const std::array<Cell_handle, 4>& created, int n)
  {
    if(made_again_.empty()) return;
    for(int k = 0; k < n; ++k)
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle d = created[k]->neighbor(i);
        if(std::find(created.begin() + k + 1, created.begin() + n, d) == created.begin() + n) continue;
        const Vertex_slot_triple key = vertex_slots(created[k], i);
        if(const std::uint32_t* entry = made_again_.find(key))
        {
          list_at(created[k], i, *entry);
          made_again_.erase(key);
        }
      }
  }

  /// Facet (c, i) now answers the cycle's list entry `entry`.
  void list_at(Cell_handle c, int i, std::uint32_t entry)
  {
    const std::size_t k = index_(c);
    state_at(k) |= State((LISTED | MOVED_IN) << i);
    const std::uint32_t here = facet_slot(k, i);
    moved_[entry] = here;
    entry_of_[here] = entry;
  }

  /// Whether list entry `entry` is where it was listed, not visited yet.
  bool is_native(std::uint32_t entry) const
  {
    const State bits = State((state_[entry / 4] >> (entry % 4)) & (LISTED | MOVED_IN));
    return bits == LISTED;
  }

  /// Visits the facet of list entry `entry` if it still exists.
  template <class Rule>
  void visit_listed(Rule& visit, std::uint32_t entry)
  {
    std::uint32_t here = entry;
    if(!is_native(entry))
    {
      const std::uint32_t* moved = moved_.find(entry);
      if(moved == nullptr) return; // a flip destroyed it
      here = *moved;
      moved_.erase(entry);
      entry_of_.erase(here);
    }
    Cell_handle c = cell_in_slot(here);
    int i = int(here % 4);
    State& s = state_[here / 4];
    CGAL_assertion(c != Cell_handle() && (s & (LISTED << i)));
    s &= State(~((LISTED | MOVED_IN) << i));
    if(!holds_facet(tr_, c, i))
    {
      const Cell_handle n = c->neighbor(i);
      i = n->index(c);
      c = n;
    }
    visit_facet(visit, c, i);
  }

  template <class Rule>
  Swap_report run_cycles(Rule& visit)
  {
    queueing_ = false;
    Swap_report report;
    report.ending = CYCLE_LIMIT_REACHED;
    const bool random = settings_.face_order != STORAGE_ORDER;
    // Random and priority order: the entries, shuffled or sorted. A deque frees its front as the cycle
    // consumes it, while the tables of moved facets grow.
    std::deque<std::uint32_t> listed;
    for(std::size_t round = 1; round <= settings_.max_rounds; ++round)
    {
      record_ = Cycle_record();
      record_.cycle = round;
      begin_cycle_tags();
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(holds_facet(tr_, c, i))
          {
            const std::size_t k = index_(c);
            state_at(k) |= State(LISTED << i);
            if(random) listed.push_back(facet_slot(k, i));
          }
      if(random)
      {
        if(settings_.face_order == RANDOM_ORDER)
          shuffle_uniformly(listed, rng_);
        else
          sort_by_priority(listed, false);
        while(!listed.empty())
        {
          const std::uint32_t entry = listed.front();
          listed.pop_front();
          visit_listed(visit, entry);
        }
      }
      else
      {
        // Storage order is slot order, so the list is the slots themselves:
        // an entry is visited at its slot if it is still there, else when
        // the slots reach it in `displaced_`.
        const std::size_t slots = state_.size();
        for(std::size_t k = 0; k < slots; ++k)
          for(int i = 0; i < 4; ++i)
          {
            const std::uint32_t entry = std::uint32_t(4 * k + std::size_t(i));
            if(!displaced_.empty() && displaced_.top() == entry)
            {
              displaced_.pop();
              visit_listed(visit, entry);
            }
            else if(is_native(entry))
              visit_listed(visit, entry);
          }
        CGAL_assertion(displaced_.empty());
      }
      // Their storage goes too: the next cycle's list would be held beside it.
      moved_ = {};
      entry_of_ = {};
      made_again_ = {};
      end_round(report);
      if(cycle_ends_run())
      {
        report.ending = CONVERGED;
        break;
      }
      if(skip_repeats_) round = skip_repeated_cycles(report, round);
    }
    return report;
  }

  // A cycle: where flips moved list entries (a destroyed entry is neither here
  // nor where it was listed), the entry of each moved facet, and the entries of
  // destroyed facets by their vertices.
  Flat_hash_map<std::uint32_t, std::uint32_t, Slot_hash> moved_;
  Flat_hash_map<std::uint32_t, std::uint32_t, Slot_hash> entry_of_;
  // Storage order: the entries that left their slot, smallest first.
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<std::uint32_t>> displaced_;
  Flat_hash_map<Vertex_slot_triple, std::uint32_t, Vertex_slot_triple_hash> made_again_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_PAPER_CYCLES_H
