// SPDX-License-Identifier: GPL-3.0-or-later
// A flip planned on a Triangulation_3: the cells it removes and the vertex
// tuples of the cells it creates, with the exact test that the result is a
// valid triangulation, and the combinatorial surgery that carries it out.
//
// New cells get their vertex order from an old cell by replacing one vertex
// (a cell stays positively oriented when a vertex is replaced by a point on
// the same side of the opposite facet), so a geometric test of each new cell
// is exactly the convexity test of the paper's appendix A.

#ifndef CGAL_EDGE_SWAPPING_3_FLIP_PLAN_H
#define CGAL_EDGE_SWAPPING_3_FLIP_PLAN_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <array>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Edge_swapping_3 {

/// The bistellar flips of five points (paper Fig. 6). `FLIP_2_2` is the flip of
/// a planar hull face: a 4-4 flip one of whose ring vertices is the infinite vertex.
enum Flip_kind { FLIP_2_3 = 0, FLIP_3_2 = 1, FLIP_2_2 = 2, FLIP_4_4 = 3 };

constexpr int number_of_flip_kinds = 4; ///< the size of the arrays of swaps by kind

/// The name of `k` ("2-3", ...), for reports.
inline const char* flip_kind_name(Flip_kind k)
{
  static const char* names[] = {"2-3", "3-2", "2-2", "4-4"};
  return names[k];
}

/// The cells a flip removes and the cells it would create (vertex tuples,
/// positively oriented when the flip is valid).
template <class Tr>
struct Flip_plan
{
  typedef typename Tr::Cell_handle Cell_handle;     ///< the triangulation's cell handle
  typedef typename Tr::Vertex_handle Vertex_handle; ///< the triangulation's vertex handle
  typedef std::array<Vertex_handle, 4> Tuple;       ///< the vertices of a cell to be made

  Flip_kind kind = FLIP_2_3;             ///< 2-3, 3-2, 2-2 (hull) or 4-4
  int number_of_old_cells = 0;           ///< the cells the flip removes
  int number_of_new_cells = 0;           ///< the cells it makes
  std::array<Cell_handle, 4> old_cells;  ///< `old_cells[0 .. number_of_old_cells)`
  std::array<Tuple, 4> new_cells;        ///< `new_cells[0 .. number_of_new_cells)`

  /// Appends a cell to be made.
  void add_new_cell(const Tuple& t) { new_cells[number_of_new_cells++] = t; }
  /// Appends a cell to be removed.
  void add_old_cell(Cell_handle c) { old_cells[number_of_old_cells++] = c; }
};

namespace internal {

template <class Tr>
typename Flip_plan<Tr>::Tuple tuple_of(typename Tr::Cell_handle c)
{
  return {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
}

/// +1 when `t` is an even permutation of the vertices of `c` (then
/// positively oriented, as `c` is), else -1: an orientation read off the
/// cell's own vertex order, without coordinates.
template <class Tr>
int permutation_sign(typename Tr::Cell_handle c, const typename Flip_plan<Tr>::Tuple& t)
{
  std::array<int, 4> p;
  for(int k = 0; k < 4; ++k) p[k] = c->index(t[k]);
  int sign = 1;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      if(p[i] > p[j]) sign = -sign;
  return sign;
}

template <class Tuple, class Vertex_handle>
Tuple replaced(Tuple t, Vertex_handle from, Vertex_handle to)
{
  for(auto& v : t)
    if(v == from) { v = to; return t; }
  CGAL_assertion(false);
  return t;
}

template <class Tuple, class Vertex_handle>
bool contains(const Tuple& t, Vertex_handle v)
{
  return t[0] == v || t[1] == v || t[2] == v || t[3] == v;
}

} // namespace internal

/// Exact orientation of a planned cell. A finite cell is tested directly. A
/// cell with the infinite vertex stands for the outside of a hull facet: it is
/// POSITIVE when no other finite vertex of the flip lies strictly beyond that
/// facet, NEGATIVE otherwise (`others` are the vertices of the old cells).
template <class Tr, class Tuple>
Orientation planned_cell_orientation(const Tr& tr, const Tuple& t,
                                     const typename Tr::Vertex_handle* others, int n_others)
{
  auto orientation = tr.geom_traits().orientation_3_object();
  int inf = -1;
  for(int k = 0; k < 4; ++k)
    if(tr.is_infinite(t[k])) inf = k;
  if(inf < 0)
    return orientation(internal::bare_point(t[0]->point()), internal::bare_point(t[1]->point()), internal::bare_point(t[2]->point()), internal::bare_point(t[3]->point()));

  for(int m = 0; m < n_others; ++m)
  {
    const auto s = others[m];
    if(tr.is_infinite(s) || internal::contains(t, s))
      continue;
    Tuple u = t;
    u[inf] = s;
    // Replacing the infinite vertex by a point beyond the facet is POSITIVE.
    if(orientation(internal::bare_point(u[0]->point()), internal::bare_point(u[1]->point()), internal::bare_point(u[2]->point()), internal::bare_point(u[3]->point())) == POSITIVE)
      return NEGATIVE;
  }
  return POSITIVE;
}

/// The least orientation among the planned cells: POSITIVE exactly when the
/// flip yields a valid triangulation (every new cell positively oriented, the
/// hull stays convex).
template <class Tr>
Orientation worst_orientation(const Tr& tr, const Flip_plan<Tr>& plan)
{
  std::array<typename Tr::Vertex_handle, 16> vertices;
  int n = 0;
  for(int k = 0; k < plan.number_of_old_cells; ++k)
    for(int i = 0; i < 4; ++i)
    {
      auto v = plan.old_cells[k]->vertex(i);
      bool seen = false;
      for(int m = 0; m < n; ++m) seen = seen || vertices[m] == v;
      if(!seen) vertices[n++] = v;
    }

  Orientation worst = POSITIVE;
  for(int k = 0; k < plan.number_of_new_cells; ++k)
  {
    const Orientation o = planned_cell_orientation(tr, plan.new_cells[k], vertices.data(), n);
    if(o == NEGATIVE) return NEGATIVE;
    if(o == COPLANAR) worst = COPLANAR;
  }
  return worst;
}

/// Carries out a valid plan: the old cells are replaced by the new ones and
/// glued to the outside. Old cells are reused in place, so handles to them
/// name other tetrahedra afterwards. Writes the handles of the new cells to
/// `created` and returns their number. Purely combinatorial. The new cells
/// take the cell data of the old ones (one subdomain), and each keeps the
/// facet data of the old facet it shares with the outside (`constraints`).
template <class Tr, class Constraints = No_constraints>
int execute_flip(Tr& tr, const Flip_plan<Tr>& plan,
                 std::array<typename Tr::Cell_handle, 4>& created,
                 const Constraints& constraints = Constraints())
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  auto& tds = tr.tds();

  // A facet is matched by the sum of its vertex addresses first (cheap), then
  // by its vertices; addresses only serve the search, never a decision.
  struct Facet_slot
  {
    std::uintptr_t key;
    std::array<Vertex_handle, 3> v;
    Cell_handle cell;
    int index;
    typename Constraints::Facet_data data;
    bool glued;
  };
  auto slot_of = [](Cell_handle c, int i) {
    Facet_slot s;
    s.v = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)};
    s.key = reinterpret_cast<std::uintptr_t>(&*s.v[0]) + reinterpret_cast<std::uintptr_t>(&*s.v[1]) +
            reinterpret_cast<std::uintptr_t>(&*s.v[2]);
    s.cell = c;
    s.index = i;
    s.glued = false;
    return s;
  };
  auto same_facet = [](const Facet_slot& a, const Facet_slot& b) {
    if(a.key != b.key) return false;
    for(const auto& w : a.v)
      if(w != b.v[0] && w != b.v[1] && w != b.v[2]) return false;
    return true;
  };

  // The facets on the boundary of the old cells, seen from the cell outside them.
  std::array<Facet_slot, 8> outside;
  int n_out = 0;
  auto is_old = [&](Cell_handle c) {
    for(int k = 0; k < plan.number_of_old_cells; ++k)
      if(plan.old_cells[k] == c) return true;
    return false;
  };
  for(int k = 0; k < plan.number_of_old_cells; ++k)
  {
    Cell_handle c = plan.old_cells[k];
    for(int i = 0; i < 4; ++i)
    {
      Cell_handle nb = c->neighbor(i);
      if(is_old(nb)) continue;
      CGAL_assertion(n_out < 8);
      Facet_slot& o = outside[n_out++];
      o = slot_of(c, i);
      o.cell = nb;
      o.index = nb->index(c);
      o.data = constraints.facet_data(c, i);
    }
  }
  const auto cell_data = constraints.cell_data(plan.old_cells[0]);

  for(int k = 0; k < plan.number_of_new_cells; ++k)
  {
    const auto& t = plan.new_cells[k];
    if(k < plan.number_of_old_cells)
    {
      created[k] = plan.old_cells[k];
      created[k]->set_vertices(t[0], t[1], t[2], t[3]);
      created[k]->tds_data().clear(); // a reused cell is a new cell: no mark (the helper's tag)
    }
    else
      created[k] = tds.create_cell(t[0], t[1], t[2], t[3]);
    constraints.set_cell_data(created[k], cell_data);
  }

  // Glue each facet of a new cell to the outside or to another new cell.
  std::array<Facet_slot, 16> inner;
  int n_in = 0;
  for(int k = 0; k < plan.number_of_new_cells; ++k)
    for(int i = 0; i < 4; ++i)
    {
      const Facet_slot f = slot_of(created[k], i);
      bool glued = false;
      for(int m = 0; m < n_out && !glued; ++m)
        if(same_facet(outside[m], f))
        {
          created[k]->set_neighbor(i, outside[m].cell);
          outside[m].cell->set_neighbor(outside[m].index, created[k]);
          constraints.set_facet_data(created[k], i, outside[m].data);
          glued = true;
        }
      for(int m = 0; m < n_in && !glued; ++m)
        if(!inner[m].glued && same_facet(inner[m], f))
        {
          created[k]->set_neighbor(i, inner[m].cell);
          inner[m].cell->set_neighbor(inner[m].index, created[k]);
          constraints.set_facet_data(created[k], i, constraints.free_facet_data());
          constraints.set_facet_data(inner[m].cell, inner[m].index, constraints.free_facet_data());
          inner[m].glued = glued = true;
        }
      if(!glued) inner[n_in++] = f;
    }
  CGAL_assertion_code(for(int m = 0; m < n_in; ++m) CGAL_assertion(inner[m].glued);)
  for(int k = 0; k < plan.number_of_new_cells; ++k)
    for(int i = 0; i < 4; ++i)
      created[k]->vertex(i)->set_cell(created[k]);

  for(int k = plan.number_of_new_cells; k < plan.number_of_old_cells; ++k)
    tds.delete_cell(plan.old_cells[k]);
  return plan.number_of_new_cells;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_FLIP_PLAN_H
