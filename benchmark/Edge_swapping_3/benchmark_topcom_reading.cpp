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
  // A whole number, digits only: "12x" or "-1" is not read as 12 or as a huge set.
  const auto number = [](const char* text, unsigned long& value) {
    const std::string s = text;
    if(s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) return false;
    value = std::stoul(s);
    return true;
  };
  unsigned long n_arg = n, set_arg = set;
  if(argc > 3 || (argc > 1 && !number(argv[1], n_arg)) || (argc > 2 && !number(argv[2], set_arg)) || n_arg < 5 ||
     n_arg > 14)
  {
    std::cerr << "usage: benchmark_topcom_reading [N [SET]] (N from 5 to 14, SET a whole number)\n";
    return 2;
  }
  n = n_arg;
  set = unsigned(set_arg);
  const auto points = ES::point_families::random_integer<K::Point_3>(n, set);
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
  std::printf("%zu random integer points, set %u: %zu triangulations, %zu cells\n", n, set, triangulations, cells);
  std::printf("TOPCOM's enumeration: %.2f CPU s; reading its list: %.2f CPU s", topcom, reading);
  // Too few points for the clock: no ratio rather than a division by zero.
  if(topcom > 0 && reading > 0)
    std::printf(" (%.3f of TOPCOM's; %.0f triangulations a second)", reading / topcom, double(triangulations) / reading);
  std::printf("\n");
  return 0;
}
