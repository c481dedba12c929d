// The schedule and the ending shared by the swap drivers; the rule (what a
// visit of a facet decides) is the caller's. Two schedules:
//  - the paper's cycles: each round lists every interior facet and visits those
//    that still exist when their turn comes;
//  - a work queue: the first round visits every interior facet, later rounds
//    only the facets whose configuration or tags changed since their last
//    visit, so a round costs what the flips before it changed.
// Driver state (the helper's tags, the queue) is kept here, in arrays indexed
// by the cells' slot numbers, never in the TDS marks that CGAL's own
// traversals clear. The paper's cycles name a facet by its three vertices,
// as the paper does; the work queue names it by a cell and an index.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

struct Driver_settings
{
  Schedule schedule = WORK_QUEUE;
  Face_order face_order = STORAGE_ORDER;
  unsigned int random_seed = 0;
  std::size_t max_rounds = 1000;
  bool record_non_delaunay_facets = false;
  Perturbation perturbation = CGAL_PERTURBATION;
  std::function<void(const Cycle_record&)> cycle_visitor;
};

/// A visitor given by value or through `std::ref`.
template <class T>
T& unwrap(T& t) { return t; }
template <class T>
T& unwrap(std::reference_wrapper<T> r) { return r.get(); }

/// A uniform random permutation (Fisher-Yates) drawn from `rng`.
template <class Vector>
void shuffle_uniformly(Vector& items, CGAL::Random& rng)
{
  for(std::size_t k = items.size(); k > 1; --k)
    std::swap(items[k - 1], items[std::size_t(rng.get_int(0, int(k)))]);
}

/// Of the two finite cells of an interior facet, the one whose opposite vertex
/// is lexicographically smaller holds it: the choice never depends on addresses.
template <class Tr>
bool holds_facet(const Tr& tr, typename Tr::Cell_handle c, int i)
{
  const auto n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n)) return false;
  const auto m = n->vertex(n->index(c));
  return tr.geom_traits().compare_xyz_3_object()(c->vertex(i)->point(), m->point()) == SMALLER;
}

/// Whether `rule` may see each facet from either of its cells in round 1. A
/// rule whose `sees_facet_from_either_side()` is true has one outcome whatever
/// the visit order (the perturbed Delaunay triangulation is unique): its facets
/// are then visited from the cell with the smaller address, a test that reads
/// no other cell. Other rules keep `holds_facet`, so that their result does not
/// depend on addresses.
template <class Rule, class = void>
struct Has_either_side_test : std::false_type {};
template <class Rule>
struct Has_either_side_test<Rule, std::void_t<decltype(std::declval<const Rule&>().sees_facet_from_either_side())>>
  : std::true_type {};

template <class Rule>
bool sees_facet_from_either_side(const Rule& rule)
{
  if constexpr(Has_either_side_test<Rule>::value) return rule.sees_facet_from_either_side();
  else return false;
}

template <class Tr, class Constraints, class Visitor>
class Swap_driver
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Facet_key<Tr> Key;
  struct Listed
  {
    Key key;
    Cell_handle hint; // a cell that held the facet when it was listed
  };
  typedef Edge_key<Tr> Edge;
  typedef Five_point_configuration<Tr> Configuration;

  Swap_driver(Tr& tr, const Driver_settings& settings, const Constraints& constraints, Visitor& visitor)
    : tr_(tr), settings_(settings), constraints_(constraints), visitor_(visitor), rng_(settings.random_seed),
      index_(tr.tds().cells())
  {}

  Tr& triangulation() { return tr_; }
  const Constraints& constraints() const { return constraints_; }
  Perturbation perturbation() const { return settings_.perturbation; }

  // ---- what a rule calls ----

  bool is_tagged(Cell_handle c) const { return any_tag_ && (state(c) & TAGGED) != 0; }

  /// Tags `c` (the helper); a new tag queues the facets whose visit it may change.
  void tag(Cell_handle c)
  {
    std::uint16_t& s = state(c);
    if(s & TAGGED) return;
    s |= TAGGED;
    any_tag_ = true;
    ++record_.new_tags;
    if(!queueing_) return;
    for(int i = 0; i < 4; ++i) facet_changed(c, i);
    if(!registered_.empty())
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) push_registered(c->vertex(i), c->vertex(j));
  }

  /// Makes the flip of a swappable, fresh configuration; returns its kind.
  int flip(const Configuration& conf)
  {
    const auto& plan = conf.flip_plan();
    current_cell_ = Cell_handle(); // the flip destroys the facet under visit, and may reuse its cell
    unwrap(visitor_).before_flip(tr_, plan);
    // The old cells' state goes with them (their slots may be reused at
    // once); in round 1 they stay marked, so that a list of cells skips them.
    // In a cycle, the facets between two old cells are known dead (unless the
    // flip makes them again).
    for(int k = 0; k < plan.number_of_old_cells; ++k)
    {
      const Cell_handle c = plan.old_cells[k];
      if(first_round_) state(c) = TOUCHED;
      else if(!state_.empty()) state(c) = 0;
      if(!queueing_)
        for(int i = 0; i < 4; ++i)
          if(is_old_cell(plan, c->neighbor(i)) && address_of(c) < address_of(c->neighbor(i)))
            moved_[facet_key<Tr>(c, i)] = Cell_handle();
    }
    std::array<Cell_handle, 4> created;
    const int n = execute_flip(tr_, plan, created, constraints_);
    unwrap(visitor_).after_flip(tr_, plan, created, n);
    for(int k = 0; k < n; ++k)
    {
      if(first_round_) state(created[k]) |= TOUCHED;
      for(int i = 0; i < 4; ++i) facet_changed(created[k], i);
    }
    if(queueing_ && !registered_.empty())
      for(int k = 0; k < n; ++k)
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j) push_registered(created[k]->vertex(i), created[k]->vertex(j));
    ++record_.swaps[plan.kind];
    return int(plan.kind);
  }

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
    if(non_delaunay) state(c) |= std::uint16_t(KEPT << i);
    Vertex_handle a, b;
    if(next_round)
      queue_facet(c, i);
    else if(conf.depends_on_edge_ring(a, b))
    {
      const Edge edge = edge_key<Tr>(a, b);
      registered_[edge].push_back(facet_slot(index_(c), i));
      may_be_registered_.insert(edge);
    }
  }

  // ---- the schedules ----

  /// `visit(driver, c, i)` decides one interior facet.
  template <class Rule>
  Swap_report run(Rule& visit)
  {
    CGAL_precondition(tr_.dimension() == 3);
    CGAL::Real_timer timer;
    timer.start();
    Swap_report report = (settings_.schedule == WORK_QUEUE) ? run_work_queue(visit) : run_cycles(visit);
    report.seconds = timer.time();
    return report;
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

  /// After a work-queue run: the interior facets that are not locally
  /// Delaunay. Every facet was visited in its last configuration, so they
  /// are among those kept (not Delaunay at their last visit).
  std::vector<Key> non_delaunay_facets_kept() const
  {
    std::vector<Key> facets;
    for_each_kept_facet([&](Cell_handle c, int i) {
      if(!tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)) &&
         !is_locally_delaunay(tr_, c, i, settings_.perturbation))
        facets.push_back(facet_key<Tr>(c, i));
    });
    return facets;
  }

  /// After a work-queue run: the facets that were not locally Delaunay at
  /// their last visit and still are (exact), plus the hull facets.
  std::size_t number_of_non_delaunay_facets_left() const
  {
    std::size_t n = 0;
    for_each_kept_facet([&](Cell_handle c, int i) {
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

private:
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
  // i not locally Delaunay at its last visit from this cell, tagged (helper),
  // changed by a flip in round 1.
  static constexpr std::uint16_t QUEUED = 1, KEPT = 1 << 4, TAGGED = 1 << 8, TOUCHED = 1 << 9;

  std::uint16_t& state_at(std::size_t k) const
  {
    if(k >= state_.size()) state_.resize(index_.number_of_slots(), 0);
    return state_[k];
  }

  std::uint16_t& state(Cell_handle c) const { return state_at(index_(c)); }

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

  /// Queues interior facet (c, i) unless it is queued already from either side.
  void queue_facet(Cell_handle c, int i)
  {
    const Cell_handle n = c->neighbor(i);
    const std::size_t k = index_(c);
    if(state_at(index_(n)) & (QUEUED << n->index(c))) return;
    std::uint16_t& sc = state_at(k);
    if(sc & (QUEUED << i)) return;
    sc |= std::uint16_t(QUEUED << i);
    next_.push_back(facet_slot(k, i));
  }

  /// Calls `f(c, i)` once for every facet kept (not Delaunay at its last visit).
  template <class F>
  void for_each_kept_facet(F f) const
  {
    for(std::size_t k = 0; k < state_.size(); ++k)
    {
      if((state_[k] & (0xF * KEPT)) == 0) continue;
      const Cell_handle c = cell_in_slot(std::uint32_t(4 * k));
      if(c == Cell_handle()) continue;
      for(int i = 0; i < 4; ++i)
      {
        if(!(state_[k] & (KEPT << i))) continue;
        const Cell_handle n = c->neighbor(i);
        if((state(n) & (KEPT << n->index(c))) && address_of(n) < address_of(c)) continue; // kept from n too
        f(c, i);
      }
    }
  }

  /// A facet of a new (or newly tagged) cell: queued, or, in a cycle, found
  /// there when its turn comes.
  void facet_changed(Cell_handle c, int i)
  {
    if(!queueing_)
    {
      moved_[facet_key<Tr>(c, i)] = c;
      return;
    }
    if(tr_.is_infinite(c) || tr_.is_infinite(c->neighbor(i))) return;
    if(is_current(c, i)) return; // the visit under way has seen it
    queue_facet(c, i);
  }

  /// The facet of a listed or queued key: its hint when no flip changed it,
  /// else where the last flip put it. It is then seen from the cell that holds
  /// it (`holds_facet`): the helper's tags depend on the side a facet is
  /// classified from, and the side must not depend on the flips' history.
  bool locate(const Key& key, Cell_handle hint, Cell_handle& c, int& i) const
  {
    const bool found = find_facet(tr_, key, hint, c, i);
    CGAL_assertion(found);
    if(found && !tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)) && !holds_facet(tr_, c, i))
    {
      const Cell_handle n = c->neighbor(i);
      i = n->index(c);
      c = n;
    }
    return found;
  }

  /// Queues the facets registered on edge `(a, b)`, whose cells changed. A
  /// registered slot may hold another cell by now: its facet is then queued
  /// for nothing (a visit too many, never one too few: the facet that was
  /// registered lost its cell, whose successor queued it).
  void push_registered(Vertex_handle a, Vertex_handle b)
  {
    if(registered_.empty()) return;
    const Edge edge = edge_key<Tr>(a, b);
    if(!may_be_registered_.contains(edge)) return;
    const std::vector<std::uint32_t>* facets = registered_.find(edge);
    if(facets == nullptr) return;
    for(std::uint32_t slot : *facets)
    {
      const Cell_handle c = cell_in_slot(slot);
      const int i = int(slot % 4);
      if(c != Cell_handle() && !tr_.is_infinite(c) && !tr_.is_infinite(c->neighbor(i)) && !is_current(c, i))
        queue_facet(c, i);
    }
    registered_.erase(edge);
  }

  template <class Rule>
  void visit_facet(Rule& visit, Cell_handle c, int i)
  {
    ++record_.visits;
    visit(*this, c, i);
  }

  void end_round(Swap_report& report)
  {
    // Registrations erased during the round left their bits: start afresh.
    if(!registered_.empty())
    {
      may_be_registered_.clear(registered_.size());
      registered_.for_each([&](const Edge& e, const std::vector<std::uint32_t>&) { may_be_registered_.insert(e); });
    }
    record_.cells = tr_.number_of_finite_cells();
    if(settings_.record_non_delaunay_facets)
      record_.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr_, settings_.perturbation);
    report.cycles.push_back(record_);
    if(settings_.cycle_visitor) settings_.cycle_visitor(record_);
  }

  template <class Rule>
  Swap_report run_cycles(Rule& visit)
  {
    queueing_ = false;
    Swap_report report;
    report.ending = CYCLE_LIMIT_REACHED;
    std::vector<Listed> facets;
    for(std::size_t round = 1; round <= settings_.max_rounds; ++round)
    {
      record_ = Cycle_record();
      record_.cycle = round;
      facets.clear();
      facets.reserve(2 * tr_.number_of_cells());
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(holds_facet(tr_, c, i)) facets.push_back({facet_key<Tr>(c, i), c});
      if(settings_.face_order == RANDOM_ORDER) shuffle_uniformly(facets, rng_);
      moved_.clear();
      for(const Listed& f : facets)
      {
        Cell_handle hint = f.hint;
        if(!moved_.empty())
        {
          if(const Cell_handle* moved = moved_.find(f.key)) hint = *moved;
        }
        Cell_handle c;
        int i;
        if(hint == Cell_handle() || !locate(f.key, hint, c, i)) continue; // a flip destroyed it
        if(tr_.is_infinite(c) || tr_.is_infinite(c->neighbor(i))) continue;
        visit_facet(visit, c, i);
      }
      end_round(report);
      // A round that tagged a cell changed what the next would do.
      if(record_.total_swaps() == 0 && record_.new_tags == 0)
      {
        report.ending = CONVERGED;
        break;
      }
    }
    return report;
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
    const bool seeded = !next_.empty();
    either_side_ = sees_facet_from_either_side(visit);
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
        std::vector<Cell_handle> cells;
        cells.reserve(tr_.number_of_finite_cells());
        for(Cell_handle c : tr_.finite_cell_handles()) cells.push_back(c);
        shuffle_uniformly(cells, rng_);
        for(Cell_handle c : cells) visit_cell(c);
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
      for(std::uint16_t& s : state_) s &= std::uint16_t(~TOUCHED);
      end_round(report);
    }

    std::vector<std::uint32_t> round;
    for(std::size_t r = seeded ? 1 : 2; r <= settings_.max_rounds + 1; ++r)
    {
      if(next_.empty())
      {
        report.ending = CONVERGED;
        break;
      }
      if(r > settings_.max_rounds) break;
      round.swap(next_);
      next_.clear();
      if(settings_.face_order == RANDOM_ORDER) shuffle_uniformly(round, rng_);
      record_ = Cycle_record();
      record_.cycle = r;
      for(std::uint32_t slot : round)
      {
        // Not queued any more: destroyed with its cell, or visited already
        // (from either side) in this round. A slot that another cell took
        // since is visited here if that cell queued the facet.
        std::uint16_t& s = state_[slot / 4];
        int i = int(slot % 4);
        if(!(s & (QUEUED << i))) continue;
        s &= std::uint16_t(~(QUEUED << i));
        Cell_handle c = cell_in_slot(slot);
        CGAL_assertion(c != Cell_handle()); // a cell's state goes with it
        const Cell_handle n = c->neighbor(i);
        const int j = n->index(c);
        state(n) &= std::uint16_t(~(QUEUED << j));
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
    }
    return report;
  }

  Tr& tr_;
  const Driver_settings& settings_;
  const Constraints& constraints_;
  Visitor& visitor_;
  CGAL::Random rng_;
  Cycle_record record_;
  bool queueing_ = false;
  bool first_round_ = false;

  mutable Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> index_;
  mutable std::vector<std::uint16_t> state_; // by slot: the bits above
  bool any_tag_ = false;
  bool either_side_ = false;                 // the rule sees a facet from either of its cells
  std::vector<std::uint32_t> next_;          // the next round: slots of facets, in queueing order
  Flat_hash_map<Key, Cell_handle, Facet_key_hash> moved_; // a cycle: facets flips changed (null: destroyed)
  Flat_hash_map<Edge, std::vector<std::uint32_t>, Edge_key_hash> registered_; // visit again when the edge's cells change
  Bit_filter<Edge, Edge_key_hash> may_be_registered_; // no false negatives: spares most lookups in registered_
  Cell_handle current_cell_; // the facet under visit
  int current_index_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
