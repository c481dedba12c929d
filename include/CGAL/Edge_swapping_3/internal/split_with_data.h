// SPDX-License-Identifier: GPL-3.0-or-later
// The split step of an insertion (1-4 in a cell, 2-6 on a facet, n-2n on an
// edge, or the join to the visible hull facets), done by CGAL's
// Triangulation_3::insert, with the cell and facet data of a domain mesh
// carried over: each new cell takes the data of the old cell whose outer facet
// it keeps, and the facets through the new vertex are free.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SPLIT_WITH_DATA_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SPLIT_WITH_DATA_H

#include <CGAL/Triangulation_3.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <algorithm>
#include <array>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

// The cells the split of the simplex located at (c, lt, li, lj) replaces.
template <class Tr>
std::vector<typename Tr::Cell_handle> cells_of_split(const Tr& tr, typename Tr::Cell_handle c,
                                                     typename Tr::Locate_type lt, int li, int lj)
{
  std::vector<typename Tr::Cell_handle> cells;
  if(lt == Tr::CELL)
    cells.push_back(c);
  else if(lt == Tr::FACET)
  {
    cells.push_back(c);
    cells.push_back(c->neighbor(li));
  }
  else if(lt == Tr::EDGE)
  {
    auto circ = tr.incident_cells(c, li, lj), done = circ;
    do cells.push_back(circ); while(++circ != done);
  }
  return cells;
}

// Whether the split may be made under `constraints`: every cell it replaces
// is in the domain and in one subdomain, and it cuts no constrained facet.
template <class Tr, class Constraints>
bool split_is_allowed(const Tr& tr, typename Tr::Cell_handle c, typename Tr::Locate_type lt,
                      int li, int lj, const Constraints& constraints)
{
  if(lt == Tr::OUTSIDE_AFFINE_HULL) return false;
  if constexpr(std::is_same<Constraints, No_constraints>::value) return true;
  if(lt == Tr::OUTSIDE_CONVEX_HULL) return constraints.is_in_domain(tr, c);
  const auto cells = cells_of_split(tr, c, lt, li, lj);
  for(const auto& d : cells)
  {
    if(!constraints.is_in_domain(tr, d) || !constraints.same_subdomain(d, c)) return false;
    if(lt == Tr::FACET && constraints.is_facet_constrained(c, li)) return false;
    if(lt == Tr::EDGE)
      for(int i = 0; i < 4; ++i) // the two facets of d through the edge
        if(d->vertex(i) != c->vertex(li) && d->vertex(i) != c->vertex(lj) &&
           constraints.is_facet_constrained(d, i))
          return false;
  }
  return true;
}

template <class Vertex_handle>
std::array<Vertex_handle, 3> sorted_facet(Vertex_handle a, Vertex_handle b, Vertex_handle c)
{
  std::array<Vertex_handle, 3> t{{a, b, c}};
  std::sort(t.begin(), t.end());
  return t;
}

// Splits and carries the data over. With `No_constraints` this is exactly
// Triangulation_3::insert.
// The Triangulation_3 a triangulation class derives from: Delaunay_ and
// Regular_triangulation_3 name it Tr_Base.
template <class Tr, class = void>
struct Plain_triangulation_of { typedef Tr type; };
template <class Tr>
struct Plain_triangulation_of<Tr, std::void_t<typename Tr::Tr_Base>> { typedef typename Tr::Tr_Base type; };

// The split of Triangulation_3 itself: Delaunay_triangulation_3 and
// Regular_triangulation_3 hide it behind their own insertion.
template <class Tr>
typename Tr::Vertex_handle plain_split(Tr& tr, const typename Tr::Point& p, typename Tr::Cell_handle c,
                                       typename Tr::Locate_type lt, int li, int lj)
{
  return static_cast<typename Plain_triangulation_of<Tr>::type&>(tr).insert(p, lt, c, li, lj);
}

template <class Tr, class Constraints>
typename Tr::Vertex_handle split_with_data(Tr& tr, const typename Tr::Point& p, typename Tr::Cell_handle c,
                                           typename Tr::Locate_type lt, int li, int lj,
                                           const Constraints& constraints)
{
  if constexpr(std::is_same<Constraints, No_constraints>::value)
    return plain_split(tr, p, c, lt, li, lj);
  else
  {
    typedef typename Tr::Vertex_handle Vertex_handle;
    struct Outer
    {
      std::array<Vertex_handle, 3> facet;
      typename Constraints::Cell_data cell;
      typename Constraints::Facet_data data;
    };
    // The outer facets of the replaced cells (sorted by vertex handle: the
    // order only serves the search, never a geometric decision).
    std::vector<Outer> outer;
    const auto cells = cells_of_split(tr, c, lt, li, lj);
    for(const auto& d : cells)
      for(int i = 0; i < 4; ++i)
        if(std::find(cells.begin(), cells.end(), d->neighbor(i)) == cells.end())
          outer.push_back({sorted_facet(d->vertex((i + 1) & 3), d->vertex((i + 2) & 3), d->vertex((i + 3) & 3)),
                           constraints.cell_data(d), constraints.facet_data(d, i)});
    const auto default_cell = constraints.cell_data(c);

    const Vertex_handle v = plain_split(tr, p, c, lt, li, lj);
    std::vector<typename Tr::Cell_handle> star;
    tr.incident_cells(v, std::back_inserter(star));
    for(const auto& d : star)
    {
      const int j = d->index(v);
      const auto key = sorted_facet(d->vertex((j + 1) & 3), d->vertex((j + 2) & 3), d->vertex((j + 3) & 3));
      constraints.set_cell_data(d, default_cell);
      for(int i = 0; i < 4; ++i) constraints.set_facet_data(d, i, constraints.free_facet_data());
      for(const auto& o : outer)
        if(o.facet == key)
        {
          constraints.set_cell_data(d, o.cell);
          constraints.set_facet_data(d, j, o.data);
        }
    }
    return v;
  }
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SPLIT_WITH_DATA_H
