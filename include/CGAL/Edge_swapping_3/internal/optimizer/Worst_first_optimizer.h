// SPDX-License-Identifier: GPL-3.0-or-later
// The quality driver as an object: hill climbing on the worst tetrahedra
// first. The queue, the change stamps and the failure tables are members;
// each group of operations is a method; `run()` is the algorithm.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_WORST_FIRST_OPTIMIZER_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_WORST_FIRST_OPTIMIZER_H

#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Quality_report.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/edge_removal.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/internal/optimizer/change_neighbourhood.h>
#include <CGAL/Edge_swapping_3/internal/worst_cell_queue.h>
#include <CGAL/Edge_swapping_3/multi_face_removal.h>
#include <CGAL/Edge_swapping_3/two_step_edge_removal.h>
#include <CGAL/Edge_swapping_3/vertex_insertion.h>
#include <CGAL/Edge_swapping_3/vertex_removal.h>
#include <CGAL/Edge_swapping_3/vertex_smoothing.h>
#include <CGAL/Real_timer.h>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The settings of the quality driver, read once from the named parameters.
/// The most smoothing moves of one vertex in a run, unless told otherwise.
/// Near a fixed boundary, vertices go on moving as their neighbours move,
/// and a low bound stops them there with bad cells left (benchmarks.md,
/// "Next to the hull").
constexpr int default_maximum_moves = 200;

struct Worst_first_settings
{
  unsigned operations = TOPOLOGICAL_OPERATIONS; ///< bits of `Quality_operation` (`BOUNDARY_SMOOTHING` implies `SMOOTHING`)
  int maximum_ring = 10;                        ///< edge removal's ring, multi-face removal's triangles
  int maximum_moves = default_maximum_moves;    ///< smoothing moves of one vertex
  double smallest_change_angle = 30;            ///< degrees: vertices change only at cells with an angle below
  double largest_change_angle = 140;            ///< ... or above this
  double enough = HUGE_VAL;                     ///< a score (larger is better) that needs no work
  std::size_t maximum_operations = 0;           ///< the operation limit
  double maximum_seconds = HUGE_VAL;            ///< the time limit
  const std::atomic<bool>* stop = nullptr;      ///< the run ends once this reads true
};

/// The worst value of the criterion's measure over the finite cells in the domain.
template <class Tr, class Criterion, class Constraints>
double worst_in_domain(const Tr& tr, const Criterion& criterion, const Constraints& constraints)
{
  constexpr bool larger_is_worse = Worst_tetrahedron_criterion_traits<Criterion>::larger_is_worse;
  double w = larger_is_worse ? -HUGE_VAL : HUGE_VAL;
  for(auto c : tr.finite_cell_handles())
    if(constraints.is_in_domain(tr, c))
    {
      const double v = criterion.measure(bare_point(c->vertex(0)->point()), bare_point(c->vertex(1)->point()),
                                         bare_point(c->vertex(2)->point()), bare_point(c->vertex(3)->point()));
      w = larger_is_worse ? (std::max)(w, v) : (std::min)(w, v);
    }
  return w;
}

/// The quality driver under `Criterion`; the report's worst values are in
/// the measure of `Reported` (the criterion the caller was given, when
/// `Criterion` guards it).
///
/// A visit takes the worst waiting cell and tries the operations on it in a
/// fixed order: the quick ones (edge removal on its six edges, multi-face
/// removal at its four facets, the flip of each facet), two-step removal,
/// then, when asked, smoothing of its vertices, the removal of a vertex and
/// the insertion of one. The first that improves the worst tetrahedron of
/// its neighbourhood is made, and the cells whose operations that changed
/// wait again. The object holds references into itself: it is neither
/// copied nor moved.
template <class Tr, class Criterion, class Reported, class Constraints, class Visitor>
class Worst_first_optimizer
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Operation_context<Tr, Criterion, Constraints, Visitor> Context;

  Worst_first_optimizer(Tr& tr, const Criterion& criterion, const Reported& reported, const Constraints& constraints,
                        const Visitor& visitor, const Worst_first_settings& settings)
    : tr_(tr), criterion_(criterion), reported_(reported), constraints_(constraints), visitor_(visitor),
      settings_(settings), operations_(settings.operations), op_{tr, criterion, constraints, visitor_,
                                                                     settings.maximum_ring, created_},
      slots_(tr.tds().cells()), queue_(batch_size()), later_(batch_size()), neighbourhood_(tr),
      failures_((operations_ & EDGE_REMOVAL) ? failure_slots() : 0),
      face_failures_((operations_ & MULTI_FACE_REMOVAL) ? failure_slots() : 0),
      two_step_failures_((operations_ & TWO_STEP_EDGE_REMOVAL) ? 4 * failure_slots() : 0),
      two_step_bounds_((operations_ & TWO_STEP_EDGE_REMOVAL) ? failure_slots() : 0), vertex_slots_(tr.tds().vertices())
  {
    CGAL_precondition(tr.dimension() == 3);
    timer_.start();
    if(operations_ & BOUNDARY_SMOOTHING) operations_ |= SMOOTHING;
    quick_operations_ = operations_ & (FLIPS | EDGE_REMOVAL | MULTI_FACE_REMOVAL);
    // With the topological operations alone, they are made in two rounds.
    // Every visit tries the quick ones; a cell they leave stuck waits in
    // `later_` for two-step removal, which runs when no cell waits for the
    // quick ones: the costly attempts are made on a neighbourhood the quick
    // ones have settled, not again at each of its changes (benchmarks.md,
    // "Quality at scale"). With smoothing or vertex changes, a visit tries
    // every operation in turn (two rounds there gave more bad cells, or
    // took longer).
    two_rounds_ = quick_operations_ != 0 && (operations_ & TWO_STEP_EDGE_REMOVAL) != 0 &&
                  (operations_ & (SMOOTHING | VERTEX_REMOVAL | VERTEX_INSERTION)) == 0;
    // With both removals, a flip of a facet of the cell is never needed: the
    // 3-2, 4-4 and 2-2 flips are edge removals of the cell's edges, the 2-3
    // flip the one-triangle disk of multi-face removal, and either removal
    // takes its best option, which beats the old cells whenever the flip would.
    flips_ = (operations_ & FLIPS) &&
             (operations_ & (EDGE_REMOVAL | MULTI_FACE_REMOVAL)) != (EDGE_REMOVAL | MULTI_FACE_REMOVAL);
    stamping_ = (operations_ & (EDGE_REMOVAL | MULTI_FACE_REMOVAL | TWO_STEP_EDGE_REMOVAL)) != 0;
    if(stamping_) stamps_.assign(vertex_slots_.number_of_slots(), 0);
    smallest_cosine_ = std::cos(settings.smallest_change_angle * CGAL_PI / 180);
    largest_cosine_ = std::cos(settings.largest_change_angle * CGAL_PI / 180);
  }

  Worst_first_optimizer(const Worst_first_optimizer&) = delete;
  Worst_first_optimizer& operator=(const Worst_first_optimizer&) = delete;

  /// Visits the worst waiting cell until none waits (with smoothing, until a
  /// sweep over every cell moves no vertex) or a limit is reached. The cells
  /// of `first` wait at the start, when given; otherwise every cell does.
  Quality_report run(const std::vector<Cell_handle>* first = nullptr)
  {
    report_.worst_before = worst_in_domain(tr_, reported_, constraints_);
    if(first != nullptr)
      for(Cell_handle c : *first) push(c, false);
    else
      for(Cell_handle c : tr_.finite_cell_handles()) push(c, false);
    while(const std::optional<Visit> visit = next_visit())
    {
      if(try_operations(*visit)) record_change();
      else if(!waits_for_later_round(*visit)) ++report_.stuck;
    }
    report_.worst_after = worst_in_domain(tr_, reported_, constraints_);
    report_.seconds = timer_.time();
    return report_;
  }

private:
  /// A cell taken from a queue, with its slot and whether it came from `later_`.
  struct Visit
  {
    Cell_handle cell;
    Worst_cell_entry entry;
    bool later_round;
  };

  std::size_t batch_size() const { return (std::max)(tr_.number_of_finite_cells() / 8, std::size_t(1024)); }
  // Failed removals in a fixed amount of memory, an 8-byte slot per eight
  // cells each (per two for two-step removal): a failure forgotten is tried
  // again. Smaller tables cost time (benchmarks.md, "Quality at scale").
  std::size_t failure_slots() const { return tr_.number_of_finite_cells() / 8; }

  // --- scores and the queues ---------------------------------------------

  double score(Cell_handle c) const
  {
    const double v = criterion_.measure(bare_point(c->vertex(0)->point()), bare_point(c->vertex(1)->point()),
                                        bare_point(c->vertex(2)->point()), bare_point(c->vertex(3)->point()));
    return Context::larger_is_worse ? -v : v;
  }

  // Cells outside the domain (subdomain 0 of a domain mesh) are neither
  // measured nor taken; the operations never join them to the domain.
  bool counted(Cell_handle c) const { return !tr_.is_infinite(c) && constraints_.is_in_domain(tr_, c); }

  // Each cell waits at most once (`queue_`, by slot): a cell pushed again
  // while it waits is skipped, not measured. An entry is taken only if its
  // slot still waits in the heap and holds a cell of the same score: a cell
  // made in a freed slot, or one whose vertex moved, is pushed anew
  // (`changed`), and its older entries are passed over. A batch of an eighth
  // of the cells is in the heap at a time (`Worst_cell_queue`).
  void push(Cell_handle c, bool changed)
  {
    const std::size_t k = slots_(c);
    if(changed)
    {
      queue_.forget(k);
      later_.forget(k);
    }
    if(queue_.waits(k) || queue_.is_settled(k) || !counted(c)) return;
    const double s = score(c);
    if(s >= settings_.enough)
    {
      // Its score changes only when it does, and then it is pushed as changed.
      queue_.settle(k, slots_.number_of_slots());
      return;
    }
    queue_.add(k, float(s), slots_.number_of_slots());
  }

  std::optional<float> score_of_slot(std::size_t k) const
  {
    typename Tr::Cell* cell = slots_.item(k);
    if(cell == nullptr) return std::nullopt;
    const Cell_handle c = tr_.tds().cells().iterator_to(*cell);
    if(!counted(c)) return std::nullopt;
    return float(score(c));
  }

  /// Whether a limit ends the run now, and the ending it gives.
  bool limit_reached()
  {
    if(report_.number_of_operations() >= settings_.maximum_operations) report_.ending = CYCLE_LIMIT_REACHED;
    else if(settings_.stop != nullptr && settings_.stop->load(std::memory_order_relaxed)) report_.ending = INTERRUPTED;
    else if(settings_.maximum_seconds < HUGE_VAL && timer_.time() >= settings_.maximum_seconds)
      report_.ending = TIME_LIMIT_REACHED;
    else return false;
    return true;
  }

  /// The next cell to visit, or none when the run ends. A smoothing move
  /// requeues only the cells around the vertex, so an empty queue is
  /// checked by a sweep over every cell; the run ends when a sweep changes
  /// nothing.
  std::optional<Visit> next_visit()
  {
    auto score_of = [this](std::size_t k) { return score_of_slot(k); };
    for(;;)
    {
      bool later_round = false;
      if(queue_.empty_heap())
      {
        if(queue_.refill(score_of)) continue;
        later_round = !later_.empty_heap() || later_.refill(score_of);
      }
      if(queue_.empty_heap() && !later_round)
      {
        if(report_.smoothing_moves == moves_at_sweep_) return std::nullopt;
        moves_at_sweep_ = report_.smoothing_moves;
        for(Cell_handle c : tr_.finite_cell_handles()) push(c, false);
        continue;
      }
      if(limit_reached()) return std::nullopt;
      Worst_cell_queue& from = later_round ? later_ : queue_;
      const Worst_cell_entry entry = from.pop();
      typename Tr::Cell* cell = slots_.item(entry.slot);
      if(cell == nullptr || !from.queued_at(entry.slot)) continue;
      const Cell_handle c = tr_.tds().cells().iterator_to(*cell);
      if(!counted(c)) continue;
      const float now = float(score(c));
      // An older entry of the slot is passed over (NaN: a degenerate cell's measure).
      if(now != entry.score && !(now != now && entry.score != entry.score)) continue;
      from.forget(entry.slot);
      return Visit{c, entry, later_round};
    }
  }

  // --- the visit -----------------------------------------------------------

  /// Tries the operations on the visited cell in turn; true when one was made
  /// (its new or moved cells are in `created_`).
  bool try_operations(const Visit& visit)
  {
    ++report_.visits;
    created_.clear();
    moved_ = false;
    stamped_ = stamping_ && changes_ < last_stamp;
    const Cell_handle c = visit.cell;
    const std::size_t slot = visit.entry.slot;
    if(!visit.later_round)
    {
      if(try_quick_operations(c, tried_at(quick_tried_, slot))) return true;
      if(quick_operations_ && stamped_) record_failure(quick_tried_, slot);
      if(two_rounds_) return false; // stuck for the quick ones: it waits for two-step removal
    }
    if(operations_ & TWO_STEP_EDGE_REMOVAL)
    {
      if(try_two_step_removal(c, tried_at(two_step_tried_, slot))) return true;
      if(stamped_) record_failure(two_step_tried_, slot);
    }
    if((operations_ & SMOOTHING) && try_smoothing(c)) return true;
    // A vertex goes or comes last: users who keep their vertices leave these off.
    if(!(operations_ & (VERTEX_REMOVAL | VERTEX_INSERTION)) || !outside_change_angles(c)) return false;
    if((operations_ & VERTEX_REMOVAL) && try_vertex_removal(c)) return true;
    return (operations_ & VERTEX_INSERTION) && try_vertex_insertion(c);
  }

  /// After a failed quick visit in two rounds: the cell waits for two-step
  /// removal (and is not counted as stuck yet).
  bool waits_for_later_round(const Visit& visit)
  {
    if(visit.later_round || !two_rounds_) return false;
    if(!later_.waits(visit.entry.slot)) later_.add(visit.entry.slot, visit.entry.score, slots_.number_of_slots());
    return true;
  }

  /// Edge removal on the cell's edges, multi-face removal at its facets, the
  /// flips of its facets: the first that improves. `tried` is when they last
  /// failed on this cell: an operation that reads only older vertices fails
  /// again and is skipped.
  bool try_quick_operations(Cell_handle c, std::uint32_t tried)
  {
    auto unchanged = [&](Vertex_handle v) { return stamp_of(v) < tried; };
    if(operations_ & EDGE_REMOVAL)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
        {
          const Vertex_handle a = c->vertex(i), b = c->vertex(j);
          if(unchanged(a) || unchanged(b)) continue;
          const typename Tr::Edge e(c, i, j);
          const auto r = stamped_ ? remove_edge(op_, e, failures_, directed_stamp_signature(a, b)) : remove_edge(op_, e);
          if(r.removed())
          {
            ++report_.edge_removals;
            return true;
          }
        }
    if(operations_ & MULTI_FACE_REMOVAL)
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle d = c->neighbor(i);
        const Vertex_handle u = c->vertex(i), w = d->vertex(d->index(c));
        if(unchanged(u) && unchanged(w)) continue;
        const typename Tr::Facet f(c, i);
        const auto r = stamped_ ? remove_faces(op_, f, face_failures_, directed_stamp_signature(u, w)) : remove_faces(op_, f);
        if(r.removed())
        {
          ++report_.face_removals;
          report_.faces_removed += std::size_t(r.faces);
          return true;
        }
      }
    if(flips_)
      for(int i = 0; i < 4; ++i)
        if(try_flip(c, i)) return true;
    return false;
  }

  bool try_flip(Cell_handle c, int i)
  {
    const auto conf = classify_facet(tr_, c, i);
    if(!conf.is_swappable() || !flip_respects_constraints(tr_, conf.flip_plan(), constraints_) ||
       !criterion_(tr_, conf))
      return false;
    const auto& plan = conf.flip_plan();
    visitor_of(visitor_).before_replacement(
        tr_, std::vector<Cell_handle>(plan.old_cells.begin(), plan.old_cells.begin() + plan.number_of_old_cells));
    std::array<Cell_handle, 4> cells;
    const int n = flip(tr_, conf, cells, constraints_);
    created_.assign(cells.begin(), cells.begin() + n);
    visitor_of(visitor_).after_replacement(tr_, created_);
    ++report_.flips[conf.flip_kind()];
    return true;
  }

  /// Two-step removal of the cell's edges, skipping those whose stars are
  /// as they were when it last failed (`tried`), and single edges that
  /// failed with the same stamps at their ends.
  bool try_two_step_removal(Cell_handle c, std::uint32_t tried)
  {
    auto unchanged = [&](Vertex_handle v) { return stamp_of(v) < tried; };
    auto ring_unchanged = [&](int i, int j) {
      auto circ = tr_.incident_cells(c, i, j), done = circ;
      do
        for(int k = 0; k < 4; ++k)
        {
          const Vertex_handle v = circ->vertex(k);
          if(v != c->vertex(i) && v != c->vertex(j) && !tr_.is_infinite(v) && !unchanged(v)) return false;
        }
      while(++circ != done);
      return true;
    };
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        if(unchanged(c->vertex(i)) && unchanged(c->vertex(j))) continue;
        // With one end older, the edge's star and every star through that
        // end are as they were; so are the others when no ring vertex is newer.
        if((unchanged(c->vertex(i)) || unchanged(c->vertex(j))) && ring_unchanged(i, j)) continue;
        const auto key = edge_key<Tr>(c->vertex(i), c->vertex(j));
        const std::uint64_t signature = stamp_signature(c->vertex(i), c->vertex(j));
        if(stamped_ && two_step_failures_.find(key, signature) != nullptr) continue;
        const auto attempt = remove_edge_in_two_steps(op_, typename Tr::Edge(c, i, j), &two_step_bounds_);
        const bool removed = attempt.removed();
        if(stamped_) two_step_failures_.record(key, signature, attempt, removed);
        if(removed)
        {
          ++report_.two_step_removals;
          return true;
        }
      }
    return false;
  }

  // The vertices whose smoothing failed since their star last changed (a
  // cell around them made or removed, or a vertex of their star moved), and
  // the moves of each vertex.
  bool may_move(Vertex_handle v) const
  {
    const int* moves = moves_of_.find(v);
    return !settled_.contains(v) && (moves == nullptr || *moves < settings_.maximum_moves);
  }

  bool try_smoothing(Cell_handle c)
  {
    for(int i = 0; i < 4; ++i)
    {
      const Vertex_handle v = c->vertex(i);
      if(!may_move(v)) continue;
      star_.clear();
      if(smooth_vertex(op_, v, default_smoothing_steps, star_, (operations_ & BOUNDARY_SMOOTHING) != 0).moved())
      {
        created_ = star_;
        moved_ = true;
        ++report_.smoothing_moves;
        ++moves_of_[v];
        return true;
      }
      settled_.insert(v);
    }
    return false;
  }

  // Vertices come and go only at cells outside the change angles: without a
  // bound, insertion would refine every cell that its neighbours beat.
  bool outside_change_angles(Cell_handle c) const
  {
    const auto cosines = dihedral_cosines(bare_point(c->vertex(0)->point()), bare_point(c->vertex(1)->point()),
                                          bare_point(c->vertex(2)->point()), bare_point(c->vertex(3)->point()));
    for(double x : cosines)
      if(x > smallest_cosine_ || x < largest_cosine_) return true;
    return false;
  }

  bool try_vertex_removal(Cell_handle c)
  {
    for(int i = 0; i < 4; ++i)
    {
      const Vertex_handle v = c->vertex(i);
      if(tr_.is_infinite(v)) continue;
      if(remove_vertex(op_, v).removed())
      {
        // Its handle may come back for a vertex made later.
        settled_.erase(v);
        moves_of_.erase(v);
        inserted_.erase(v);
        ++report_.vertex_removals;
        return true;
      }
    }
    return false;
  }

  // No vertex goes in a cell that has an inserted vertex. Next to a facet
  // that bounds the quality (a needle on the hull), each new vertex would
  // otherwise gain a little on the last, on and on (the figures: user
  // manual, section 2, `vertex_change_angles`).
  bool try_vertex_insertion(Cell_handle c)
  {
    for(int i = 0; i < 4; ++i)
      if(inserted_.contains(c->vertex(i))) return false;
    Vertex_handle made;
    if(!insert_vertex(op_, c, default_cavity_depth, &made).inserted()) return false;
    inserted_.insert(made);
    ++report_.vertex_insertions;
    return true;
  }

  // --- after a change ------------------------------------------------------

  // Each change stamps every vertex of a new or moved cell with its time
  // (every vertex of a removed cell is in a new one). An operation reads only
  // cells through some vertices, and a change to one of those cells stamps
  // them: edge removal reads the cells through both ends of its edge (a
  // change there stamps both), multi-face removal those through either
  // vertex off its facet, two-step removal those through both ends (the
  // edge's star) and through an end and a ring vertex (the first steps).
  // Each cell keeps (by slot) the times at which its quick operations and
  // its two-step removals last failed; an operation whose cells cannot have
  // changed since fails again and is not tried. A cell made later in the
  // slot has newer vertices. The infinite vertex has no stamp: the
  // operations through it (a hull facet's) fail. Stamps are by vertex slot;
  // a vertex made in a freed slot takes a new stamp. Times are counts of
  // changes, plus one (0: never tried), in 32 bits: past 2^32 - 2 changes no
  // stamp moves, and nothing is skipped. Two-step failures of single edges
  // are also remembered with the stamps of the edge's ends.
  std::uint32_t stamp_of(Vertex_handle v)
  {
    const std::size_t k = vertex_slots_(v);
    return k < stamps_.size() ? stamps_[k] : std::uint32_t(0);
  }

  // The failure tables' signature of an attempt that reads only cells
  // through `a` or `b` (or through both): it changes with every change there.
  std::uint64_t stamp_signature(Vertex_handle a, Vertex_handle b)
  {
    return mix_bits(stamp_of(a)) + mix_bits(stamp_of(b));
  }

  // The same, told apart from the attempt from the other end: that one
  // orders its ring or its sandwich otherwise, and may end otherwise (the
  // last bits of a measure depend on the order of the points).
  std::uint64_t directed_stamp_signature(Vertex_handle from, Vertex_handle to)
  {
    return mix_bits(mix_bits(stamp_of(from)) ^ std::uint64_t(address_of(from))) + mix_bits(stamp_of(to));
  }

  std::uint32_t tried_at(const std::vector<std::uint32_t>& tried, std::size_t slot) const
  {
    return stamped_ && slot < tried.size() ? tried[slot] : std::uint32_t(0);
  }

  void record_failure(std::vector<std::uint32_t>& tried, std::size_t slot)
  {
    if(slot >= tried.size()) tried.resize((std::max)(slots_.number_of_slots(), slot + 1), 0);
    tried[slot] = std::uint32_t(changes_ + 1);
  }

  /// Stamps the vertices of the new cells, and queues the cells whose
  /// operations the change may have changed.
  void record_change()
  {
    ++changes_;
    if(!stamps_.empty() && changes_ <= last_stamp)
      for(Cell_handle n : created_)
        for(int i = 0; i < 4; ++i)
          if(!tr_.is_infinite(n->vertex(i)))
          {
            const std::size_t k = vertex_slots_(n->vertex(i));
            if(k >= stamps_.size()) stamps_.resize(vertex_slots_.number_of_slots(), 0);
            stamps_[k] = std::uint32_t(changes_);
          }
    if(!settled_.empty())
      for(Cell_handle n : created_)
        for(int i = 0; i < 4; ++i) settled_.erase(n->vertex(i));
    if(moved_)
      for(Cell_handle n : created_) push(n, true);
    else
    {
      for(Cell_handle n : created_) push(n, true);
      for(Cell_handle n : neighbourhood_(created_, operations_ & MULTI_FACE_REMOVAL, settings_.maximum_ring))
        push(n, false);
    }
  }

  static constexpr std::uint64_t last_stamp = std::numeric_limits<std::uint32_t>::max() - 1;

  Tr& tr_;
  const Criterion& criterion_;
  const Reported& reported_;
  const Constraints& constraints_;
  Visitor visitor_;
  const Worst_first_settings settings_;
  unsigned operations_;
  unsigned quick_operations_ = 0;
  bool two_rounds_ = false, flips_ = false, stamping_ = false;
  double smallest_cosine_ = 1, largest_cosine_ = -1;
  std::vector<Cell_handle> created_; ///< the new or moved cells of the visit's change
  const Context op_;

  Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> slots_;
  Worst_cell_queue queue_, later_;
  Change_neighbourhood<Tr> neighbourhood_;

  Edge_removal_failures<Tr> failures_;
  Multi_face_removal_failures<Tr> face_failures_;
  Edge_removal_failures<Tr> two_step_failures_;
  // Bounds on the best of the stars of two-step removal's steps, 16 bytes a
  // place, a place per eight cells (the driver then holds 1.25 times the
  // triangulation at 10^5 points; benchmarks.md): a star that cannot beat a
  // floor is not solved again.
  Edge_removal_bounds<Tr> two_step_bounds_;

  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> vertex_slots_;
  std::vector<std::uint32_t> stamps_;
  std::vector<std::uint32_t> quick_tried_, two_step_tried_; ///< by slot: when they last failed
  std::uint64_t changes_ = 0;
  bool stamped_ = false; ///< whether the visit's failures are stamped
  bool moved_ = false;   ///< whether the visit's change is a move

  Flat_hash_set<Vertex_handle, Handle_hash> settled_;
  Flat_hash_map<Vertex_handle, int, Handle_hash> moves_of_;
  Flat_hash_set<Vertex_handle, Handle_hash> inserted_; ///< by vertex insertion
  std::vector<Cell_handle> star_;
  std::size_t moves_at_sweep_ = 0;

  CGAL::Real_timer timer_;
  Quality_report report_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_WORST_FIRST_OPTIMIZER_H
