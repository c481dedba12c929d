// SPDX-License-Identifier: GPL-3.0-or-later
// One pass over every interior facet of a triangulation, with a read-only
// test, split among threads with TBB (when the program links it, as CGAL's
// parallel algorithms: CGAL_LINKED_WITH_TBB; else on this thread alone): the
// facets that fail it, in storage order (the same list whatever the number
// of threads). The Delaunay work queue's first
// round is such a pass: a locally Delaunay facet is a visit that decides
// nothing, so only the facets that fail the in-sphere test need a visit of
// the driver (which looks up per-cell state and classifies).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H

#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The interior facets `(c, i)` of `tr` (neither cell infinite), each once
/// (from the cell at the higher address), for which `fails(c, i)` is true,
/// in the storage order of the cells; and the number of facets tested.
/// `fails` must only read the triangulation: it runs on up to `threads`
/// threads at once (TBB's), each on a run of the cell container (1, or no
/// TBB: this thread alone). An exception thrown by `fails` is passed on.
template <class Tr, class Test>
std::pair<std::vector<std::pair<typename Tr::Cell_handle, int>>, std::size_t>
failing_interior_facets(Tr& tr, Test fails, unsigned threads = 1)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef std::vector<std::pair<Cell_handle, int>> Facets;
  auto& cells = tr.tds().cells();
  // Below a few thousand cells a thread costs more than it saves.
#ifdef CGAL_LINKED_WITH_TBB
  threads = (std::max)(1u, (std::min)(threads, unsigned(cells.size() / 4096 + 1)));
#else
  threads = 1;
#endif
  std::vector<Cell_handle> cuts{cells.begin()};
  const std::size_t share = cells.size() / threads;
  for(unsigned t = 1; t < threads; ++t) cuts.push_back(std::next(cuts.back(), std::ptrdiff_t(share)));
  cuts.push_back(cells.end());
  std::vector<Facets> found(threads);
  std::vector<std::size_t> tested(threads, 0);
  auto scan = [&](unsigned t) {
    Facets failing; // local until the end: no two threads write near each other meanwhile
    std::size_t n_tested = 0;
    for(Cell_handle c = cuts[t]; c != cuts[t + 1]; ++c)
    {
      Cell_handle ahead = c;
      if(++ahead != cuts[t + 1] && ++ahead != cuts[t + 1]) prefetch_around(ahead);
      if(tr.is_infinite(c)) continue;
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        if(&*n > &*c || tr.is_infinite(n)) continue;
        ++n_tested;
        if(fails(c, i)) failing.emplace_back(c, i);
      }
    }
    found[t] = std::move(failing);
    tested[t] = n_tested;
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(threads > 1)
  {
    tbb::task_arena arena{int(threads)};
    arena.execute([&]() { tbb::parallel_for(0u, threads, [&](unsigned t) { scan(t); }); });
  }
  else
#endif
    scan(0);
  Facets all = std::move(found[0]);
  std::size_t all_tested = tested[0];
  for(unsigned t = 1; t < threads; ++t)
  {
    all.insert(all.end(), found[t].begin(), found[t].end());
    all_tested += tested[t];
  }
  return {std::move(all), all_tested};
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H
