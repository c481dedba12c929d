// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap demo: the paper's main experiments on random points in a unit cube.

#ifndef EDGE_SWAP_DEMO_COMMAND_H
#define EDGE_SWAP_DEMO_COMMAND_H

#include "progress.h"
#include "types.h"
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/mesh_statistics.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/edge_swapping_3.h>
#include <cstdio>

namespace edge_swap {

/// 0 when the helper strategy ended on CGAL's Delaunay triangulation, else 1.
inline int run_demo(std::size_t n, unsigned int seed)
{

  if(n < 4) throw Usage_error("--points must be at least 4");
  CGAL::Random rng(seed);
  std::vector<Point> points;
  for(std::size_t k = 0; k < n; ++k)
    points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  std::cout << n << " random points in the unit cube (seed " << seed << ")\n\n";

  // 1. An arbitrary triangulation, then the helper strategy.
  Triangulation tr;
  ES::insert_by_placing(tr, points);
  std::cout << "1. Start: placing (each point splits its tetrahedron, no flip): "
            << tr.number_of_finite_cells() << " cells, "
            << ES::number_of_non_delaunay_facets(tr) << " faces not locally Delaunay\n";
  namespace np = ES::parameters;
  const auto report = CGAL::swap_edges_with_helper(
    tr, np::face_order(ES::RANDOM_ORDER, np::cycle_visitor(cycle_progress("helper"), CGAL::parameters::random_seed(seed))));
  const auto t = report.total_swaps();
  std::cout << "   Helper strategy (random face order): " << ES::swap_ending_name(report.ending) << " after "
            << report.number_of_cycles() << " rounds, " << t[0] << " 2-3, " << t[1] << " 3-2, " << t[2]
            << " 2-2, " << t[3] << " 4-4 swaps, " << report.seconds << " s\n";
  const auto cmp = ES::compare_with_delaunay(tr);
  std::cout << "   Equal to CGAL's Delaunay_triangulation_3, cell for cell: " << (cmp.identical ? "yes" : "NO")
            << " (" << cmp.cells << " cells; " << cmp.cells_not_in_delaunay << " differ)\n\n";

  // 2. Minimum edges from the Delaunay triangulation (paper section 4).
  Triangulation dt;
  ES::insert_delaunay(dt, points);
  const auto before = ES::mesh_statistics(dt);
  const auto min_edges = CGAL::swap_edges(
    dt, ES::Min_edges_criterion(),
    np::face_order(ES::STORAGE_ORDER, np::cycle_visitor(cycle_progress("min-edges"), CGAL::parameters::random_seed(seed))));
  const auto after = ES::mesh_statistics(dt);
  std::cout << "2. Minimum-edge swapping from the Delaunay triangulation: " << min_edges.total_swaps()[1]
            << " 3-2 swaps in " << min_edges.number_of_cycles() << " rounds\n\n";
  std::printf("           %10s %10s   %10s %10s\n", "ours", "", "paper", "");
  std::printf("           %10s %10s   %10s %10s\n", "before", "after", "before", "after");
  std::printf("   Nodes   %10zu %10zu   %10d %10d\n", before.vertices, after.vertices, 8000, 8000);
  std::printf("   Edges   %10zu %10zu   %10d %10d\n", before.edges, after.edges, 60928, 54653);
  std::printf("   Faces   %10zu %10zu   %10d %10d\n", before.faces, after.faces, 105729, 93179);
  std::printf("   Cells   %10zu %10zu   %10d %10d\n", before.cells, after.cells, 52800, 46525);
  std::printf("   Cells removed: ours %.1f%%, paper %.1f%%\n",
              100.0 * double(before.cells - after.cells) / double(before.cells), 100.0 * (52800 - 46525) / 52800.0);
  return cmp.identical ? 0 : 1;
}

} // namespace edge_swap

#endif
