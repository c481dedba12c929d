// SPDX-License-Identifier: GPL-3.0-or-later
// The visitor of the quality operations (model of `ReplacementVisitor_3`):
// edge removal, two-step edge removal and multi-face removal replace a set of
// cells by new ones, the quality driver's flips too, smoothing moves a
// vertex, vertex insertion adds one and vertex removal takes one away; users
// carry their own cell and vertex data through each.

#ifndef CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H
#define CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H

#include <array>
#include <functional>
#include <type_traits>
#include <utility>
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
///    the cells around it are the same cells, with new shapes;
///  - optionally `after_insertion(tr, v, corners, weights)`: vertex insertion
///    made `v`, at the point `weights` (barycentric coordinates, sum 1) of
///    the old vertices `corners`; give `v` its data here;
///  - optionally `before_removal(tr, v, onto)`: vertex removal is about to
///    delete `v`, contracting its edge to `onto`.
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
  /// Does nothing.
  template <class Tr>
  void after_insertion(const Tr&, typename Tr::Vertex_handle, const std::array<typename Tr::Vertex_handle, 4>&,
                       const std::array<double, 4>&) const {}
  /// Does nothing.
  template <class Tr>
  void before_removal(const Tr&, typename Tr::Vertex_handle, typename Tr::Vertex_handle) const {}
};

namespace internal {

/// A visitor given by value or through `std::ref`.
template <class T>
T& visitor_of(T& t) { return t; }
template <class T>
T& visitor_of(std::reference_wrapper<T> r) { return r.get(); }

// The two optional functions: a visitor written before vertices could be
// added or removed keeps compiling, and is simply not told.
template <class V, class Tr, class = void>
struct Has_after_insertion : std::false_type {};
template <class V, class Tr>
struct Has_after_insertion<V, Tr, std::void_t<decltype(std::declval<V&>().after_insertion(
                                      std::declval<const Tr&>(), std::declval<typename Tr::Vertex_handle>(),
                                      std::declval<const std::array<typename Tr::Vertex_handle, 4>&>(),
                                      std::declval<const std::array<double, 4>&>()))>> : std::true_type {};
template <class V, class Tr, class = void>
struct Has_before_removal : std::false_type {};
template <class V, class Tr>
struct Has_before_removal<V, Tr, std::void_t<decltype(std::declval<V&>().before_removal(
                                     std::declval<const Tr&>(), std::declval<typename Tr::Vertex_handle>(),
                                     std::declval<typename Tr::Vertex_handle>()))>> : std::true_type {};

/// Tells the visitor of a new vertex, if it listens.
template <class Visitor, class Tr>
void tell_insertion(Visitor& visitor, const Tr& tr, typename Tr::Vertex_handle v,
                    const std::array<typename Tr::Vertex_handle, 4>& corners, const std::array<double, 4>& weights)
{
  auto& to = visitor_of(visitor);
  if constexpr(Has_after_insertion<std::remove_reference_t<decltype(to)>, Tr>::value)
    to.after_insertion(tr, v, corners, weights);
}

/// Tells the visitor of a vertex about to go, if it listens.
template <class Visitor, class Tr>
void tell_removal(Visitor& visitor, const Tr& tr, typename Tr::Vertex_handle v, typename Tr::Vertex_handle onto)
{
  auto& to = visitor_of(visitor);
  if constexpr(Has_before_removal<std::remove_reference_t<decltype(to)>, Tr>::value)
    to.before_removal(tr, v, onto);
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_REPLACEMENT_VISITOR_H
