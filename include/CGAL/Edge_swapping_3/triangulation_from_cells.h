// Builds a Triangulation_3 from points and tetrahedra (a mesh read from a
// file), and says precisely what is wrong when they do not form a valid
// triangulation of the convex hull of the points.

#ifndef CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H
#define CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H

#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// Makes the empty `tr` the triangulation with the given points and
/// tetrahedra (0-based indices). Accepts every tetrahedron positively
/// oriented, or every one negatively oriented (then all are reversed).
/// Returns an empty string on success; otherwise the problem (a point index
/// out of range or repeated in a tetrahedron, flat or
/// inverted tetrahedron, a facet shared by three tetrahedra, overlapping
/// neighbours, unused point, boundary not a closed convex surface), and
/// `tr` is left empty. `vertices` receives the vertex of each point.
template <class Tr>
std::string build_triangulation_from_cells(Tr& tr, const std::vector<typename Tr::Point>& points,
                                           std::vector<std::array<std::size_t, 4>> cells,
                                           std::vector<typename Tr::Vertex_handle>& vertices)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<std::size_t, 3> Key;
  CGAL_precondition(tr.number_of_vertices() == 0);
  auto orientation = tr.geom_traits().orientation_3_object();
  auto cell_name = [](std::size_t k) { return "tetrahedron " + std::to_string(k); };

  std::string problem = point_set_problem(points, tr.geom_traits());
  if(!problem.empty()) return problem;
  if(cells.empty()) return "no tetrahedra";
  // Every reader hands its cells over here: indices are checked once, first.
  for(std::size_t k = 0; k < cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      if(cells[k][i] >= points.size())
        return cell_name(k) + " names point " + std::to_string(cells[k][i]) + ", but there are only " +
               std::to_string(points.size()) + " points";
      for(int j = 0; j < i; ++j)
        if(cells[k][i] == cells[k][j])
          return cell_name(k) + " names point " + std::to_string(cells[k][i]) + " twice";
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
  if(sign < 0)
    for(auto& t : cells) std::swap(t[0], t[1]);

  std::vector<char> used(points.size(), 0);
  for(const auto& t : cells)
    for(auto v : t) used[v] = 1;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!used[v]) return "point " + std::to_string(v) + " is not a vertex of any tetrahedron";

  auto& tds = tr.tds();
  // An empty Triangulation_3 (dimension -1) holds one cell for its infinite vertex.
  std::vector<Cell_handle> initial;
  for(auto it = tds.cells().begin(); it != tds.cells().end(); ++it) initial.push_back(it);
  for(Cell_handle c : initial) tds.delete_cell(c);
  tds.set_dimension(3);
  vertices.resize(points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    vertices[v] = tds.create_vertex();
    vertices[v]->set_point(points[v]);
  }
  auto fail = [&](const std::string& why) {
    tr.clear();
    vertices.clear();
    return why;
  };

  // Glue the finite cells through their facets.
  std::map<Key, std::pair<Cell_handle, int>> open; // facets seen once
  std::vector<Cell_handle> handles;
  handles.reserve(cells.size());
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    const auto& t = cells[k];
    Cell_handle c = tds.create_cell(vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[t[3]]);
    handles.push_back(c);
    for(int i = 0; i < 4; ++i)
    {
      c->vertex(i)->set_cell(c);
      Key key = {t[(i + 1) & 3], t[(i + 2) & 3], t[(i + 3) & 3]};
      std::sort(key.begin(), key.end());
      auto it = open.find(key);
      if(it == open.end()) { open.emplace(key, std::make_pair(c, i)); continue; }
      Cell_handle d = it->second.first;
      const int j = it->second.second;
      if(d->neighbor(j) != Cell_handle())
        return fail("facet " + std::to_string(key[0]) + " " + std::to_string(key[1]) + " " +
                    std::to_string(key[2]) + " is shared by more than two tetrahedra (non-conforming)");
      if(c->vertex(i) == d->vertex(j))
        return fail(cell_name(k) + " is a repeated tetrahedron");
      // Positive neighbours lie on opposite sides of their common facet.
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = d->vertex(j);
      if(orientation(u[0]->point(), u[1]->point(), u[2]->point(), u[3]->point()) != NEGATIVE)
        return fail(cell_name(k) + " overlaps a neighbour across facet " + std::to_string(key[0]) + " " +
                    std::to_string(key[1]) + " " + std::to_string(key[2]));
      c->set_neighbor(i, d);
      d->set_neighbor(j, c);
    }
  }

  // One infinite cell outside each boundary facet, then glue those together.
  const Vertex_handle inf = tr.infinite_vertex();
  std::map<std::pair<Vertex_handle, Vertex_handle>, std::pair<Cell_handle, int>> ridges;
  for(Cell_handle c : handles)
    for(int i = 0; i < 4; ++i)
    {
      if(c->neighbor(i) != Cell_handle()) continue;
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = inf;
      std::swap(u[(i + 1) & 3], u[(i + 2) & 3]); // the infinite vertex lies on the other side
      Cell_handle o = tds.create_cell(u[0], u[1], u[2], u[3]);
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
        auto key = std::minmax(p, q);
        auto it = ridges.find(key);
        if(it == ridges.end()) { ridges.emplace(key, std::make_pair(o, m)); continue; }
        if(it->second.first == Cell_handle())
          return fail("the boundary is not a closed surface: an edge lies on more than two boundary facets");
        o->set_neighbor(m, it->second.first);
        it->second.first->set_neighbor(it->second.second, o);
        it->second.first = Cell_handle();
      }
    }
  for(const auto& r : ridges)
    if(r.second.first != Cell_handle())
      return fail("the boundary is not a closed surface: an edge lies on a single boundary facet");

  // Convex boundary: no vertex beyond the hull facet next to it.
  for(auto c : tr.all_cell_handles())
  {
    int i;
    if(!c->has_vertex(inf, i)) continue;
    for(int m = 0; m < 4; ++m)
    {
      if(m == i) continue;
      const Vertex_handle w = c->neighbor(m)->vertex(c->neighbor(m)->index(c));
      std::array<Vertex_handle, 4> u = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
      u[i] = w;
      if(orientation(u[0]->point(), u[1]->point(), u[2]->point(), u[3]->point()) == POSITIVE)
        return fail("the mesh does not cover the convex hull of its points: its boundary is not convex");
    }
  }
  if(!tr.is_valid(false))
    return fail("the tetrahedra do not form a valid triangulation");
  return std::string();
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TRIANGULATION_FROM_CELLS_H
