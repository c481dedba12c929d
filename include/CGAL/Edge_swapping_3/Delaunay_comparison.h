// SPDX-License-Identifier: GPL-3.0-or-later
// Exact verification: compares a triangulation with CGAL's own
// Delaunay_triangulation_3 of the same points, cell for cell.

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_COMPARISON_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_COMPARISON_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/internal/point_numbering.h>
#include <algorithm>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// The outcome of `compare_with_delaunay()`: a triangulation against CGAL's
/// `Delaunay_triangulation_3` of its vertices, cell for cell.
struct Delaunay_comparison
{
  bool identical = false;              ///< the same set of finite cells
  std::size_t cells = 0;               ///< finite cells of the triangulation compared
  std::size_t delaunay_cells = 0;      ///< finite cells of CGAL's Delaunay triangulation
  std::size_t cells_not_in_delaunay = 0;  ///< finite cells that CGAL's triangulation does not have
  std::size_t delaunay_cells_missing = 0; ///< finite cells of CGAL's triangulation that are missing
  std::size_t non_delaunay_facets = 0; ///< facets not locally Delaunay (CGAL's perturbation)
};

/// Builds CGAL's Delaunay triangulation of the finite vertices of `tr` and
/// compares the two sets of finite cells (each cell as its sorted vertices).
template <class Tr>
Delaunay_comparison compare_with_delaunay(const Tr& tr)
{
  typedef typename Tr::Geom_traits Gt;
  typedef typename Tr::Point Point;
  typedef std::array<std::size_t, 4> Cell_key;

  std::vector<Point> points;
  points.reserve(tr.number_of_vertices());
  for(auto v : tr.finite_vertex_handles()) points.push_back(v->point());
  const internal::Point_numbering<Gt> numbering(points, tr.geom_traits());

  CGAL::Delaunay_triangulation_3<Gt> dt(points.begin(), points.end());

  auto keys = [&](const auto& t) {
    std::vector<Cell_key> out;
    out.reserve(t.number_of_finite_cells());
    for(auto c : t.finite_cell_handles())
    {
      Cell_key k;
      for(int i = 0; i < 4; ++i) k[i] = numbering.index(c->vertex(i)->point());
      std::sort(k.begin(), k.end());
      out.push_back(k);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<Cell_key> a = keys(tr), b = keys(dt);

  Delaunay_comparison r;
  r.cells = a.size();
  r.delaunay_cells = b.size();
  std::vector<Cell_key> diff;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
  r.cells_not_in_delaunay = diff.size();
  diff.clear();
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(diff));
  r.delaunay_cells_missing = diff.size();
  r.identical = r.cells_not_in_delaunay == 0 && r.delaunay_cells_missing == 0;
  r.non_delaunay_facets = internal::number_of_non_delaunay_facets(tr, CGAL_PERTURBATION);
  return r;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_COMPARISON_H
