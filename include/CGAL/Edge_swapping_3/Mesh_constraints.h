// SPDX-License-Identifier: GPL-3.0-or-later
// What a local transformation must respect in a domain mesh: constrained
// facets (boundaries and interfaces) are never removed, cells of different
// subdomains are never joined, and the data of cells and facets (subdomain
// index, boundary reference) follows the tetrahedra through flips and splits.
//
// Users name a domain in CGAL's vocabulary (Tetrahedral_remeshing's), and the
// functions build a model of the concept `MeshConstraints_3`
// (doc/Edge_swapping_3/Concepts/MeshConstraints_3.md) from it:
// - the triangulation of a `Mesh_complex_3_in_triangulation_3` (Mesh_3's
//   output, or Tetrahedral_remeshing's): its cells' `subdomain_index()` and
//   `surface_patch_index(i)` are the domain (`Complex_constraints`);
// - `facet_is_constrained_map` and `cell_is_selected_map` (named parameters,
//   read once; written back at the end when writable) on any triangulation,
//   alone or on top of the complex's indices (`Selected_constraints`);
// - `No_constraints` for a triangulation of a point set (the default).
// `Domain_constraints` (cells whose `info()` is a `Domain_cell_info`) is the
// model of the program's files; any model can be given with the package's
// parameter `mesh_constraints`.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_CONSTRAINTS_H
#define CGAL_EDGE_SWAPPING_3_MESH_CONSTRAINTS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <boost/property_map/property_map.hpp>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// Model of `MeshConstraints_3` for a plain triangulation: nothing is constrained.
struct No_constraints
{
  /// \name Types and operations of `MeshConstraints_3` (doc/Edge_swapping_3/Concepts/MeshConstraints_3.md)
  /// @{
  struct Cell_data {}; ///< the data of a cell (none)
  struct Facet_data {}; ///< the data of a facet (none)

  /// The data of a cell, and so on: the operations of the concept.
  template <class Cell_handle> Cell_data cell_data(Cell_handle) const { return {}; }
  template <class Cell_handle> void set_cell_data(Cell_handle, const Cell_data&) const {}
  template <class Cell_handle> Facet_data facet_data(Cell_handle, int) const { return {}; }
  template <class Cell_handle> void set_facet_data(Cell_handle, int, const Facet_data&) const {}
  Facet_data free_facet_data() const { return {}; }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle, int) const { return false; }
  template <class Cell_handle> bool same_subdomain(Cell_handle, Cell_handle) const { return true; }
  // A point set's domain is all of space: the infinite cells too.
  template <class Tr> bool is_in_domain(const Tr&, typename Tr::Cell_handle) const { return true; }
  /// @}
};

/// The data a domain mesh keeps in each cell: its subdomain index (0 is
/// outside the domain, as in Mesh_3) and, for each facet, a boundary
/// reference (`no_reference` when the facet is not constrained).
struct Domain_cell_info
{
  static constexpr int no_reference = -1; ///< the reference of a facet that is not constrained
  /// The subdomain of the cells the package adds outside a domain that is not
  /// convex (or has cavities, or several parts) to complete it to a
  /// triangulation of a convex region: outside the domain, and never written.
  static constexpr int completion = (std::numeric_limits<int>::min)();
  int subdomain = 0;                      ///< 0 (or `completion`) outside the domain
  /// The boundary reference of facet `i` (the one opposite vertex `i`).
  std::array<int, 4> facet_reference{{no_reference, no_reference, no_reference, no_reference}};
};

/// Model of `MeshConstraints_3` for cells with `info()` of type `Domain_cell_info`.
struct Domain_constraints
{
  /// \name Types and operations of `MeshConstraints_3` (doc/Edge_swapping_3/Concepts/MeshConstraints_3.md)
  /// @{
  typedef int Cell_data; ///< the subdomain index
  typedef int Facet_data;

  template <class Cell_handle> Cell_data cell_data(Cell_handle c) const { return c->info().subdomain; }
  template <class Cell_handle> void set_cell_data(Cell_handle c, Cell_data d) const { c->info().subdomain = d; }
  template <class Cell_handle> Facet_data facet_data(Cell_handle c, int i) const { return c->info().facet_reference[i]; }
  template <class Cell_handle> void set_facet_data(Cell_handle c, int i, Facet_data d) const
  {
    c->info().facet_reference[i] = d;
  }
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
    return !tr.is_infinite(c) && c->info().subdomain != 0 && c->info().subdomain != Domain_cell_info::completion;
  }
  /// @}
};

/// Model of `MeshConstraints_3` for the triangulation of a
/// `Mesh_complex_3_in_triangulation_3` (cells model `MeshCellBase_3`, as
/// Mesh_3's and Tetrahedral_remeshing's do): a facet is constrained when it
/// is in the complex (a surface patch index is set on it), a cell is in the
/// domain when its subdomain index is set, and both follow the tetrahedra.
template <class Tr>
struct Complex_constraints
{
  /// \name Types and operations of `MeshConstraints_3` (doc/Edge_swapping_3/Concepts/MeshConstraints_3.md)
  /// @{
  typedef typename Tr::Cell Cell; ///< the triangulation's cell
  typedef std::decay_t<decltype(std::declval<const Cell&>().subdomain_index())> Cell_data;
  typedef std::decay_t<decltype(std::declval<const Cell&>().surface_patch_index(0))> Facet_data;

  template <class Cell_handle> Cell_data cell_data(Cell_handle c) const { return c->subdomain_index(); }
  template <class Cell_handle> void set_cell_data(Cell_handle c, const Cell_data& d) const { c->set_subdomain_index(d); }
  template <class Cell_handle> Facet_data facet_data(Cell_handle c, int i) const { return c->surface_patch_index(i); }
  template <class Cell_handle> void set_facet_data(Cell_handle c, int i, const Facet_data& d) const
  {
    c->set_surface_patch_index(i, d);
  }
  Facet_data free_facet_data() const { return Facet_data(); }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle c, int i) const { return c->is_facet_on_surface(i); }
  template <class Cell_handle> bool same_subdomain(Cell_handle a, Cell_handle b) const
  {
    return a->subdomain_index() == b->subdomain_index();
  }
  bool is_in_domain(const Tr& tr, typename Tr::Cell_handle c) const
  {
    return !tr.is_infinite(c) && c->subdomain_index() != Cell_data();
  }
  /// @}
};

namespace internal {

/// Stands for a map that was not given.
struct No_map {};

template <class Map, class Key>
bool map_value(const Map& map, const Key& key)
{
  if constexpr(std::is_same<Map, No_map>::value) return false;
  else return bool(get(map, key));
}

template <class Map>
constexpr bool is_writable_map()
{
  if constexpr(std::is_same<Map, No_map>::value) return false;
  else return std::is_convertible<typename boost::property_traits<Map>::category, boost::writable_property_map_tag>::value;
}

} // namespace internal

/// Model of `MeshConstraints_3` that adds, on top of `Base`, the facets that
/// `facet_is_constrained_map` marks and the cells that `cell_is_selected_map`
/// selects, as Tetrahedral_remeshing reads them: a constrained facet is never
/// removed, and only selected cells change (a flip never joins a selected
/// cell with another). A map that is not given is `internal::No_map`: no
/// facet is marked, or every cell is selected (the infinite ones too, so that
/// hull flips and insertions outside the hull stay allowed). With a cell map,
/// the infinite cells are not selected.
///
/// A cell's status is read from the maps the first time it is needed and is
/// kept from then on in a table of the model's own (a byte per cell slot,
/// shared by the model's copies), which follows the tetrahedra through flips
/// and splits. `write_back()` puts the status of every cell read or made
/// into the maps that are writable.
template <class Tr, class Base, class Cell_map = internal::No_map, class Facet_map = internal::No_map>
class Selected_constraints
{
public:
  /// \name Types and operations of `MeshConstraints_3` (doc/Edge_swapping_3/Concepts/MeshConstraints_3.md)
  /// @{
  typedef std::pair<typename Base::Cell_data, bool> Cell_data;   ///< base data, selected
  typedef std::pair<typename Base::Facet_data, bool> Facet_data; ///< base data, constrained

  /// The constraints of `base`, with the selection of `cells` and the
  /// constrained facets of `facets` on `tr` added (not read yet).
  Selected_constraints(Tr& tr, const Base& base, const Cell_map& cells, const Facet_map& facets)
    : base_(base), table_(std::make_shared<Table>(tr, cells, facets))
  {}

  template <class Cell_handle> Cell_data cell_data(Cell_handle c) const { return {base_.cell_data(c), is_selected(c)}; }
  template <class Cell_handle> void set_cell_data(Cell_handle c, const Cell_data& d) const
  {
    base_.set_cell_data(c, d.first);
    set_bit(c, selected_bit, d.second);
  }
  template <class Cell_handle> Facet_data facet_data(Cell_handle c, int i) const
  {
    return {base_.facet_data(c, i), bool(bits(c) & (1u << i))};
  }
  template <class Cell_handle> void set_facet_data(Cell_handle c, int i, const Facet_data& d) const
  {
    base_.set_facet_data(c, i, d.first);
    set_bit(c, i, d.second);
  }
  Facet_data free_facet_data() const { return {base_.free_facet_data(), false}; }
  template <class Cell_handle> bool is_facet_constrained(Cell_handle c, int i) const
  {
    return (bits(c) & (1u << i)) || base_.is_facet_constrained(c, i);
  }
  template <class Cell_handle> bool same_subdomain(Cell_handle a, Cell_handle b) const
  {
    return is_selected(a) && is_selected(b) && base_.same_subdomain(a, b);
  }
  bool is_in_domain(const Tr& tr, typename Tr::Cell_handle c) const
  {
    return is_selected(c) && base_.is_in_domain(tr, c);
  }
  /// @}

  /// Whether `c` is selected (in `cell_is_selected_map`, or made from selected cells).
  template <class Cell_handle> bool is_selected(Cell_handle c) const { return bits(c) & (1u << selected_bit); }

  /// Puts the status of the cells read or made into the writable maps.
  void write_back() const
  {
    Table& t = *table_;
    for(std::size_t k : t.known)
    {
      auto* item = t.index.item(k);
      if(item == nullptr || !(t.bits[k] & (1u << known_bit))) continue;
      const typename Tr::Cell_handle c = t.tr.tds().cells().iterator_to(*item);
      if(t.tr.is_infinite(c)) continue;
      if constexpr(internal::is_writable_map<Cell_map>()) put(t.cells, c, is_selected(c));
      if constexpr(internal::is_writable_map<Facet_map>())
        for(int i = 0; i < 4; ++i) put(t.facets, typename Tr::Facet(c, i), is_facet_constrained(c, i));
    }
  }

private:
  static constexpr int selected_bit = 4, known_bit = 5;
  typedef internal::Compact_container_index<typename Tr::Triangulation_data_structure::Cell_range> Index;
  struct Table
  {
    Table(Tr& tr, const Cell_map& cells, const Facet_map& facets)
      : tr(tr), index(tr.tds().cells()), cells(cells), facets(facets)
    {}
    Tr& tr;
    Index index;
    Cell_map cells;
    Facet_map facets;
    std::vector<std::uint8_t> bits; // by slot: four facets, selected, known
    std::vector<std::size_t> known; // the slots read or made, for write_back
  };

  // The slot of `c`, its status read from the maps on its first need. A cell
  // that is being made (`made`: its neighbours are not glued yet) is not
  // read: every setting of it follows.
  template <class Cell_handle> std::size_t slot(Cell_handle c, bool made = false) const
  {
    Table& t = *table_;
    const std::size_t k = t.index(c);
    if(k >= t.bits.size()) t.bits.resize((std::max)(t.index.number_of_slots(), k + 1), 0);
    if(made && !(t.bits[k] & (1u << known_bit)))
    {
      t.bits[k] = std::uint8_t(1u << known_bit);
      t.known.push_back(k);
    }
    else if(!(t.bits[k] & (1u << known_bit)))
    {
      // First need of this cell: its status from the maps. A facet is asked
      // from its finite sides.
      std::uint8_t b = std::uint8_t(1u << known_bit);
      const bool finite = !t.tr.is_infinite(c);
      if(std::is_same<Cell_map, internal::No_map>::value || (finite && internal::map_value(t.cells, c)))
        b |= std::uint8_t(1u << selected_bit);
      for(int i = 0; i < 4 && !std::is_same<Facet_map, internal::No_map>::value; ++i)
      {
        const auto n = c->neighbor(i);
        if((finite && internal::map_value(t.facets, typename Tr::Facet(c, i))) ||
           (!t.tr.is_infinite(n) && internal::map_value(t.facets, typename Tr::Facet(n, n->index(c)))))
          b |= std::uint8_t(1u << i);
      }
      t.bits[k] = b;
      t.known.push_back(k);
    }
    return k;
  }
  template <class Cell_handle> std::uint8_t bits(Cell_handle c) const { return table_->bits[slot(c)]; }
  template <class Cell_handle> void set_bit(Cell_handle c, int bit, bool on) const
  {
    std::uint8_t& b = table_->bits[slot(c, true)];
    b = std::uint8_t(on ? (b | (1u << bit)) : (b & ~(1u << bit)));
  }

  Base base_;
  std::shared_ptr<Table> table_;
};

namespace internal {

template <class Cell, class = void>
struct Is_complex_cell : std::false_type {};
template <class Cell>
struct Is_complex_cell<Cell, std::void_t<decltype(std::declval<const Cell&>().subdomain_index()),
                                         decltype(std::declval<const Cell&>().surface_patch_index(0))>>
  : std::true_type {};

/// The constraints a triangulation's own cells carry: a complex's indices, or none.
template <class Tr>
auto cell_constraints()
{
  if constexpr(Is_complex_cell<typename Tr::Cell>::value) return Complex_constraints<Tr>();
  else return No_constraints();
}

template <class Map>
auto map_or_none(const Map& map) { return map; }
inline No_map map_or_none(const CGAL::internal_np::Param_not_found&) { return {}; }

/// Runs `f(constraints)` with the model of `MeshConstraints_3` that `np`
/// names (see the file's comment), then writes the maps back.
template <class Tr, class NamedParameters, class F>
auto with_domain_constraints(Tr& tr, const NamedParameters& np, F f)
{
  using CGAL::parameters::get_parameter;
  typedef std::decay_t<decltype(get_parameter(np, internal_np::mesh_constraints))> Given;
  const auto cells = map_or_none(get_parameter(np, CGAL::internal_np::cell_selector));
  const auto facets = map_or_none(get_parameter(np, CGAL::internal_np::facet_is_constrained));
  typedef std::decay_t<decltype(cells)> Cells;
  typedef std::decay_t<decltype(facets)> Facets;
  constexpr bool given = !std::is_same<Given, CGAL::internal_np::Param_not_found>::value;
  constexpr bool maps = !std::is_same<Cells, No_map>::value || !std::is_same<Facets, No_map>::value;
  static_assert(!(given && maps),
                "mesh_constraints replaces facet_is_constrained_map and cell_is_selected_map: give one or the others");

  if constexpr(given)
    return f(get_parameter(np, internal_np::mesh_constraints));
  else if constexpr(!maps)
    return f(cell_constraints<Tr>());
  else
  {
    typedef decltype(cell_constraints<Tr>()) Base;
    const Selected_constraints<Tr, Base, Cells, Facets> constraints(tr, cell_constraints<Tr>(), cells, facets);
    auto result = f(constraints);
    constraints.write_back();
    return result;
  }
}

} // namespace internal

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
