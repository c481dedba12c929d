// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the benchmarks: run a contender in a child process of its own
// (so its peak memory is its own), the random points, and TetGen's Delaunay.

#ifndef EDGE_SWAPPING_3_BENCHMARK_COMMON_H
#define EDGE_SWAPPING_3_BENCHMARK_COMMON_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Random.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include "huge_pages.h"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;

// Every contender runs as `edge_swap` does, with glibc's huge pages
// (tools/edge_swap/huge_pages.h): the benchmark starts itself again with
// them, and its children (CGAL's, TetGen, the programs) inherit the setting.
// GLIBC_TUNABLES=glibc.malloc.hugetlb=0 measures without them.
inline void start_benchmark(char** argv)
{
  edge_swap::restart_with_huge_pages(argv);
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("GLIBC_TUNABLES=%s\n", tunables ? tunables : "");
}

// What a child measured, sent back through a pipe, and its peak memory.
struct Measure
{
  double values[10] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
  double peak_mib = -1;
};

// Runs `work` in a child process; `work` fills the values.
inline Measure in_child(const std::function<void(double*)>& work)
{
  int fd[2];
  if(pipe(fd) != 0) return {};
  std::fflush(stdout); // else the child writes the parent's buffered lines again
  const pid_t pid = fork();
  if(pid == 0)
  {
    close(fd[0]);
    Measure m;
    work(m.values);
    if(write(fd[1], m.values, sizeof m.values) != ssize_t(sizeof m.values)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  Measure m;
  if(read(fd[0], m.values, sizeof m.values) != ssize_t(sizeof m.values)) m = Measure();
  close(fd[0]);
  int status = 0;
  struct rusage usage;
  if(wait4(pid, &status, 0, &usage) == pid) m.peak_mib = double(usage.ru_maxrss) / 1024.0;
  return m;
}

// Runs a program (its standard output dropped) in a child process; its
// seconds and peak MiB.
inline std::pair<double, double> run_program(const std::vector<std::string>& args)
{
  CGAL::Real_timer t;
  t.start();
  std::fflush(stdout);
  const pid_t pid = fork();
  if(pid == 0)
  {
    if(!freopen("/dev/null", "w", stdout)) _exit(1);
    std::vector<char*> argv;
    for(const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  return {t.time(), double(usage.ru_maxrss) / 1024.0};
}

// The benchmarks' points: `n` uniform in the unit cube from CGAL::Random(seed).
inline std::vector<K::Point_3> random_points(std::size_t n, int seed = 1)
{
  CGAL::Random rng(seed);
  std::vector<K::Point_3> points;
  for(std::size_t k = 0; k < n; ++k) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  return points;
}

// CGAL's Delaunay_triangulation_3 of the points, timed (its range constructor
// sorts them spatially).
inline void cgal_delaunay(std::size_t n, double* out, int seed = 1)
{
  const auto points = random_points(n, seed);
  CGAL::Real_timer t;
  t.start();
  CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
  out[0] = t.time();
}

// TetGen's own "Delaunay seconds" on the points (file reading excluded), or -1.
inline void tetgen(std::size_t n, double* out, int seed = 1)
{
  if(std::system("command -v tetgen > /dev/null 2>&1") != 0) return;
  const std::string stem =
      (std::filesystem::temp_directory_path() / ("edge_swapping_3_bench_" + std::to_string(::getpid()))).string();
  {
    std::vector<std::array<double, 3>> p;
    for(const auto& q : random_points(n, seed)) p.push_back({q.x(), q.y(), q.z()});
    std::ofstream file(stem + ".node");
    ES::IO::write_node_file(file, p, {}, 1);
  }
  const std::string log = stem + ".log";
  // exec, not system: the child's peak memory is then TetGen's.
  std::fflush(stdout);
  const pid_t pid = fork();
  if(pid == 0)
  {
    if(!freopen(log.c_str(), "w", stdout)) _exit(1);
    execlp("tetgen", "tetgen", "-V", "-N", "-E", "-F", (stem + ".node").c_str(), (char*)nullptr);
    _exit(1);
  }
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  std::ifstream in(log);
  std::string line;
  while(std::getline(in, line))
    if(line.rfind("Delaunay seconds:", 0) == 0) out[0] = std::stod(line.substr(17));
  out[1] = double(usage.ru_maxrss) / 1024.0;
  std::remove((stem + ".node").c_str());
  std::remove(log.c_str());
}

#endif
