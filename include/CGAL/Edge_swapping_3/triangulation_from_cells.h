// SPDX-License-Identifier: GPL-3.0-or-later
// Builds a Triangulation_3 from points and tetrahedra (a mesh read from a
// file), and says precisely what is wrong when they do not form a valid
// triangulation of the convex hull of the points.

#ifndef CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H
#define CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/open_facet_table.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

struct Vertex_pair_hash
{
  template <class Pair>
  std::size_t operator()(const Pair& p) const { return std::size_t(address_of(p.first) ^ rotate_left(address_of(p.second), 32)); }
};

/// Point index to its point (for a Hilbert sort of the indices).
template <class Point>
struct Point_of_index
{
  typedef std::uint32_t key_type;
  typedef Point value_type;
  typedef const Point& reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<Point>* points;
  friend reference get(const Point_of_index& m, std::uint32_t k) { return (*m.points)[k]; }
};

/// The tetrahedra in the Hilbert order of the points: each one comes with
/// its vertex that is first in that order (a counting sort, so the sort is
/// of the points, not of the tetrahedra, which are about 6.5 times as many).
template <class Traits, class Point>
std::vector<std::uint32_t> tetrahedra_in_hilbert_order(const std::vector<Point>& points,
                                                        const std::vector<std::array<std::size_t, 4>>& cells,
                                                        const Traits& traits, std::vector<std::uint32_t>& by_rank)
{
  std::vector<std::uint32_t> rank(points.size());
  {
    by_rank.resize(points.size());
    for(std::size_t v = 0; v < by_rank.size(); ++v) by_rank[v] = std::uint32_t(v);
    CGAL::hilbert_sort(by_rank.begin(), by_rank.end(),
                       CGAL::Spatial_sort_traits_adapter_3<Traits, Point_of_index<Point>>(Point_of_index<Point>{&points}, traits));
    for(std::size_t r = 0; r < by_rank.size(); ++r) rank[by_rank[r]] = std::uint32_t(r);
  }
  auto first_rank = [&](const std::array<std::size_t, 4>& t) {
    return (std::min)((std::min)(rank[t[0]], rank[t[1]]), (std::min)(rank[t[2]], rank[t[3]]));
  };
  std::vector<std::uint32_t> start(points.size() + 1, 0);
  for(const auto& t : cells) ++start[first_rank(t) + 1];
  for(std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
  std::vector<std::uint32_t> order(cells.size());
  for(std::size_t k = 0; k < cells.size(); ++k) order[start[first_rank(cells[k])]++] = std::uint32_t(k);
  return order;
}

/// `build_triangulation_from_cells`, in the Hilbert order of the points when
/// there are more than `hilbert_order_above` tetrahedra. When it fails only
/// because the boundary is not one closed convex surface (a domain that a
/// fill of its outside completes), `*boundary_shape` (if given) is set.
template <class Tr>
std::string build_triangulation_from_cells(Tr& tr, const std::vector<typename Tr::Point>& points,
                                           const std::vector<std::array<std::size_t, 4>>& cells,
                                           std::vector<typename Tr::Vertex_handle>& vertices,
                                           std::vector<typename Tr::Cell_handle>& cell_handles,
                                           std::size_t hilbert_order_above, bool* boundary_shape = nullptr,
                                           const Point_names& point_name = Point_names())
{
  if(boundary_shape) *boundary_shape = false;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  CGAL_precondition(tr.number_of_vertices() == 0);
  auto orientation = tr.geom_traits().orientation_3_object();
  auto cell_name = [](std::size_t k) { return "tetrahedron " + std::to_string(k); };

  std::string problem = point_set_problem(points, CGAL::parameters::geom_traits(tr.geom_traits()), point_name);
  if(!problem.empty()) return problem;
  if(cells.empty()) return "no tetrahedra";
  // The table of open facets packs indices and places in 32 bits.
  if(points.size() >= internal::Open_facet_table::limit || cells.size() >= internal::Open_facet_table::limit / 4 - 1)
    return "too many points or tetrahedra (the limit is 2^32 points and 2^30 tetrahedra)";
  // Every reader hands its cells over here: indices are checked once, first.
  for(std::size_t k = 0; k < cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      if(cells[k][i] >= points.size())
        return cell_name(k) + " names point " + point_name(cells[k][i]) + ", but there are only " +
               std::to_string(points.size()) + " points";
      for(int j = 0; j < i; ++j)
        if(cells[k][i] == cells[k][j])
          return cell_name(k) + " names point " + point_name(cells[k][i]) + " twice";
    }

  // Orientation: all one way, no flat cell.
  int sign = 0;
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    const auto& t = cells[k];
    const Orientation o = orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
    if(o == COPLANAR) return cell_name(k) + " is flat (zero volume)";
    if(sign == 0) sign = int(o);
    else if(int(o) != sign)
      return cell_name(k) + " is inverted (its orientation differs from " + cell_name(0) + ")";
  }
  // Negatively oriented input is read with its first two points exchanged
  // (no copy of the cells: they can be most of the memory).
  const bool reversed = sign < 0;

  std::vector<char> used(points.size(), 0);
  for(const auto& t : cells)
    for(auto v : t) used[v] = 1;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!used[v]) return "point " + point_name(v) + " is not a vertex of any tetrahedron";

  auto& tds = tr.tds();
  // An empty Triangulation_3 (dimension -1) holds one cell for its infinite vertex.
  std::vector<Cell_handle> initial;
  for(auto it = tds.cells().begin(); it != tds.cells().end(); ++it) initial.push_back(it);
  for(Cell_handle c : initial) tds.delete_cell(c);
  tds.set_dimension(3);
  // In the Hilbert order of the points (vertices created in it, each
  // tetrahedron with its first vertex in it), a facet's second tetrahedron
  // comes soon after its first: the table of open facets stays small and in
  // cache, and neighbours lie close in memory, whatever the order of the file.
  // Measured (benchmarks.md, Files): building 6.7 million tetrahedra, 10.7 s
  // when the tetrahedra themselves were sorted, 7.0 s now; 672,000, 0.39 s in
  // the file's order, 0.30 s in this. Small meshes keep the file's order,
  // which is then the storage order: the laboratory's cases replay in it.
  std::vector<std::uint32_t> order, points_in_order;
  if(cells.size() > hilbert_order_above) order = tetrahedra_in_hilbert_order(points, cells, tr.geom_traits(), points_in_order);
  else
  {
    order.resize(cells.size());
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
  }
  vertices.resize(points.size());
  for(std::size_t r = 0; r < points.size(); ++r)
  {
    const std::size_t v = points_in_order.empty() ? r : points_in_order[r];
    vertices[v] = tds.create_vertex();
    vertices[v]->set_point(points[v]);
  }
  auto fail = [&](const std::string& why) {
    tr.clear();
    vertices.clear();
    return why;
  };
  auto fail_by_shape = [&](const std::string& why) {
    if(boundary_shape) *boundary_shape = true;
    return fail(why);
  };

  // Glue the finite cells through their facets.
  internal::Open_facet_table open(cells.size() / 8);
  std::vector<Cell_handle>& handles = cell_handles;
  handles.clear();
  tds.cells().reserve(cells.size() + cells.size() / 4);
  handles.resize(cells.size());
  // The sorted points of the four facets of the tetrahedron at each
  // position, made once, `lookahead` positions ahead: the table is larger
  // than the cache, so its slots for them are asked for then. (Three
  // exchanges, not std::sort: that was 6% of `check` at 10^6 points.)
  typedef std::array<std::array<std::uint32_t, 3>, 4> Facet_keys;
  constexpr std::size_t lookahead = 4;
  std::array<Facet_keys, lookahead + 1> keys_ahead;
  auto make_keys = [&](std::size_t position, Facet_keys& keys) {
    std::array<std::size_t, 4> t = cells[order[position]];
    if(reversed) std::swap(t[0], t[1]);
    for(int i = 0; i < 4; ++i)
    {
      std::uint32_t a = std::uint32_t(t[(i + 1) & 3]), b = std::uint32_t(t[(i + 2) & 3]), d = std::uint32_t(t[(i + 3) & 3]);
      if(b < a) std::swap(a, b);
      if(d < b) std::swap(b, d);
      if(b < a) std::swap(a, b);
      keys[i] = {a, b, d};
    }
  };
  for(std::size_t position = 0; position < (std::min)(lookahead, order.size()); ++position)
    make_keys(position, keys_ahead[position % (lookahead + 1)]);
  for(std::size_t position = 0; position < order.size(); ++position)
  {
    if(position + lookahead < order.size())
    {
      Facet_keys& ahead = keys_ahead[(position + lookahead) % (lookahead + 1)];
      make_keys(position + lookahead, ahead);
      for(const auto& key : ahead) open.prefetch(key[0], key[1], key[2]);
    }
    const Facet_keys& keys = keys_ahead[position % (lookahead + 1)];
    const std::size_t k = order[position];
    std::array<std::size_t, 4> t = cells[k];
    if(reversed) std::swap(t[0], t[1]);
    Cell_handle c = tds.create_cell(vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[t[3]]);
    handles[k] = c;
    for(int i = 0; i < 4; ++i)
    {
      c->vertex(i)->set_cell(c);
      const auto& key = keys[i];
      // Glued facets leave the table; a facet of three or more tetrahedra is
      // found below, by the open facets it leaves inside.
      const std::int64_t first = open.close_or_open(key[0], key[1], key[2], std::uint32_t(4 * k + i));
      if(first < 0) continue;
      const Cell_handle d = handles[std::size_t(first) / 4];
      const int j = int(first % 4);
      if(c->vertex(i) == d->vertex(j))
        return fail(cell_name(k) + " is a repeated tetrahedron");
      // Positive neighbours lie on opposite sides of their common facet.
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = d->vertex(j);
      if(orientation(u[0]->point(), u[1]->point(), u[2]->point(), u[3]->point()) != NEGATIVE)
        return fail(cell_name(k) + " overlaps a neighbour across facet " + point_name(key[0]) + " " +
                    point_name(key[1]) + " " + point_name(key[2]));
      c->set_neighbor(i, d);
      d->set_neighbor(j, c);
    }
  }

  // One infinite cell outside each boundary facet, then glue those together.
  const Vertex_handle inf = tr.infinite_vertex();
  std::vector<Cell_handle> outside_cells; // the checks below read these, not every cell
  internal::Flat_hash_map<std::pair<Vertex_handle, Vertex_handle>, std::pair<Cell_handle, int>, internal::Vertex_pair_hash> ridges;
  for(Cell_handle c : handles)
    for(int i = 0; i < 4; ++i)
    {
      if(c->neighbor(i) != Cell_handle()) continue;
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = inf;
      std::swap(u[(i + 1) & 3], u[(i + 2) & 3]); // the infinite vertex lies on the other side
      Cell_handle o = tds.create_cell(u[0], u[1], u[2], u[3]);
      outside_cells.push_back(o);
      inf->set_cell(o);
      o->set_neighbor(i, c);
      c->set_neighbor(i, o);
      for(int m = 0; m < 4; ++m)
      {
        if(m == i) continue;
        // The ridge of this infinite facet: its two finite vertices.
        Vertex_handle p, q;
        for(int r = 0; r < 4; ++r)
          if(r != m && r != i) (p == Vertex_handle() ? p : q) = o->vertex(r);
        if(internal::address_of(q) < internal::address_of(p)) std::swap(p, q);
        const auto slot = ridges.emplace(std::make_pair(p, q), std::make_pair(o, m));
        if(slot.second) continue;
        if(slot.first->first == Cell_handle())
          return fail_by_shape("the boundary is not a closed surface: an edge lies on more than two boundary facets");
        o->set_neighbor(m, slot.first->first);
        slot.first->first->set_neighbor(slot.first->second, o);
        slot.first->first = Cell_handle();
      }
    }
  bool open_ridge = false;
  ridges.for_each([&](const auto&, const std::pair<Cell_handle, int>& r) { open_ridge = open_ridge || r.first != Cell_handle(); });
  if(open_ridge) return fail_by_shape("the boundary is not a closed surface: an edge lies on a single boundary facet");

  // One boundary surface. With every tetrahedron positive and every shared
  // facet between tetrahedra on its two sides, the tetrahedra cover each
  // point a constant number of times; a closed, connected, locally convex
  // boundary is the hull once, so that number is one and nothing overlaps.
  // A facet of three or more tetrahedra, or a second sheet, leaves facets
  // open inside: they close up into a second surface (or fail the ridges).
  {
    const std::size_t outside = outside_cells.size();
    std::vector<Cell_handle> stack = {inf->cell()};
    internal::Flat_hash_set<Cell_handle, internal::Handle_hash> seen;
    seen.insert(inf->cell());
    while(!stack.empty())
    {
      const Cell_handle c = stack.back();
      stack.pop_back();
      for(int m = 0; m < 4; ++m)
      {
        const Cell_handle d = c->neighbor(m);
        if(d->has_vertex(inf) && seen.insert(d)) stack.push_back(d);
      }
    }
    if(seen.size() != outside)
      return fail_by_shape("the boundary is more than one surface: a facet is shared by more than two "
                           "tetrahedra, or tetrahedra overlap");
  }

  // Convex boundary: no vertex beyond the hull facet next to it.
  for(Cell_handle c : outside_cells)
  {
    const int i = c->index(inf);
    for(int m = 0; m < 4; ++m)
    {
      if(m == i) continue;
      const Vertex_handle w = c->neighbor(m)->vertex(c->neighbor(m)->index(c));
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = w;
      if(orientation(u[0]->point(), u[1]->point(), u[2]->point(), u[3]->point()) == POSITIVE)
        return fail_by_shape("the mesh does not cover the convex hull of its points: its boundary is not convex");
    }
  }
  return std::string();
}

} // namespace internal

/// Makes the empty `tr` the triangulation with the given points and
/// tetrahedra (0-based indices). Accepts every tetrahedron positively
/// oriented, or every one negatively oriented (then all are reversed).
/// Returns an empty string on success; otherwise the problem (a point index
/// out of range or repeated in a tetrahedron, flat or
/// inverted tetrahedron, a facet shared by three tetrahedra, overlapping
/// neighbours, unused point, boundary not one closed convex surface), and
/// `tr` is left empty. `vertices` receives the vertex of each point, and
/// `cell_handles` the cell of each tetrahedron.
/// Facets are glued through a hash table of their sorted point indices (a
/// facet leaves the table when its second tetrahedron comes), so the time is linear.
/// Above 100,000 tetrahedra, the vertices and cells are stored in the
/// Hilbert order of the points; up to that, in the order given.
template <class Tr>
std::string build_triangulation_from_cells(Tr& tr, const std::vector<typename Tr::Point>& points,
                                           const std::vector<std::array<std::size_t, 4>>& cells,
                                           std::vector<typename Tr::Vertex_handle>& vertices,
                                           std::vector<typename Tr::Cell_handle>& cell_handles)
{
  return internal::build_triangulation_from_cells(tr, points, cells, vertices, cell_handles, 100000);
}

/// As above, without the cells of the tetrahedra.
template <class Tr>
std::string build_triangulation_from_cells(Tr& tr, const std::vector<typename Tr::Point>& points,
                                           const std::vector<std::array<std::size_t, 4>>& cells,
                                           std::vector<typename Tr::Vertex_handle>& vertices)
{
  std::vector<typename Tr::Cell_handle> cell_handles;
  return build_triangulation_from_cells(tr, points, cells, vertices, cell_handles);
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H
