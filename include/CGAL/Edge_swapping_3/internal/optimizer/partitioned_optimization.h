// SPDX-License-Identifier: GPL-3.0-or-later
// The worst-first optimizer on several threads, by parts with frozen
// frontiers, in rounds. A round cuts its vertices into parts by recursive
// bisection along the longest side of their box; each part is optimized with
// its frontier frozen (`Part_constraints`), the first in the triangulation
// itself and each other on a copy of it, all at once; the parts' cells are
// glued back in part order. The first round takes every vertex; the second,
// the band of vertices within `frontier_band_rings` rings of the first
// round's frontiers (a slab, cut across), with only the cells around the
// frontiers waiting at its start; the band around the second round's
// frontiers, small, is optimized last on one thread.
//
// Each part's run reads only its own triangulation, so the result depends on
// the number of parts and not on the timing of the threads: the same input
// and number of parts give the same mesh, cell for cell and in the same
// order, with or without TBB (without it the parts run one after another).
// Copies, rather than one triangulation shared by the threads, because a
// user's TDS stores cells in a sequential container: made in turns, cells
// would take slots in an order the timing decides.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PARTITIONED_OPTIMIZATION_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PARTITIONED_OPTIMIZATION_H

#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_report.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/optimizer/Part_constraints.h>
#include <CGAL/Edge_swapping_3/internal/optimizer/Worst_first_optimizer.h>
#include <CGAL/Real_timer.h>
#include <CGAL/assertions.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Whether a model of `MeshConstraints_3` keeps all it knows in the cells'
/// own data, so that it reads a copy of the triangulation as it reads the
/// triangulation (a model with tables of its own, or a Mesh_3 complex
/// whose cells cache constructions, runs on one thread).
template <class Constraints>
struct Constraints_held_by_cells : std::false_type {};
template <>
struct Constraints_held_by_cells<No_constraints> : std::true_type {};
template <>
struct Constraints_held_by_cells<Domain_constraints> : std::true_type {};

/// The fewest cells a part has: below this, one thread.
constexpr std::size_t smallest_part = 5000;
/// The rings of vertices around a round's frontiers that the next round
/// optimizes, and the rounds in parts (the last band runs on one thread).
constexpr int frontier_band_rings = 2;
constexpr int last_parallel_round = 2;

/// The threads `number_of_threads(n)` asks for: n, or every core for 0.
inline unsigned threads_asked(unsigned n)
{
  if(n != 0) return n;
#ifdef CGAL_LINKED_WITH_TBB
  return unsigned((std::max)(1, tbb::this_task_arena::max_concurrency()));
#else
  return (std::max)(1u, std::thread::hardware_concurrency());
#endif
}

/// The parts a run on `threads` threads cuts `tr` into (1: no cut).
template <class Constraints, class Tr>
unsigned number_of_parts(const Tr& tr, unsigned threads)
{
  if(!Constraints_held_by_cells<Constraints>::value) return 1;
  return unsigned((std::max)(std::size_t(1), (std::min)(std::size_t(threads), tr.number_of_finite_cells() / smallest_part)));
}

/// Runs `f(0)`, ..., `f(n - 1)`, on up to `n` of TBB's threads (without TBB,
/// one after another).
template <class F>
void for_each_part(unsigned n, F f)
{
#ifdef CGAL_LINKED_WITH_TBB
  // More threads than cores only make TBB complain: the parts then share them.
  tbb::task_arena arena{(std::min)(int(n), tbb::this_task_arena::max_concurrency())};
  arena.execute([&] { tbb::parallel_for(0u, n, [&](unsigned p) { f(p); }); });
#else
  for(unsigned p = 0; p < n; ++p) f(p);
#endif
}

/// The part of each vertex by rank (its place in the vertex container) that
/// `active` holds (the others, and the infinite vertex, are in none: -1):
/// recursive bisection, each cut across
/// the longest side of the box of the vertices it splits, at the count that
/// gives each side its share of the parts.
template <class Tr>
std::vector<int> bisected_vertex_parts(const Tr& tr, int parts, const std::vector<char>& active)
{
  std::vector<int> part_of_rank;
  std::vector<std::array<double, 3>> at;
  std::vector<std::uint32_t> rank_of;
  for(auto v = tr.tds().vertices().begin(); v != tr.tds().vertices().end(); ++v)
  {
    part_of_rank.push_back(-1);
    if(tr.is_infinite(v) || !active[part_of_rank.size() - 1]) continue;
    const auto& p = bare_point(v->point());
    at.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    rank_of.push_back(std::uint32_t(part_of_rank.size() - 1));
  }
  std::vector<std::uint32_t> order(at.size());
  for(std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
  auto split = [&](auto& self, std::uint32_t* begin, std::uint32_t* end, int first, int count) -> void {
    if(count == 1 || end - begin < 2)
    {
      for(auto* k = begin; k != end; ++k) part_of_rank[rank_of[*k]] = first;
      return;
    }
    std::array<double, 3> low{{HUGE_VAL, HUGE_VAL, HUGE_VAL}}, high{{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
    for(auto* k = begin; k != end; ++k)
      for(int a = 0; a < 3; ++a)
      {
        low[a] = (std::min)(low[a], at[*k][a]);
        high[a] = (std::max)(high[a], at[*k][a]);
      }
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(high[a] - low[a] > high[axis] - low[axis]) axis = a;
    const int left = count / 2;
    std::uint32_t* middle = begin + (end - begin) * left / count;
    // Ties go by rank: the cut does not depend on the sort's whims.
    std::nth_element(begin, middle, end, [&](std::uint32_t a, std::uint32_t b) {
      return at[a][axis] < at[b][axis] || (at[a][axis] == at[b][axis] && a < b);
    });
    self(self, begin, middle, first, left);
    self(self, middle, end, first + left, count - left);
  };
  split(split, order.data(), order.data() + order.size(), 0, parts);
  return part_of_rank;
}

/// The vertices of `tr` by rank.
template <class Tr>
std::vector<typename Tr::Vertex_handle> vertices_by_rank(const Tr& tr)
{
  std::vector<typename Tr::Vertex_handle> v;
  v.reserve(tr.tds().vertices().size());
  for(auto it = tr.tds().vertices().begin(); it != tr.tds().vertices().end(); ++it) v.push_back(it);
  return v;
}

/// The parts by vertex slot of `tr` (what `Part_constraints` reads), from parts by vertex.
template <class Tr>
std::vector<int> parts_by_slot(const Tr& tr, const std::vector<typename Tr::Vertex_handle>& vertices,
                               const std::vector<int>& parts)
{
  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> slots(tr.tds().vertices());
  std::vector<int> by_slot(slots.number_of_slots(), -1);
  for(std::size_t k = 0; k < vertices.size(); ++k) by_slot[slots(vertices[k])] = parts[k];
  return by_slot;
}

/// The vertices a part made and removed, in order.
template <class Tr>
struct Part_vertex_log
{
  std::vector<std::pair<typename Tr::Vertex_handle, bool>> events; ///< the vertex, and true when made

  /// Replays the log: the vertices made and still there, in the order they
  /// were made, and those removed that were there before, in order. A
  /// handle may name a vertex made in the slot of one removed earlier.
  void replay(std::vector<typename Tr::Vertex_handle>& made, std::vector<typename Tr::Vertex_handle>& removed) const
  {
    typedef typename Tr::Vertex_handle Vertex_handle;
    std::vector<Vertex_handle> all_made;
    std::vector<char> alive;
    Flat_hash_map<Vertex_handle, std::size_t, Handle_hash> alive_at; // index in `all_made`
    for(const auto& [v, is_made] : events)
    {
      if(is_made)
      {
        alive_at[v] = all_made.size();
        all_made.push_back(v);
        alive.push_back(1);
      }
      else if(const std::size_t* k = alive_at.find(v))
      {
        alive[*k] = 0;
        alive_at.erase(v);
      }
      else removed.push_back(v);
    }
    for(std::size_t k = 0; k < all_made.size(); ++k)
      if(alive[k]) made.push_back(all_made[k]);
  }
};

/// Tells the one visitor of all parts, one part at a time (it need not be
/// thread-safe), and logs the vertices the part makes and removes.
template <class Tr, class Visitor>
struct Part_visitor
{
  Visitor* shared;
  std::mutex* mutex;
  Part_vertex_log<Tr>* log;

  void before_replacement(const Tr& tr, const std::vector<typename Tr::Cell_handle>& cells) const
  {
    std::lock_guard<std::mutex> lock(*mutex);
    visitor_of(*shared).before_replacement(tr, cells);
  }
  void after_replacement(const Tr& tr, const std::vector<typename Tr::Cell_handle>& cells) const
  {
    std::lock_guard<std::mutex> lock(*mutex);
    visitor_of(*shared).after_replacement(tr, cells);
  }
  void after_move(const Tr& tr, typename Tr::Vertex_handle v, const typename Tr::Point& from) const
  {
    std::lock_guard<std::mutex> lock(*mutex);
    visitor_of(*shared).after_move(tr, v, from);
  }
  void after_insertion(const Tr& tr, typename Tr::Vertex_handle v, const std::array<typename Tr::Vertex_handle, 4>& corners,
                       const std::array<double, 4>& weights) const
  {
    log->events.push_back({v, true});
    std::lock_guard<std::mutex> lock(*mutex);
    tell_insertion(*shared, tr, v, corners, weights);
  }
  void before_removal(const Tr& tr, typename Tr::Vertex_handle v, typename Tr::Vertex_handle onto) const
  {
    log->events.push_back({v, false});
    std::lock_guard<std::mutex> lock(*mutex);
    tell_removal(*shared, tr, v, onto);
  }
};

template <class Vertex, class = void>
struct Has_vertex_info : std::false_type {};
template <class Vertex>
struct Has_vertex_info<Vertex, std::void_t<decltype(std::declval<Vertex&>().info())>> : std::true_type {};

/// The cells of `tr` in a part (each finite vertex in it), by part.
template <class Tr>
std::vector<std::vector<typename Tr::Cell_handle>> cells_by_part(const Tr& tr, const std::vector<int>& parts_of_slots,
                                                                  int parts)
{
  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> slots(tr.tds().vertices());
  std::vector<std::vector<typename Tr::Cell_handle>> cells(static_cast<std::size_t>(parts));
  for(auto c = tr.tds().cells().begin(); c != tr.tds().cells().end(); ++c)
  {
    int part = -1;
    bool one = true;
    for(int i = 0; i < 4 && one; ++i)
    {
      if(tr.is_infinite(c->vertex(i))) continue;
      const int q = parts_of_slots[slots(c->vertex(i))];
      one = q >= 0 && (part < 0 || q == part);
      part = q;
    }
    if(one && part >= 0) cells[std::size_t(part)].push_back(c);
  }
  return cells;
}

/// Puts part `part` of `copy` (its cells under `in_part`, made from the
/// cells `old_cells` of `tr`) in place of `old_cells`: the vertices the part
/// kept take their new points (and data), those it removed go, those it made
/// come, in the order it made them. `vertices` and `copy_vertices` are the
/// vertices of both by rank, `parts` their parts.
template <class Tr, class In_part>
void glue_part(Tr& tr, const std::vector<typename Tr::Cell_handle>& old_cells, const Tr& copy, const In_part& in_part,
               int part, const std::vector<int>& parts, const std::vector<typename Tr::Vertex_handle>& vertices,
               const std::vector<typename Tr::Vertex_handle>& copy_vertices, const Part_vertex_log<Tr>& log,
               std::vector<typename Tr::Vertex_handle>& made)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  auto& tds = tr.tds();
  Flat_hash_map<Vertex_handle, Vertex_handle, Handle_hash> vertex_of;
  Flat_hash_map<Vertex_handle, std::size_t, Handle_hash> rank_of;
  vertex_of[copy.infinite_vertex()] = tr.infinite_vertex();
  for(std::size_t r = 0; r < parts.size(); ++r)
    if(parts[r] == part)
    {
      vertex_of[copy_vertices[r]] = vertices[r];
      rank_of[copy_vertices[r]] = r;
    }
  std::vector<char> gone(parts.size(), 0);
  std::vector<Vertex_handle> copies_made, copies_removed, removed;
  log.replay(copies_made, copies_removed);
  for(Vertex_handle v : copies_removed)
  {
    const std::size_t r = *rank_of.find(v);
    gone[r] = 1;
    removed.push_back(vertices[r]);
    vertex_of.erase(v);
    rank_of.erase(v);
  }
  for(Vertex_handle v : copies_made)
  {
    const Vertex_handle n = tds.create_vertex(*v);
    vertex_of[v] = n;
    made.push_back(n);
  }

  // The facets between the old cells and the rest, by their sorted vertices.
  typedef std::array<const void*, 3> Key;
  auto key_of = [](Cell_handle c, int i) {
    Key k{{&*c->vertex((i + 1) & 3), &*c->vertex((i + 2) & 3), &*c->vertex((i + 3) & 3)}};
    std::sort(k.begin(), k.end());
    return k;
  };
  Flat_hash_set<Cell_handle, Handle_hash> is_old;
  for(Cell_handle c : old_cells) is_old.insert(c);
  std::vector<std::pair<Key, std::pair<Cell_handle, int>>> outer;
  for(Cell_handle c : old_cells)
    for(int i = 0; i < 4; ++i)
      if(!is_old.contains(c->neighbor(i))) outer.push_back({key_of(c, i), {c->neighbor(i), c->neighbor(i)->index(c)}});
  std::sort(outer.begin(), outer.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  Flat_hash_map<Cell_handle, Cell_handle, Handle_hash> cell_of;
  std::vector<std::pair<Cell_handle, Cell_handle>> pairs; // copy's cell, new cell
  for(auto c = copy.tds().cells().begin(); c != copy.tds().cells().end(); ++c)
  {
    if(!in_part(c)) continue;
    const Cell_handle n = tds.create_cell(*c);
    for(int i = 0; i < 4; ++i) n->set_vertex(i, *vertex_of.find(c->vertex(i)));
    cell_of[c] = n;
    pairs.push_back({c, n});
  }
  for(const auto& [c, n] : pairs)
    for(int i = 0; i < 4; ++i)
    {
      if(const Cell_handle* inner = cell_of.find(c->neighbor(i)))
      {
        n->set_neighbor(i, *inner);
        continue;
      }
      const Key k = key_of(n, i);
      const auto at = std::lower_bound(outer.begin(), outer.end(), k,
                                       [](const auto& a, const Key& b) { return a.first < b; });
      CGAL_assertion(at != outer.end() && at->first == k);
      n->set_neighbor(i, at->second.first);
      at->second.first->set_neighbor(at->second.second, n);
    }
  for(Cell_handle c : old_cells) tds.delete_cell(c);
  for(Vertex_handle v : removed) tds.delete_vertex(v);
  for(std::size_t r = 0; r < parts.size(); ++r)
  {
    if(parts[r] != part || gone[r]) continue;
    vertices[r]->set_point(copy_vertices[r]->point());
    if constexpr(Has_vertex_info<typename Tr::Vertex>::value) vertices[r]->info() = copy_vertices[r]->info();
  }
  for(const auto& [c, n] : pairs)
    for(int i = 0; i < 4; ++i) n->vertex(i)->set_cell(n);
}

/// A copy of the triangulation for one part: its vertices by rank, their
/// parts by slot, and the cells waiting at the start of the part's run.
template <class Tr>
struct Part_copy
{
  std::unique_ptr<Tr> tr;
  std::vector<typename Tr::Vertex_handle> vertices;
  std::vector<int> slot_parts;
  std::vector<typename Tr::Cell_handle> first;
};

/// Copies of `tr` for parts 1 to `parts - 1` (part 0 runs in `tr`), made at
/// once; the cells `first` of `tr` (if given) are found in a copy by their
/// place in the container, which copying keeps.
template <class Tr>
std::vector<Part_copy<Tr>> copies_for_parts(const Tr& tr, unsigned parts, const std::vector<int>& rank_parts,
                                            const std::vector<typename Tr::Cell_handle>* first)
{
  typedef typename Tr::Cell_handle Cell_handle;
  std::vector<std::size_t> first_places;
  if(first != nullptr)
  {
    Flat_hash_set<Cell_handle, Handle_hash> waiting;
    for(Cell_handle c : *first) waiting.insert(c);
    std::size_t place = 0;
    for(auto c = tr.tds().cells().begin(); c != tr.tds().cells().end(); ++c, ++place)
      if(waiting.contains(c)) first_places.push_back(place);
  }
  std::vector<Part_copy<Tr>> copies(parts);
  for_each_part(parts, [&](unsigned p) {
    if(p == 0) return;
    Part_copy<Tr>& copy = copies[p];
    copy.tr = std::make_unique<Tr>(tr);
    copy.vertices = vertices_by_rank(*copy.tr);
    copy.slot_parts = parts_by_slot(*copy.tr, copy.vertices, rank_parts);
    auto c = copy.tr->tds().cells().begin();
    std::size_t place = 0;
    for(std::size_t wanted : first_places)
    {
      std::advance(c, std::ptrdiff_t(wanted - place));
      place = wanted;
      copy.first.push_back(c);
    }
  });
  return copies;
}

/// The next round's vertices (`active`, by slot) and the cells waiting at
/// its start (`first`), after a round whose parts were `rank_parts` (for
/// `vertices`, by rank) and which made `made` (by part): the vertices of the
/// cells across the frontiers and their neighbours to `frontier_band_rings`
/// rings. Only the cells around the frontiers' vertices wait at first: the
/// parts settled the others, and the changes the next round makes requeue
/// those they touch.
template <class Tr>
void next_band(const Tr& tr, const std::vector<typename Tr::Vertex_handle>& vertices,
               const std::vector<int>& rank_parts, const std::vector<std::vector<typename Tr::Vertex_handle>>& made,
               std::vector<char>& active, std::vector<typename Tr::Cell_handle>& first)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  // The parts of the vertices now (those made are in their part's; a
  // removed vertex is in no cell, and its slot may hold one made later).
  Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> slots(tr.tds().vertices());
  std::vector<int> now(slots.number_of_slots(), -1);
  for(std::size_t r = 0; r < vertices.size(); ++r)
    if(rank_parts[r] >= 0) now[slots(vertices[r])] = rank_parts[r];
  for(std::size_t p = 0; p < made.size(); ++p)
    for(Vertex_handle v : made[p]) now[slots(v)] = int(p);
  active.assign(now.size(), 0);
  std::vector<Vertex_handle> ring, next, around;
  for(auto c : tr.finite_cell_handles())
  {
    // Across: its vertices were all in the round, in different parts (the
    // cells at the edge of a band stay as the rounds before left them).
    const int part = now[slots(c->vertex(0))];
    bool across = false, in_round = part >= 0;
    for(int i = 1; i < 4; ++i)
    {
      const int q = now[slots(c->vertex(i))];
      across = across || q != part;
      in_round = in_round && q >= 0;
    }
    if(!across || !in_round) continue;
    for(int i = 0; i < 4; ++i)
      if(!active[slots(c->vertex(i))])
      {
        active[slots(c->vertex(i))] = 1;
        ring.push_back(c->vertex(i));
      }
  }
  first.clear();
  Flat_hash_set<Cell_handle, Handle_hash> seen;
  std::vector<Cell_handle> incident;
  for(Vertex_handle v : ring)
  {
    incident.clear();
    tr.finite_incident_cells(v, std::back_inserter(incident));
    for(Cell_handle c : incident)
      if(seen.insert(c)) first.push_back(c);
  }
  for(int k = 0; k < frontier_band_rings; ++k)
  {
    next.clear();
    for(Vertex_handle v : ring)
    {
      around.clear();
      tr.finite_adjacent_vertices(v, std::back_inserter(around));
      for(Vertex_handle w : around)
        if(!active[slots(w)])
        {
          active[slots(w)] = 1;
          next.push_back(w);
        }
    }
    ring.swap(next);
  }
}

/// Adds `b` to `a`: the counts, and the first ending that is not convergence.
inline void add_report(Quality_report& a, const Quality_report& b)
{
  if(a.ending == CONVERGED) a.ending = b.ending;
  a.visits += b.visits;
  a.stuck += b.stuck;
  a.edge_removals += b.edge_removals;
  a.two_step_removals += b.two_step_removals;
  a.face_removals += b.face_removals;
  a.faces_removed += b.faces_removed;
  a.smoothing_moves += b.smoothing_moves;
  a.vertex_removals += b.vertex_removals;
  a.vertex_insertions += b.vertex_insertions;
  for(std::size_t k = 0; k < a.flips.size(); ++k) a.flips[k] += b.flips[k];
}

/// The worst-first optimizer in `parts` parts (at least 2) with frozen
/// frontiers, in rounds (see the file's comment).
template <class Tr, class Criterion, class Reported, class Constraints, class Visitor>
Quality_report optimize_in_parts(Tr& tr, const Criterion& criterion, const Reported& reported,
                                 const Constraints& constraints, const Visitor& visitor, Worst_first_settings settings,
                                 unsigned parts)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef Part_constraints<Tr, Constraints> Part;
  typedef Part_visitor<Tr, Visitor> Logging_visitor;
  typedef Worst_first_optimizer<Tr, Criterion, Reported, Part, Logging_visitor> Optimizer;
  typedef Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> Vertex_slots;
  CGAL::Real_timer timer;
  timer.start();
  Quality_report total;
  total.worst_before = worst_in_domain(tr, reported, constraints);
  Visitor shared = visitor;
  std::mutex mutex;
  // The part's constraints are kept: they know which of the cells it made are its own.
  auto run = [&](Tr& t, const Part& part, Part_vertex_log<Tr>& log, const std::vector<Cell_handle>* first) {
    Worst_first_settings s = settings;
    s.maximum_seconds = settings.maximum_seconds - timer.time();
    return Optimizer(t, criterion, reported, part, Logging_visitor{&shared, &mutex, &log}, s).run(first);
  };

  // The vertices each round works on, by slot (1: active); the first round
  // works on all of them, and every cell waits at its start.
  std::vector<char> active;
  std::vector<Cell_handle> first;
  for(int round = 0;; ++round)
  {
    const std::vector<Vertex_handle> vertices = vertices_by_rank(tr);
    std::vector<char> rank_active(vertices.size(), 1);
    if(round > 0)
    {
      Vertex_slots slots(tr.tds().vertices());
      for(std::size_t r = 0; r < vertices.size(); ++r) rank_active[r] = active[slots(vertices[r])];
    }
    const std::vector<int> rank_parts = bisected_vertex_parts(tr, int(parts), rank_active);
    const std::vector<int> slot_parts = parts_by_slot(tr, vertices, rank_parts);
    const auto old_cells = cells_by_part(tr, slot_parts, int(parts));
    std::size_t smallest = old_cells[0].size();
    for(const auto& cells : old_cells) smallest = (std::min)(smallest, cells.size());
    if(round > 0 && (smallest < smallest_part || round == last_parallel_round))
    {
      // The last band, too small to share: on this thread.
      std::vector<int> band(slot_parts.size(), -1);
      for(std::size_t k = 0; k < band.size(); ++k)
        if(slot_parts[k] >= 0) band[k] = 0;
      Part_vertex_log<Tr> log;
      add_report(total, run(tr, Part(tr, constraints, band, 0), log, &first));
      break;
    }

    // The first part in `tr`, the others on copies made first (the copies
    // only read `tr`).
    std::vector<Part_copy<Tr>> copies = copies_for_parts(tr, parts, rank_parts, round > 0 ? &first : nullptr);
    std::vector<Part_vertex_log<Tr>> logs(parts);
    std::vector<Quality_report> reports(parts);
    std::vector<std::optional<Part>> part_constraints(parts);
    for_each_part(parts, [&](unsigned p) {
      const bool all = round == 0;
      if(p == 0) part_constraints[0].emplace(tr, constraints, slot_parts, 0);
      else part_constraints[p].emplace(*copies[p].tr, constraints, copies[p].slot_parts, int(p));
      reports[p] = run(p == 0 ? tr : *copies[p].tr, *part_constraints[p], logs[p],
                       all ? nullptr : p == 0 ? &first : &copies[p].first);
    });

    // Glued back in part order.
    std::vector<std::vector<Vertex_handle>> made(parts);
    std::vector<Vertex_handle> removed_in_place;
    logs[0].replay(made[0], removed_in_place);
    for(unsigned p = 1; p < parts; ++p)
    {
      const Part& in_part = *part_constraints[p];
      glue_part(tr, old_cells[p], *copies[p].tr, [&](auto c) { return in_part.in_part(c); }, int(p), rank_parts,
                vertices, copies[p].vertices, logs[p], made[p]);
      part_constraints[p].reset();
      copies[p] = Part_copy<Tr>();
    }
    for(const Quality_report& r : reports) add_report(total, r);
    if(total.ending != CONVERGED) break;

    next_band(tr, vertices, rank_parts, made, active, first);
  }
  total.worst_after = worst_in_domain(tr, reported, constraints);
  total.seconds = timer.time();
  return total;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PARTITIONED_OPTIMIZATION_H
