// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): a quality criterion at scale. From CGAL's Delaunay
// triangulation of N random points, `swap_edges` with the MinMax dihedral
// criterion (work queue, storage order) to its local optimum; beside CGAL's
// construction of the same points, each in a child process of its own.
// Reported: the driver's time, its ratio to CGAL's construction, the flips,
// the time per flip, the rounds and visits, the largest dihedral angle before
// and after (cells with no vertex on the fixed hull) with the number of them
// above 165 degrees, and the driver's peak memory beyond the triangulation.
// With --worst-first, also `improve_worst_tetrahedra` (MinMax) from the same
// start, with flips only and with the topological operations.
//
//   benchmark_quality_at_scale [--worst-first] [N ...]   (default 100000 1000000)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/improve_worst_tetrahedra.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include "allocation_counter.h"
#include "benchmark_common.h"
#include <algorithm>
#include <iterator>
#include <set>

typedef CGAL::Triangulation_3<K> Triangulation;

namespace {

// The largest dihedral angle of the cells with no vertex on the hull (the
// hull is fixed: its slivers cannot be swapped away), and how many of those
// cells have one above 165 degrees.
std::pair<double, std::size_t> interior_dihedral_extremes(const Triangulation& tr)
{
  std::set<Triangulation::Vertex_handle> hull;
  tr.adjacent_vertices(tr.infinite_vertex(), std::inserter(hull, hull.end()));
  double worst = 0;
  std::size_t above_165 = 0;
  for(auto c : tr.finite_cell_handles())
  {
    if(hull.count(c->vertex(0)) || hull.count(c->vertex(1)) || hull.count(c->vertex(2)) || hull.count(c->vertex(3)))
      continue;
    const double a = ES::Largest_dihedral_angle()(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                                  c->vertex(3)->point());
    worst = std::max(worst, a);
    if(a > 165) ++above_165;
  }
  return {worst, above_165};
}

// In a child: the Delaunay mesh of `n` random points, then `optimize(tr, out)`,
// which fills out[0..3]; out[4..9] get the dihedral extremes before and after
// and the memory beyond the triangulation.
template <class Optimize>
Measure measure_optimizer(std::size_t n, Optimize optimize)
{
  return in_child([n, optimize](double* out) {
    Triangulation tr;
    ES::insert_delaunay(tr, random_points(n));
    const auto before = interior_dihedral_extremes(tr);
    const double triangulation_bytes = double(allocation_counter::current);
    allocation_counter::reset_peak();
    optimize(tr, out);
    out[6] = double(allocation_counter::peak) - triangulation_bytes;
    out[7] = triangulation_bytes;
    const auto after = interior_dihedral_extremes(tr);
    out[4] = before.first;
    out[5] = after.first;
    out[8] = double(before.second);
    out[9] = double(after.second);
  });
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  std::vector<std::size_t> sizes;
  bool worst_first = false;
  for(int a = 1; a < argc; ++a)
  {
    if(std::string(argv[a]) == "--worst-first") worst_first = true;
    else sizes.push_back(std::stoul(argv[a]));
  }
  if(sizes.empty()) sizes = {100000, 1000000};
  std::printf("%9s | %7s | %8s %6s %9s %7s %6s %10s | %7s %7s %7s %7s | %7s %7s\n", "points", "CGAL s", "ours s",
              "ratio", "flips", "us/flip", "rounds", "visits", "max in", ">165", "max out", ">165", "tri MiB", "drv MiB");
  for(std::size_t n : sizes)
  {
    const Measure cgal = in_child([n](double* out) { cgal_delaunay(n, out); });
    const Measure ours = measure_optimizer(n, [](Triangulation& tr, double* out) {
      const auto r = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion());
      const auto s = r.total_swaps();
      out[0] = r.seconds;
      out[1] = double(s[0] + s[1] + s[2] + s[3]);
      out[2] = double(r.number_of_cycles());
      out[3] = double(r.number_of_visits());
    });
    const double* v = ours.values;
    std::printf("%9zu | %7.2f | %8.2f %6.2f %9.0f %7.2f %6.0f %10.0f | %7.2f %7.0f %7.2f %7.0f | %7.0f %7.1f\n", n,
                cgal.values[0], v[0], v[0] / cgal.values[0], v[1], 1e6 * v[0] / std::max(1.0, v[1]), v[2], v[3], v[4],
                v[8], v[5], v[9], v[7] / 1048576.0, v[6] / 1048576.0);
    std::fflush(stdout);
    if(!worst_first) continue;
    for(unsigned operations : {unsigned(ES::FLIPS), unsigned(ES::TOPOLOGICAL_OPERATIONS)})
    {
      const Measure worst = measure_optimizer(n, [operations](Triangulation& tr, double* out) {
        const auto r = ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(),
                                                    ES::parameters::operations(operations));
        out[0] = r.seconds;
        out[1] = double(r.number_of_operations());
        out[3] = double(r.visits);
      });
      const double* w = worst.values;
      std::printf("%9s | %7s | %8.2f %6.2f %9.0f %7.2f %6s %10.0f | %7.2f %7.0f %7.2f %7.0f | %7.0f %7.1f  worst first, %s\n",
                  "", "", w[0], w[0] / cgal.values[0], w[1], 1e6 * w[0] / std::max(1.0, w[1]), "", w[3], w[4], w[8],
                  w[5], w[9], w[7] / 1048576.0, w[6] / 1048576.0, operations == ES::FLIPS ? "flips" : "topological");
      std::fflush(stdout);
    }
  }
  return 0;
}
