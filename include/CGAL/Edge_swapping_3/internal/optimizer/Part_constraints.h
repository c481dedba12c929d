// SPDX-License-Identifier: GPL-3.0-or-later
// The constraints of one part of a partitioned optimization: the mesh's
// own, and the part's frontier frozen. Each vertex has a part; a cell
// belongs to a part when each of its finite vertices does. Only the part's
// cells change (a flip never joins one of them with another cell), the
// facets between them and the other cells are constrained, and no vertex
// with a cell of another part around it moves, even along a flat boundary:
// the other cells keep their shapes, so the part's result can be glued back
// to cells that other parts changed meanwhile.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PART_CONSTRAINTS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PART_CONSTRAINTS_H

#include <CGAL/Edge_swapping_3/internal/boundary_motion.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Model of `MeshConstraints_3`: `Base` restricted to the cells of part
/// `part` (the parts of the vertices by slot, `vertex_parts`; a vertex
/// beyond the table, made later, is in no part). A cell's status is read
/// from its vertices the first time it is needed, and follows the cells
/// through flips and splits from then on (a byte per cell slot, shared by
/// the copies of the model).
template <class Tr, class Base>
class Part_constraints
{
  typedef Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> Cell_index;
  typedef Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> Vertex_index;

public:
  typedef std::pair<typename Base::Cell_data, bool> Cell_data; ///< base data, in the part
  /// The base data, and for a facet on the part's frontier a tag of its
  /// own: no two frontier facets compare equal, so boundary smoothing sees
  /// every vertex of the frontier as a corner and leaves it in place.
  struct Facet_data
  {
    typename Base::Facet_data base;
    const void* frontier = nullptr;
    bool operator==(const Facet_data& o) const
    {
      return frontier == nullptr && o.frontier == nullptr && same_facet_data(base, o.base);
    }
  };

  Part_constraints(const Tr& tr, const Base& base, const std::vector<int>& vertex_parts, int part)
    : base_(base), table_(std::make_shared<Table>(tr, vertex_parts, part))
  {}

  /// \name Types and operations of `MeshConstraints_3`
  /// @{
  template <class Cell_handle> Cell_data cell_data(Cell_handle c) const { return {base_.cell_data(c), in_part(c)}; }
  template <class Cell_handle> void set_cell_data(Cell_handle c, const Cell_data& d) const
  {
    base_.set_cell_data(c, d.first);
    Table& t = *table_;
    const std::size_t k = t.cells(c);
    if(k >= t.status.size()) t.status.resize((std::max)(t.cells.number_of_slots(), k + 1), unknown);
    t.status[k] = d.second ? inside : outside;
    t.recent[Table::recent_place(&*c)] = {&*c, d.second};
  }
  template <class Cell_handle> Facet_data facet_data(Cell_handle c, int i) const
  {
    Facet_data d{base_.facet_data(c, i), nullptr};
    if(on_frontier(c, i)) d.frontier = static_cast<const char*>(static_cast<const void*>(&*c)) + i;
    return d;
  }
  template <class Cell_handle> void set_facet_data(Cell_handle c, int i, const Facet_data& d) const
  {
    base_.set_facet_data(c, i, d.base);
  }
  Facet_data free_facet_data() const { return {base_.free_facet_data(), nullptr}; }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle c, int i) const
  {
    return base_.is_facet_constrained(c, i) || on_frontier(c, i);
  }
  template <class Cell_handle> bool same_subdomain(Cell_handle a, Cell_handle b) const
  {
    return in_part(a) && in_part(b) && base_.same_subdomain(a, b);
  }
  bool is_in_domain(const Tr& tr, typename Tr::Cell_handle c) const { return in_part(c) && base_.is_in_domain(tr, c); }
  /// @}

  /// Whether `c` is a cell of the part.
  template <class Cell_handle> bool in_part(Cell_handle c) const
  {
    Table& t = *table_;
    // The operations ask of the same few cells again and again: the last
    // answers are kept by address (a slot lookup is a binary search).
    Recent& r = t.recent[Table::recent_place(&*c)];
    if(r.cell == &*c) return r.in;
    r = {&*c, slow_in_part(c)};
    return r.in;
  }

private:
  template <class Cell_handle> bool slow_in_part(Cell_handle c) const
  {
    Table& t = *table_;
    const std::size_t k = t.cells(c);
    if(k >= t.status.size()) t.status.resize((std::max)(t.cells.number_of_slots(), k + 1), unknown);
    if(t.status[k] == unknown)
    {
      bool in = true;
      for(int i = 0; i < 4 && in; ++i)
        if(!t.tr.is_infinite(c->vertex(i))) in = t.part_of(c->vertex(i)) == t.part;
      t.status[k] = in ? inside : outside;
    }
    return t.status[k] == inside;
  }

  enum : std::uint8_t { unknown, inside, outside };
  struct Recent
  {
    const void* cell = nullptr;
    bool in = false;
  };
  struct Table
  {
    static std::size_t recent_place(const void* cell) { return (std::size_t(cell) >> 6) & 1023; }
    Table(const Tr& tr, const std::vector<int>& vertex_parts, int part)
      : tr(tr), cells(tr.tds().cells()), vertices(tr.tds().vertices()), vertex_parts(vertex_parts), part(part)
    {}
    template <class Vertex_handle> int part_of(Vertex_handle v)
    {
      const std::size_t k = vertices(v);
      return k < vertex_parts.size() ? vertex_parts[k] : -1;
    }
    const Tr& tr;
    Cell_index cells;
    Vertex_index vertices;
    const std::vector<int>& vertex_parts;
    const int part;
    std::vector<std::uint8_t> status; // by cell slot
    std::array<Recent, 1024> recent;
  };

  template <class Cell_handle> bool on_frontier(Cell_handle c, int i) const
  {
    return in_part(c) != in_part(c->neighbor(i));
  }

  Base base_;
  std::shared_ptr<Table> table_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_PART_CONSTRAINTS_H
