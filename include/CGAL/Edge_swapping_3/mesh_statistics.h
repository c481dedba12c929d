// SPDX-License-Identifier: GPL-3.0-or-later
// Counts and quality extremes of a triangulation, as the paper reports them.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H
#define CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// The counts of the paper's tables and the extreme qualities of a mesh (`mesh_statistics()`).
struct Mesh_statistics
{
  std::size_t vertices = 0;             ///< finite vertices
  std::size_t edges = 0;                ///< finite edges, hull included
  std::size_t faces = 0;                ///< finite facets, hull included
  std::size_t cells = 0;                ///< finite cells
  double min_dihedral_angle = HUGE_VAL; ///< degrees
  double max_dihedral_angle = 0;        ///< degrees
  double max_edge_length_ratio = 0;     ///< longest over shortest edge, worst cell
  double max_radius_ratio = 0;          ///< circumradius over inradius, worst cell
};

/// \ingroup PkgEdgeSwapping3Functions
/// The counts and extreme qualities of the finite part of `tr`.
template <class Tr>
Mesh_statistics mesh_statistics(const Tr& tr)
{
  Mesh_statistics s;
  s.vertices = tr.number_of_vertices();
  s.edges = tr.number_of_finite_edges();
  s.faces = tr.number_of_finite_facets();
  s.cells = tr.number_of_finite_cells();
  for(auto c : tr.finite_cell_handles())
  {
    const auto& p0 = internal::bare_point(c->vertex(0)->point());
    const auto& p1 = internal::bare_point(c->vertex(1)->point());
    const auto& p2 = internal::bare_point(c->vertex(2)->point());
    const auto& p3 = internal::bare_point(c->vertex(3)->point());
    for(double a : dihedral_angles(p0, p1, p2, p3))
    {
      s.min_dihedral_angle = (std::min)(s.min_dihedral_angle, a);
      s.max_dihedral_angle = (std::max)(s.max_dihedral_angle, a);
    }
    s.max_edge_length_ratio = (std::max)(s.max_edge_length_ratio, edge_length_ratio(p0, p1, p2, p3));
    s.max_radius_ratio = (std::max)(s.max_radius_ratio, radius_ratio(p0, p1, p2, p3));
  }
  return s;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H
