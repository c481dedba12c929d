// SPDX-License-Identifier: GPL-3.0-or-later
// Replacing a set of cells by another triangulation of the same region,
// glued to the rest: the last step of edge removal and multi-face removal.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REPLACE_CELLS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REPLACE_CELLS_H

#include <CGAL/assertions.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Replaces `old_cells` by `new_cells` (positively oriented tuples that fill
/// the same region), glued to the outside and to each other; the new cells
/// take the cell data of the old ones and each keeps the facet data of the
/// outer facet it takes over. The visitor sees the old cells before and the
/// new ones after. Returns the new cells.
template <class Tr, class Old_cells, class New_cells, class Constraints, class Visitor>
std::vector<typename Tr::Cell_handle> replace_cells(Tr& tr, const Old_cells& old_range, const New_cells& new_cells,
                                                    const Constraints& constraints, Visitor& visitor)
{
  typedef typename Tr::Cell_handle Cell_handle;
  // The visitor takes a vector; the attempts that lead here keep theirs on the stack.
  const std::vector<Cell_handle> old_cells(old_range.begin(), old_range.end());
  visitor_of(visitor).before_replacement(tr, old_cells);
  typedef typename Tr::Vertex_handle Vertex_handle;
  auto& tds = tr.tds();
  struct Slot
  {
    std::array<Vertex_handle, 3> v; // sorted by address: only to match facets
    Cell_handle cell;
    int index;
    typename Constraints::Facet_data data;
    bool glued = false;
  };
  auto slot_of = [](Cell_handle c, int i) {
    Slot s;
    s.v = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)};
    std::sort(s.v.begin(), s.v.end(), [](Vertex_handle x, Vertex_handle y) { return &*x < &*y; });
    s.cell = c;
    s.index = i;
    return s;
  };
  // The outer facets: those of old cells whose neighbour is not an old cell.
  auto is_old = [&](Cell_handle c) { return std::find(old_cells.begin(), old_cells.end(), c) != old_cells.end(); };
  std::vector<Slot> outside;
  for(Cell_handle c : old_cells)
    for(int i = 0; i < 4; ++i)
    {
      if(is_old(c->neighbor(i))) continue;
      Slot o = slot_of(c, i);
      o.cell = c->neighbor(i);
      o.index = o.cell->index(c);
      o.data = constraints.facet_data(c, i);
      outside.push_back(o);
    }
  // Finite cells take the data of a finite old cell, infinite ones that of
  // an infinite old cell (outside the domain).
  Cell_handle finite_model = old_cells.front(), infinite_model = old_cells.front();
  for(Cell_handle c : old_cells) (tr.is_infinite(c) ? infinite_model : finite_model) = c;
  const auto finite_data = constraints.cell_data(finite_model), infinite_data = constraints.cell_data(infinite_model);
  std::vector<Cell_handle> created;
  for(const auto& t : new_cells)
  {
    created.push_back(tds.create_cell(t[0], t[1], t[2], t[3]));
    constraints.set_cell_data(created.back(), tr.is_infinite(created.back()) ? infinite_data : finite_data);
  }
  std::vector<Slot> inner;
  for(Cell_handle c : created)
    for(int i = 0; i < 4; ++i)
    {
      const Slot f = slot_of(c, i);
      bool glued = false;
      for(Slot& o : outside)
        if(!o.glued && o.v == f.v)
        {
          c->set_neighbor(i, o.cell);
          o.cell->set_neighbor(o.index, c);
          constraints.set_facet_data(c, i, o.data);
          o.glued = glued = true;
          break;
        }
      for(std::size_t m = 0; m < inner.size() && !glued; ++m)
        if(!inner[m].glued && inner[m].v == f.v)
        {
          c->set_neighbor(i, inner[m].cell);
          inner[m].cell->set_neighbor(inner[m].index, c);
          constraints.set_facet_data(c, i, constraints.free_facet_data());
          constraints.set_facet_data(inner[m].cell, inner[m].index, constraints.free_facet_data());
          inner[m].glued = glued = true;
        }
      if(!glued) inner.push_back(f);
    }
  CGAL_assertion_code(for(const Slot& o : outside) CGAL_assertion(o.glued);)
  CGAL_assertion_code(for(const Slot& f : inner) CGAL_assertion(f.glued);)
  for(Cell_handle c : created)
    for(int i = 0; i < 4; ++i) c->vertex(i)->set_cell(c);
  for(Cell_handle c : old_cells) tds.delete_cell(c);
  visitor_of(visitor).after_replacement(tr, created);
  return created;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REPLACE_CELLS_H
