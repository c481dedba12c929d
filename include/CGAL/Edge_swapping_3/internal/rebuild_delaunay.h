// SPDX-License-Identifier: GPL-3.0-or-later
// The last step of the Delaunay repair: the cells of a triangulation replaced
// by those of CGAL's Delaunay triangulation of its vertices. The vertices (and
// their data) stay; every cell is new.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Returns the number of finite cells made. `tr` must be of dimension 3 and
/// its points distinct (a valid triangulation), so no vertex is lost.
///
/// Memory: CGAL's triangulation and ours are never held at once. Our cells
/// go first; CGAL's cells are copied into two arrays of 32-bit numbers
/// (vertices and neighbours, 32 bytes a cell) and freed; ours are made from
/// the arrays.
template <class Tr>
std::size_t rebuild_as_delaunay(Tr& tr)
{
  typedef typename Tr::Geom_traits Gt;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Gt> Vb;
  typedef CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Gt, CGAL::Delaunay_triangulation_cell_base_3<Gt>> Cb;
  typedef CGAL::Delaunay_triangulation_3<Gt, CGAL::Triangulation_data_structure_3<Vb, Cb>> Delaunay;

  // Vertex k + 1 is vertices[k]; 0 is the infinite vertex.
  std::vector<Vertex_handle> vertices;
  vertices.reserve(tr.number_of_vertices());
  std::vector<std::array<std::uint32_t, 4>> cell_vertices, cell_neighbors;
  std::size_t finite_cells = 0;
  {
    std::vector<std::pair<typename Tr::Point, std::uint32_t>> points;
    points.reserve(tr.number_of_vertices());
    for(Vertex_handle v : tr.finite_vertex_handles())
    {
      vertices.push_back(v);
      points.emplace_back(v->point(), std::uint32_t(vertices.size()));
    }
    tr.tds().cells().clear();
    Delaunay dt(points.begin(), points.end(), tr.geom_traits());
    CGAL_assertion(dt.number_of_vertices() == vertices.size() && dt.dimension() == 3);
    points = {};
    dt.infinite_vertex()->info() = 0;
    std::uint32_t n = 0;
    for(auto c : dt.all_cell_handles()) c->info() = n++;
    cell_vertices.resize(n);
    cell_neighbors.resize(n);
    for(auto c : dt.all_cell_handles())
      for(int i = 0; i < 4; ++i)
      {
        cell_vertices[c->info()][i] = c->vertex(i)->info();
        cell_neighbors[c->info()][i] = c->neighbor(i)->info();
      }
    finite_cells = dt.number_of_finite_cells();
  }
  auto vertex_of = [&](std::uint32_t k) { return k == 0 ? tr.infinite_vertex() : vertices[k - 1]; };
  auto& tds = tr.tds();
  std::vector<Cell_handle> made(cell_vertices.size());
  for(std::size_t k = 0; k < made.size(); ++k)
  {
    const auto& v = cell_vertices[k];
    made[k] = tds.create_cell(vertex_of(v[0]), vertex_of(v[1]), vertex_of(v[2]), vertex_of(v[3]));
  }
  cell_vertices = {};
  for(std::size_t k = 0; k < made.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      made[k]->set_neighbor(i, made[cell_neighbors[k][i]]);
      made[k]->vertex(i)->set_cell(made[k]);
    }
  return finite_cells;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
