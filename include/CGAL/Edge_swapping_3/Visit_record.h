// SPDX-License-Identifier: GPL-3.0-or-later
// What one visit of a facet saw and did, for the drivers' `visit_visitor`:
// the material of a trace (Laboratory/Visit_trace.h) that an independent
// program checks decision by decision.

#ifndef CGAL_EDGE_SWAPPING_3_VISIT_RECORD_H
#define CGAL_EDGE_SWAPPING_3_VISIT_RECORD_H

#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <array>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// One visit of an interior facet by `swap_edges()` or `swap_edges_with_helper()`.
/// Cells are given by their vertices, since a flip destroys them.
template <class Tr>
struct Visit_record
{
  typedef typename Tr::Vertex_handle Vertex_handle;  ///< the triangulation's vertex handle
  typedef std::array<Vertex_handle, 4> Cell_vertices; ///< a cell's vertices, in the cell's order

  std::array<Vertex_handle, 3> facet;  ///< the facet's vertices, seen from `cells[0]`
  std::array<Vertex_handle, 2> apexes; ///< the vertex of `cells[0]` opposite the facet, then that of the cell across
  bool locally_delaunay = true;        ///< the facet passed the (perturbed) in-sphere test before the visit
  Configuration_kind kind = HULL_FACET; ///< the five points' configuration before the visit
  /// The cells made of the five points before the visit (the two of the facet first).
  std::vector<Cell_vertices> cells;
  std::vector<bool> tagged_before;      ///< helper: whether each of `cells` was tagged before the visit
  std::vector<Cell_vertices> new_tags;  ///< helper: the cells the visit tagged
  int flip = -1;                        ///< the `Flip_kind` of the swap the visit made, or -1
  std::vector<Cell_vertices> created;   ///< the finite cells the swap made
  /// The work queue's first round with the Delaunay criterion: the facet was
  /// visited by the scan that runs the in-sphere test alone, found locally
  /// Delaunay and so left alone (the rule decides nothing there).
  bool scanned = false;
};

/// \ingroup PkgEdgeSwapping3Reports
/// The `visit_visitor` that does nothing (the default: no cost).
/// A visit visitor has `visit(tr, record)`, called after each visit, and
/// `end_of_round(tr, cycle_record, is_tagged)`, called after each round with a
/// function that says whether a cell is tagged.
struct No_visit_visitor
{
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_VISIT_RECORD_H
