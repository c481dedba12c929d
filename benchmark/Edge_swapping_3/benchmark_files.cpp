// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): the mesh pipeline. The Delaunay mesh of N random
// points written and read in each format (TetGen .node/.ele, Medit .mesh,
// VTK .vtu), then built into a Triangulation_3 and validated exactly once;
// beside CGAL's own Delaunay construction of the same points. Then
// `edge_swap check` and `edge_swap stats` as whole processes, with their peak
// memory, against the memory of the triangulation alone.
//
//   benchmark_files [N ...]   (default 100000 1000000)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/vtu.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/Mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include "allocation_counter.h"
#include "benchmark_common.h"
#include <iostream>

// The program's triangulation type.
typedef ES::Numbered_domain_triangulation_3<K> Triangulation;
typedef K::Point_3 Point;


int main(int argc, char** argv)
{
  start_benchmark(argv);
  std::vector<std::size_t> sizes;
  for(int a = 1; a < argc; ++a) sizes.push_back(std::stoul(argv[a]));
  if(sizes.empty()) sizes = {100000, 1000000};
  const std::string dir = (std::filesystem::temp_directory_path() / ("edge_swapping_3_files_" + std::to_string(getpid()))).string();
  std::filesystem::create_directories(dir);

  for(std::size_t n : sizes)
  {
    // The mesh: CGAL's Delaunay triangulation of the points, as index arrays.
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 4>> cells;
    double cgal_seconds = 0;
    {
      const auto p = random_points(n);
      Triangulation tr;
      CGAL::Real_timer t;
      t.start();
      const auto vertices = ES::insert_delaunay(tr, p);
      cgal_seconds = t.time();
      for(std::size_t k = 0; k < vertices.size(); ++k) vertices[k]->info() = k;
      for(const auto& q : p) points.push_back({q.x(), q.y(), q.z()});
      for(auto c : tr.finite_cell_handles())
        cells.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    }
    const double m = double(cells.size()) / 1e6;
    std::printf("\n%zu points, %zu cells; CGAL's Delaunay construction %.2f s\n", n, cells.size(), cgal_seconds);
    std::printf("%-10s %10s %12s %10s %12s %10s\n", "format", "write s", "Mcells/s", "read s", "Mcells/s", "MiB");

    auto timed = [](auto work) {
      CGAL::Real_timer t;
      t.start();
      work();
      return t.time();
    };
    auto report = [&](const char* name, double w, double r, const std::string& file) {
      std::printf("%-10s %10.2f %12.2f %10.2f %12.2f %10.1f\n", name, w, m / w, r, m / r,
                  double(std::filesystem::file_size(file)) / 1048576.0);
    };
    {
      const std::string node = dir + "/m.node", ele = dir + "/m.ele";
      const double w = timed([&] {
        std::ofstream a(node), b(ele);
        ES::IO::write_node_file(a, points, {}, 1);
        ES::IO::write_ele_file(b, cells, 1);
      });
      std::size_t read_cells = 0;
      const double r = timed([&] {
        const auto nf = ES::IO::read_node_file(node);
        read_cells = ES::IO::read_ele_file(ele, nf.points.size(), nf.first_index).size();
      });
      report("tetgen", w, r, ele);
      if(read_cells != cells.size()) std::printf("  READ %zu CELLS\n", read_cells);
    }
    {
      ES::IO::Medit_mesh mesh;
      mesh.points = points;
      mesh.tetrahedra = cells;
      mesh.tetrahedron_references.assign(cells.size(), 1);
      const std::string file = dir + "/m.mesh";
      const double w = timed([&] {
        std::ofstream a(file);
        ES::IO::write_medit_file(a, mesh);
      });
      const double r = timed([&] { ES::IO::read_medit_file(file); });
      report("medit", w, r, file);
    }
    {
      const std::string file = dir + "/m.vtu";
      const double w = timed([&] {
        std::ofstream a(file);
        ES::IO::write_vtu_file(a, points, cells, {}, {});
      });
      const double r = timed([&] { ES::IO::read_vtu_file(file); });
      report("vtu", w, r, file);
    }

    // Build and validate once; the triangulation's own memory.
    double triangulation_mib = 0;
    {
      std::vector<Point> p;
      for(const auto& q : points) p.emplace_back(q[0], q[1], q[2]);
      const std::size_t before = allocation_counter::current;
      Triangulation tr;
      std::vector<Triangulation::Vertex_handle> vertices;
      std::string problem;
      const double b = timed([&] { problem = ES::build_triangulation_from_cells(tr, p, cells, vertices); });
      triangulation_mib = double(allocation_counter::current - before) / 1048576.0;
      std::printf("build and validate: %.2f s, %.2f Mcells/s (%.2f times CGAL's construction)%s; triangulation %.0f MiB\n",
                  b, m / b, b / cgal_seconds, problem.empty() ? "" : (" PROBLEM: " + problem).c_str(), triangulation_mib);
    }
    // The files just written are flushed first: their write-back competed
    // with the programs (check at 10^6: 10.6 s without the flush, 7.9 s with it).
    ::sync();
    for(const char* command : {"check", "stats"})
    {
      const auto [seconds, mib] = run_program({EDGE_SWAP_BINARY, command, dir + "/m.ele"});
      std::printf("edge_swap %s m.ele: %.2f s, peak %.0f MiB (%.2f times the triangulation)\n", command, seconds, mib,
                  mib / triangulation_mib);
    }
    std::fflush(stdout);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
