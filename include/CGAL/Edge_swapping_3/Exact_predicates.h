// SPDX-License-Identifier: GPL-3.0-or-later
// The package decides every flip by orientation and in-sphere tests; with a
// kernel whose predicates round (Simple_cartesian<double>), a decision can be
// wrong and a flip can make inverted cells. The requirement is checked at
// compile time.

#ifndef CGAL_EDGE_SWAPPING_3_EXACT_PREDICATES_H
#define CGAL_EDGE_SWAPPING_3_EXACT_PREDICATES_H

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/tags.h>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class K, class = void>
struct Has_filtered_predicates_tag : std::false_type {};
template <class K>
struct Has_filtered_predicates_tag<K, std::void_t<typename K::Has_filtered_predicates_tag>>
    : std::bool_constant<K::Has_filtered_predicates_tag::value> {};

} // namespace internal

/// \ingroup PkgEdgeSwapping3Traits
/// Whether the geometric traits `K` decide orientation and in-sphere tests
/// exactly: true for kernels with filtered predicates (CGAL's
/// `Exact_predicates_inexact_constructions_kernel` and
/// `Exact_predicates_exact_constructions_kernel`, and classes derived from
/// them) and for kernels over an exact number type
/// (`Simple_cartesian<CGAL::Gmpq>`); false for `Simple_cartesian<double>`.
/// Specialize it as `std::true_type` for traits of your own whose predicates
/// are exact some other way.
template <class K>
struct Has_exact_predicates
    : std::bool_constant<internal::Has_filtered_predicates_tag<K>::value ||
                         std::is_same<typename Algebraic_structure_traits<typename K::FT>::Is_exact, Tag_true>::value>
{};

namespace internal {

/// Stops the compilation with a message for traits whose predicates round.
template <class K>
constexpr void require_exact_predicates()
{
  static_assert(Has_exact_predicates<K>::value,
                "Edge_swapping_3 decides flips by exact predicates: use a kernel with exact predicates, such as "
                "CGAL::Exact_predicates_inexact_constructions_kernel (or specialize "
                "CGAL::Edge_swapping_3::Has_exact_predicates for traits that are exact some other way)");
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_EXACT_PREDICATES_H
