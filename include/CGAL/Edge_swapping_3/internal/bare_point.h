// SPDX-License-Identifier: GPL-3.0-or-later
// The bare point of a vertex. A Regular_triangulation_3 (Mesh_3's output is
// one) stores weighted points; orientation, quality measures and the other
// predicates of flips and quality criteria take the bare point.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_BARE_POINT_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_BARE_POINT_H

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class P, class = void>
struct Is_weighted_point : std::false_type {};
template <class P>
struct Is_weighted_point<P, std::void_t<decltype(std::declval<const P&>().point()),
                                        decltype(std::declval<const P&>().weight())>> : std::true_type {};

/// `p` itself, or the point of a weighted point.
template <class P>
decltype(auto) bare_point(const P& p)
{
  if constexpr(Is_weighted_point<P>::value) return p.point();
  else return (p);
}

/// A point of the triangulation's type at `where`, with the weight of `like`.
template <class P, class Bare>
P moved_point(const P& like, const Bare& where)
{
  if constexpr(Is_weighted_point<P>::value) return P(where, like.weight());
  else return where;
}

/// A point of type `P` at `where`: weight 0 for a weighted point.
template <class P, class Bare>
P point_at(const Bare& where)
{
  if constexpr(Is_weighted_point<P>::value) return P(where);
  else return where;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_BARE_POINT_H
