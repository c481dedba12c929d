// SPDX-License-Identifier: GPL-3.0-or-later
// The last step of the Delaunay repair: the cells of a triangulation replaced
// by those of CGAL's Delaunay triangulation of its vertices. The vertices (and
// their data) stay; every cell is new.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Returns the number of finite cells made. `tr` must be of dimension 3 and
/// its points distinct (a valid triangulation), so no vertex is lost.
template <class Tr>
std::size_t rebuild_as_delaunay(Tr& tr)
{
  typedef typename Tr::Geom_traits Gt;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::size_t, Gt> Vb;
  typedef CGAL::Delaunay_triangulation_cell_base_3<Gt> Cb;
  typedef CGAL::Delaunay_triangulation_3<Gt, CGAL::Triangulation_data_structure_3<Vb, Cb>> Delaunay;

  std::vector<Vertex_handle> vertices;
  std::vector<std::pair<typename Tr::Point, std::size_t>> points;
  vertices.reserve(tr.number_of_vertices());
  points.reserve(tr.number_of_vertices());
  for(Vertex_handle v : tr.finite_vertex_handles())
  {
    points.emplace_back(v->point(), vertices.size());
    vertices.push_back(v);
  }
  const Delaunay dt(points.begin(), points.end(), tr.geom_traits());
  CGAL_assertion(dt.number_of_vertices() == vertices.size() && dt.dimension() == 3);

  auto& tds = tr.tds();
  tds.cells().clear();
  std::unordered_map<typename Delaunay::Cell_handle, Cell_handle, Handle_hash> image;
  image.reserve(dt.number_of_cells());
  auto vertex_of = [&](typename Delaunay::Vertex_handle v) {
    return dt.is_infinite(v) ? tr.infinite_vertex() : vertices[v->info()];
  };
  for(auto dc : dt.all_cell_handles())
    image[dc] = tds.create_cell(vertex_of(dc->vertex(0)), vertex_of(dc->vertex(1)), vertex_of(dc->vertex(2)),
                                vertex_of(dc->vertex(3)));
  for(auto dc : dt.all_cell_handles())
  {
    const Cell_handle c = image[dc];
    for(int i = 0; i < 4; ++i)
    {
      c->set_neighbor(i, image[dc->neighbor(i)]);
      c->vertex(i)->set_cell(c);
    }
  }
  return dt.number_of_finite_cells();
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
