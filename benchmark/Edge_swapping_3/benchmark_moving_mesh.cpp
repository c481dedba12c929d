// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): repairing a moving mesh. The Delaunay triangulation
// of N random points; every point off the hull moved by up to F times the mean
// edge length in a random direction, unless the move would invert one of its
// cells (then it stays). Contenders, each in a child process of its own:
//   CGAL    Delaunay_triangulation_3 of the moved points, from scratch
//   repair  swap_edges with the Delaunay criterion (work queue, Delaunay repair)
//   repair2 the same with number_of_threads(2): round 1's scan on two threads
//   random  the same in random face order (a uniform permutation per round)
//   helper  swap_edges_with_helper (work queue)
//   cycles  swap_edges, the paper's cycles, no repair
//   rcycles the same in random face order (a uniform permutation of the facets per cycle)
// Each result is compared with CGAL's, cell for cell. Memory: the bytes the
// driver allocated beyond the triangulation at its peak (operator new counted).
//
// With --programs, also the whole programs: `edge_swap optimize` of the moved
// mesh (.node/.ele) against `cgal_delaunay_of_node`, which reads the same
// points and writes CGAL's Delaunay mesh; each reads, computes and writes.
//
//   benchmark_moving_mesh [--sizes N,...] [--moves F,...] [--contenders repair,repair2,random,helper,cycles,rcycles] [--programs [--keep-moved DIR]]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include "allocation_counter.h"
#include "benchmark_common.h"
#include <cmath>
#include <iostream>
#include <sstream>

#include <CGAL/Triangulation_vertex_base_with_info_3.h>

typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K>,
                                             CGAL::Triangulation_cell_base_3<K>> Tds;
typedef CGAL::Triangulation_3<K, Tds> Triangulation;
typedef K::Point_3 Point;

namespace {

std::vector<double> list_of(const std::string& text)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ',')) values.push_back(std::stod(item));
  return values;
}

double mean_edge_length(const Triangulation& tr)
{
  double sum = 0;
  std::size_t n = 0;
  for(auto e : tr.finite_edges())
  {
    sum += std::sqrt(CGAL::squared_distance(e.first->vertex(e.second)->point(), e.first->vertex(e.third)->point()));
    ++n;
  }
  return sum / double(n);
}

// The moved triangulation: Delaunay of `points`, then the moves, in place.
// Returns the number of points moved.
std::size_t build_moved(Triangulation& tr, const std::vector<Point>& points, double fraction)
{
  const auto vertices = ES::insert_delaunay(tr, points);
  const double step = fraction * mean_edge_length(tr);
  std::vector<bool> on_hull(points.size(), false);
  std::vector<Triangulation::Vertex_handle> hull;
  tr.adjacent_vertices(tr.infinite_vertex(), std::back_inserter(hull));
  for(std::size_t k = 0; k < vertices.size(); ++k) vertices[k]->info() = k;
  for(auto v : hull) on_hull[v->info()] = true;
  CGAL::Random rng(2);
  std::size_t moved = 0;
  std::vector<Triangulation::Cell_handle> cells;
  for(std::size_t k = 0; k < vertices.size(); ++k)
  {
    const double dx = rng.get_double(-1, 1), dy = rng.get_double(-1, 1), dz = rng.get_double(-1, 1);
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz), r = rng.get_double(0, step);
    if(on_hull[k] || length == 0) continue;
    const auto v = vertices[k];
    const Point old = v->point();
    v->set_point(Point(old.x() + r * dx / length, old.y() + r * dy / length, old.z() + r * dz / length));
    cells.clear();
    tr.finite_incident_cells(v, std::back_inserter(cells));
    bool inverted = false;
    for(auto c : cells) inverted = inverted || tr.orientation(c->vertex(0)->point(), c->vertex(1)->point(),
                                                              c->vertex(2)->point(), c->vertex(3)->point()) != CGAL::POSITIVE;
    if(inverted) v->set_point(old);
    else ++moved;
  }
  return moved;
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  std::vector<double> sizes = {100000}, moves = {0.001, 0.01, 0.1};
  std::string contenders = "repair,helper,cycles";
  bool programs = false;
  std::string keep; // --keep-moved DIR: the moved meshes stay there, for runs of the programs by hand
  for(int a = 1; a < argc; a += 2)
  {
    const std::string o = argv[a];
    if(o == "--programs") { programs = true; --a; continue; }
    if(a + 1 >= argc) { std::cerr << "option " << o << " needs a value\n"; return 2; }
    if(o == "--sizes") sizes = list_of(argv[a + 1]);
    else if(o == "--moves") moves = list_of(argv[a + 1]);
    else if(o == "--contenders") contenders = argv[a + 1];
    else if(o == "--keep-moved") keep = argv[a + 1];
    else { std::cerr << "unknown option " << o << '\n'; return 2; }
  }
  {
    std::stringstream names(contenders);
    for(std::string name; std::getline(names, name, ',');)
      if(name != "repair" && name != "repair2" && name != "random" && name != "helper" && name != "cycles" && name != "rcycles")
      {
        std::cerr << "--contenders: unknown contender '" << name << "'\n";
        return 2;
      }
  }
  std::printf("%8s %6s %8s | %7s | %-7s %8s %6s %8s %6s %9s %-12s %5s | %8s %8s %6s\n", "points", "move", "moved",
              "CGAL s", "ours", "s", "ratio", "flips", "rounds", "visits", "path", "equal", "tri MiB", "drv MiB",
              "ratio");
  for(double dn : sizes)
    for(double f : moves)
    {
      const std::size_t n = std::size_t(dn);
      // CGAL from scratch on the moved points.
      const Measure cgal = in_child([&](double* out) {
        Triangulation tr;
        out[1] = double(build_moved(tr, random_points(n), f));
        std::vector<Point> moved;
        for(auto v : tr.finite_vertex_handles()) moved.push_back(v->point());
        CGAL::Real_timer t;
        t.start();
        CGAL::Delaunay_triangulation_3<K> dt(moved.begin(), moved.end());
        out[0] = t.time();
      });
      std::stringstream names(contenders);
      std::string name;
      while(std::getline(names, name, ','))
      {
        const Measure ours = in_child([&](double* out) {
          Triangulation tr;
          build_moved(tr, random_points(n), f);
          const double triangulation_bytes = double(allocation_counter::current);
          allocation_counter::reset_peak();
          namespace np = ES::parameters;
          ES::Swap_report r;
          // The call's whole time, measured here (not the report's own seconds).
          CGAL::Real_timer call;
          call.start();
          if(name == "repair") r = CGAL::swap_edges(tr, ES::Delaunay_criterion());
          else if(name == "repair2") r = CGAL::swap_edges(tr, ES::Delaunay_criterion(), np::number_of_threads(2u));
          else if(name == "random") r = CGAL::swap_edges(tr, ES::Delaunay_criterion(), np::face_order(ES::RANDOM_ORDER));
          else if(name == "helper") r = CGAL::swap_edges_with_helper(tr);
          else if(name == "rcycles")
            r = CGAL::swap_edges(tr, ES::Delaunay_criterion(),
                                 np::schedule(ES::PAPER_CYCLES, np::face_order(ES::RANDOM_ORDER, np::delaunay_repair(false))));
          else r = CGAL::swap_edges(tr, ES::Delaunay_criterion(), np::schedule(ES::PAPER_CYCLES, np::delaunay_repair(false)));
          out[0] = call.time();
          out[6] = double(allocation_counter::peak) - triangulation_bytes;
          out[7] = triangulation_bytes;
          const auto s = r.total_swaps();
          out[1] = double(s[0] + s[1] + s[2] + s[3]);
          out[2] = double(r.number_of_cycles());
          out[3] = double(r.number_of_visits());
          out[4] = (name == "repair" || name == "repair2" || name == "random") ? double(r.repair_path) : -1.0 - double(r.ending);
          out[5] = ES::compare_with_delaunay(tr).identical ? 1 : 0;
        });
        const double* v = ours.values;
        // The repair's path, or the other drivers' ending.
        const char* path = v[4] < 0 ? ES::swap_ending_name(ES::Swap_ending(int(-1.0 - v[4])))
                                    : ES::delaunay_repair_path_name(ES::Delaunay_repair_path(int(v[4])));
        std::printf("%8zu %5.1f%% %8.0f | %7.3f | %-7s %8.3f %6.2f %8.0f %6.0f %9.0f %-12s %5s | %8.1f %8.1f %6.2f\n", n,
                    100 * f, cgal.values[1], cgal.values[0], name.c_str(), v[0], v[0] / cgal.values[0], v[1], v[2],
                    v[3], path, v[5] > 0 ? "yes" : "NO", v[7] / 1048576.0, v[6] / 1048576.0, (v[7] + v[6]) / v[7]);
        std::fflush(stdout);
      }
      if(programs)
      {
        const std::string stem =
          (std::filesystem::temp_directory_path() / ("edge_swapping_3_moving_" + std::to_string(getpid()))).string();
        in_child([&](double*) {
          Triangulation tr;
          build_moved(tr, random_points(n), f);
          std::vector<std::array<double, 3>> points(tr.number_of_vertices());
          for(auto v : tr.finite_vertex_handles()) points[v->info()] = {v->point().x(), v->point().y(), v->point().z()};
          std::vector<std::array<std::size_t, 4>> cells;
          for(auto c : tr.finite_cell_handles())
            cells.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
          std::ofstream node(stem + ".node"), ele(stem + ".ele");
          ES::IO::write_node_file(node, points, {}, 0);
          ES::IO::write_ele_file(ele, cells, 0);
        });
        const auto ours = run_program({EDGE_SWAP_BINARY, "optimize", stem + ".ele", "-o", stem + "_ours.ele"});
        const auto cgal_program = run_program({CGAL_PROGRAM_BINARY, stem + ".node", stem + "_cgal.ele"});
        std::printf("%8zu %5.1f%% whole programs: edge_swap optimize %.2f s (%.0f MiB), CGAL reading and building %.2f s "
                    "(%.0f MiB): ratio %.2f\n", n, 100 * f, ours.first, ours.second, cgal_program.first,
                    cgal_program.second, ours.first / cgal_program.first);
        for(const char* suffix : {".node", ".ele", "_ours.node", "_ours.ele", "_cgal.node", "_cgal.ele"})
        {
          const std::string kept = keep + "/moved_" + std::to_string(n) + "_" + std::to_string(f) + suffix;
          if(keep.empty() || std::string(suffix).find('_') != std::string::npos || std::rename((stem + suffix).c_str(), kept.c_str()) != 0)
            std::remove((stem + suffix).c_str());
        }
        std::fflush(stdout);
      }
    }
  return 0;
}
