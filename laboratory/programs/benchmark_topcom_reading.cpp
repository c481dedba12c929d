// SPDX-License-Identifier: GPL-3.0-or-later
// What reading TOPCOM's list costs beside TOPCOM's own enumeration. The
// laboratory streams millions of triangulations from
// topcom-points2allfinetriangs (every shard of a streamed set reads the whole
// list), so the reading should stay small beside the enumeration.
//
//   benchmark_topcom_reading [N [SET]]
//
// runs for_each_topcom_triangulation() on the laboratory's N random integer
// points of set SET (default 11 and 1: 125,344 triangulations) and prints the
// CPU seconds of TOPCOM (the child process) and of this process (reading the
// lines and turning them into cells), and their ratio.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include "laboratory_arguments.h"
#include <sys/resource.h>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

namespace {

double cpu_seconds(int who)
{
  rusage u{};
  ::getrusage(who, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

} // namespace

int main(int argc, char** argv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  namespace ES = CGAL::Edge_swapping_3;
  // Digits only (laboratory_arguments.h): "12x" or "-1" is not read as 12 or as a huge set.
  std::size_t n = 11, set = 1;
  if(argc > 3 || (argc > 1 && !laboratory_arguments::whole_number(argv[1], n, 14)) ||
     (argc > 2 && !laboratory_arguments::whole_number(argv[2], set, std::numeric_limits<unsigned>::max())) || n < 5)
  {
    std::cerr << "usage: benchmark_topcom_reading [N [SET]] (N from 5 to 14, SET a whole number up to 4294967295)\n";
    return 2;
  }
  const auto points = ES::point_families::random_integer<K::Point_3>(n, unsigned(set));
  const double self0 = cpu_seconds(RUSAGE_SELF), topcom0 = cpu_seconds(RUSAGE_CHILDREN);
  std::size_t cells = 0, triangulations = 0;
  try
  {
    triangulations = ES::IO::for_each_topcom_triangulation(
      points, std::size_t(-1), [&](std::size_t, const std::vector<std::array<std::size_t, 4>>& t) {
        cells += t.size();
        return true;
      });
  }
  catch(const std::exception& e) // TOPCOM missing or failing, or a line it printed that is not a triangulation
  {
    std::cerr << "benchmark_topcom_reading: " << e.what() << '\n';
    return 1;
  }
  const double reading = cpu_seconds(RUSAGE_SELF) - self0, topcom = cpu_seconds(RUSAGE_CHILDREN) - topcom0;
  std::printf("%zu random integer points, set %zu: %zu triangulations, %zu cells\n", n, set, triangulations, cells);
  std::printf("TOPCOM's enumeration: %.2f CPU s; reading its list: %.2f CPU s", topcom, reading);
  // Too few points for the clock: no ratio rather than a division by zero.
  if(topcom > 0 && reading > 0)
    std::printf(" (%.3f of TOPCOM's; %.0f triangulations a second)", reading / topcom, double(triangulations) / reading);
  std::printf("\n");
  return 0;
}
