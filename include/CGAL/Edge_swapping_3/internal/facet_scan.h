// SPDX-License-Identifier: GPL-3.0-or-later
// One pass over every interior facet of a triangulation, with a read-only
// test, split among threads: the facets that fail it, in storage order (the
// same list whatever the number of threads). The Delaunay work queue's first
// round is such a pass: a locally Delaunay facet is a visit that decides
// nothing, so only the facets that fail the in-sphere test need a visit of
// the driver (which looks up per-cell state and classifies).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SCAN_H

#include <CGAL/Edge_swapping_3/internal/prefetch.h>
#include <algorithm>
#include <exception>
#include <iterator>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The interior facets `(c, i)` of `tr` (neither cell infinite), each once
/// (from the cell at the higher address), for which `fails(c, i)` is true,
/// in the storage order of the cells; and the number of facets tested.
/// `fails` must only read the triangulation: it runs on `threads` threads
/// at once, each on a run of the cell container (1: this thread alone). A
/// thread that cannot start leaves its run to this one.
template <class Tr, class Test>
std::pair<std::vector<std::pair<typename Tr::Cell_handle, int>>, std::size_t>
failing_interior_facets(Tr& tr, Test fails, unsigned threads = 1)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef std::vector<std::pair<Cell_handle, int>> Facets;
  auto& cells = tr.tds().cells();
  // Below a few thousand cells a thread costs more than it saves.
  threads = (std::max)(1u, (std::min)(threads, unsigned(cells.size() / 4096 + 1)));
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
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  unsigned started = 1;
  for(; started < threads; ++started)
  {
    try
    {
      const unsigned t = started;
      pool.emplace_back([&, t]() {
        try
        {
          scan(t);
        }
        catch(...)
        {
          errors[t] = std::current_exception();
        }
      });
    }
    catch(const std::system_error&)
    {
      break;
    }
  }
  try
  {
    scan(0);
    for(unsigned t = started; t < threads; ++t) scan(t);
  }
  catch(...)
  {
    errors[0] = std::current_exception();
  }
  for(auto& thread : pool) thread.join();
  for(const auto& e : errors)
    if(e) std::rethrow_exception(e);
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
