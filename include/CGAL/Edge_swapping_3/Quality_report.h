// SPDX-License-Identifier: GPL-3.0-or-later
// The operations of the quality driver, as bits, and what it reports.

#ifndef CGAL_EDGE_SWAPPING_3_QUALITY_REPORT_H
#define CGAL_EDGE_SWAPPING_3_QUALITY_REPORT_H

#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <array>
#include <cstddef>

namespace CGAL {
namespace Edge_swapping_3 {

/// The operations of the quality driver, as bits.
enum Quality_operation : unsigned
{
  FLIPS = 1,              ///< 2-3, 3-2, 2-2 and 4-4 flips of the cell's facets
  EDGE_REMOVAL = 2,       ///< edge removal on the cell's edges
  MULTI_FACE_REMOVAL = 4, ///< multi-face removal at the cell's facets
  SMOOTHING = 8,          ///< smoothing of the cell's interior vertices (moves points)
  TWO_STEP_EDGE_REMOVAL = 16, ///< edge removal after the removal of an edge of the edge's star
  /// smoothing that also moves vertices within flat boundary patches and along
  /// straight boundary edges (`move_on_flat_boundary` of `smooth_vertex`);
  /// implies `SMOOTHING`
  BOUNDARY_SMOOTHING = 32,
  /// removal of the cell's interior vertices by edge contraction (`remove_vertex`)
  VERTEX_REMOVAL = 64,
  /// insertion of a vertex in the cell (`insert_vertex`), off the boundary
  VERTEX_INSERTION = 128,
  /// every operation that keeps the points
  TOPOLOGICAL_OPERATIONS = FLIPS | EDGE_REMOVAL | MULTI_FACE_REMOVAL | TWO_STEP_EDGE_REMOVAL,
  /// every operation that keeps the vertices (interior ones may move)
  ALL_OPERATIONS = TOPOLOGICAL_OPERATIONS | SMOOTHING,
  /// every operation, vertices removed and inserted too (boundary vertices stay)
  ALL_WITH_VERTEX_CHANGES = ALL_OPERATIONS | VERTEX_REMOVAL | VERTEX_INSERTION
};

/// The report of `improve_worst_tetrahedra`.
struct Quality_report
{
  /// CONVERGED (queue empty), CYCLE_LIMIT_REACHED (operation limit),
  /// TIME_LIMIT_REACHED (`maximum_running_time`) or INTERRUPTED (`stop_flag`)
  Swap_ending ending = CONVERGED;
  std::size_t visits = 0;                       ///< cells taken from the queue that still existed
  std::size_t stuck = 0;                        ///< of those, the cells no operation improved
  std::size_t edge_removals = 0;                ///< edges removed (in one step)
  std::size_t two_step_removals = 0;            ///< edges removed in two steps (two edges each)
  std::size_t face_removals = 0;                ///< multi-face removals made
  std::size_t faces_removed = 0;                ///< triangles they removed
  std::size_t smoothing_moves = 0;              ///< smoothing moves made (a vertex may move more than once)
  std::size_t vertex_removals = 0;              ///< vertices removed
  std::size_t vertex_insertions = 0;            ///< vertices inserted
  std::array<std::size_t, number_of_flip_kinds> flips{}; ///< flips by kind
  double worst_before = 0;                      ///< the worst value over the finite cells in the domain, before
  double worst_after = 0;                       ///< the same after
  double seconds = 0;                           ///< the time of the run

  /// The operations made, flips included.
  std::size_t number_of_operations() const
  {
    std::size_t n = edge_removals + two_step_removals + face_removals + smoothing_moves + vertex_removals +
                    vertex_insertions;
    for(std::size_t f : flips) n += f;
    return n;
  }
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_QUALITY_REPORT_H
