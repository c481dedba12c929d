// SPDX-License-Identifier: GPL-3.0-or-later
// What every quality operation (edge removal, multi-face removal, two-step
// removal, smoothing, vertex removal and insertion) works with: the
// triangulation, the criterion, the constraints, the visitor, the ring
// limit and where the new cells go. One argument instead of six.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPERATION_CONTEXT_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPERATION_CONTEXT_H

#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The measure and direction of a `Worst_tetrahedron_criterion`.
template <class Criterion>
struct Worst_tetrahedron_criterion_traits;

template <class Measure_, bool larger_is_worse_>
struct Worst_tetrahedron_criterion_traits<Worst_tetrahedron_criterion<Measure_, larger_is_worse_>>
{
  typedef Measure_ Measure;
  static constexpr bool larger_is_worse = larger_is_worse_;
};

/// The settings an operation reads and the vector it appends its new cells
/// to. It holds references only: it is made where the objects live, and
/// copied freely.
template <class Tr, class Criterion_, class Constraints_, class Visitor_>
struct Operation_context
{
  typedef Tr Triangulation;
  typedef Criterion_ Criterion;
  typedef Constraints_ Constraints;
  typedef Visitor_ Visitor;
  typedef typename Worst_tetrahedron_criterion_traits<Criterion>::Measure Measure;
  static constexpr bool larger_is_worse = Worst_tetrahedron_criterion_traits<Criterion>::larger_is_worse;
  typedef typename Tr::Cell_handle Cell_handle;

  Tr& tr;
  const Criterion& criterion;
  const Constraints& constraints;
  Visitor& visitor;
  /// The largest ring edge removal considers, and the most triangles
  /// multi-face removal explores.
  int maximum_ring;
  /// The new cells of each operation made (finite and infinite) are appended here.
  std::vector<Cell_handle>& created;
};

template <class Tr, class Criterion, class Constraints, class Visitor>
Operation_context<Tr, Criterion, Constraints, Visitor>
make_operation_context(Tr& tr, const Criterion& criterion, const Constraints& constraints, Visitor& visitor,
                       int maximum_ring, std::vector<typename Tr::Cell_handle>& created)
{
  return {tr, criterion, constraints, visitor, maximum_ring, created};
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPERATION_CONTEXT_H
