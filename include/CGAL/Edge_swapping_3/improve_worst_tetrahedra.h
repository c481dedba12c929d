// SPDX-License-Identifier: GPL-3.0-or-later
// The quality driver: hill climbing on the worst tetrahedra first. A queue
// holds the finite cells by the criterion's measure, worst first; the worst
// cell is taken and the operations are tried on it in a fixed order (edge
// removal on its six edges, multi-face removal at its four facets, the flip
// of each of its four facets, then, when asked, the smoothing of each of its
// vertices, the removal of each of its vertices and the insertion of a vertex
// in it); the first that improves the worst tetrahedron of its
// neighbourhood is made, and the cells whose operations that changed go into
// the queue. The run ends when the queue is empty (with smoothing, when a
// sweep over every cell moves no vertex): then no operation improves any
// cell, and a second run makes no change (with smoothing, none but moves of
// the vertices that used up their `maximum_moves_per_vertex`; with vertex
// insertion, it may insert in cells whose inserted vertices barred it).

#ifndef CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H
#define CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/Dihedral_angle_guard.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/edge_removal.h>
#include <CGAL/Edge_swapping_3/multi_face_removal.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/worst_cell_queue.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/two_step_edge_removal.h>
#include <CGAL/Edge_swapping_3/vertex_insertion.h>
#include <CGAL/Edge_swapping_3/vertex_removal.h>
#include <CGAL/Edge_swapping_3/vertex_smoothing.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// The operations of the quality driver, as bits.
enum Quality_operation : unsigned
{
  FLIPS = 1,              ///< 2-3, 3-2, 2-2 and 4-4 flips of the cell's facets
  EDGE_REMOVAL = 2,       ///< edge removal on the cell's edges
  MULTI_FACE_REMOVAL = 4, ///< multi-face removal at the cell's facets
  SMOOTHING = 8,          ///< smoothing of the cell's interior vertices (moves points)
  TWO_STEP_EDGE_REMOVAL = 16, ///< edge removal after the removal of an edge of the edge's star
  /// smoothing that also moves vertices within flat boundary patches and along
  /// straight boundary edges (`move_on_flat_boundary` of `smooth_vertex`);
  /// implies `SMOOTHING`
  BOUNDARY_SMOOTHING = 32,
  /// removal of the cell's interior vertices by edge contraction (`remove_vertex`)
  VERTEX_REMOVAL = 64,
  /// insertion of a vertex in the cell (`insert_vertex`), off the boundary
  VERTEX_INSERTION = 128,
  /// every operation that keeps the points
  TOPOLOGICAL_OPERATIONS = FLIPS | EDGE_REMOVAL | MULTI_FACE_REMOVAL | TWO_STEP_EDGE_REMOVAL,
  /// every operation that keeps the vertices (interior ones may move)
  ALL_OPERATIONS = TOPOLOGICAL_OPERATIONS | SMOOTHING,
  /// every operation, vertices removed and inserted too (boundary vertices stay)
  ALL_WITH_VERTEX_CHANGES = ALL_OPERATIONS | VERTEX_REMOVAL | VERTEX_INSERTION
};

/// The report of `improve_worst_tetrahedra`.
struct Quality_report
{
  Swap_ending ending = CONVERGED;               ///< CONVERGED (queue empty) or CYCLE_LIMIT_REACHED (operation limit)
  std::size_t visits = 0;                       ///< cells taken from the queue that still existed
  std::size_t stuck = 0;                        ///< of those, the cells no operation improved
  std::size_t edge_removals = 0;                ///< edges removed (in one step)
  std::size_t two_step_removals = 0;            ///< edges removed in two steps (two edges each)
  std::size_t face_removals = 0;                ///< multi-face removals made
  std::size_t faces_removed = 0;                ///< triangles they removed
  std::size_t smoothing_moves = 0;              ///< smoothing moves made (a vertex may move more than once)
  std::size_t vertex_removals = 0;              ///< vertices removed
  std::size_t vertex_insertions = 0;            ///< vertices inserted
  std::array<std::size_t, number_of_flip_kinds> flips{}; ///< flips by kind
  double worst_before = 0;                      ///< the worst value over the finite cells in the domain, before
  double worst_after = 0;                       ///< the same after
  double seconds = 0;                           ///< the time of the run

  /// The operations made, flips included.
  std::size_t number_of_operations() const
  {
    std::size_t n = edge_removals + two_step_removals + face_removals + smoothing_moves + vertex_removals +
                    vertex_insertions;
    for(std::size_t f : flips) n += f;
    return n;
  }
};

namespace internal {

/// Removes the repeated items of `items`, keeping each first occurrence in
/// place: the order stays the order met, which no address decides.
template <class Handle>
void keep_first_occurrences(std::vector<Handle>& items)
{
  std::vector<std::pair<Handle, std::size_t>> sorted;
  sorted.reserve(items.size());
  for(std::size_t k = 0; k < items.size(); ++k) sorted.emplace_back(items[k], k);
  std::sort(sorted.begin(), sorted.end());
  std::vector<bool> keep(items.size(), false);
  for(std::size_t k = 0; k < sorted.size(); ++k)
    if(k == 0 || !(sorted[k].first == sorted[k - 1].first)) keep[sorted[k].second] = true;
  std::size_t n = 0;
  for(std::size_t k = 0; k < items.size(); ++k)
    if(keep[k]) items[n++] = items[k];
  items.resize(n);
}

} // namespace internal

namespace internal {

/// The worst value of the criterion's measure over the finite cells in the domain.
template <class Tr, class Measure, bool larger_is_worse, class Constraints>
double worst_in_domain(const Tr& tr, const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                       const Constraints& constraints)
{
  double w = larger_is_worse ? -HUGE_VAL : HUGE_VAL;
  for(auto c : tr.finite_cell_handles())
    if(constraints.is_in_domain(tr, c))
    {
      const double v = criterion.measure(internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()),
                                         internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point()));
      w = larger_is_worse ? (std::max)(w, v) : (std::min)(w, v);
    }
  return w;
}

/// The driver under `criterion`; the report's worst values are in the measure
/// of `reported` (the criterion that the caller was given, when `criterion`
/// guards it).
template <class Tr, class Measure, bool larger_is_worse, class Reported, class Constraints, class NamedParameters>
Quality_report improve_worst_tetrahedra(Tr& tr, const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                        const Reported& reported, const Constraints& constraints,
                                        const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Tr::Cell_handle Cell_handle;
  CGAL_precondition(tr.dimension() == 3);
  unsigned operations = choose_parameter(get_parameter(np, internal_np::operations), unsigned(TOPOLOGICAL_OPERATIONS));
  if(operations & BOUNDARY_SMOOTHING) operations |= SMOOTHING;
  const int maximum_ring = choose_parameter(get_parameter(np, internal_np::maximum_ring_size), 10);
  const int maximum_moves = choose_parameter(get_parameter(np, internal_np::maximum_moves_per_vertex), 20);
  const std::pair<double, double> change_angles =
      choose_parameter(get_parameter(np, internal_np::vertex_change_angles), std::pair<double, double>(30, 140));
  // Vertices come and go only at cells outside these angles: without a
  // bound, insertion would refine every cell that its neighbours beat.
  const double smallest_cosine = std::cos(change_angles.first * CGAL_PI / 180),
               largest_cosine = std::cos(change_angles.second * CGAL_PI / 180);
  auto outside_change_angles = [&](Cell_handle c) {
    const auto cosines = internal::dihedral_cosines(internal::bare_point(c->vertex(0)->point()),
                                                    internal::bare_point(c->vertex(1)->point()),
                                                    internal::bare_point(c->vertex(2)->point()),
                                                    internal::bare_point(c->vertex(3)->point()));
    for(double x : cosines)
      if(x > smallest_cosine || x < largest_cosine) return true;
    return false;
  };
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  const double target = choose_parameter(get_parameter(np, internal_np::quality_target),
                                         larger_is_worse ? -HUGE_VAL : HUGE_VAL);
  // Scores are larger-is-better: a cell scoring at least this needs no work.
  const double enough = larger_is_worse ? -target : target;
  const std::size_t limit = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                             100 * tr.number_of_finite_cells());
  CGAL::Real_timer timer;
  timer.start();

  auto score = [&](Cell_handle c) {
    auto at = [&](int i) -> decltype(auto) { return internal::bare_point(c->vertex(i)->point()); };
    const double v = criterion.measure(at(0), at(1), at(2), at(3));
    return larger_is_worse ? -v : v;
  };
  // Cells outside the domain (subdomain 0 of a domain mesh) are neither
  // measured nor taken; the operations never join them to the domain.
  auto counted = [&](Cell_handle c) { return !tr.is_infinite(c) && constraints.is_in_domain(tr, c); };
  // Each cell waits at most once (`queue`, by slot): a cell pushed again
  // while it waits is skipped, not measured. An entry is taken only if its
  // slot still waits in the heap and holds a cell of the same score: a cell
  // made in a freed slot, or one whose vertex moved, is pushed anew
  // (`changed`), and its older entries are passed over. A batch of an eighth
  // of the cells is in the heap at a time (`Worst_cell_queue`).
  internal::Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> slots(tr.tds().cells());
  internal::Worst_cell_queue queue((std::max)(tr.number_of_finite_cells() / 8, std::size_t(1024)));
  // With the topological operations alone, they are made in two rounds.
  // Every visit tries the quick ones (edge removal, multi-face removal,
  // flips); a cell they leave stuck waits in `later` for two-step removal,
  // which runs when no cell waits for the quick ones: the costly attempts
  // are made on a neighbourhood the quick ones have settled, not again at
  // each of its changes (on 15,000 random points with the 140 degree target,
  // 3.2 s instead of 6.1 s, and fewer bad cells: benchmarks.md). With
  // smoothing or vertex changes, a visit tries every operation in turn
  // (two rounds there gave more bad cells, or took longer).
  const unsigned quick_operations = operations & (FLIPS | EDGE_REMOVAL | MULTI_FACE_REMOVAL);
  const bool two_rounds = quick_operations != 0 && (operations & TWO_STEP_EDGE_REMOVAL) != 0 &&
                          (operations & (SMOOTHING | VERTEX_REMOVAL | VERTEX_INSERTION)) == 0;
  internal::Worst_cell_queue later((std::max)(tr.number_of_finite_cells() / 8, std::size_t(1024)));
  auto push = [&](Cell_handle c, bool changed) {
    const std::size_t k = slots(c);
    if(changed)
    {
      queue.forget(k);
      later.forget(k);
    }
    if(queue.waits(k) || queue.is_settled(k) || !counted(c)) return;
    const double s = score(c);
    if(s >= enough)
    {
      // Its score changes only when it does, and then it is pushed as changed.
      queue.settle(k, slots.number_of_slots());
      return;
    }
    queue.add(k, float(s), slots.number_of_slots());
  };
  auto score_of_slot = [&](std::size_t k) -> std::optional<float> {
    typename Tr::Cell* cell = slots.item(k);
    if(cell == nullptr) return std::nullopt;
    const Cell_handle c = tr.tds().cells().iterator_to(*cell);
    if(!counted(c)) return std::nullopt;
    return float(score(c));
  };
  // The cells whose operations may have changed, each pushed once. With edge
  // removal alone: those sharing an edge with a new cell (the ring of that
  // edge changed). With multi-face removal: a sandwich at a facet of a cell
  // reads cells around the two vertices off that facet, no more than
  // `maximum_ring` + 1 steps away through facets around that vertex, from
  // the cell or from its neighbour across the facet. So for each vertex v
  // of a new cell, the cells around v within `maximum_ring` + 2 such steps
  // of a new cell, and their neighbours (a walk, not the whole star: a
  // vertex of a placing triangulation has thousands of cells).
  std::vector<Cell_handle> around;
  std::vector<typename Tr::Vertex_handle> corners;
  std::vector<std::pair<Cell_handle, int>> walk;
  internal::Flat_hash_set<Cell_handle, internal::Handle_hash> seen;
  auto push_around = [&](const std::vector<Cell_handle>& created) {
    around.clear();
    if(operations & MULTI_FACE_REMOVAL)
    {
      corners.clear();
      for(Cell_handle c : created)
        for(int i = 0; i < 4; ++i)
          if(!tr.is_infinite(c->vertex(i))) corners.push_back(c->vertex(i));
      internal::keep_first_occurrences(corners);
      for(auto v : corners)
      {
        // Breadth first from the new cells around v, through facets around v.
        walk.clear();
        seen.clear();
        for(Cell_handle c : created)
          if(c->has_vertex(v) && seen.insert(c)) walk.emplace_back(c, 0);
        for(std::size_t k = 0; k < walk.size(); ++k)
        {
          const auto [c, depth] = walk[k];
          around.push_back(c);
          for(int i = 0; i < 4; ++i)
          {
            // A neighbour through v is walked, and so pushed, unless the
            // walk ends here or has been there.
            const Cell_handle n = c->neighbor(i);
            if(c->vertex(i) == v || depth == maximum_ring + 2) around.push_back(n);
            else if(seen.insert(n)) walk.emplace_back(n, depth + 1);
          }
        }
      }
    }
    else
      for(Cell_handle c : created)
      {
        if(tr.is_infinite(c)) continue;
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j)
          {
            auto circ = tr.incident_cells(c, i, j), done = circ;
            do around.push_back(circ);
            while(++circ != done);
          }
      }
    for(Cell_handle c : created) push(c, true);
    for(Cell_handle c : around) push(c, false);
  };

  Quality_report report;
  report.worst_before = worst_in_domain(tr, reported, constraints);
  for(Cell_handle c : tr.finite_cell_handles()) push(c, false);
  std::vector<Cell_handle> created;
  // Failed removals in a fixed amount of memory, an 8-byte slot per eight
  // cells each (per two for two-step removal, below): a failure forgotten is
  // tried again. Smaller tables cost time (benchmarks.md, "Quality at scale").
  const std::size_t failure_slots = tr.number_of_finite_cells() / 8;
  internal::Edge_removal_failures<Tr> failures((operations & EDGE_REMOVAL) ? failure_slots : 0);
  internal::Multi_face_removal_failures<Tr> face_failures((operations & MULTI_FACE_REMOVAL) ? failure_slots : 0);
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
  // slot has newer vertices. The infinite vertex has no stamp: the operations through it
  // (a hull facet's) fail. Stamps are by vertex slot; a vertex made in a
  // freed slot takes a new stamp. Times are counts of changes, plus one (0:
  // never tried), in 32 bits: past 2^32 - 2 changes no stamp moves, and
  // nothing is skipped. Two-step failures of single edges are also
  // remembered with the stamps of the edge's ends.
  const bool stamping = (operations & (EDGE_REMOVAL | MULTI_FACE_REMOVAL | TWO_STEP_EDGE_REMOVAL)) != 0;
  internal::Edge_removal_failures<Tr> two_step_failures((operations & TWO_STEP_EDGE_REMOVAL) ? 4 * failure_slots : 0);
  // Bounds on the best of the stars of two-step removal's steps, 16 bytes a
  // place, a place per eight cells (the driver then holds 1.25 times the
  // triangulation at 10^5 points; benchmarks.md): a star that cannot beat a
  // floor is not solved again.
  internal::Edge_removal_bounds<Tr> two_step_bounds((operations & TWO_STEP_EDGE_REMOVAL) ? failure_slots : 0);
  internal::Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> vertex_slots(
      tr.tds().vertices());
  std::vector<std::uint32_t> stamps(stamping ? vertex_slots.number_of_slots() : 0, 0);
  // By slot: when the quick operations, and when two-step removal, last failed.
  std::vector<std::uint32_t> quick_tried, two_step_tried;
  std::uint64_t changes = 0;
  const std::uint64_t last_stamp = std::numeric_limits<std::uint32_t>::max() - 1;
  auto record_failure = [&](std::vector<std::uint32_t>& tried, std::size_t slot) {
    if(slot >= tried.size()) tried.resize((std::max)(slots.number_of_slots(), slot + 1), 0);
    tried[slot] = std::uint32_t(changes + 1);
  };
  auto stamp_of = [&](typename Tr::Vertex_handle v) {
    const std::size_t k = vertex_slots(v);
    return k < stamps.size() ? stamps[k] : std::uint32_t(0);
  };
  // The vertices whose smoothing failed since their star last changed (a
  // cell around them made or removed, or a vertex of their star moved), and
  // the moves of each vertex.
  internal::Flat_hash_set<typename Tr::Vertex_handle, internal::Handle_hash> settled;
  internal::Flat_hash_map<typename Tr::Vertex_handle, int, internal::Handle_hash> moves_of;
  auto may_move = [&](typename Tr::Vertex_handle v) {
    const int* moves = moves_of.find(v);
    return !settled.contains(v) && (moves == nullptr || *moves < maximum_moves);
  };
  std::vector<Cell_handle> star;
  internal::Flat_hash_set<typename Tr::Vertex_handle, internal::Handle_hash> inserted; // by vertex insertion
  // With both removals, a flip of a facet of the cell is never needed: the
  // 3-2, 4-4 and 2-2 flips are edge removals of the cell's edges, the 2-3 flip
  // the one-triangle disk of multi-face removal, and either removal takes its
  // best option, which beats the old cells whenever the flip would.
  const bool flips = (operations & FLIPS) &&
                     (operations & (EDGE_REMOVAL | MULTI_FACE_REMOVAL)) != (EDGE_REMOVAL | MULTI_FACE_REMOVAL);
  // A smoothing move requeues only the cells around the vertex, so an
  // empty queue is checked by a sweep over every cell; the run ends when a
  // sweep changes nothing.
  std::size_t moves_at_sweep = 0;
  for(;;)
  {
    bool later_round = false;
    if(queue.empty_heap())
    {
      if(queue.refill(score_of_slot)) continue;
      later_round = !later.empty_heap() || later.refill(score_of_slot);
    }
    if(queue.empty_heap() && !later_round)
    {
      if(report.smoothing_moves == moves_at_sweep) break;
      moves_at_sweep = report.smoothing_moves;
      for(Cell_handle c : tr.finite_cell_handles()) push(c, false);
      continue;
    }
    if(report.number_of_operations() >= limit)
    {
      report.ending = CYCLE_LIMIT_REACHED;
      break;
    }
    internal::Worst_cell_queue& from = later_round ? later : queue;
    const internal::Worst_cell_entry entry = from.pop();
    typename Tr::Cell* cell = slots.item(entry.slot);
    if(cell == nullptr || !from.queued_at(entry.slot)) continue;
    const Cell_handle c = tr.tds().cells().iterator_to(*cell);
    if(!counted(c)) continue;
    const float now = float(score(c));
    // An older entry of the slot is passed over (NaN: a degenerate cell's measure).
    if(now != entry.score && !(now != now && entry.score != entry.score)) continue;
    from.forget(entry.slot);
    ++report.visits;
    created.clear();
    bool improved = false, moved = false;
    // When the cell's quick operations, and its two-step removals, last
    // failed (0: never, or no time is kept), and whether a vertex is older.
    const bool stamped = stamping && changes < last_stamp;
    auto tried_at = [&](const std::vector<std::uint32_t>& tried) {
      return stamped && entry.slot < tried.size() ? tried[entry.slot] : std::uint32_t(0);
    };
    std::uint32_t tried = tried_at(quick_tried);
    auto unchanged = [&](typename Tr::Vertex_handle v) { return stamp_of(v) < tried; };
    auto ring_unchanged = [&](Cell_handle x, int i, int j) {
      auto circ = tr.incident_cells(x, i, j), done = circ;
      do
        for(int k = 0; k < 4; ++k)
        {
          const typename Tr::Vertex_handle v = circ->vertex(k);
          if(v != x->vertex(i) && v != x->vertex(j) && !tr.is_infinite(v) && !unchanged(v)) return false;
        }
      while(++circ != done);
      return true;
    };
    const bool quick = !later_round;
    if(quick && (operations & EDGE_REMOVAL))
      for(int i = 0; i < 4 && !improved; ++i)
        for(int j = i + 1; j < 4 && !improved; ++j)
          if(!unchanged(c->vertex(i)) && !unchanged(c->vertex(j)) &&
             internal::remove_edge(tr, typename Tr::Edge(c, i, j), criterion, constraints, visitor, maximum_ring,
                                    created, &failures)
                 .removed())
          {
            ++report.edge_removals;
            improved = true;
          }
    if(quick && (operations & MULTI_FACE_REMOVAL))
      for(int i = 0; i < 4 && !improved; ++i)
      {
        const Cell_handle d = c->neighbor(i);
        if(unchanged(c->vertex(i)) && unchanged(d->vertex(d->index(c)))) continue;
        const auto r =
            internal::remove_faces(tr, typename Tr::Facet(c, i), criterion, constraints, visitor, maximum_ring, created,
                                 &face_failures);
        if(r.removed())
        {
          ++report.face_removals;
          report.faces_removed += std::size_t(r.faces);
          improved = true;
        }
      }
    if(quick && flips)
      for(int i = 0; i < 4 && !improved; ++i)
      {
        const auto conf = classify_facet(tr, c, i);
        if(!conf.is_swappable() || !flip_respects_constraints(tr, conf.flip_plan(), constraints) || !criterion(tr, conf))
          continue;
        const auto& plan = conf.flip_plan();
        internal::visitor_of(visitor).before_replacement(
            tr, std::vector<Cell_handle>(plan.old_cells.begin(), plan.old_cells.begin() + plan.number_of_old_cells));
        std::array<Cell_handle, 4> cells;
        const int n = flip(tr, conf, cells, constraints);
        created.assign(cells.begin(), cells.begin() + n);
        internal::visitor_of(visitor).after_replacement(tr, created);
        ++report.flips[conf.flip_kind()];
        improved = true;
      }
    if(quick && quick_operations && !improved && stamped) record_failure(quick_tried, entry.slot);
    if(quick && two_rounds && !improved)
    {
      // Stuck for the quick operations: it waits for two-step removal.
      if(!later.waits(entry.slot)) later.add(entry.slot, entry.score, slots.number_of_slots());
      continue;
    }
    tried = tried_at(two_step_tried);
    if((operations & TWO_STEP_EDGE_REMOVAL) && !improved)
      for(int i = 0; i < 4 && !improved; ++i)
        for(int j = i + 1; j < 4 && !improved; ++j)
        {
          if(unchanged(c->vertex(i)) && unchanged(c->vertex(j))) continue;
          // With one end older, the edge's star and every star through that
          // end are as they were; so are the others when no ring vertex is newer.
          if((unchanged(c->vertex(i)) || unchanged(c->vertex(j))) && ring_unchanged(c, i, j)) continue;
          const std::uint32_t stamp_i = stamp_of(c->vertex(i)), stamp_j = stamp_of(c->vertex(j));
          const auto key = internal::edge_key<Tr>(c->vertex(i), c->vertex(j));
          const std::uint64_t signature = internal::mix_bits(stamp_i) + internal::mix_bits(stamp_j);
          if(stamped && two_step_failures.find(key, signature) != nullptr) continue;
          const auto attempt = internal::remove_edge_in_two_steps(tr, typename Tr::Edge(c, i, j), criterion,
                                                                  constraints, visitor, maximum_ring, created,
                                                                  &two_step_bounds);
          improved = attempt.removed();
          if(stamped) two_step_failures.record(key, signature, attempt, improved);
          if(improved) ++report.two_step_removals;
        }
    if((operations & TWO_STEP_EDGE_REMOVAL) && !improved && stamped) record_failure(two_step_tried, entry.slot);
    if(operations & SMOOTHING)
      for(int i = 0; i < 4 && !improved; ++i)
      {
        if(!may_move(c->vertex(i))) continue;
        star.clear();
        if(internal::smooth_vertex(tr, c->vertex(i), criterion, constraints, visitor,
                                   internal::default_smoothing_steps, star,
                                   (operations & BOUNDARY_SMOOTHING) != 0).moved())
        {
          created = star;
          moved = true;
          ++report.smoothing_moves;
          improved = true;
          ++moves_of[c->vertex(i)];
        }
        else
          settled.insert(c->vertex(i));
      }
    // A vertex goes or comes last: users who keep their vertices leave these off.
    const bool may_change_vertices =
        (operations & (VERTEX_REMOVAL | VERTEX_INSERTION)) && !improved && outside_change_angles(c);
    if((operations & VERTEX_REMOVAL) && may_change_vertices)
      for(int i = 0; i < 4 && !improved; ++i)
      {
        const typename Tr::Vertex_handle v = c->vertex(i);
        if(tr.is_infinite(v)) continue;
        if(internal::remove_vertex(tr, v, criterion, constraints, visitor, created).removed())
        {
          // Its handle may come back for a vertex made later.
          settled.erase(v);
          moves_of.erase(v);
          inserted.erase(v);
          ++report.vertex_removals;
          improved = true;
        }
      }
    if((operations & VERTEX_INSERTION) && may_change_vertices && !improved)
    {
      // No vertex goes in a cell that has an inserted vertex. Next to a
      // facet that bounds the quality (a needle on the hull), each new vertex
      // would otherwise gain a little on the last, on and on: on 2,000
      // random points, 17,415 insertions in 412 s; with this rule, 521
      // in 10 s, and fewer bad cells (doc/Edge_swapping_3/user_manual.md).
      bool inserted_corner = false;
      for(int i = 0; i < 4; ++i) inserted_corner = inserted_corner || inserted.contains(c->vertex(i));
      typename Tr::Vertex_handle made;
      if(!inserted_corner &&
         internal::insert_vertex(tr, c, criterion, constraints, visitor, internal::default_cavity_depth, created, &made)
             .inserted())
      {
        inserted.insert(made);
        ++report.vertex_insertions;
        improved = true;
      }
    }
    if(improved)
    {
      ++changes;
      if(!stamps.empty() && changes <= last_stamp)
        for(Cell_handle n : created)
          for(int i = 0; i < 4; ++i)
            if(!tr.is_infinite(n->vertex(i)))
            {
              const std::size_t k = vertex_slots(n->vertex(i));
              if(k >= stamps.size()) stamps.resize(vertex_slots.number_of_slots(), 0);
              stamps[k] = std::uint32_t(changes);
            }
      if(!settled.empty())
        for(Cell_handle n : created)
          for(int i = 0; i < 4; ++i) settled.erase(n->vertex(i));
      if(moved) for(Cell_handle n : created) push(n, true);
      else push_around(created);
    }
    else ++report.stuck;
  }
  report.worst_after = worst_in_domain(tr, reported, constraints);
  report.seconds = timer.time();
  return report;
}

} // namespace internal

/// Improves the worst tetrahedra of `tr` under `criterion` (any
/// `Worst_tetrahedron_criterion`: MinMax or MaxMin dihedral angle, an aspect
/// ratio) by hill climbing, worst first: edge removal (`remove_edge`) on each
/// edge of the worst cell, multi-face removal (`remove_faces`) at each of its
/// facets, the flip of each of its facets, then, with `SMOOTHING`, the
/// smoothing (`smooth_vertex`) of each of its vertices, with `VERTEX_REMOVAL`
/// the removal (`remove_vertex`) of each of its vertices and with
/// `VERTEX_INSERTION` the insertion of a vertex in it (`insert_vertex`), the
/// first that improves the worst tetrahedron where it acts. Every change improves
/// that worst value beyond the criterion's relative tolerance, so the worst
/// value over the mesh never gets worse and the run ends.
///
/// By default no change makes a dihedral angle smaller than the smallest of
/// the domain before the run, or larger than the largest
/// (`Dihedral_angle_guard.h`): a one-sided criterion such as MinMax would
/// otherwise trade small angles for large ones, and smoothing under it can
/// flatten cells.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{operations} bits of `Quality_operation` (default `TOPOLOGICAL_OPERATIONS`: no
///     point moves unless asked) \cgalParamNEnd
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{maximum_ring_size} the largest ring edge removal considers, and the most
///     triangles multi-face removal explores, default 10 \cgalParamNEnd
///   \cgalParamNBegin{maximum_moves_per_vertex} with `SMOOTHING`, the most times a vertex moves in a run,
///     default 20: smoothing a vertex to the best place of its star moves its neighbours' best places, and
///     without a bound the gains shrink for long (measured on 300 random points, MaxMin dihedral sine:
///     8,376 moves, 4.6 s without a bound; 3,793 moves, 2.0 s with 20; the worst sine 0.127 and 0.072)
///     \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} the most operations made (smoothing moves included), default 100
///     times the number of cells \cgalParamNEnd
///   \cgalParamNBegin{quality_target} a value of the measure: only the cells worse than it are taken from the
///     queue (as TetGen's optimizer works only on the cells above its target angle); default: every cell, and
///     the run ends when no operation improves any cell \cgalParamNEnd
///   \cgalParamNBegin{keep_dihedral_angle_range} `bool`, default true: refuse every operation that makes a
///     dihedral angle outside the range of the domain's before the run \cgalParamNEnd
///   \cgalParamNBegin{vertex_change_angles} `std::pair<double, double>`, default (30, 140): with `VERTEX_REMOVAL`
///     or `VERTEX_INSERTION`, vertices are removed and inserted only at cells with a dihedral angle, in degrees,
///     below the first or above the second; no vertex is inserted in a cell that has a vertex inserted in the run
///     \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor`: told of
///     every flip, removal (each step of a two-step removal), move, vertex insertion and vertex removal \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Quality_report improve_worst_tetrahedra(Tr& tr, const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool keep_range = choose_parameter(get_parameter(np, internal_np::keep_dihedral_angle_range), true);
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    if(!keep_range) return internal::improve_worst_tetrahedra(tr, criterion, criterion, constraints, np);
    const Dihedral_angle_range range = dihedral_angle_range(
        tr, [&](typename Tr::Cell_handle c) { return constraints.is_in_domain(tr, c); });
    // Reported in the criterion's own measure (the guard computes the
    // angles on the points in another order: the last bits may differ).
    return internal::improve_worst_tetrahedra(tr, guarded_by_dihedral_angles(criterion, range), criterion,
                                              constraints, np);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H
