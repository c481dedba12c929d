// SPDX-License-Identifier: GPL-3.0-or-later
// The work queue, the swap driver's default schedule: a round visits only
// the facets whose configuration or tags changed since their last visit.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_WORK_QUEUE_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_WORK_QUEUE_H

#include <CGAL/Edge_swapping_3/internal/same_cycle_sweeps.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The work queue: the first round visits every interior facet, later
/// rounds only the facets whose configuration or tags changed since their
/// last visit, so a round costs what the flips before it changed.
template <class Derived, class Base>
class Work_queue : public Base
{
protected:
  CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES
  CGAL_EDGE_SWAPPING_3_DRIVER_VISITS_NAMES

public:
  Work_queue(Tr& tr, const Driver_settings& settings) : Base(tr, settings) {}

  /// A visit that made no swap: `non_delaunay` says the facet is not locally
  /// Delaunay; `next_round` queues it for the next round whatever happens
  /// (the helper: its decision depends on tags and on the cells around all
  /// its edges, and watching them all cost more than the visit, measured);
  /// else it is visited again when the cells around the edge its
  /// configuration looked at change.
  void keep(const Configuration& conf, bool non_delaunay, bool next_round)
  {
    if(!queueing_) return;
    const Cell_handle c = conf.cell();
    const int i = conf.index();
    if(non_delaunay) state(c) |= State(KEPT << i);
    Vertex_handle a, b;
    if(next_round)
      queue_facet(c, i);
    else if(conf.depends_on_edge_ring(a, b))
      register_facet(c, i, a, b);
  }

  /// Makes the first round of the work queue visit `facets` only, instead
  /// of every interior facet: for a rule that does nothing elsewhere (the
  /// helper without tags does nothing on a Delaunay facet).
  void seed(const std::vector<Key>& facets)
  {
    for(const Key& key : facets)
    {
      Cell_handle c;
      int i;
      if(find_facet(tr_, key, Cell_handle(), c, i) && !tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)))
        queue_facet(c, i);
    }
  }

  /// Makes the first round of the work queue visit `facets` only: the
  /// facets that a scan of all `scanned` interior facets found to need a visit
  /// (those the rule decides nothing on are not queued). The round counts the
  /// scan's visits, so that every interior facet is visited in it (once by
  /// the scan; again, or first if it is new, when the Delaunay repair's
  /// first flips test it). `earlier`: visits and swaps of round 1 made before
  /// the driver (those first flips), added to its record.
  void seed_scanned(const std::vector<std::pair<Cell_handle, int>>& facets, std::size_t scanned,
                    const Cycle_record& earlier = Cycle_record())
  {
    this->trace_scanned_visits(facets);
    for(const auto& [c, i] : facets) queue_facet(c, i);
    seeded_ = true;
    scanned_visits_ = scanned - (std::min)(scanned, facets.size()) + earlier.visits;
    first_round_swaps_ = earlier.swaps;
  }

  /// After a work-queue run: the interior facets that are not locally
  /// Delaunay. A facet visited in its last configuration is among those kept
  /// (not Delaunay at their last visit); one changed since, when the round
  /// limit ended the run, is still queued.
  std::vector<Key> non_delaunay_facets_kept() const
  {
    std::vector<Key> facets;
    for_each_kept_or_queued_facet([&](Cell_handle c, int i) {
      if(!tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)) &&
         !is_locally_delaunay(tr_, c, i, settings_.perturbation))
        facets.push_back(facet_key<Tr>(c, i));
    });
    return facets;
  }

  /// After a work-queue run: the facets kept or still queued that are not
  /// locally Delaunay (exact), plus the hull facets that are not.
  std::size_t number_of_non_delaunay_facets_left() const
  {
    std::size_t n = 0;
    for_each_kept_or_queued_facet([&](Cell_handle c, int i) {
      if(!is_locally_delaunay(tr_, c, i, settings_.perturbation)) ++n;
    });
    std::vector<Cell_handle> outside;
    tr_.incident_cells(tr_.infinite_vertex(), std::back_inserter(outside));
    for(Cell_handle c : outside)
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle d = c->neighbor(i);
        if(tr_.is_infinite(d) && address_of(d) < address_of(c)) continue; // counted from d
        if(!is_locally_delaunay(tr_, c, i, settings_.perturbation)) ++n;
      }
    return n;
  }


protected:
  /// Before a flip, for each cell it destroys (its state `s`): its queue
  /// entries are dead and its registrations gone.
  void forget_queued_facets(Cell_handle c, State s)
  {
    queued_facets_ -= number_of_bits(s & (0xF * QUEUED));
    // Its entries in the queue are dead; the slot may be reused at once by a
    // cell that queues a facet for the next round, which they must not visit.
    if(queueing_ && (s & (0xF * QUEUED))) // in a cycle the bits are LISTED, and there is no queue
      for(int i = 0; i < 4; ++i)
        if(s & (QUEUED << i)) add_dead_entry(facet_slot(index_(c), i));
    registered_facets_ -= number_of_bits(s & (0xF * REGISTERED));
  }

  /// After a flip: the facets of the new cells are queued, and the facets
  /// registered around their edges.
  void queue_after_flip(const std::array<Cell_handle, 4>& created, int n)
  {
    if(queueing_)
      for(int k = 0; k < n; ++k)
      {
        if(first_round_) state(created[k]) |= TOUCHED;
        for(int i = 0; i < 4; ++i) facet_changed(created[k], i);
      }
    if(queueing_ && registered_facets_ > 0)
    {
      // Each edge of the new cells once (a 2-3 flip makes 18 cell edges, 10 edges).
      std::array<Edge, 24> done;
      int number_done = 0;
      for(int k = 0; k < n; ++k)
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j)
          {
            const Edge e = edge_key<Tr>(created[k]->vertex(i), created[k]->vertex(j));
            if(std::find(done.begin(), done.begin() + number_done, e) != done.begin() + number_done) continue;
            done[number_done++] = e;
            push_registered(created[k], i, j);
          }
    }
  }

  /// After a new tag on `c`: the facets whose visit it may change are queued.
  void queue_after_tag(Cell_handle c)
  {
    if(!queueing_) return;
    for(int i = 0; i < 4; ++i) facet_changed(c, i);
    if(registered_facets_ > 0)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) push_registered(c, i, j);
  }

  /// Queues interior facet (c, i) unless it is queued already from either side.
  void queue_facet(Cell_handle c, int i)
  {
    // From the cell that holds it: a flip that destroys that cell drops the
    // entry (its facet is queued again behind), so the side must depend on the
    // state, not on the cells' addresses.
    if(!holds_facet(tr_, c, i) && !tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)))
    {
      const Cell_handle d = c->neighbor(i);
      i = d->index(c);
      c = d;
    }
    const Cell_handle n = c->neighbor(i);
    const std::size_t k = index_(c);
    if(state_at(index_(n)) & (QUEUED << n->index(c))) return;
    State& sc = state_at(k);
    if(sc & (QUEUED << i)) return;
    sc |= State(QUEUED << i);
    ++queued_facets_;
    queue_.push_back(facet_slot(k, i));
    // Entries of destroyed cells and of facets visited early pile up: past
    // one and a half times the facets queued, the queue keeps only its live
    // entries (a pass over the queue for every half of it pushed since).
    if(2 * queue_.size() > 3 * queued_facets_ + 8192) compact_queue();
  }

  /// Whether the queue entry `slot` is the first left of a cell that a flip
  /// destroyed while the entry was queued; if so, it is used up.
  bool is_dead_entry(std::uint32_t slot)
  {
    if(dead_entries_ == 0) return false;
    const std::size_t cell = slot / 4;
    if(cell >= dead_counts_.size()) return false;
    std::uint8_t& counts = dead_counts_[cell];
    const int shift = 2 * int(slot % 4), n = (counts >> shift) & 3;
    if(n == 0) return false;
    --dead_entries_;
    if(n == 3 && !dead_overflow_.empty())
      if(std::uint32_t* more = dead_overflow_.find(slot))
      {
        if(--*more == 0) dead_overflow_.erase(slot);
        return true;
      }
    counts = std::uint8_t(counts - (1 << shift));
    return true;
  }

  /// Counts a queue entry `slot` of a cell being destroyed as dead.
  void add_dead_entry(std::uint32_t slot)
  {
    const std::size_t cell = slot / 4;
    if(cell >= dead_counts_.size()) dead_counts_.resize((std::max)(state_.size(), cell + 1), 0);
    std::uint8_t& counts = dead_counts_[cell];
    const int shift = 2 * int(slot % 4);
    if(((counts >> shift) & 3) < 3) counts = std::uint8_t(counts + (1 << shift));
    else ++dead_overflow_[slot];
    ++dead_entries_;
  }

  /// Drops the queue's dead entries in place (the first entry of each queued
  /// facet stays, in order: the one a round would visit). The bits of the
  /// entries kept are cleared on the way, so that later copies are dropped,
  /// and set again at the end.
  void compact_queue()
  {
    std::size_t kept = 0, kept_of_round = 0;
    for(std::size_t k = 0; k < queue_.size(); ++k)
    {
      const std::uint32_t slot = queue_[k];
      if(is_dead_entry(slot)) continue;
      State& s = state_[slot / 4];
      const State bit = State(QUEUED << (slot % 4));
      if(!(s & bit)) continue;
      s &= State(~bit);
      if(k < round_left_) ++kept_of_round;
      queue_[kept++] = slot;
    }
    queue_.resize(kept);
    for(std::uint32_t slot : queue_) state_[slot / 4] |= State(QUEUED << (slot % 4));
    round_left_ = kept_of_round;
  }

  /// Calls `f(c, i)` once for every facet kept (not Delaunay at its last
  /// visit) or queued (changed since; the queue is empty unless the round
  /// limit ended the run): together, every facet that may not be Delaunay.
  template <class F>
  void for_each_kept_or_queued_facet(F f) const
  {
    auto marked = [](State s, int i) { return (s & ((KEPT | QUEUED) << i)) != 0; };
    for(std::size_t k = 0; k < state_.size(); ++k)
    {
      if((state_[k] & (0xF * (KEPT | QUEUED))) == 0) continue;
      const Cell_handle c = cell_in_slot(std::uint32_t(4 * k));
      if(c == Cell_handle()) continue;
      for(int i = 0; i < 4; ++i)
      {
        if(!marked(state_[k], i)) continue;
        const Cell_handle n = c->neighbor(i);
        if(marked(state(n), n->index(c)) && index_(n) < k) continue; // marked from n too, listed there
        f(c, i);
      }
    }
  }

  /// A facet of a new (or newly tagged) cell: queued (the work queue).
  void facet_changed(Cell_handle c, int i)
  {
    if(tr_.is_infinite(c) || tr_.is_infinite(c->neighbor(i))) return;
    if(is_current(c, i)) return; // the visit under way has seen it
    queue_facet(c, i);
  }

  /// Facet (c, i) is visited again when the cells around its edge (a, b)
  /// change. The edge goes into a filter; the facet keeps a bit.
  void register_facet(Cell_handle c, int i, Vertex_handle a, Vertex_handle b)
  {
    State& s = state(c);
    if(!(s & (REGISTERED << i)))
    {
      s |= State(REGISTERED << i);
      ++registered_facets_;
    }
    // Four bits per cell slot: a refill (a pass over the slots) waits for at
    // least a quarter of the slots' worth of registrations.
    if(may_be_registered_.is_empty()) may_be_registered_.clear(state_.size() / 2);
    may_be_registered_.insert(edge_key<Tr>(a, b));
    if(may_be_registered_.is_crowded()) refill_filter();
  }

  /// The filter again from the registered facets (all three edges of each),
  /// when erased registrations have filled it.
  void refill_filter()
  {
    // Sized so that the refill leaves at most a thirty-second of the bits
    // set (three edges per facet): the next refill waits for at least as many
    // insertions as there are bits set after this one.
    may_be_registered_.clear(std::max(12 * registered_facets_, state_.size() / 2));
    for(std::size_t k = 0; k < state_.size(); ++k)
    {
      if((state_[k] & (0xF * REGISTERED)) == 0) continue;
      const Cell_handle c = cell_in_slot(std::uint32_t(4 * k));
      for(int i = 0; i < 4; ++i)
        if(state_[k] & (REGISTERED << i))
          for(int u = 0; u < 4; ++u)
            for(int v = u + 1; v < 4; ++v)
              if(u != i && v != i) may_be_registered_.insert(edge_key<Tr>(c->vertex(u), c->vertex(v)));
    }
  }

  /// Queues the registered facets around the edge (i, j) of `c`, whose cells
  /// changed: the facets of the cells around the edge that contain it. Any
  /// registered facet found there is queued, whichever of its edges it was
  /// registered on: a visit too many, not one too few.
  void push_registered(Cell_handle c, int i, int j)
  {
    const Vertex_handle a = c->vertex(i), b = c->vertex(j);
    if(!may_be_registered_.contains(edge_key<Tr>(a, b))) return;
    const auto start = tr_.incident_cells(c, i, j);
    auto around = start;
    do
    {
      const Cell_handle d = around;
      const std::size_t slot = index_(d);
      State found = state_at(slot) & (0xF * REGISTERED);
      if(found == 0) continue;
      found &= State(~((REGISTERED << d->index(a)) | (REGISTERED << d->index(b)))); // facets with the edge
      state_[slot] &= State(~found);
      registered_facets_ -= number_of_bits(found);
      for(int k = 0; k < 4; ++k)
        if((found & (REGISTERED << k)) && !tr_.is_infinite(d) && !tr_.is_infinite(d->neighbor(k)) && !is_current(d, k))
          queue_facet(d, k);
    } while(++around != start);
  }

  template <class Rule>
  Swap_report run_work_queue(Rule& visit)
  {
    queueing_ = true;
    Swap_report report;
    report.ending = CYCLE_LIMIT_REACHED;

    // Round 1: every interior facet, cell by cell (unless seeded: then the
    // seeds). A cell that a flip touched is skipped: its facets that still
    // exist are queued for round 2.
    either_side_ = sees_facet_from_either_side(visit);
    // Priority order: round 1 is every interior facet, sorted like the others.
    if(settings_.face_order == PRIORITY_ORDER && !seeded_ && queue_.empty())
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(!tr_.is_infinite(c->neighbor(i)) && address_of(c) < address_of(c->neighbor(i))) queue_facet(c, i);
    const bool seeded = seeded_ || !queue_.empty();
    if(!seeded)
    {
      first_round_ = true;
      record_ = Cycle_record();
      record_.cycle = 1;
      auto visit_cell = [&](Cell_handle c) {
        if((record_.total_swaps() > 0 && (state(c) & TOUCHED)) || tr_.is_infinite(c)) return;
        for(int i = 0; i < 4; ++i)
        {
          if(either_side_)
          {
            const Cell_handle n = c->neighbor(i);
            if(address_of(n) < address_of(c) || tr_.is_infinite(n)) continue;
          }
          else if(!holds_facet(tr_, c, i))
            continue;
          const std::size_t flips = record_.total_swaps();
          current_cell_ = c;
          current_index_ = i;
          visit_facet(visit, c, i);
          if(record_.total_swaps() != flips) break; // c is gone; its facets are queued
        }
      };
      if(settings_.face_order == RANDOM_ORDER)
      {
        // The cells by slot (half the memory of handles); a slot that a
        // flip freed is skipped, one it reused is touched.
        std::vector<std::uint32_t> cells;
        cells.reserve(tr_.number_of_finite_cells());
        for(Cell_handle c : tr_.finite_cell_handles()) cells.push_back(facet_slot(index_(c), 0) / 4);
        shuffle_uniformly(cells, rng_);
        for(std::uint32_t k : cells)
        {
          const Cell_handle c = cell_in_slot(4 * k);
          if(c != Cell_handle()) visit_cell(c);
        }
      }
      else
      {
        // The container itself, without a list: a flip may free or reuse cells
        // ahead of the iterator (touched: skipped) but never frees the cell
        // under it, which each flip made here reuses as its first new cell.
        // Round 1 is bound by cache misses: the cells two ahead are prefetched.
        for_each_cell_prefetching(tr_.tds().cells(), visit_cell);
      }
      current_cell_ = Cell_handle();
      first_round_ = false;
      for(State& s : state_) s &= State(~TOUCHED);
      end_round(report);
    }

    for(std::size_t r = seeded ? 1 : 2; r <= settings_.max_rounds + 1; ++r)
    {
      if(queue_.empty())
      {
        if(r == 1) // the scan found nothing to do: its visits are the round
        {
          record_ = Cycle_record();
          record_.cycle = 1;
          record_.visits = scanned_visits_;
          record_.swaps = first_round_swaps_;
          end_round(report);
        }
        report.ending = CONVERGED;
        break;
      }
      if(r > settings_.max_rounds) break;
      // The queue holds this round; the next round's facets join it at the
      // back as this round's leave the front.
      round_left_ = queue_.size();
      if(settings_.face_order == RANDOM_ORDER) shuffle_uniformly(queue_, rng_);
      if(settings_.face_order == PRIORITY_ORDER) sort_by_priority(queue_, true);
      record_ = Cycle_record();
      record_.cycle = r;
      if(r == 1)
      {
        record_.visits = scanned_visits_;
        record_.swaps = first_round_swaps_;
      }
      while(round_left_ > 0)
      {
        --round_left_;
        const std::uint32_t slot = queue_.front();
        queue_.pop_front();
        if(is_dead_entry(slot)) continue;
        // Not queued any more: visited already (from either side) in this
        // round. An entry of a destroyed cell was skipped just above, even if
        // another cell took its slot since and queued that facet.
        State& s = state_[slot / 4];
        int i = int(slot % 4);
        if(!(s & (QUEUED << i))) continue;
        s &= State(~(QUEUED << i));
        --queued_facets_;
        Cell_handle c = cell_in_slot(slot);
        CGAL_assertion(c != Cell_handle()); // a cell's state goes with it
        const Cell_handle n = c->neighbor(i);
        const int j = n->index(c);
        CGAL_assertion(!(state(n) & (QUEUED << j))); // queued from one side only
        if(tr_.is_infinite(c) || tr_.is_infinite(n)) continue;
        // Seen from the cell that holds it (`holds_facet`): the helper's tags
        // depend on the side a facet is classified from, and the side must not
        // depend on the flips' history.
        if(!either_side_ && !holds_facet(tr_, c, i))
        {
          c = n;
          i = j;
        }
        current_cell_ = c;
        current_index_ = i;
        visit_facet(visit, c, i);
      }
      current_cell_ = Cell_handle();
      end_round(report);
      // No swap and no new tag: every later round would visit the same
      // facets in the same state and decide the same, so the run can make no
      // progress (the Delaunay ending then says STUCK, as on the cycles).
      if(cycle_ends_run())
      {
        report.ending = CONVERGED;
        break;
      }
    }
    return report;
  }


  bool first_round_ = false;
  bool seeded_ = false;              // the first round's facets were given (a scan found them)
  std::size_t scanned_visits_ = 0;   // the scan's visits of facets not queued
  std::array<std::size_t, number_of_flip_kinds> first_round_swaps_{}; // made before the driver
  bool either_side_ = false;                 // the rule sees a facet from either of its cells
  std::deque<std::uint32_t> queue_;          // facets as slot and index, in queueing order
  std::size_t round_left_ = 0;               // entries of the round under way at the front of queue_
  std::size_t queued_facets_ = 0;            // QUEUED bits set
  // By queue entry (slot): entries of destroyed cells still in the queue. In
  // the queue's order, the first entries of a slot are the dead ones (a new
  // cell's entries come behind), so they are skipped first. A count of up to
  // 3 per entry in 2 bits (a byte per cell slot), more in a table: a table
  // of every count held 6.3 MB at the peak of the helper at 10% moves of
  // 10^5 points (heaptrack), 1.27 times the triangulation's memory in all.
  std::vector<std::uint8_t> dead_counts_;
  Flat_hash_map<std::uint32_t, std::uint32_t, Slot_hash> dead_overflow_;
  std::size_t dead_entries_ = 0;
  std::size_t registered_facets_ = 0;       // REGISTERED bits set
  // Edges with a registered facet, and some others. Hashed by the points, not
  // the addresses: which edges pass decides which facets are visited again,
  // and a run must not depend on where the cells are in memory.
  Bit_filter<Edge, Edge_point_hash> may_be_registered_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_WORK_QUEUE_H
