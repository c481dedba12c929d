// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment: how plain Algorithm 3 and the helper strategy end from placing
// starts, over many seeds, in storage and in random face order.
//
//   experiment_endings [points=1000] [seeds=100] [max_cycles=1000]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <cstdio>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_3<K> Triangulation;
namespace ES = CGAL::Edge_swapping_3;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 1000;
  const unsigned seeds = argc > 2 ? unsigned(std::stoul(argv[2])) : 100;
  const std::size_t max_cycles = argc > 3 ? std::stoul(argv[3]) : 1000;

  std::printf("%zu random points in a unit cube, placing start (spatial order), seeds 1..%u, cycle limit %zu\n\n",
              n, seeds, max_cycles);
  std::printf("%-8s %-8s %10s %8s %8s %12s %14s\n", "strategy", "order", "converged", "stuck", "limit",
              "equal CGAL", "mean cycles");
  for(bool helper : {false, true})
    for(auto order : {ES::STORAGE_ORDER, ES::RANDOM_ORDER})
    {
      unsigned ending[3] = {0, 0, 0}, equal = 0;
      double cycles = 0;
      for(unsigned seed = 1; seed <= seeds; ++seed)
      {
        CGAL::Random rng(seed);
        std::vector<K::Point_3> points;
        for(std::size_t k = 0; k < n; ++k) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
        Triangulation tr;
        ES::insert_by_placing(tr, points);
        namespace np = ES::parameters;
        const auto options =
          np::schedule(ES::PAPER_CYCLES, np::face_order(order, np::delaunay_repair(false, CGAL::parameters::random_seed(seed)
                                                                                        .number_of_iterations(max_cycles))));
        const auto report = helper ? CGAL::swap_edges_with_helper(tr, options)
                                   : CGAL::swap_edges(tr, ES::Delaunay_criterion(), options);
        ++ending[report.ending];
        cycles += double(report.number_of_cycles());
        if(ES::compare_with_delaunay(tr).identical) ++equal;
      }
      std::printf("%-8s %-8s %10u %8u %8u %12u %14.1f\n", helper ? "helper" : "plain",
                  order == ES::STORAGE_ORDER ? "storage" : "random", ending[ES::CONVERGED], ending[ES::STUCK],
                  ending[ES::CYCLE_LIMIT_REACHED], equal, cycles / seeds);
      std::fflush(stdout);
    }
  return 0;
}
