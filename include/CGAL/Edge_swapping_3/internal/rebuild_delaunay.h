// SPDX-License-Identifier: GPL-3.0-or-later
// The last step of the Delaunay repair: the cells of a triangulation replaced
// by those of the Delaunay triangulation of its vertices. The vertices (and
// their data) stay; every cell is new.
//
// The rebuild is the paper's own flip insertion (`delaunay_by_insertion`,
// which ends on Delaunay by Joe's 1991 theorem; with CGAL's perturbation it
// gives CGAL's cells, as the tests check) into a second triangulation, whose cells are then moved into
// `tr` onto its own vertices. Only the old vertices, the new triangulation and
// arrays of a few words per vertex are held at once.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H

#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Returns the number of finite cells made. `tr` must be of dimension 3 and
/// its points distinct (a valid triangulation), so no vertex is lost. If an
/// exception is thrown, `tr` is left without cells. Should flip insertion
/// leave a facet stuck, its triangulation (valid, not Delaunay) is kept all
/// the same: the caller counts what is not Delaunay and says so.
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
      made = delaunay_by_insertion(built, points).vertices;
    }
    CGAL_assertion(built.dimension() == 3 && made.size() == vertices.size());
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
    }
  }
  return tr.number_of_finite_cells();
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REBUILD_DELAUNAY_H
