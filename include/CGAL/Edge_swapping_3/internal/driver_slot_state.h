// SPDX-License-Identifier: GPL-3.0-or-later
// A swap driver's state by cell slot: the bits of each cell (the work
// queue's, the paper's cycles' and the helper's tag), kept in arrays indexed
// by the cells' slot numbers, never in the TDS marks that CGAL's own
// traversals clear; and the order of facets the schedules share.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SLOT_STATE_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SLOT_STATE_H

#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Visit_record.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/driver_settings.h>
#include <CGAL/Edge_swapping_3/internal/facet_priority.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The state a swap driver keeps: one word of bits per cell slot (queued,
/// kept, registered or listed facets, the helper's tag), the round's record,
/// the facet under visit, and the facet order helpers every schedule uses.
/// The base of the driver's layers (driver_visits.h, loop_detection.h,
/// paper_cycles.h, same_cycle_sweeps.h, work_queue.h, swap_driver.h).
template <class Tr>
class Driver_slot_state
{
public:
  typedef Tr Triangulation;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Facet_key<Tr> Key;
  typedef Edge_key<Tr> Edge;
  typedef Five_point_configuration<Tr> Configuration;
  typedef std::uint16_t State; ///< a cell's bits in the driver (see QUEUED)

  Driver_slot_state(Tr& tr, const Driver_settings& settings)
    : tr_(tr), settings_(settings), rng_(settings.random_seed), index_(tr.tds().cells()),
      vertex_index_(tr.tds().vertices())
  {}

  Tr& triangulation() { return tr_; }
  Perturbation perturbation() const { return settings_.perturbation; }

  // ---- what a rule calls ----

  bool is_tagged(Cell_handle c) const { return any_tag_ && (state(c) & TAGGED) != 0; }


protected:
  static bool is_old_cell(const Flip_plan<Tr>& plan, Cell_handle c)
  {
    for(int k = 0; k < plan.number_of_old_cells; ++k)
      if(plan.old_cells[k] == c) return true;
    return false;
  }

  bool is_current(Cell_handle c, int i) const
  {
    if(current_cell_ == Cell_handle()) return false;
    return (c == current_cell_ && i == current_index_) ||
           (c->neighbor(i) == current_cell_ && current_cell_->neighbor(current_index_) == c);
  }

  // ---- per-cell state (slot-indexed) and the work queue ----

  // Bits of a cell's state: facet i queued from this cell (work queue), facet
  // i not locally Delaunay at its last visit from this cell, facet i to visit
  // again when the cells around one of its edges change, tagged (helper),
  // changed by a flip in round 1.
  static constexpr State QUEUED = 1, KEPT = 1 << 4, REGISTERED = 1 << 8, TAGGED = 1 << 12, TOUCHED = 1 << 13;
  // The paper's cycles use neither the queue nor the kept bits; there, facet i
  // is listed in this cycle and not visited yet, and was moved to this cell
  // by a flip (its entry is then found in `entry_of_`).
  static constexpr State LISTED = QUEUED, MOVED_IN = KEPT;

  static std::size_t number_of_bits(State s)
  {
    std::size_t n = 0;
    for(; s != 0; s &= s - 1) ++n;
    return n;
  }

  State& state_at(std::size_t k) const
  {
    if(k >= state_.size())
    {
      // Exactly the container's slots: resize alone would double the capacity.
      state_.reserve(index_.number_of_slots());
      state_.resize(index_.number_of_slots(), 0);
    }
    return state_[k];
  }

  State& state(Cell_handle c) const { return state_at(index_(c)); }

  /// A facet in the queue: the slot of a cell that held it, and its index there.
  static std::uint32_t facet_slot(std::size_t k, int i)
  {
    if(k >= (std::size_t(1) << 30)) throw std::length_error("Edge_swapping_3: more than 2^30 cells");
    return std::uint32_t(4 * k + std::size_t(i));
  }

  Cell_handle cell_in_slot(std::uint32_t slot) const
  {
    typename Tr::Cell* cell = index_.item(slot / 4);
    return cell == nullptr ? Cell_handle() : tr_.tds().cells().iterator_to(*cell);
  }


  /// Tags `c`; false if it was tagged already.
  bool set_tag(Cell_handle c)
  {
    State& s = state(c);
    if(s & TAGGED) return false;
    s |= TAGGED;
    any_tag_ = true;
    ++record_.new_tags;
    if(settings_.reading.tag_lifetime == TAGS_NEVER_CLEARED) remembered_tags_.insert(vertex_slots(c));
    return true;
  }

  /// A cell made again on the vertices of a cell once tagged is tagged
  /// (the reading TAGS_NEVER_CLEARED).
  void tag_if_remembered(Cell_handle c)
  {
    if(!remembered_tags_.empty() && !tr_.is_infinite(c) && remembered_tags_.count(vertex_slots(c)))
      state(c) |= TAGGED;
  }

  typename Visit_record<Tr>::Cell_vertices cell_vertices(Cell_handle c) const
  {
    return {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
  }

  /// The priority of facet (c, i) in `PRIORITY_ORDER`.
  std::uint64_t priority_of(Cell_handle c, int i) const
  {
    return facet_priority(settings_.random_seed, bare_point(c->vertex((i + 1) & 3)->point()),
                          bare_point(c->vertex((i + 2) & 3)->point()), bare_point(c->vertex((i + 3) & 3)->point()));
  }

  /// The sorted points of facet (c, i): the order of facets of equal priority.
  std::array<typename Tr::Geom_traits::Point_3, 3> sorted_points(Cell_handle c, int i) const
  {
    std::array<typename Tr::Geom_traits::Point_3, 3> p;
    for(int k = 0; k < 3; ++k) p[k] = bare_point(c->vertex((i + 1 + k) & 3)->point());
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    std::sort(p.begin(), p.end(), [&](const auto& a, const auto& b) { return compare(a, b) == SMALLER; });
    return p;
  }

  /// Sorts facet entries (slot and index) into `PRIORITY_ORDER`; with
  /// `queued_only`, entries whose facet is not queued go last.
  template <class Entries>
  void sort_by_priority(Entries& entries, bool queued_only)
  {
    constexpr std::uint64_t none = std::numeric_limits<std::uint64_t>::max();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    keyed.reserve(entries.size());
    for(std::uint32_t slot : entries)
    {
      const bool live = !queued_only || (state_[slot / 4] & (QUEUED << (slot % 4)));
      keyed.emplace_back(live ? priority_of(cell_in_slot(slot), int(slot % 4)) : none, slot);
    }
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
      if(a.first != b.first) return a.first < b.first;
      if(a.first == none || a.second == b.second) return a.second < b.second;
      const auto p = sorted_points(cell_in_slot(a.second), int(a.second % 4));
      const auto q = sorted_points(cell_in_slot(b.second), int(b.second % 4));
      for(int k = 0; k < 3; ++k)
        if(const auto r = compare(p[k], q[k]); r != EQUAL) return r == SMALLER;
      return a.second < b.second; // the same facet from its two cells
    });
    std::size_t k = 0;
    for(auto& entry : entries) entry = keyed[k++].second;
  }

  /// `tr_.number_of_finite_cells()` without a sweep: no flip changes the
  /// vertices, hence neither the hull's vertices nor its number of facets,
  /// which is the number of infinite cells.
  std::size_t number_of_finite_cells()
  {
    if(tr_.dimension() != 3) return tr_.number_of_finite_cells();
    if(infinite_cells_ == 0)
    {
      std::vector<Cell_handle> outside;
      tr_.incident_cells(tr_.infinite_vertex(), std::back_inserter(outside));
      infinite_cells_ = outside.size();
    }
    return tr_.number_of_cells() - infinite_cells_;
  }

  void begin_cycle_tags()
  {
    if(settings_.reading.tag_lifetime == TAGS_CLEARED_EACH_CYCLE && any_tag_)
    {
      for(State& s : state_) s &= State(~TAGGED);
      any_tag_ = false;
    }
  }

  /// Whether the cycle that just ended ends the run.
  bool cycle_ends_run() const
  {
    // A round that tagged a cell changed what the next would do (unless the
    // reading ends on the first cycle without a swap).
    return record_.total_swaps() == 0 && (record_.new_tags == 0 || settings_.reading.cycle_ending == NO_SWAP);
  }
  /// The cell's vertices by their slots, in increasing order.
  Vertex_slot_quadruple vertex_slots(Cell_handle c)
  {
    Vertex_slot_quadruple t;
    for(int k = 0; k < 4; ++k) t[k] = std::uint32_t(vertex_index_(c->vertex(k)));
    std::sort(t.begin(), t.end());
    return t;
  }

  Vertex_slot_triple vertex_slots(Cell_handle c, int i)
  {
    std::array<std::uint32_t, 3> t;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t slot = vertex_index_(c->vertex((i + 1 + k) & 3));
      if(slot >= (std::size_t(1) << 32)) throw std::length_error("Edge_swapping_3: more than 2^32 vertices");
      t[k] = std::uint32_t(slot);
    }
    std::sort(t.begin(), t.end());
    return {t[0], t[1], t[2]};
  }


  Tr& tr_;
  const Driver_settings& settings_;
  Round_rule round_rule_ = PLAIN_RULE; // the rule of the run, for the reports
  CGAL::Random rng_;
  Cycle_record record_;
  bool queueing_ = false; // the work queue runs (else a cycle of the paper)
  mutable Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> index_;
  mutable std::vector<State> state_; // by slot: the bits above
  bool any_tag_ = false;
  std::size_t infinite_cells_ = 0;  // 0 until counted
  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> vertex_index_;
  // The reading TAGS_NEVER_CLEARED: the vertices of every cell ever tagged.
  std::set<Vertex_slot_quadruple> remembered_tags_;
  Cell_handle current_cell_; // the facet under visit
  int current_index_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

// The names of Driver_slot_state in a layer derived from it (`Base`): the
// members of a dependent base are found only through `this->` or these
// using-declarations.
#define CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES \
  typedef typename Base::Triangulation Tr; \
  typedef typename Base::Cell_handle Cell_handle; \
  typedef typename Base::Vertex_handle Vertex_handle; \
  typedef typename Base::Key Key; \
  typedef typename Base::Edge Edge; \
  typedef typename Base::Configuration Configuration; \
  typedef typename Base::State State; \
  using Base::QUEUED; \
  using Base::KEPT; \
  using Base::REGISTERED; \
  using Base::TAGGED; \
  using Base::TOUCHED; \
  using Base::LISTED; \
  using Base::MOVED_IN; \
  using Base::tr_; \
  using Base::settings_; \
  using Base::round_rule_; \
  using Base::rng_; \
  using Base::record_; \
  using Base::queueing_; \
  using Base::index_; \
  using Base::state_; \
  using Base::any_tag_; \
  using Base::vertex_index_; \
  using Base::remembered_tags_; \
  using Base::current_cell_; \
  using Base::current_index_; \
  using Base::is_tagged; \
  using Base::is_old_cell; \
  using Base::is_current; \
  using Base::number_of_bits; \
  using Base::state_at; \
  using Base::state; \
  using Base::facet_slot; \
  using Base::cell_in_slot; \
  using Base::cell_vertices; \
  using Base::priority_of; \
  using Base::sort_by_priority; \
  using Base::number_of_finite_cells; \
  using Base::begin_cycle_tags; \
  using Base::cycle_ends_run; \
  using Base::vertex_slots;

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SLOT_STATE_H
