// SPDX-License-Identifier: GPL-3.0-or-later
// The glue from Mesh_3's output to the package's files: a
// `Mesh_complex_3_in_triangulation_3` as a `Mesh_with_fields`. The whole
// triangulation is kept (cells outside the complex get reference 0), so the
// result triangulates the convex hull and every function can work on it.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_FROM_COMPLEX_H
#define CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_FROM_COMPLEX_H

#include <CGAL/Edge_swapping_3/Mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <unordered_map>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Domains
/// The triangulation of `c3t3` as a mesh with bare points (the protecting
/// balls' weights dropped): every finite cell, with the reference
/// `cell_reference(c3t3.subdomain_index(c))` (0 for the cells not in the
/// complex), and every facet of the complex as a boundary triangle with the
/// reference `facet_reference(c3t3.surface_patch_index(f))`.
/// \tparam C3t3 a `Mesh_complex_3_in_triangulation_3`
/// \param c3t3 the complex (Mesh_3's output)
/// \param cell_reference a callable from `C3t3::Subdomain_index` to `int`
/// \param facet_reference a callable from `C3t3::Surface_patch_index` to `int`
template <class C3t3, class Cell_reference, class Facet_reference>
auto mesh_with_fields_from_complex(const C3t3& c3t3, Cell_reference cell_reference, Facet_reference facet_reference)
{
  typedef typename C3t3::Triangulation Tr;
  typedef typename Tr::Geom_traits::Point_3 Point;
  const Tr& tr = c3t3.triangulation();
  Mesh_with_fields<Point> mesh;
  mesh.is_mesh = mesh.has_references = true;
  std::unordered_map<typename Tr::Vertex_handle, std::size_t> index;
  index.reserve(tr.number_of_vertices());
  for(auto v : tr.finite_vertex_handles())
  {
    index.emplace(v, mesh.points.size());
    mesh.points.push_back(internal::bare_point(v->point()));
  }
  for(auto c : tr.finite_cell_handles())
  {
    mesh.cells.push_back({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
    mesh.cell_references.push_back(c3t3.is_in_complex(c) ? cell_reference(c3t3.subdomain_index(c)) : 0);
  }
  for(auto it = c3t3.facets_in_complex_begin(); it != c3t3.facets_in_complex_end(); ++it)
  {
    const auto& f = *it;
    std::array<std::size_t, 3> t;
    for(int k = 0; k < 3; ++k) t[k] = index[f.first->vertex((f.second + 1 + k) & 3)];
    mesh.triangles.push_back(t);
    mesh.triangle_references.push_back(facet_reference(c3t3.surface_patch_index(f)));
  }
  return mesh;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_FROM_COMPLEX_H
