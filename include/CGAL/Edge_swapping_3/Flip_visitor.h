// SPDX-License-Identifier: GPL-3.0-or-later
// The per-flip visitor of the swap drivers (model of `FlipVisitor_3`), in the
// spirit of Tetrahedral_remeshing's visitor: users carry their own cell data
// and fields through flips.

#ifndef CGAL_EDGE_SWAPPING_3_FLIP_VISITOR_H
#define CGAL_EDGE_SWAPPING_3_FLIP_VISITOR_H

#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <array>

namespace CGAL {
namespace Edge_swapping_3 {

/// Does nothing. A visitor has both functions:
///  - `before_flip(tr, plan)`: the old cells (`plan.old_cells`) are still
///    intact; read their data here, because flips reuse cells in place;
///  - `after_flip(tr, plan, new_cells, n)`: the `n` new cells exist (their
///    vertex tuples are `plan.new_cells`); write their data here.
/// The drivers copy the visitor once, like CGAL's; keep state behind a
/// pointer or pass `std::ref(visitor)`.
struct Default_flip_visitor
{
  /// Does nothing.
  template <class Tr>
  void before_flip(const Tr&, const Flip_plan<Tr>&) const {}
  /// Does nothing.
  template <class Tr>
  void after_flip(const Tr&, const Flip_plan<Tr>&, const std::array<typename Tr::Cell_handle, 4>&, int) const {}
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_FLIP_VISITOR_H
