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
#include <CGAL/Edge_swapping_3/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <sys/resource.h>
#include <cstdio>
#include <iostream>
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
  std::size_t n = 11;
  unsigned set = 1;
  try
  {
    if(argc > 1) n = std::stoul(argv[1]);
    if(argc > 2) set = unsigned(std::stoul(argv[2]));
  }
  catch(const std::exception&)
  {
    std::cerr << "usage: benchmark_topcom_reading [N [SET]]\n";
    return 2;
  }
  if(argc > 3 || n < 5 || n > 14)
  {
    std::cerr << "usage: benchmark_topcom_reading [N [SET]] (N from 5 to 14)\n";
    return 2;
  }
  const auto points = ES::point_families::random_integer<K::Point_3>(n, set);
  const double self0 = cpu_seconds(RUSAGE_SELF), topcom0 = cpu_seconds(RUSAGE_CHILDREN);
  std::size_t cells = 0;
  const std::size_t triangulations = ES::IO::for_each_topcom_triangulation(
    points, std::size_t(-1), [&](std::size_t, const std::vector<std::array<std::size_t, 4>>& t) {
      cells += t.size();
      return true;
    });
  const double reading = cpu_seconds(RUSAGE_SELF) - self0, topcom = cpu_seconds(RUSAGE_CHILDREN) - topcom0;
  std::printf("%zu random integer points, set %u: %zu triangulations, %zu cells\n", n, set, triangulations, cells);
  std::printf("TOPCOM's enumeration: %.2f CPU s; reading its list: %.2f CPU s (%.3f of TOPCOM's; %.0f triangulations a second)\n",
              topcom, reading, reading / topcom, reading > 0 ? double(triangulations) / reading : 0.0);
  return 0;
}
