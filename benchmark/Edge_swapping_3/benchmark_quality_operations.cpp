// Benchmark (not a test): the quality operations on the inputs of issue 11.
// Inputs: the two-spheres domain mesh (`edge_swap mesh-domain two-spheres`,
// measured on its flow region, boundaries and subdomains kept), and the
// Delaunay triangulation of 8,000 random points (measured on the cells with
// no vertex on the fixed hull). Rows: the input, the flip driver
// (`swap_edges`, MinMax), and the worst-first driver
// (`improve_worst_tetrahedra`) with flips, edge removal, or both, for MinMax
// and MaxMin dihedral angles, then with both for the radius ratio, the
// dihedral sine and the volume-length ratio. Columns as in issue 11's table: smallest and
// largest dihedral angle, cells below 10 and above 165 and 175 degrees, the
// 1st percentile of the radius ratio 3 r / R (1 for a regular tetrahedron),
// then the time and the operations.
//
//   benchmark_quality_operations

#include <CGAL/Real_timer.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include "benchmark_common.h"
#include "mesh_files.h"
#include <algorithm>
#include <functional>
#include <iterator>
#include <memory>
#include <set>

typedef edge_swap::Triangulation Triangulation;

namespace {

typedef std::function<bool(Triangulation::Cell_handle)> Cell_filter;

struct Quality_row
{
  double smallest = 180, largest = 0, radius_ratio_1st_percentile = 0;
  std::size_t below_10 = 0, above_165 = 0, above_175 = 0, cells = 0;
};

// The quality of the cells `counted` selects.
Quality_row quality(const Triangulation& tr, const Cell_filter& counted)
{
  Quality_row q;
  std::vector<double> ratios;
  for(auto c : tr.finite_cell_handles())
  {
    if(!counted(c)) continue;
    const auto& p0 = c->vertex(0)->point();
    const auto& p1 = c->vertex(1)->point();
    const auto& p2 = c->vertex(2)->point();
    const auto& p3 = c->vertex(3)->point();
    const auto angles = ES::dihedral_angles(p0, p1, p2, p3);
    const double lo = *std::min_element(angles.begin(), angles.end());
    const double hi = *std::max_element(angles.begin(), angles.end());
    q.smallest = std::min(q.smallest, lo);
    q.largest = std::max(q.largest, hi);
    q.below_10 += lo < 10;
    q.above_165 += hi > 165;
    q.above_175 += hi > 175;
    ratios.push_back(3 / ES::radius_ratio(p0, p1, p2, p3));
    ++q.cells;
  }
  std::sort(ratios.begin(), ratios.end());
  if(!ratios.empty()) q.radius_ratio_1st_percentile = ratios[ratios.size() / 100];
  return q;
}

void print(const char* name, const Quality_row& q, double seconds, const std::string& operations)
{
  std::printf("%-34s %6.2f / %6.2f %6zu %6zu %6zu %8.3f %8zu %8.2f  %s\n", name, q.smallest, q.largest, q.below_10,
              q.above_165, q.above_175, q.radius_ratio_1st_percentile, q.cells, seconds, operations.c_str());
  std::fflush(stdout);
}

std::string operations_of(const ES::Quality_report& r)
{
  return std::to_string(r.edge_removals) + " edge removals, " + std::to_string(r.flips[ES::FLIP_2_3]) + " 2-3, " +
         std::to_string(r.flips[ES::FLIP_3_2]) + " 3-2, " + std::to_string(r.flips[ES::FLIP_4_4] + r.flips[ES::FLIP_2_2]) +
         " 4-4/2-2";
}

// Every row on a fresh copy of the input (`make`), measured on the cells that
// `counted(tr)` selects.
template <class Constraints>
void rows(const std::function<void(Triangulation&)>& make, const Constraints& constraints,
          const std::function<Cell_filter(const Triangulation&)>& counted)
{
  std::printf("%-34s %15s %6s %6s %6s %8s %8s %8s  %s\n", "optimizer", "min / max deg", "<10", ">165", ">175",
              "rr 1%", "cells", "s", "operations");
  {
    Triangulation tr;
    make(tr);
    print("input", quality(tr, counted(tr)), 0, "");
  }
  {
    Triangulation tr;
    make(tr);
    const auto r = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion(), ES::parameters::mesh_constraints(constraints));
    const auto s = r.total_swaps();
    print("swap_edges MinMax (flips)", quality(tr, counted(tr)), r.seconds,
          std::to_string(s[0]) + " 2-3, " + std::to_string(s[1]) + " 3-2, " + std::to_string(s[2] + s[3]) + " 4-4/2-2");
  }
  const std::pair<const char*, unsigned> variants[] = {
      {"flips", ES::FLIPS}, {"edge removal", ES::EDGE_REMOVAL}, {"edge removal + flips", ES::ALL_OPERATIONS}};
  for(bool minmax : {true, false})
    for(const auto& [name, operations] : variants)
    {
      Triangulation tr;
      make(tr);
      const auto np = ES::parameters::operations(operations, ES::parameters::mesh_constraints(constraints));
      const auto r = minmax ? ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(), np)
                            : ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(), np);
      const std::string row = std::string("worst first ") + (minmax ? "MinMax, " : "MaxMin, ") + name;
      print(row.c_str(), quality(tr, counted(tr)), r.seconds, operations_of(r));
    }
  // The other measures, with both operations.
  auto other = [&](const auto& criterion, const char* row) {
    Triangulation tr;
    make(tr);
    const auto r = ES::improve_worst_tetrahedra(tr, criterion, ES::parameters::mesh_constraints(constraints));
    print(row, quality(tr, counted(tr)), r.seconds, operations_of(r));
  };
  other(ES::Max_min_radius_ratio_criterion(), "worst first radius ratio, both");
  other(ES::Max_min_dihedral_sine_criterion(), "worst first dihedral sine, both");
  other(ES::Max_min_volume_length_criterion(), "worst first volume-length, both");
}

} // namespace

int main(int, char** argv)
{
  start_benchmark(argv);
  const std::string dir = (std::filesystem::temp_directory_path() / ("edge_swapping_3_quality_" + std::to_string(getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string mesh = dir + "/two_spheres.mesh";
  run_program({EDGE_SWAP_BINARY, "mesh-domain", "two-spheres", "-o", mesh});
  const edge_swap::Input two_spheres = edge_swap::read_input(mesh);
  std::filesystem::remove_all(dir);

  std::printf("\nTwo-spheres domain mesh, flow region (subdomain 1); boundaries and subdomains kept\n");
  rows([&](Triangulation& tr) { edge_swap::build_mesh(tr, two_spheres); }, ES::Domain_constraints(),
       [](const Triangulation&) { return Cell_filter([](Triangulation::Cell_handle c) { return c->info().subdomain == 1; }); });

  std::printf("\nDelaunay triangulation of 8,000 random points, cells with no vertex on the hull\n");
  const auto points = random_points(8000);
  rows(
    [&](Triangulation& tr) {
      ES::insert_delaunay(tr, points);
      edge_swap::mark_point_set_domain(tr);
    },
    ES::No_constraints(),
    [](const Triangulation& tr) {
      auto hull = std::make_shared<std::set<Triangulation::Vertex_handle>>();
      tr.adjacent_vertices(tr.infinite_vertex(), std::inserter(*hull, hull->end()));
      return Cell_filter([hull](Triangulation::Cell_handle c) {
        for(int i = 0; i < 4; ++i)
          if(hull->count(c->vertex(i))) return false;
        return true;
      });
    });
  return 0;
}
