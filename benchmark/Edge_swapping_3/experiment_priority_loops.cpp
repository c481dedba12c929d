// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment (not a test): from every fine triangulation of a case's points
// (TOPCOM), the helper strategy in the fixed face order (PRIORITY_ORDER) for
// each seed; how many starts have not converged by the cycle limit.
//
//   experiment_priority_loops CASE LAST_SEED MAX_CYCLES [READING]
//
// READING names a reading of Algorithm 4 (Helper_reading.h), for example
// "cleared-each-cycle,any-tetrahedron,no-swap"; the default is the package's.
//
// A start counted here can be written as a case and its trace certified:
// doc/Edge_swapping_3/traces.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;

int main(int argc, char** argv)
{
  if(argc != 4 && argc != 5)
  {
    std::cerr << "usage: experiment_priority_loops CASE LAST_SEED MAX_CYCLES [READING]\n";
    return 2;
  }
  auto c = ES::IO::read_conjecture_case_file<K::Point_3>(argv[1]);
  const auto all = ES::IO::topcom_triangulations(c.points, 1000000);
  std::cout << c.points.size() << " points, " << all.triangulations.size() << " triangulations\n";
  c.strategy = ES::HELPER_STRATEGY;
  c.order = ES::PRIORITY_ORDER;
  c.start = ES::GIVEN_CELLS_START;
  c.max_cycles = std::stoul(argv[3]);
  if(argc == 5 && !ES::helper_reading_from_name(argv[4], c.reading))
  {
    std::cerr << "experiment_priority_loops: unknown reading '" << argv[4] << "'\n";
    return 2;
  }
  std::cout << "reading " << ES::helper_reading_name(c.reading) << '\n';
  for(unsigned seed = 1; seed <= std::stoul(argv[2]); ++seed)
  {
    std::size_t not_converged = 0;
    long long first = -1;
    for(std::size_t t = 0; t < all.triangulations.size(); ++t)
    {
      c.cells = ES::oriented_cells(c.points, all.triangulations[t]);
      c.seed = seed;
      if(!ES::run_conjecture_case(c).equal_to_cgal)
      {
        ++not_converged;
        if(first < 0) first = (long long)t;
      }
    }
    std::cout << "seed " << seed << ": " << not_converged << " starts not converged by cycle " << c.max_cycles
              << " (first: triangulation " << first << ")\n";
  }
  return 0;
}
