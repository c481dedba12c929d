// SPDX-License-Identifier: GPL-3.0-or-later
// Asking the processor early for the memory of cells about to be visited.
// A pass over every facet of a large triangulation is bound by cache misses
// on neighbouring cells and their vertices, not by the predicates.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_PREFETCH_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_PREFETCH_H

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Asks for the memory a visit of `c`'s facets reads: its neighbours and vertices.
template <class Cell_handle>
void prefetch_around(Cell_handle c)
{
#if defined(__GNUC__)
  for(int k = 0; k < 4; ++k)
  {
    __builtin_prefetch(&*c->neighbor(k));
    __builtin_prefetch(&*c->vertex(k));
  }
#else
  (void)c;
#endif
}

/// Calls `f(c)` for every cell of `cells` (a Compact_container) in storage
/// order, asking for the memory around the cell two ahead. `f` may free or
/// reuse cells other than `c`.
template <class Cells, class F>
void for_each_cell_prefetching(Cells& cells, F f)
{
  for(auto it = cells.begin(); it != cells.end(); ++it)
  {
    auto ahead = it;
    if(++ahead != cells.end() && ++ahead != cells.end()) prefetch_around(ahead);
    f(it);
  }
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_PREFETCH_H
