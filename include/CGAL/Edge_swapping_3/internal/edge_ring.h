// SPDX-License-Identifier: GPL-3.0-or-later
// The cells around an edge, in turning order, with the ring of vertices they
// share, and the plans of the edge flips (3-2, 4-4 and the hull 2-2) on it.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_EDGE_RING_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_EDGE_RING_H

#include <CGAL/Edge_swapping_3/Flip_plan.h>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Tr>
class Edge_ring
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;

  /// The edge of cell `c` between its vertices `i` and `j`. Only the first
  /// five cells are kept: no flip involves more than four.
  Edge_ring(const Tr& tr, Cell_handle c, int i, int j)
    : tr_(tr), p_(c->vertex(i)), q_(c->vertex(j))
  {
    auto circ = tr.incident_cells(c, i, j), done = circ;
    do {
      cells_[n_++] = circ;
      ++circ;
    } while(circ != done && n_ < 5);
    if(n_ > 4) return;
    // s_k is shared by cells k-1 and k; cell k holds s_k and s_{k+1}.
    for(int k = 0; k < n_; ++k)
    {
      Cell_handle prev = cells_[(k + n_ - 1) % n_], cur = cells_[k];
      for(int m = 0; m < 4; ++m)
      {
        Vertex_handle v = cur->vertex(m);
        if(v != p_ && v != q_ && prev->has_vertex(v)) { ring_[k] = v; break; }
      }
    }
  }

  int size() const { return n_; }
  Vertex_handle ring(int k) const { return ring_[k]; }

  /// The diagonal (0: s0-s2, 1: s1-s3) of a four-cell ring joining u and v, or -1.
  int diagonal_through(Vertex_handle u, Vertex_handle v) const
  {
    for(int d = 0; d < 2; ++d)
      if((ring_[d] == u && ring_[d + 2] == v) || (ring_[d] == v && ring_[d + 2] == u))
        return d;
    return -1;
  }

  /// Plans the flip that removes the edge: for three cells, 3-2 (the new
  /// facet is the ring); for four, 4-4 or 2-2 to diagonal `d`.
  bool plan_flip(Flip_plan<Tr>& plan, int d) const
  {
    if(d < 0 || (n_ != 3 && n_ != 4)) return false;
    plan = Flip_plan<Tr>();
    for(int k = 0; k < n_; ++k) plan.add_old_cell(cells_[k]);
    if(n_ == 3)
    {
      plan.kind = FLIP_3_2;
      add_ear(plan, 0, ring_[2]);
      return true;
    }
    plan.kind = FLIP_4_4;
    for(int k = 0; k < 4; ++k)
      if(tr_.is_infinite(ring_[k]) || tr_.is_infinite(p_) || tr_.is_infinite(q_))
        plan.kind = FLIP_2_2;
    add_ear(plan, d, ring_[d + 2]);
    add_ear(plan, d + 2, ring_[d]);
    return true;
  }

private:
  // Cell k (holding s_k and s_k+1) with either end of the edge replaced by s.
  void add_ear(Flip_plan<Tr>& plan, int k, Vertex_handle s) const
  {
    const auto t = tuple_of<Tr>(cells_[k]);
    plan.add_new_cell(replaced(t, q_, s));
    plan.add_new_cell(replaced(t, p_, s));
  }

  const Tr& tr_;
  Vertex_handle p_, q_;
  int n_ = 0;
  std::array<Cell_handle, 5> cells_;
  std::array<Vertex_handle, 4> ring_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_EDGE_RING_H
