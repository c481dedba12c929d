// SPDX-License-Identifier: GPL-3.0-or-later
// The last step of the Delaunay repair: the cells of a triangulation replaced
// by those of the Delaunay triangulation of its vertices. The vertices (and
// their data) stay; every cell is new.
//
// The rebuild is the paper's own flip insertion (`delaunay_by_insertion`,
// which ends on Delaunay by Joe's 1991 theorem; with CGAL's perturbation it
// gives CGAL's cells, as the tests check) into a second triangulation, whose cells are then moved into
// `tr` onto its own vertices. Only the old vertices, the new triangulation and
// arrays of a few words per vertex are held at once. Should an insertion
// leave a facet stuck (never observed in the tests and benchmarks),
// CGAL's `Delaunay_triangulation_3` rebuilds instead.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

// The cells of CGAL's Delaunay triangulation of `vertices` made in the empty
// TDS of `tr`. CGAL's cells are copied into two arrays of 32-bit numbers
// (vertices and neighbours, 32 bytes a cell) and freed before ours are made.
template <class Tr>
void rebuild_with_cgal(Tr& tr, const std::vector<typename Tr::Vertex_handle>& vertices)
{
  typedef typename Tr::Geom_traits Gt;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Gt> Vb;
  typedef CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Gt, CGAL::Delaunay_triangulation_cell_base_3<Gt>> Cb;
  typedef CGAL::Delaunay_triangulation_3<Gt, CGAL::Triangulation_data_structure_3<Vb, Cb>> Delaunay;

  // Vertex k + 1 is vertices[k]; 0 is the infinite vertex.
  std::vector<std::array<std::uint32_t, 4>> cell_vertices, cell_neighbors;
  {
    std::vector<std::pair<typename Tr::Point, std::uint32_t>> points;
    points.reserve(vertices.size());
    if(vertices.size() >= std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Edge_swapping_3: the rebuild through CGAL numbers at most 2^32 - 1 vertices");
    for(std::size_t k = 0; k < vertices.size(); ++k) points.emplace_back(vertices[k]->point(), std::uint32_t(k + 1));
    Delaunay dt(points.begin(), points.end(), tr.geom_traits());
    CGAL_assertion(dt.number_of_vertices() == vertices.size() && dt.dimension() == 3);
    points = {};
    if(dt.number_of_cells() > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Edge_swapping_3: the rebuild through CGAL numbers at most 2^32 cells");
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
}

/// Returns the number of finite cells made. `tr` must be of dimension 3 and
/// its points distinct (a valid triangulation), so no vertex is lost. If an
/// exception is thrown, `tr` is left without cells.
template <class Tr>
std::size_t rebuild_as_delaunay(Tr& tr)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  std::vector<Vertex_handle> vertices;
  vertices.reserve(tr.number_of_vertices());
  for(Vertex_handle v : tr.finite_vertex_handles()) vertices.push_back(v);
  tr.tds().cells().clear();
  {
    Tr built(tr.geom_traits());
    std::vector<Vertex_handle> made; // made[k] in `built` is vertices[k]
    {
      std::vector<typename Tr::Point> points;
      points.reserve(vertices.size());
      for(Vertex_handle v : vertices) points.push_back(v->point());
      auto report = delaunay_by_insertion(built, points);
      if(report.stuck_facets == 0 && built.dimension() == 3) made = std::move(report.vertices);
    }
    if(!made.empty())
    {
      // Each vertex of `built` by its slot number, replaced by ours.
      Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> index(built.tds().vertices());
      std::vector<Vertex_handle> ours(index.number_of_slots());
      for(std::size_t k = 0; k < made.size(); ++k) ours[index(made[k])] = vertices[k];
      ours[index(built.infinite_vertex())] = tr.infinite_vertex();
      made = {};
      for(auto c : built.tds().cell_handles())
        for(int i = 0; i < 4; ++i)
        {
          const Vertex_handle v = ours[index(c->vertex(i))];
          c->set_vertex(i, v);
          v->set_cell(c);
        }
      tr.tds().cells().swap(built.tds().cells()); // `built` goes with its vertices alone
      return tr.number_of_finite_cells();
    }
  }
  rebuild_with_cgal(tr, vertices);
  return tr.number_of_finite_cells();
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
