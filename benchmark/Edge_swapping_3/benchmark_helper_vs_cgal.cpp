// Benchmark (not a test): the helper strategy from a placing start to the
// Delaunay triangulation, beside CGAL's Delaunay_triangulation_3 and TetGen's
// Delaunay on the same points in the same run. Prints one table row per size.
//
//   benchmark_helper_vs_cgal [N ...]        (default: 100000 1000000)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_3<K> Triangulation;
typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
namespace ES = CGAL::Edge_swapping_3;

// TetGen's own "Delaunay seconds" on the points, or -1 if tetgen is not installed.
double tetgen_seconds(const std::vector<K::Point_3>& points)
{
  if(std::system("command -v tetgen > /dev/null 2>&1") != 0) return -1;
  const std::string stem = "/tmp/edge_swapping_3_bench_" + std::to_string(::getpid());
  {
    std::vector<std::array<double, 3>> p;
    for(const auto& q : points) p.push_back({q.x(), q.y(), q.z()});
    std::ofstream out(stem + ".node");
    ES::IO::write_node_file(out, p, {}, 1);
  }
  const std::string log = stem + ".log";
  const int status = std::system(("tetgen -V -N -E -F " + stem + ".node > " + log + " 2>&1").c_str());
  double seconds = -1;
  std::ifstream in(log);
  std::string line;
  while(status == 0 && std::getline(in, line))
    if(line.rfind("Delaunay seconds:", 0) == 0) seconds = std::stod(line.substr(17));
  std::remove((stem + ".node").c_str());
  std::remove(log.c_str());
  return seconds;
}

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes;
  for(int a = 1; a < argc; ++a) sizes.push_back(std::stoul(argv[a]));
  if(sizes.empty()) sizes = {100000, 1000000};

  std::printf("%9s %9s %9s %9s %9s %7s %9s %9s %7s %s\n", "points", "CGAL s", "TetGen s", "placing s", "helper s",
              "cycles", "swaps", "ours s", "ratio", "equal");
  for(std::size_t n : sizes)
  {
    CGAL::Random rng(1);
    std::vector<K::Point_3> points;
    for(std::size_t k = 0; k < n; ++k) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());

    CGAL::Real_timer t;
    t.start();
    Delaunay dt(points.begin(), points.end()); // CGAL spatially sorts the range
    t.stop();
    const double cgal = t.time();
    dt.clear();

    const double tetgen = tetgen_seconds(points);

    Triangulation tr;
    t.reset();
    t.start();
    ES::insert_by_placing(tr, points);
    t.stop();
    const double placing = t.time();

    ES::Swap_options options;
    options.face_order = ES::RANDOM_ORDER;
    options.random_seed = 1;
    options.cycle_visitor = [](const ES::Cycle_record& r) {
      std::cerr << "  cycle " << r.cycle << ": " << r.total_swaps() << " swaps\n";
    };
    const ES::Swap_report report = CGAL::swap_edges_with_helper(tr, options);
    const auto s = report.total_swaps();
    const bool equal = ES::compare_with_delaunay(tr).identical; // not timed

    const double ours = placing + report.seconds;
    std::printf("%9zu %9.2f %9.2f %9.2f %9.2f %7zu %9zu %9.2f %7.1f %s\n", n, cgal, tetgen, placing, report.seconds,
                report.number_of_cycles(), s[0] + s[1] + s[2] + s[3], ours, ours / cgal, equal ? "yes" : "NO");
    std::fflush(stdout);
  }
  return 0;
}
