// SPDX-License-Identifier: GPL-3.0-or-later
// One pass over every interior facet of a triangulation, in storage order,
// with a read-only test: the facets that fail it. The Delaunay work queue's
// first round is such a pass: a locally Delaunay facet is a visit that
// decides nothing, so only the facets that fail the in-sphere test need a
// visit of the driver (which looks up per-cell state and classifies).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H

#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The interior facets `(c, i)` of `tr` (neither cell infinite), each once
/// (from the cell at the higher address), for which `fails(c, i)` is true,
/// in the storage order of the cells; and the number of facets tested.
template <class Tr, class Test>
std::pair<std::vector<std::pair<typename Tr::Cell_handle, int>>, std::size_t> failing_interior_facets(Tr& tr,
                                                                                                       Test fails)
{
  typedef typename Tr::Cell_handle Cell_handle;
  std::vector<std::pair<Cell_handle, int>> failing;
  std::size_t tested = 0;
  for_each_cell_prefetching(tr.tds().cells(), [&](Cell_handle c) {
    if(tr.is_infinite(c)) return;
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      if(&*n > &*c || tr.is_infinite(n)) continue;
      ++tested;
      if(fails(c, i)) failing.emplace_back(c, i);
    }
  });
  return {std::move(failing), tested};
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H
