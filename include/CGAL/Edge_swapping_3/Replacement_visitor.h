// SPDX-License-Identifier: GPL-3.0-or-later
// The visitor of the quality operations (model of `ReplacementVisitor_3`):
// edge removal, two-step edge removal and multi-face removal replace a set of
// cells by new ones, the quality driver's flips too, and smoothing moves a
// vertex; users carry their own cell and vertex data through each.

#ifndef CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H
#define CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H

#include <functional>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// Does nothing. A visitor has the three functions:
///  - `before_replacement(tr, old_cells)`: the cells of `old_cells` are
///    about to be replaced, and are still intact: read their data here;
///  - `after_replacement(tr, new_cells)`: the new cells exist and fill the
///    same region; write their data here (handles of old cells are no
///    longer valid, or, after a flip, may name new cells);
///  - `after_move(tr, v, old_point)`: smoothing moved `v` from `old_point`;
///    the cells around it are the same cells, with new shapes.
/// The operations copy the visitor, like CGAL's; keep state behind a
/// pointer or pass `std::ref(visitor)`.
struct Default_replacement_visitor
{
  /// Does nothing.
  template <class Tr>
  void before_replacement(const Tr&, const std::vector<typename Tr::Cell_handle>&) const {}
  /// Does nothing.
  template <class Tr>
  void after_replacement(const Tr&, const std::vector<typename Tr::Cell_handle>&) const {}
  /// Does nothing.
  template <class Tr>
  void after_move(const Tr&, typename Tr::Vertex_handle, const typename Tr::Point&) const {}
};

namespace internal {

/// A visitor given by value or through `std::ref`.
template <class T>
T& visitor_of(T& t) { return t; }
template <class T>
T& visitor_of(std::reference_wrapper<T> r) { return r.get(); }

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H
