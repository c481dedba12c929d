// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule and the ending shared by the swap drivers; the rule (what a
// visit of a facet decides) is the caller's. Two schedules:
//  - the paper's cycles: each round lists every interior facet and visits those
//    that still exist when their turn comes;
//  - a work queue: the first round visits every interior facet, later rounds
//    only the facets whose configuration or tags changed since their last
//    visit, so a round costs what the flips before it changed.
// Driver state (the helper's tags, the queue) is kept here, in arrays indexed
// by the cells' slot numbers, never in the TDS marks that CGAL's own
// traversals clear. Both name a facet by a cell slot and an index; the
// paper's cycles follow a listed facet across the flips that replace its cell,
// so that it is visited whenever a facet with its three vertices exists.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Flip_visitor.h>
#include <CGAL/Edge_swapping_3/Helper_reading.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/Visit_record.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/facet_priority.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <queue>
#include <set>
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
  Helper_reading reading; // the helper's, on the paper's cycles
  // Under the fixed face order on the paper's cycles, a state that comes back
  // ends the work: its period is added up to the limit, not run (see
  // `skip_repeated_cycles`). Only for a rule that reads nothing but the cells
  // and the tags (`Rule::reads_only_cells_and_tags`), and with no flip or
  // visit visitor, which would miss the flips not run.
  bool skip_repeated_cycles = true;
  std::size_t* cycles_skipped = nullptr; // if given, the cycles added up instead of run
};

/// Whether a rule declares that its decisions read only the cells and the
/// driver's tags (then a state that comes back repeats the run).
template <class Rule, class = void>
struct Reads_only_cells_and_tags : std::false_type {};
template <class Rule>
struct Reads_only_cells_and_tags<Rule, std::void_t<decltype(Rule::reads_only_cells_and_tags)>>
  : std::bool_constant<Rule::reads_only_cells_and_tags> {};

/// The rule a driver applies, for its rounds' records: `Rule::round_rule`,
/// else the plain rule (Algorithm 2 under a criterion).
template <class Rule, class = void>
struct Round_rule_of : std::integral_constant<Round_rule, PLAIN_RULE> {};
template <class Rule>
struct Round_rule_of<Rule, std::void_t<decltype(Rule::round_rule)>>
  : std::integral_constant<Round_rule, Rule::round_rule> {};

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
  return tr.geom_traits().compare_xyz_3_object()(internal::bare_point(c->vertex(i)->point()), internal::bare_point(m->point())) == SMALLER;
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

/// A hash of an edge by the coordinates of its two points, in either order.
struct Edge_point_hash
{
  template <class Point>
  static std::uint64_t bits_of(const Point& p)
  {
    std::uint64_t h = 0;
    for(const double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())})
    {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = mix_bits(h ^ b);
    }
    return h;
  }
  template <class Key>
  std::size_t operator()(const Key& e) const
  {
    return std::size_t(bits_of(internal::bare_point(e.a->point())) + bits_of(internal::bare_point(e.b->point())));
  }
};

/// A cell slot or a list entry as a hash key (the map mixes the bits).
struct Slot_hash
{
  std::size_t operator()(std::uint32_t k) const { return k; }
};

/// A facet by the slots of its three vertices, in increasing order: half the
/// size of a `Facet_key`, for tables that hold many facets.
struct Vertex_slot_triple
{
  std::uint32_t a, b, c;
  friend bool operator==(const Vertex_slot_triple& x, const Vertex_slot_triple& y)
  {
    return x.a == y.a && x.b == y.b && x.c == y.c;
  }
};

typedef std::array<std::uint32_t, 4> Vertex_slot_quadruple;

struct Vertex_slot_triple_hash
{
  std::size_t operator()(const Vertex_slot_triple& t) const
  {
    return std::size_t((std::uint64_t(t.a) << 32 | t.b) ^ rotate_left(t.c, 17));
  }
};

template <class Tr, class Constraints, class Visitor, class VisitVisitor = No_visit_visitor>
class Swap_driver
{
  static constexpr bool tracing = !std::is_same<std::decay_t<decltype(unwrap(std::declval<VisitVisitor&>()))>,
                                                No_visit_visitor>::value;

public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Facet_key<Tr> Key;
  typedef Edge_key<Tr> Edge;
  typedef Five_point_configuration<Tr> Configuration;
  typedef std::uint16_t State; ///< a cell's bits in the driver (see QUEUED)

  Swap_driver(Tr& tr, const Driver_settings& settings, const Constraints& constraints, Visitor& visitor)
    : tr_(tr), settings_(settings), constraints_(constraints), visitor_(visitor), rng_(settings.random_seed),
      index_(tr.tds().cells()), vertex_index_(tr.tds().vertices())
  {}

  Swap_driver(Tr& tr, const Driver_settings& settings, const Constraints& constraints, Visitor& visitor,
              VisitVisitor& visit_visitor)
    : Swap_driver(tr, settings, constraints, visitor)
  {
    visit_visitor_ = &visit_visitor;
  }

  Tr& triangulation() { return tr_; }
  const Constraints& constraints() const { return constraints_; }
  Perturbation perturbation() const { return settings_.perturbation; }

  // ---- what a rule calls ----

  bool is_tagged(Cell_handle c) const { return any_tag_ && (state(c) & TAGGED) != 0; }

  /// Tags `c` (the helper); a new tag queues the facets whose visit it may change.
  void tag(Cell_handle c)
  {
    State& s = state(c);
    if(s & TAGGED) return;
    s |= TAGGED;
    any_tag_ = true;
    ++record_.new_tags;
    if(settings_.reading.tag_lifetime == TAGS_NEVER_CLEARED) remembered_tags_.insert(vertex_slots(c));
    if constexpr(tracing)
      if(trace_ != nullptr) trace_->new_tags.push_back(cell_vertices(c));
    if(!queueing_) return;
    for(int i = 0; i < 4; ++i) facet_changed(c, i);
    if(registered_facets_ > 0)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) push_registered(c, i, j);
  }

  /// Makes the flip of a swappable, fresh configuration; returns its kind.
  int flip(const Configuration& conf)
  {
    const auto& plan = conf.flip_plan();
    current_cell_ = Cell_handle(); // the flip destroys the facet under visit, and may reuse its cell
    unwrap(visitor_).before_flip(tr_, plan);
    // The old cells' state goes with them (their slots may be reused at
    // once); in round 1 they stay marked, so that a list of cells skips them.
    // In a cycle, their listed facets move to the cells across first.
    if(!queueing_)
      for(int k = 0; k < plan.number_of_old_cells; ++k) move_listed_facets(plan, plan.old_cells[k]);
    for(int k = 0; k < plan.number_of_old_cells; ++k)
    {
      if(state_.empty()) break;
      State& s = state(plan.old_cells[k]);
      queued_facets_ -= number_of_bits(s & (0xF * QUEUED));
      // Its entries in the queue are dead; the slot may be reused at once by a
      // cell that queues a facet for the next round, which they must not visit.
      if(queueing_ && (s & (0xF * QUEUED))) // in a cycle the bits are LISTED, and there is no queue
        for(int i = 0; i < 4; ++i)
          if(s & (QUEUED << i)) add_dead_entry(facet_slot(index_(plan.old_cells[k]), i));
      registered_facets_ -= number_of_bits(s & (0xF * REGISTERED));
      s = first_round_ ? TOUCHED : 0;
    }
    std::array<Cell_handle, 4> created;
    const int n = execute_flip(tr_, plan, created, constraints_);
    if(!remembered_tags_.empty())
      for(int k = 0; k < n; ++k)
        if(!tr_.is_infinite(created[k]) && remembered_tags_.count(vertex_slots(created[k])))
          state(created[k]) |= TAGGED; // made again on tagged vertices
    if(sweeping_) made_.assign(created.begin(), created.begin() + n);
    unwrap(visitor_).after_flip(tr_, plan, created, n);
    if constexpr(tracing)
      if(trace_ != nullptr)
      {
        trace_->flip = int(plan.kind);
        for(int k = 0; k < n; ++k) // a 2-2 flip also makes cells outside the hull
          if(!tr_.is_infinite(created[k])) trace_->created.push_back(cell_vertices(created[k]));
      }
    if(!queueing_)
      relist_made_again(created, n);
    else
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
    if(non_delaunay) state(c) |= State(KEPT << i);
    Vertex_handle a, b;
    if(next_round)
      queue_facet(c, i);
    else if(conf.depends_on_edge_ring(a, b))
      register_facet(c, i, a, b);
  }

  // ---- the schedules ----

  /// `visit(driver, c, i)` decides one interior facet.
  template <class Rule>
  Swap_report run(Rule& visit)
  {
    CGAL_precondition(tr_.dimension() == 3);
    CGAL::Real_timer timer;
    timer.start();
    constexpr bool plain_visitor =
      std::is_same<std::decay_t<decltype(unwrap(std::declval<Visitor&>()))>, Default_flip_visitor>::value;
    skip_repeats_ = settings_.skip_repeated_cycles && settings_.face_order == PRIORITY_ORDER &&
                    Reads_only_cells_and_tags<Rule>::value && plain_visitor && !tracing;
    round_rule_ = Round_rule_of<Rule>::value;
    kept_round_ = 0;
    kept_for_ = 1;
    candidate_round_ = 0;
    round_hashes_.clear();
    Swap_report report = (settings_.schedule == WORK_QUEUE)                         ? run_work_queue(visit)
                         : (settings_.reading.made_facets == MADE_FACETS_SAME_CYCLE) ? run_sweeps(visit)
                                                                                      : run_cycles(visit);
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
    if constexpr(tracing)
    {
      // The trace lists the scan's visits of the facets it found locally Delaunay.
      std::set<std::array<Vertex_handle, 3>> failing;
      auto key = [](Cell_handle c, int i) {
        std::array<Vertex_handle, 3> k{c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)};
        std::sort(k.begin(), k.end());
        return k;
      };
      for(const auto& [c, i] : facets) failing.insert(key(c, i));
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(!tr_.is_infinite(c->neighbor(i)) && holds_facet(tr_, c, i) && !failing.count(key(c, i)))
          {
            Visit_record<Tr> record;
            before_visit(record, c, i);
            record.scanned = true;
            unwrap(*visit_visitor_).visit(tr_, record);
          }
    }
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
  void visit_facet(Rule& visit, Cell_handle c, int i)
  {
    ++record_.visits;
    if constexpr(tracing)
    {
      Visit_record<Tr> record;
      before_visit(record, c, i);
      trace_ = &record;
      visit(*this, c, i);
      trace_ = nullptr;
      unwrap(*visit_visitor_).visit(tr_, record);
    }
    else
      visit(*this, c, i);
  }

  typename Visit_record<Tr>::Cell_vertices cell_vertices(Cell_handle c) const
  {
    return {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
  }

  /// What a trace says of facet (c, i) before its visit.
  void before_visit(Visit_record<Tr>& record, Cell_handle c, int i) const
  {
    const Cell_handle n = c->neighbor(i);
    for(int k = 0; k < 3; ++k) record.facet[k] = c->vertex((i + 1 + k) & 3);
    record.apexes = {c->vertex(i), n->vertex(n->index(c))};
    if constexpr(!Is_weighted_point<typename Tr::Point>::value)
      record.locally_delaunay = is_locally_delaunay(tr_, c, i, settings_.perturbation);
    const Configuration conf = classify_facet(tr_, c, i);
    record.kind = conf.kind();
    record.cells.push_back(cell_vertices(c));
    record.tagged_before.push_back(is_tagged(c));
    record.cells.push_back(cell_vertices(n));
    record.tagged_before.push_back(is_tagged(n));
    for(int k = 1; k < conf.number_of_tetrahedra(); ++k)
      if(conf.tetrahedron(k) != n)
      {
        record.cells.push_back(cell_vertices(conf.tetrahedron(k)));
        record.tagged_before.push_back(is_tagged(conf.tetrahedron(k)));
      }
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

  void end_round(Swap_report& report)
  {
    record_.rule = round_rule_;
    record_.cells = number_of_finite_cells();
    if(settings_.record_non_delaunay_facets)
      record_.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr_, settings_.perturbation);
    report.cycles.push_back(record_);
    if(settings_.cycle_visitor) settings_.cycle_visitor(record_);
    if constexpr(tracing)
      unwrap(*visit_visitor_).end_of_round(tr_, record_, [this](Cell_handle c) { return is_tagged(c); });
  }

  // ---- the paper's cycles ----

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
  //
  // A cycle lists every interior facet once, as slot and index (4 bytes), and
  // visits each at its turn if it still exists, whatever flips happened in
  // between: a flip that destroys the cell a facet was listed from moves its
  // entry to the cell across (`move_listed_facets`), and a facet destroyed and
  // made again later in the cycle is found again (`relist_made_again`).
  // Unvisited listed facets carry the LISTED bit where they are now; an entry
  // that moved is forwarded through `moved_`, keyed by the entry.

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

  // ---- the paper's cycles, the facets made during a cycle visited in it ----
  //
  // A cycle is a sweep through a total order of vertex triples: the fixed
  // order (priority), or one drawn for the cycle (random: the priority of a
  // seed made from the run's seed and the cycle's number). A facet is visited
  // when the sweep reaches its place if it exists then, whether it was there
  // when the cycle began or a flip made it since; one whose place the sweep
  // has passed waits for the next cycle. A triple has one place, so a cycle
  // visits it at most once and ends.

  struct Sweep_place
  {
    std::uint64_t priority;
    std::array<Vertex_handle, 3> v; // by their points, lexicographically
  };

  Sweep_place sweep_place(std::uint64_t seed, Cell_handle c, int i) const
  {
    Sweep_place p;
    for(int k = 0; k < 3; ++k) p.v[k] = c->vertex((i + 1 + k) & 3);
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    std::sort(p.v.begin(), p.v.end(), [&](Vertex_handle a, Vertex_handle b) {
      return compare(bare_point(a->point()), bare_point(b->point())) == SMALLER;
    });
    p.priority = facet_priority(seed, bare_point(p.v[0]->point()), bare_point(p.v[1]->point()),
                                bare_point(p.v[2]->point()));
    return p;
  }

  bool comes_before(const Sweep_place& a, const Sweep_place& b) const
  {
    if(a.priority != b.priority) return a.priority < b.priority;
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    for(int k = 0; k < 3; ++k)
      if(a.v[k] != b.v[k]) return compare(bare_point(a.v[k]->point()), bare_point(b.v[k]->point())) == SMALLER;
    return false;
  }

  template <class Rule>
  Swap_report run_sweeps(Rule& visit)
  {
    if(settings_.face_order == STORAGE_ORDER)
      throw std::invalid_argument("Edge_swapping_3: visiting the facets made during a cycle in it needs the "
                                  "priority or the random face order");
    queueing_ = false;
    sweeping_ = true;
    Swap_report report;
    report.ending = CYCLE_LIMIT_REACHED;
    auto before = [this](const Sweep_place& a, const Sweep_place& b) { return comes_before(a, b); };
    for(std::size_t round = 1; round <= settings_.max_rounds; ++round)
    {
      record_ = Cycle_record();
      record_.cycle = round;
      begin_cycle_tags();
      const std::uint64_t seed = settings_.face_order == RANDOM_ORDER
                                   ? random_sweep_seed(settings_.random_seed, round)
                                   : std::uint64_t(settings_.random_seed);
      std::set<Sweep_place, decltype(before)> ahead(before);
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(holds_facet(tr_, c, i)) ahead.insert(sweep_place(seed, c, i));
      while(!ahead.empty())
      {
        const Sweep_place place = *ahead.begin();
        ahead.erase(ahead.begin());
        Cell_handle c;
        int i;
        std::array<Vertex_handle, 3> v = place.v;
        std::sort(v.begin(), v.end(), [](Vertex_handle a, Vertex_handle b) { return address_of(a) < address_of(b); });
        if(!find_facet(tr_, Key{v[0], v[1], v[2]}, Cell_handle(), c, i)) continue; // destroyed
        if(tr_.is_infinite(c) || tr_.is_infinite(c->neighbor(i))) continue;
        if(!holds_facet(tr_, c, i))
        {
          const Cell_handle n = c->neighbor(i);
          i = n->index(c);
          c = n;
        }
        made_.clear();
        visit_facet(visit, c, i);
        for(Cell_handle m : made_)
          for(int j = 0; j < 4; ++j)
            if(holds_facet(tr_, m, j))
            {
              const Sweep_place p = sweep_place(seed, m, j);
              if(comes_before(place, p)) ahead.insert(p);
            }
      }
      end_round(report);
      if(cycle_ends_run())
      {
        report.ending = CONVERGED;
        break;
      }
      if(skip_repeats_) round = skip_repeated_cycles(report, round);
    }
    sweeping_ = false;
    return report;
  }

  // ---- a state that comes back, under the fixed face order ----
  //
  // Under the fixed order a cycle is a function of the state it starts from:
  // the cells by their vertices, their tags, and the tags the reading
  // remembers by vertices (the order is one of vertex triples; a rule that
  // says `reads_only_cells_and_tags` reads nothing else). When the state at
  // the end of cycle i is that of cycle i - p, the run repeats its last p
  // cycles until the limit: their records are added again for each whole
  // period left, and the cycles left over are run, so that the report and the
  // triangulation at the end are those of running every cycle. Brent's
  // method finds p on hashes of the states (a sum over the cells): one
  // cycle's hash is kept and compared with each later one's, and the kept one
  // moves on after 1, 2, 4, ... cycles. A match is only likely: the state of
  // that cycle is kept and compared, exactly, with the state p cycles on. So
  // no state is held but on a likely loop (a mesh's cells, 20 bytes each).

  struct Cycle_state
  {
    std::vector<std::array<std::uint32_t, 5>> cells; // vertex slots in increasing order, then the tag
    std::size_t remembered = 0; // remembered tags: a set that only grows, so its size tells it
    bool operator==(const Cycle_state& o) const { return remembered == o.remembered && cells == o.cells; }
  };

  std::array<std::uint32_t, 5> cell_state(Cell_handle c)
  {
    const Vertex_slot_quadruple q = vertex_slots(c);
    return {q[0], q[1], q[2], q[3], std::uint32_t(is_tagged(c))};
  }

  std::uint64_t state_hash()
  {
    std::uint64_t h = mix_bits(remembered_tags_.size());
    for(Cell_handle c : tr_.finite_cell_handles())
    {
      std::uint64_t g = 0;
      for(std::uint32_t x : cell_state(c)) g = mix_bits(g ^ x);
      h += g; // a sum: the cells in any order
    }
    return h;
  }

  Cycle_state cycle_state()
  {
    Cycle_state s;
    s.remembered = remembered_tags_.size();
    for(Cell_handle c : tr_.finite_cell_handles()) s.cells.push_back(cell_state(c));
    std::sort(s.cells.begin(), s.cells.end());
    return s;
  }

  /// After cycle `round`, which did not end the run: the cycle the run is at,
  /// `round` or later if the state came back (the cycles between added up).
  std::size_t skip_repeated_cycles(Swap_report& report, std::size_t round)
  {
    const std::uint64_t h = state_hash();
    round_hashes_.push_back(h); // of round round_hashes_.size()
    if(candidate_round_ > 0 && round == candidate_round_ + candidate_period_)
    {
      if(h == candidate_hash_ && cycle_state() == candidate_state_)
        return add_periods(report, round, candidate_period_);
      candidate_round_ = 0; // two states with one hash
      candidate_state_ = Cycle_state();
    }
    if(candidate_round_ == 0 && kept_round_ > 0 && h == kept_hash_)
    {
      candidate_state_ = cycle_state();
      candidate_hash_ = h;
      candidate_round_ = round;
      candidate_period_ = round - kept_round_;
    }
    if(round - kept_round_ == kept_for_)
    {
      kept_hash_ = h;
      kept_round_ = round;
      kept_for_ *= 2;
    }
    return round;
  }

  /// The state at the end of cycle `round` is that of `period` cycles before:
  /// the whole periods left are added up; returns the cycle they end on.
  std::size_t add_periods(Swap_report& report, std::size_t round, std::size_t period)
  {
    const std::size_t added = (settings_.max_rounds - round) / period * period;
    for(std::size_t k = 1; k <= added; ++k)
    {
      Cycle_record r = report.cycles[report.cycles.size() - period]; // a copy: the vector grows
      r.cycle = round + k;
      report.cycles.push_back(r);
      if(settings_.cycle_visitor) settings_.cycle_visitor(r);
    }
    if(settings_.cycles_skipped != nullptr) *settings_.cycles_skipped += added;
    locate_loop(report, period);
    skip_repeats_ = false; // fewer cycles than a period are left
    candidate_state_ = Cycle_state();
    return round + added;
  }

  /// The run loops with a period dividing `period` (states compared exactly):
  /// the report gets where it first came back, by the rounds' hashes (the
  /// first round i whose hash is that of round i + `period`, then the
  /// shortest period from there; hashes equal by chance would misplace it).
  void locate_loop(Swap_report& report, std::size_t period)
  {
    const std::vector<std::uint64_t>& h = round_hashes_; // h[k]: after round k + 1
    std::size_t i = 0;
    while(h[i] != h[i + period]) ++i; // ends: the last round's hash is that of `period` before
    std::size_t p = 1;
    while(period % p != 0 || h[i] != h[i + p]) ++p;
    report.loop_round = i + 1 + p;
    report.loop_period = p;
    round_hashes_ = {};
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

  Tr& tr_;
  const Driver_settings& settings_;
  Round_rule round_rule_ = PLAIN_RULE; // the rule of the run, for the reports
  const Constraints& constraints_;
  Visitor& visitor_;
  CGAL::Random rng_;
  Cycle_record record_;
  bool queueing_ = false;
  bool first_round_ = false;
  bool seeded_ = false;              // the first round's facets were given (a scan found them)
  std::size_t scanned_visits_ = 0;   // the scan's visits of facets not queued
  std::array<std::size_t, number_of_flip_kinds> first_round_swaps_{}; // made before the driver

  mutable Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> index_;
  mutable std::vector<State> state_; // by slot: the bits above
  bool any_tag_ = false;
  std::size_t infinite_cells_ = 0;  // 0 until counted
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
  // A cycle: where flips moved list entries (a destroyed entry is neither here
  // nor where it was listed), the entry of each moved facet, and the entries of
  // destroyed facets by their vertices.
  Flat_hash_map<std::uint32_t, std::uint32_t, Slot_hash> moved_;
  Flat_hash_map<std::uint32_t, std::uint32_t, Slot_hash> entry_of_;
  // Storage order: the entries that left their slot, smallest first.
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<std::uint32_t>> displaced_;
  Flat_hash_map<Vertex_slot_triple, std::uint32_t, Vertex_slot_triple_hash> made_again_;
  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> vertex_index_;
  std::size_t registered_facets_ = 0;       // REGISTERED bits set
  // Edges with a registered facet, and some others. Hashed by the points, not
  // the addresses: which edges pass decides which facets are visited again,
  // and a run must not depend on where the cells are in memory.
  Bit_filter<Edge, Edge_point_hash> may_be_registered_;
  // The reading TAGS_NEVER_CLEARED: the vertices of every cell ever tagged.
  std::set<Vertex_slot_quadruple> remembered_tags_;
  bool sweeping_ = false;          // run_sweeps: a flip lists the cells it made in made_
  std::vector<Cell_handle> made_;
  Cell_handle current_cell_; // the facet under visit
  int current_index_ = 0;
  VisitVisitor* visit_visitor_ = nullptr;
  Visit_record<Tr>* trace_ = nullptr; // the record of the visit under way (tracing only)
  // skip_repeated_cycles: on in this run; the hash kept, its cycle (0: none) and
  // the cycles until it moves on; a likely loop: the state, hash and cycle (0:
  // none) to find again, and the period after which to look.
  bool skip_repeats_ = false;
  std::uint64_t kept_hash_ = 0;
  std::size_t kept_round_ = 0;
  std::size_t kept_for_ = 1;
  Cycle_state candidate_state_;
  std::uint64_t candidate_hash_ = 0;
  std::size_t candidate_round_ = 0;
  std::size_t candidate_period_ = 0;
  std::vector<std::uint64_t> round_hashes_; // the state's hash after each round, to place a loop
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SWAP_DRIVER_H
