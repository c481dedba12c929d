// SPDX-License-Identifier: GPL-3.0-or-later
// The first round of the Delaunay repair on an unconstrained triangulation:
// plain flips (Lawson's, in three dimensions) from the facets the scan found
// not locally Delaunay, made by the package's 2-3 and 3-2 flips (common_flips.h)
// with a first-in first-out queue of cells, the way flip-based insertion
// flips a link. The driver's queue, per-slot state and edge-ring watches cost
// several times the flip itself; far from Delaunay (a placing start) nearly
// every swap of the repair is made here.
//
// Each test is a visit the plain rule makes (swap a swappable configuration
// that is not locally Delaunay), in the order of a paper cycle that also
// visits the facets made in it, so the driver's meaning is unchanged. A
// facet the two common flips cannot make Delaunay (concave at an edge of more
// than three cells, a degenerate configuration, a hull facet) is left to the
// driver, which gets exactly the facets still not locally Delaunay.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_LAWSON_FLIPS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_LAWSON_FLIPS_H

#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/internal/common_flips.h>
#include <algorithm>
#include <array>
#include <deque>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Tr>
struct Lawson_flips_result
{
  std::array<std::size_t, number_of_flip_kinds> swaps{}; ///< indexed by `Flip_kind`
  std::size_t visits = 0;                                ///< facets tested
  std::size_t compactions = 0;                           ///< times the list of cells set aside was cut
  /// The interior facets not locally Delaunay at the end, each once.
  std::vector<std::pair<typename Tr::Cell_handle, int>> left;
};

/// Flips from `facets` (interior facets, each given once) until no 2-3 or
/// 3-2 flip of a facet that is not locally Delaunay is left. `facets` is
/// emptied as it is read. The cells' TDS marks are used and left clear.
template <class Tr>
Lawson_flips_result<Tr> lawson_flips(Tr& tr, std::vector<std::pair<typename Tr::Cell_handle, int>>& facets,
                                     Perturbation perturbation)
{
  typedef typename Tr::Cell_handle Cell_handle;
  Lawson_flips_result<Tr> result;
  const auto& cells = tr.tds().cells();
  // A cell is queued at most once (marked in conflict), or set aside (marked
  // on the boundary): a facet of it failed and could not be flipped then.
  std::deque<Cell_handle> queue;
  std::vector<Cell_handle> aside;
  auto push = [&](Cell_handle c) {
    if(c->tds_data().is_in_conflict()) return;
    c->tds_data().mark_in_conflict();
    queue.push_back(c);
  };
  // A cell set aside, then queued again and set aside again, is listed
  // twice, and a listed cell may be freed: far from Delaunay the list would
  // grow with the flips (to two million entries from a placing start of
  // 10^5 points).
  // When it doubles it is cut to the cells still set aside, each once (the
  // mark in conflict meanwhile says "listed").
  std::size_t compact_at = 4096;
  auto compact_aside = [&]() {
    std::size_t kept = 0;
    for(Cell_handle c : aside)
      if(cells.is_used(c) && c->tds_data().is_on_boundary())
      {
        c->tds_data().mark_in_conflict();
        aside[kept++] = c;
      }
    aside.resize(kept);
    for(Cell_handle c : aside) c->tds_data().mark_on_boundary();
    compact_at = (std::max)(compact_at, 2 * kept);
    ++result.compactions;
  };
  std::array<Cell_handle, 4> made;
  bool progress = false;
  // Tests the interior facet (c, i); flips it if it fails and a common flip
  // makes it, queueing the new cells (true: c is gone or new); else sets c aside.
  auto visit = [&](Cell_handle c, int i) {
    ++result.visits;
    if(is_locally_delaunay(tr, c, i, perturbation)) return false;
    const Common_flip flip = common_flip_at(tr, c, i);
    if(flip.kind == NOT_FLIPPABLE_NOW || flip.kind == NEEDS_GENERAL_FLIP)
    {
      if(!c->tds_data().is_on_boundary())
      {
        c->tds_data().mark_on_boundary();
        aside.push_back(c);
        if(aside.size() >= compact_at) compact_aside();
      }
      return false;
    }
    c->tds_data().clear(); // c is a new cell
    const int m = make_common_flip(tr, c, i, flip, made);
    for(int k = 0; k < m; ++k) push(made[k]);
    ++result.swaps[m == 3 ? FLIP_2_3 : FLIP_3_2];
    progress = true;
    return true;
  };
  // Tests the facets of the cells queued, until the queue is empty.
  auto drain = [&]() {
    while(!queue.empty())
    {
      const Cell_handle c = queue.front();
      queue.pop_front();
      // A slot freed by a 3-2 flip (and maybe reused by a cell queued anew).
      if(!cells.is_used(c) || !c->tds_data().is_in_conflict()) continue;
      c->tds_data().clear();
      if(tr.is_infinite(c)) continue;
      for(int i = 0; i < 4; ++i)
      {
        // A facet between two queued cells is tested from the second taken
        // off the queue (half the facets of the cells a flip makes).
        const Cell_handle n = c->neighbor(i);
        if(tr.is_infinite(n) || n->tds_data().is_in_conflict()) continue;
        if(visit(c, i)) break;
      }
    }
  };
  // Each seed in storage order (the cells' order in memory, spatial for a
  // mesh built in spatial order) with the flips it causes before the next:
  // the cells a flip touches are still in the cache. A seed's other facets
  // passed the scan, or are seeds, or belong to cells made since (queued).
  for(const auto& [c, i] : facets)
    if(cells.is_used(c) && !tr.is_infinite(c->neighbor(i)) && visit(c, i)) drain();
  facets.clear();
  facets.shrink_to_fit();
  // A facet set aside may be flippable now that flips changed the cells
  // around its edges: they are tried again as long as flips are made.
  while(progress)
  {
    for(Cell_handle c : aside)
      if(cells.is_used(c) && c->tds_data().is_on_boundary())
      {
        c->tds_data().clear();
        push(c);
      }
    aside.clear();
    progress = false;
    drain();
  }
  // No flip in the last pass: the facets still failing are all on cells set
  // aside. Each is listed once, from the cell at the higher address when both
  // of its cells are aside; a cell listed is marked in conflict meanwhile.
  auto is_aside = [](Cell_handle c) { return c->tds_data().is_on_boundary() || c->tds_data().is_in_conflict(); };
  for(Cell_handle c : aside)
  {
    if(!cells.is_used(c) || !c->tds_data().is_on_boundary()) continue;
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      if(tr.is_infinite(n) || (is_aside(n) && &*n > &*c)) continue;
      if(!is_locally_delaunay(tr, c, i, perturbation)) result.left.emplace_back(c, i);
    }
    c->tds_data().mark_in_conflict();
  }
  for(Cell_handle c : aside)
    if(cells.is_used(c)) c->tds_data().clear();
  return result;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_LAWSON_FLIPS_H
