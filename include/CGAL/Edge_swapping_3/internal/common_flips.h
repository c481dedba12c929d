// SPDX-License-Identifier: GPL-3.0-or-later
// The two common flips of a facet that is not locally Delaunay, decided by
// three exact orientation tests and made by the package's flip (the direct
// flip `execute_flip` makes of the plan `classify_facet` would make, given
// the facet instead of the plan): the 2-3 flip
// when the apex e across the facet (c, i) lies strictly inside the wedge of
// c at that facet, the 3-2 flip when it lies strictly beyond
// exactly one other facet of c and the edge between the two has three cells.
// These are the signs of the barycentric coordinates of e in c (appendix A),
// so the decision is classify_facet's in those two cases; a degenerate or
// hull case is left to the general planned flip.
//
// For triangulations with no constraints: reused cells keep their place, and
// neither facet nor cell data is moved.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_COMMON_FLIPS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_COMMON_FLIPS_H

#include <CGAL/Edge_swapping_3/Exact_predicates.h>
#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <CGAL/Edge_swapping_3/internal/orientations_with_apex.h>
#include <array>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// What the configuration at a facet allows now.
enum Common_flip_kind
{
  COMMON_FLIP_2_3,
  COMMON_FLIP_3_2,
  NOT_FLIPPABLE_NOW, ///< concave at an edge of more than three cells, or at two edges
  NEEDS_GENERAL_FLIP ///< a hull facet, or an apex on the plane of a facet of c
};

struct Common_flip
{
  Common_flip_kind kind;
  int reflex = -1; ///< 3-2: the index in c of the facet beyond which the apex lies
};

/// The flip the interior or hull facet `(c, i)` allows in the common cases.
template <class Tr>
Common_flip common_flip_at(const Tr& tr, typename Tr::Cell_handle c, int i)
{
  require_exact_predicates<typename Tr::Geom_traits>();
  const auto n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n)) return {NEEDS_GENERAL_FLIP};
  const auto apex = n->vertex(n->index(c));
  const auto& e = apex->point();
  typedef typename Tr::Geom_traits Gt;
  const std::array<const typename Tr::Point*, 4> p = {&c->vertex(0)->point(), &c->vertex(1)->point(),
                                                      &c->vertex(2)->point(), &c->vertex(3)->point()};
  std::array<Orientation, 4> o;
  if constexpr(has_double_coordinates<Gt>())
    o = orientations_with_apex(tr.geom_traits(), p, i, e);
  else
    for(int k = 0; k < 4; ++k)
      if(k != i)
      {
        auto q = p;
        q[k] = &e;
        o[k] = tr.geom_traits().orientation_3_object()(*q[0], *q[1], *q[2], *q[3]);
      }
  int reflex = -1;
  for(int k = 0; k < 4; ++k)
  {
    if(k == i) continue;
    if(o[k] == COPLANAR) return {NEEDS_GENERAL_FLIP};
    if(o[k] == NEGATIVE)
    {
      // Concave at the edge opposite i and k: flippable only if that edge has
      // three cells and the apex is beyond no other facet.
      if(reflex >= 0 || !c->neighbor(k)->has_vertex(apex)) return {NOT_FLIPPABLE_NOW};
      reflex = k;
    }
  }
  return {reflex < 0 ? COMMON_FLIP_2_3 : COMMON_FLIP_3_2, reflex};
}

/// Makes the flip `f` (a 2-3 or 3-2 flip from `common_flip_at(tr, c, i)`);
/// returns the number of new cells, put in `made`.
template <class Tr>
int make_common_flip(Tr& tr, typename Tr::Cell_handle c, int i, const Common_flip& f,
                     std::array<typename Tr::Cell_handle, 4>& made)
{
  // The flip execute_flip makes of plan_flip_2_3's or plan_flip_3_2's plan,
  // without the plan: nothing here reads the new cells before they are made.
  if(f.kind == COMMON_FLIP_2_3) return execute_flip_2_3(tr, c, i, made, No_constraints());
  CGAL_precondition(f.kind == COMMON_FLIP_3_2);
  return execute_flip_3_2(tr, c, i, f.reflex, made, No_constraints());
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_COMMON_FLIPS_H
