// SPDX-License-Identifier: GPL-3.0-or-later
// The whole-program reference of benchmark_moving_mesh: reads the points of a
// TetGen .node file, builds CGAL's Delaunay_triangulation_3 of them and
// writes it as Y.node and Y.ele, with the package's reader and writers.
//
//   cgal_delaunay_of_node IN.node OUT.ele
//
// It runs with huge pages, as edge_swap does (tools/edge_swap/huge_pages.h).

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include "huge_pages.h"
#include <fstream>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K>,
                                             CGAL::Delaunay_triangulation_cell_base_3<K>> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> Delaunay;
namespace IO = CGAL::Edge_swapping_3::IO;

int main(int argc, char** argv)
{
  if(argc != 3) { std::cerr << "usage: cgal_delaunay_of_node IN.node OUT.ele\n"; return 2; }
  edge_swap::restart_with_huge_pages(argv); // as edge_swap does
  const auto node = IO::read_node_file(argv[1]);
  std::vector<std::pair<K::Point_3, std::size_t>> points;
  for(std::size_t k = 0; k < node.points.size(); ++k)
    points.emplace_back(K::Point_3(node.points[k][0], node.points[k][1], node.points[k][2]), k);
  const Delaunay dt(points.begin(), points.end());
  std::vector<std::array<std::size_t, 4>> cells;
  cells.reserve(dt.number_of_finite_cells());
  for(auto c : dt.finite_cell_handles())
    cells.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  const std::string out = argv[2];
  std::ofstream ele(out), nodes(out.substr(0, out.size() - 4) + ".node");
  IO::write_node_file(nodes, node.points, {}, node.first_index);
  IO::write_ele_file(ele, cells, node.first_index);
  return ele && nodes ? 0 : 1;
}
