// The loop shared by Algorithms 3 and 4: cycle over the interior facets, let
// the strategy swap, until a cycle makes no swap or the cycle limit is reached.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_CYCLE_DRIVER_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_CYCLE_DRIVER_H

#include <CGAL/Real_timer.h>
#include <CGAL/Edge_swapping_3/internal/facet_sweep.h>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// `visit(c, i)` handles one interior facet and returns the kind of the flip it
/// made, or -1. Returns the report with the ending still to be decided by the
/// caller when the last cycle made no swap (CONVERGED is set).
template <class Tr, class Visit>
Swap_report run_cycles(Tr& tr, const Swap_options& options, Visit visit)
{
  CGAL_precondition(tr.dimension() == 3);
  CGAL::Real_timer timer;
  timer.start();
  CGAL::Random rng(options.random_seed);
  std::vector<Facet_key<Tr>> facets;
  Swap_report report;
  report.ending = CYCLE_LIMIT_REACHED;

  for(std::size_t cycle = 1; cycle <= options.max_cycles; ++cycle)
  {
    Cycle_record record;
    record.cycle = cycle;
    collect_interior_facets(tr, facets);
    const std::size_t block = 512;
    for(std::size_t b : visiting_blocks(facets, options.face_order, rng, block))
      for(std::size_t k = b * block; k < (std::min)(facets.size(), (b + 1) * block); ++k)
      {
        typename Tr::Cell_handle c;
        int i;
        if(!find_facet(tr, facets[k], c, i)) continue;
        if(tr.is_infinite(c) || tr.is_infinite(c->neighbor(i))) continue;
        const int kind = visit(c, i);
        if(kind >= 0) ++record.swaps[kind];
      }
    record.cells = tr.number_of_finite_cells();
    if(options.record_non_delaunay_facets)
      record.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr, options.perturbation);
    report.cycles.push_back(record);
    if(options.cycle_visitor) options.cycle_visitor(record);
    if(record.total_swaps() == 0)
    {
      report.ending = CONVERGED;
      break;
    }
  }
  report.seconds = timer.time();
  return report;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_CYCLE_DRIVER_H
