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
  int facet_index = -1;  ///< 2-3 and 3-2 plans of `classify_facet()`: the facet's index in `old_cells[0]` (then glued directly); else -1
  int reflex_index = -1; ///< 3-2 plans of `classify_facet()`: the index in `old_cells[0]` of the facet the apex lies beyond; else -1

  /// Empties the plan for a new flip of kind `k` (the handle arrays are
  /// left as they are: only their first cells count).
  void reset(Flip_kind k)
  {
    kind = k;
    number_of_old_cells = number_of_new_cells = 0;
    facet_index = reflex_index = -1;
  }
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

/// The 2-3 flip of the interior facet `(c, i)`: `c` and its neighbour `n`
/// become three cells, `c` with its vertex `k` replaced by the apex of `n`
/// for each `k != i` in increasing order.
template <class Tr>
void plan_flip_2_3(Flip_plan<Tr>& plan, typename Tr::Cell_handle c, int i)
{
  const auto n = c->neighbor(i);
  const auto e = n->vertex(n->index(c));
  plan.reset(FLIP_2_3);
  plan.add_old_cell(c);
  plan.add_old_cell(n);
  const auto t = tuple_of<Tr>(c);
  for(int k = 0; k < 4; ++k)
    if(k != i)
    {
      plan.add_new_cell(t);
      plan.new_cells[plan.number_of_new_cells - 1][k] = e; // c with its vertex k replaced by the apex
    }
  plan.facet_index = i;
}

/// The 3-2 flip at the interior facet `(c, i)` whose apex lies beyond the
/// facet `k` of `c`, where the edge `(a, b)` of `c` opposite `i` and `k`
/// (`a < b`) has the three cells `c`, its neighbours `i` and `k`: they
/// become `c` with `b`, and `c` with `a`, replaced by the apex. The old
/// cells are listed in turning order around the edge, as CGAL's circulator
/// gives them.
template <class Tr>
void plan_flip_3_2(Flip_plan<Tr>& plan, typename Tr::Cell_handle c, int i, int k)
{
  const auto n = c->neighbor(i), t = c->neighbor(k);
  const auto e = n->vertex(n->index(c));
  int a = -1, b = -1;
  for(int m = 0; m < 4; ++m)
    if(m != i && m != k) (a < 0 ? a : b) = m;
  const bool n_next = (Tr::next_around_edge(a, b) == i);
  plan.reset(FLIP_3_2);
  plan.add_old_cell(c);
  plan.add_old_cell(n_next ? n : t);
  plan.add_old_cell(n_next ? t : n);
  const auto tc = tuple_of<Tr>(c);
  plan.add_new_cell(tc);
  plan.new_cells[0][b] = e; // c with b replaced by the apex
  plan.add_new_cell(tc);
  plan.new_cells[1][a] = e; // c with a replaced by the apex
  plan.facet_index = i;
  plan.reflex_index = k;
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

namespace internal {

// The cells of a plan made: the old cells reused in place first (a reused
// cell is a new cell: no mark, such as the helper's tag), then new ones, all
// with the cell data of the first old cell (one subdomain).
template <class Tr, class Constraints>
void make_planned_cells(Tr& tr, const Flip_plan<Tr>& plan, std::array<typename Tr::Cell_handle, 4>& created,
                        const Constraints& constraints)
{
  const auto cell_data = constraints.cell_data(plan.old_cells[0]);
  for(int k = 0; k < plan.number_of_new_cells; ++k)
  {
    const auto& t = plan.new_cells[k];
    if(k < plan.number_of_old_cells)
    {
      created[k] = plan.old_cells[k];
      created[k]->set_vertices(t[0], t[1], t[2], t[3]);
      created[k]->tds_data().clear();
    }
    else
      created[k] = tr.tds().create_cell(t[0], t[1], t[2], t[3]);
    constraints.set_cell_data(created[k], cell_data);
  }
}

// The last step of every flip: each vertex points to a new cell, and the old
// cells not reused are freed.
template <class Tr>
int finish_flip(Tr& tr, const Flip_plan<Tr>& plan, const std::array<typename Tr::Cell_handle, 4>& created)
{
  for(int k = 0; k < plan.number_of_new_cells; ++k)
    for(int i = 0; i < 4; ++i) created[k]->vertex(i)->set_cell(created[k]);
  for(int k = plan.number_of_new_cells; k < plan.number_of_old_cells; ++k) tr.tds().delete_cell(plan.old_cells[k]);
  return plan.number_of_new_cells;
}

// A facet of an old cell on the boundary of the flipped region: the cell
// outside, the facet's index there, and the data the old cell had on it.
template <class Tr, class Constraints>
struct Outer_facet
{
  typename Tr::Cell_handle cell;
  int index;
  typename Constraints::Facet_data data;

  Outer_facet() = default;
  Outer_facet(typename Tr::Cell_handle old, int i, const Constraints& constraints)
      : cell(old->neighbor(i)), index(cell->index(old)), data(constraints.facet_data(old, i)) {}

  // Glued to the facet `i` of the new cell `c`.
  void glue(typename Tr::Cell_handle c, int i, const Constraints& constraints) const
  {
    c->set_neighbor(i, cell);
    cell->set_neighbor(index, c);
    constraints.set_facet_data(c, i, data);
  }
};

template <class Cell_handle, class Constraints>
void glue_inner_facet(Cell_handle c, int i, Cell_handle d, int j, const Constraints& constraints)
{
  c->set_neighbor(i, d);
  d->set_neighbor(j, c);
  constraints.set_facet_data(c, i, constraints.free_facet_data());
  constraints.set_facet_data(d, j, constraints.free_facet_data());
}

// `d`, a neighbour of `from`, made a neighbour of `to` in its place.
template <class Cell_handle>
void relink(Cell_handle d, Cell_handle from, Cell_handle to)
{
  d->set_neighbor(d->index(from), to);
}

// The 2-3 flip at the facet `(c, i)` (plan_flip_2_3's, which it needs not
// be given), with j0 < j1 < j2 the other indices and e the apex across:
// the new cells are c with its vertex j0, j1 or j2 replaced by e, made of
// c (one vertex set: its facet j0 keeps its outside), of n (n's facet
// opposite c's vertex j1 keeps its outside) and of a new cell m. Across
// the facet jk of each is the old outside of c there, across its facet i
// the outside of n opposite c's vertex jk, across the others the other new
// cells. Each vertex ends pointing to the last new cell that holds it, as
// with the flip by matching. What it needs of c and n is read before either
// is written, with no loop and no index searched twice: this is the
// flip of the Lawson pass and of flip insertion, and it takes CGAL's
// `flip_flippable`'s time to within a few percent (benchmarks.md).
// Declared inline because GCC 12 keeps it out of line otherwise, and the
// call then costs about 15% of the flip's instructions.
template <class Tr, class Constraints>
inline int execute_flip_2_3(Tr& tr, typename Tr::Cell_handle c, int i,
                            std::array<typename Tr::Cell_handle, 4>& created, const Constraints& constraints)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const Cell_handle n = c->neighbor(i);
  const int in = n->index(c);
  const Vertex_handle e = n->vertex(in);
  // j0 < j1 < j2: the indices other than i.
  const int j0 = (i == 0) ? 1 : 0, j1 = (i <= 1) ? 2 : 1, j2 = (i <= 2) ? 3 : 2;
  const Vertex_handle vi = c->vertex(i), v0 = c->vertex(j0), v1 = c->vertex(j1), v2 = c->vertex(j2);
  const int n0 = n->index(v0), n1 = n->index(v1), n2 = 6 - in - n0 - n1;
  const Cell_handle oc1 = c->neighbor(j1), oc2 = c->neighbor(j2);
  const Cell_handle on0 = n->neighbor(n0), on1 = n->neighbor(n1), on2 = n->neighbor(n2);
  const auto dc1 = constraints.facet_data(c, j1), dc2 = constraints.facet_data(c, j2);
  const auto dn0 = constraints.facet_data(n, n0), dn1 = constraints.facet_data(n, n1),
             dn2 = constraints.facet_data(n, n2);
  const auto free_data = constraints.free_facet_data();
  const auto cell_data = constraints.cell_data(c);

  const Cell_handle m = tr.tds().create_cell(c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3));
  m->set_vertex(j2, e);
  n->set_vertices(c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3));
  n->set_vertex(j1, e);
  c->set_vertex(j0, e);
  c->tds_data().clear(); // a reused cell is a new cell: no mark
  n->tds_data().clear();
  constraints.set_cell_data(c, cell_data);
  constraints.set_cell_data(n, cell_data);
  constraints.set_cell_data(m, cell_data);

  // c: across i the outside of n opposite v0; across j1 and j2 the new cells.
  c->set_neighbor(i, on0);
  relink(on0, n, c);
  constraints.set_facet_data(c, i, dn0);
  c->set_neighbor(j1, n);
  constraints.set_facet_data(c, j1, free_data);
  c->set_neighbor(j2, m);
  constraints.set_facet_data(c, j2, free_data);
  // n: across j1 the outside of c there; across i its own outside opposite
  // v1, which points to n already; across j0 and j2 the new cells.
  n->set_neighbor(j1, oc1);
  relink(oc1, c, n);
  constraints.set_facet_data(n, j1, dc1);
  n->set_neighbor(i, on1);
  constraints.set_facet_data(n, i, dn1);
  n->set_neighbor(j0, c);
  constraints.set_facet_data(n, j0, free_data);
  n->set_neighbor(j2, m);
  constraints.set_facet_data(n, j2, free_data);
  // m: across j2 the outside of c there, across i that of n opposite v2.
  m->set_neighbor(j2, oc2);
  relink(oc2, c, m);
  constraints.set_facet_data(m, j2, dc2);
  m->set_neighbor(i, on2);
  relink(on2, n, m);
  constraints.set_facet_data(m, i, dn2);
  m->set_neighbor(j0, c);
  constraints.set_facet_data(m, j0, free_data);
  m->set_neighbor(j1, n);
  constraints.set_facet_data(m, j1, free_data);

  v0->set_cell(m);
  v1->set_cell(m);
  vi->set_cell(m);
  e->set_cell(m);
  v2->set_cell(n);
  created[0] = c;
  created[1] = n;
  created[2] = m;
  return 3;
}

// The 3-2 flip at the facet `(c, i)` whose apex lies beyond the facet `k`
// of `c` (plan_flip_3_2's, which it needs not be given): new cell 0 is c
// with b replaced by the apex e, new cell 1 c with a replaced; across the
// facet of each opposite the apex is the old outside of c, across its facets
// i and k those of n and t opposite the replaced vertex, and across the last
// the other new cell. New cell 0 is c (one vertex set: its facet b stays),
// new cell 1 reuses the old cell that follows c around the edge (a, b), n or
// t, keeping the outside of its outer facet; the third is deleted. Written
// and declared as the 2-3 flip is.
template <class Tr, class Constraints>
inline int execute_flip_3_2(Tr& tr, typename Tr::Cell_handle c, int i, int k,
                            std::array<typename Tr::Cell_handle, 4>& created, const Constraints& constraints)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const Cell_handle n = c->neighbor(i), t = c->neighbor(k);
  const Vertex_handle e = n->vertex(n->index(c));
  // a < b: the two indices other than i and k.
  static constexpr signed char lower_other[4][4] = {{-1, 2, 1, 1}, {2, -1, 0, 0}, {1, 0, -1, 0}, {1, 0, 0, -1}};
  const int a = lower_other[i][k], b = 6 - i - k - a;
  const bool n_next = (Tr::next_around_edge(a, b) == i);
  const Cell_handle second = n_next ? n : t, third = n_next ? t : n;
  const Vertex_handle va = c->vertex(a), vb = c->vertex(b), vd = c->vertex(i), vk = c->vertex(k);
  const int na = n->index(va), nb = n->index(vb), ta = t->index(va), tb = t->index(vb);
  const Cell_handle oc = c->neighbor(a);
  const Cell_handle on0 = n->neighbor(nb), ot0 = t->neighbor(tb), on1 = n->neighbor(na), ot1 = t->neighbor(ta);
  const auto dc = constraints.facet_data(c, a);
  const auto dn0 = constraints.facet_data(n, nb), dt0 = constraints.facet_data(t, tb),
             dn1 = constraints.facet_data(n, na), dt1 = constraints.facet_data(t, ta);
  const auto free_data = constraints.free_facet_data();
  const auto cell_data = constraints.cell_data(c);

  second->set_vertices(c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3));
  second->set_vertex(a, e);
  c->set_vertex(b, e);
  c->tds_data().clear(); // a reused cell is a new cell: no mark
  second->tds_data().clear();
  constraints.set_cell_data(c, cell_data);
  constraints.set_cell_data(second, cell_data);

  // c: across i and k the outsides of n and t opposite b.
  c->set_neighbor(i, on0);
  relink(on0, n, c);
  constraints.set_facet_data(c, i, dn0);
  c->set_neighbor(k, ot0);
  relink(ot0, t, c);
  constraints.set_facet_data(c, k, dt0);
  // second: across a the outside of c there, across i and k those of n and
  // t opposite a (the one of second itself points to it already).
  second->set_neighbor(a, oc);
  relink(oc, c, second);
  constraints.set_facet_data(second, a, dc);
  second->set_neighbor(i, on1);
  if(second != n) relink(on1, n, second);
  constraints.set_facet_data(second, i, dn1);
  second->set_neighbor(k, ot1);
  if(second != t) relink(ot1, t, second);
  constraints.set_facet_data(second, k, dt1);
  c->set_neighbor(a, second);
  constraints.set_facet_data(c, a, free_data);
  second->set_neighbor(b, c);
  constraints.set_facet_data(second, b, free_data);

  vb->set_cell(second);
  vd->set_cell(second);
  vk->set_cell(second);
  e->set_cell(second);
  va->set_cell(c);
  tr.tds().delete_cell(third);
  created[0] = c;
  created[1] = second;
  return 2;
}

// Any valid plan carried out: each facet of a new cell glued to the outside
// or to another new cell by matching vertices.
template <class Tr, class Constraints>
int execute_flip_by_matching(Tr& tr, const Flip_plan<Tr>& plan, std::array<typename Tr::Cell_handle, 4>& created,
                             const Constraints& constraints)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;

  // A facet is matched by the sum of its vertex addresses first (cheap), then
  // by its vertices; addresses only serve the search, never a decision.
  struct Facet_slot
  {
    std::uintptr_t key;
    std::array<Vertex_handle, 3> v;
    Cell_handle cell;
    int index;
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
  std::array<Outer_facet<Tr, Constraints>, 8> outer;
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
      if(is_old(c->neighbor(i))) continue;
      CGAL_assertion(n_out < 8);
      outside[n_out] = slot_of(c, i);
      outer[n_out++] = Outer_facet<Tr, Constraints>(c, i, constraints);
    }
  }
  make_planned_cells(tr, plan, created, constraints);

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
          outer[m].glue(created[k], i, constraints);
          glued = true;
        }
      for(int m = 0; m < n_in && !glued; ++m)
        if(!inner[m].glued && same_facet(inner[m], f))
        {
          glue_inner_facet(created[k], i, inner[m].cell, inner[m].index, constraints);
          inner[m].glued = glued = true;
        }
      if(!glued) inner[n_in++] = f;
    }
  CGAL_assertion_code(for(int m = 0; m < n_in; ++m) CGAL_assertion(inner[m].glued);)
  return finish_flip(tr, plan, created);
}

} // namespace internal

/// Carries out a valid plan: the old cells are replaced by the new ones and
/// glued to the outside. Old cells are reused in place, so handles to them
/// name other tetrahedra afterwards. Writes the handles of the new cells to
/// `created` and returns their number. Purely combinatorial. The new cells
/// take the cell data of the old ones (one subdomain), and each keeps the
/// facet data of the old facet it shares with the outside (`constraints`).
/// This is the package's one flip: every driver, the Delaunay repair, flip
/// insertion and scrambling make their flips through it.
template <class Tr, class Constraints = No_constraints>
int execute_flip(Tr& tr, const Flip_plan<Tr>& plan,
                 std::array<typename Tr::Cell_handle, 4>& created,
                 const Constraints& constraints = Constraints())
{
  if(plan.facet_index >= 0)
    return plan.kind == FLIP_2_3
               ? internal::execute_flip_2_3(tr, plan.old_cells[0], plan.facet_index, created, constraints)
               : internal::execute_flip_3_2(tr, plan.old_cells[0], plan.facet_index, plan.reflex_index, created,
                                            constraints);
  return internal::execute_flip_by_matching(tr, plan, created, constraints);
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_FLIP_PLAN_H
