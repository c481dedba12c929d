// SPDX-License-Identifier: GPL-3.0-or-later
// What a local transformation must respect in a domain mesh: constrained
// facets (boundaries and interfaces) are never removed, cells of different
// subdomains are never joined, and the data of cells and facets (subdomain
// index, boundary reference) follows the tetrahedra through flips and splits.
//
// Models of the concept `MeshConstraints_3` (doc/Edge_swapping_3/Concepts):
// - `No_constraints`: a triangulation of a point set; every finite cell is in
//   the domain and every flip is allowed (the default everywhere);
// - `Domain_constraints`: cells whose `info()` is a `Domain_cell_info`
//   (subdomain index, per-facet boundary reference), the model used by the
//   program and by `domain_triangulation_from_c3t3`.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_CONSTRAINTS_H
#define CGAL_EDGE_SWAPPING_3_MESH_CONSTRAINTS_H

#include <array>

namespace CGAL {
namespace Edge_swapping_3 {

/// Model of `MeshConstraints_3` for a plain triangulation: nothing is constrained.
struct No_constraints
{
  struct Cell_data {};
  struct Facet_data {};

  template <class Cell_handle> Cell_data cell_data(Cell_handle) const { return {}; }
  template <class Cell_handle> void set_cell_data(Cell_handle, const Cell_data&) const {}
  template <class Cell_handle> Facet_data facet_data(Cell_handle, int) const { return {}; }
  template <class Cell_handle> void set_facet_data(Cell_handle, int, const Facet_data&) const {}
  Facet_data free_facet_data() const { return {}; }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle, int) const { return false; }
  template <class Cell_handle> bool same_subdomain(Cell_handle, Cell_handle) const { return true; }
  /// Whether cell `c` belongs to the domain, where points may be inserted. A
  /// point set's domain is all of space: the infinite cells too.
  template <class Tr> bool is_in_domain(const Tr&, typename Tr::Cell_handle) const { return true; }
};

/// The data a domain mesh keeps in each cell: its subdomain index (0 is
/// outside the domain, as in Mesh_3) and, for each facet, a boundary
/// reference (`no_reference` when the facet is not constrained).
struct Domain_cell_info
{
  static constexpr int no_reference = -1;
  int subdomain = 0;
  std::array<int, 4> facet_reference{{no_reference, no_reference, no_reference, no_reference}};
};

/// Model of `MeshConstraints_3` for cells with `info()` of type `Domain_cell_info`.
struct Domain_constraints
{
  typedef int Cell_data;
  typedef int Facet_data;

  template <class Cell_handle> Cell_data cell_data(Cell_handle c) const { return c->info().subdomain; }
  template <class Cell_handle> void set_cell_data(Cell_handle c, Cell_data d) const { c->info().subdomain = d; }
  template <class Cell_handle> Facet_data facet_data(Cell_handle c, int i) const { return c->info().facet_reference[i]; }
  template <class Cell_handle> void set_facet_data(Cell_handle c, int i, Facet_data d) const
  {
    c->info().facet_reference[i] = d;
  }
  /// The data of a facet that is not constrained.
  Facet_data free_facet_data() const { return Domain_cell_info::no_reference; }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle c, int i) const
  {
    return c->info().facet_reference[i] != Domain_cell_info::no_reference;
  }
  template <class Cell_handle> bool same_subdomain(Cell_handle a, Cell_handle b) const
  {
    return a->info().subdomain == b->info().subdomain;
  }
  template <class Tr> bool is_in_domain(const Tr& tr, typename Tr::Cell_handle c) const
  {
    return !tr.is_infinite(c) && c->info().subdomain != 0;
  }
};

/// Whether a planned flip respects `constraints`: all its old cells lie in
/// one subdomain and none of the facets it removes (those between two old
/// cells) is constrained.
template <class Tr, class Plan, class Constraints>
bool flip_respects_constraints(const Tr&, const Plan& plan, const Constraints& constraints)
{
  for(int k = 0; k < plan.number_of_old_cells; ++k)
  {
    const auto c = plan.old_cells[k];
    if(!constraints.same_subdomain(c, plan.old_cells[0])) return false;
    for(int i = 0; i < 4; ++i)
    {
      bool inner = false;
      for(int m = 0; m < plan.number_of_old_cells; ++m) inner = inner || c->neighbor(i) == plan.old_cells[m];
      if(inner && constraints.is_facet_constrained(c, i)) return false;
    }
  }
  return true;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MESH_CONSTRAINTS_H
