// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the program's input (TetGen .node/.ele, Medit .mesh, VTK .vtu) and
// adding its mesh outputs to the files written all or nothing.

#ifndef EDGE_SWAP_MESH_FILES_H
#define EDGE_SWAP_MESH_FILES_H

#include "output_files.h"
#include "types.h"
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/IO/vtu.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace edge_swap {

namespace IO = CGAL::Edge_swapping_3::IO;
namespace ES = CGAL::Edge_swapping_3;

inline bool ends_with(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

inline std::string stem(const std::string& path) { return path.substr(0, path.rfind('.')); }

/// What an input holds: points with named fields and, for a mesh, tetrahedra
/// (with subdomain references and boundary triangles for Medit files).
/// Points inserted by the program are appended, so `points` and `fields`
/// describe the current mesh, numbered by the vertices' `info()`.
struct Input
{
  std::vector<Point> points;
  std::vector<std::string> field_names;
  std::vector<std::vector<double>> fields; ///< fields[f][point]
  int first_index = 1;                     ///< of TetGen files
  std::vector<std::array<std::size_t, 4>> cells;
  std::vector<int> cell_references;        ///< empty: every cell in subdomain 1
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<int> triangle_references;
  bool is_mesh = false;
  bool has_references = false;             ///< Medit input: constraints apply

  int field_index(const std::string& name) const
  {
    const auto it = std::find(field_names.begin(), field_names.end(), name);
    return it == field_names.end() ? -1 : int(it - field_names.begin());
  }
};

/// The largest field value supported: differences, interpolations and the
/// gradient indicator of such values stay finite.
constexpr double max_field_value = 1e100;

/// The input in `text`, the content of the file `path` (its extension says
/// the format); for an .ele file, `node_text` is the content of the .node
/// beside it. Throws IO::Input_error or Usage_error naming the file.
inline Input input_from_text(const std::string& path, std::string_view text, std::string_view node_text = {})
{
  Input in;
  std::vector<std::array<double, 3>> coordinates;
  if(ends_with(path, ".node") || ends_with(path, ".ele"))
  {
    const bool ele = ends_with(path, ".ele");
    IO::Node_file node = ele ? IO::read_node_text(stem(path) + ".node", node_text) : IO::read_node_text(path, text);
    coordinates = node.points;
    in.first_index = node.first_index;
    const std::size_t n_attr = node.attributes.empty() ? 0 : node.attributes.front().size();
    for(std::size_t a = 0; a < n_attr; ++a)
    {
      in.field_names.push_back("attribute" + std::to_string(a + 1));
      in.fields.emplace_back();
      for(const auto& values : node.attributes) in.fields.back().push_back(values[a]);
    }
    if(ele)
    {
      in.cells = IO::read_ele_text(path, text, coordinates.size(), node.first_index);
      in.is_mesh = true;
    }
  }
  else if(ends_with(path, ".mesh"))
  {
    IO::Medit_mesh m = IO::read_medit_text(path, text);
    coordinates = m.points;
    in.cells = m.tetrahedra;
    in.cell_references = m.tetrahedron_references;
    in.triangles = m.triangles;
    in.triangle_references = m.triangle_references;
    in.is_mesh = in.has_references = true;
    if(in.cells.empty()) throw IO::Input_error(path + ": no Tetrahedra");
  }
  else if(ends_with(path, ".vtu"))
  {
    IO::Vtu_mesh m = IO::read_vtu_text(path, text);
    coordinates = m.points;
    in.cells = m.tetrahedra;
    in.is_mesh = !in.cells.empty();
    for(auto& [name, values] : m.point_fields)
    {
      in.field_names.push_back(name);
      in.fields.push_back(std::move(values));
    }
    for(const auto& [name, values] : m.cell_fields)
      if(name == "subdomain")
      {
        in.has_references = true;
        for(std::size_t k = 0; k < values.size(); ++k)
        {
          const double v = values[k];
          if(!(v == std::floor(v) && std::abs(v) <= 1e9))
            throw IO::Input_error(path + ": cell field 'subdomain': the value of cell " + std::to_string(k) +
                                  " is not a whole number of at most 1e9 in magnitude");
          in.cell_references.push_back(int(v));
        }
      }
  }
  else
    throw Usage_error("input '" + path + "' is not a .node, .ele, .mesh or .vtu file");
  for(std::size_t f = 0; f < in.fields.size(); ++f)
    for(std::size_t k = 0; k < in.fields[f].size(); ++k)
      if(!(std::abs(in.fields[f][k]) <= max_field_value))
        throw IO::Input_error(path + ": field '" + in.field_names[f] + "' at point " + std::to_string(k) +
                              " is larger than 1e100 in magnitude, the largest field value supported");
  for(const auto& p : coordinates) in.points.emplace_back(p[0], p[1], p[2]);
  return in;
}

/// Reads the input file `path` (and the .node beside an .ele).
inline Input read_input(const std::string& path)
{
  if(!ends_with(path, ".node") && !ends_with(path, ".ele") && !ends_with(path, ".mesh") && !ends_with(path, ".vtu"))
    throw Usage_error("input '" + path + "' is not a .node, .ele, .mesh or .vtu file");
  if(ends_with(path, ".ele"))
  {
    const std::string node_text = IO::read_text_file(stem(path) + ".node");
    return input_from_text(path, IO::read_text_file(path), node_text);
  }
  return input_from_text(path, IO::read_text_file(path));
}

/// Throws IO::Input_error unless the points can be triangulated in 3-D.
inline void require_valid_point_set(const Input& in, const std::string& path)
{
  const std::string problem = ES::point_set_problem(in.points);
  if(!problem.empty()) throw IO::Input_error(path + ": " + problem);
}

/// Builds the mesh of a mesh input, with subdomains and constrained facets;
/// an empty string, or what is wrong with it.
inline std::string build_mesh(Triangulation& tr, const Input& in)
{
  std::vector<Triangulation::Vertex_handle> vertices;
  std::vector<Triangulation::Cell_handle> cells;
  const std::string problem = ES::build_triangulation_from_cells(tr, in.points, in.cells, vertices, cells);
  if(!problem.empty()) return problem;
  for(std::size_t k = 0; k < vertices.size(); ++k) vertices[k]->info() = k;
  for(auto c : tr.all_cell_handles())
  {
    c->info() = ES::Domain_cell_info();
    if(tr.is_infinite(c)) c->info().subdomain = 0;
  }
  // The cells come in the order of the tetrahedra read.
  for(std::size_t k = 0; k < cells.size(); ++k)
    cells[k]->info().subdomain = in.cell_references.empty() ? 1 : in.cell_references[k];
  for(std::size_t k = 0; k < in.triangles.size(); ++k)
  {
    const auto& t = in.triangles[k];
    Triangulation::Cell_handle c;
    int i, j, l;
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
       !tr.is_facet(vertices[t[0]], vertices[t[1]], vertices[t[2]], c, i, j, l))
      return "triangle " + std::to_string(k + 1) + " is not a facet of the tetrahedra";
    const int f = 6 - i - j - l;
    c->info().facet_reference[f] = in.triangle_references[k];
    c->neighbor(f)->info().facet_reference[c->neighbor(f)->index(c)] = in.triangle_references[k];
  }
  return {};
}

/// A point set's triangulation: every finite cell in subdomain 1, no constraint.
inline void mark_point_set_domain(Triangulation& tr)
{
  for(auto c : tr.all_cell_handles())
  {
    c->info() = ES::Domain_cell_info();
    c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
  }
}

/// Calls `run(constraints)`: `Domain_constraints` for an input with
/// references (subdomains, boundary triangles), else `No_constraints`.
template <class Run>
auto with_constraints(const Input& in, Run run)
{
  if(in.has_references) return run(ES::Domain_constraints());
  return run(ES::No_constraints());
}

/// Gives a new vertex its number and its field values.
inline void add_vertex(Input& in, Triangulation::Vertex_handle v, const std::vector<double>& values)
{
  v->info() = in.points.size();
  in.points.push_back(v->point());
  for(std::size_t f = 0; f < in.fields.size(); ++f) in.fields[f].push_back(values[f]);
}

/// Whether `path` names an output format the program writes.
inline void require_output_format(const std::string& path)
{
  if(!ends_with(path, ".ele") && !ends_with(path, ".mesh") && !ends_with(path, ".vtu"))
    throw Usage_error("output '" + path + "' is not an .ele, .mesh or .vtu file");
}

/// The files a mesh output `path` writes: Y.ele comes with Y.node.
inline std::vector<std::string> mesh_output_paths(const std::string& path)
{
  require_output_format(path);
  if(ends_with(path, ".ele")) return {path, stem(path) + ".node"};
  return {path};
}

/// Adds the files of the output `path`: Y.ele with Y.node (fields as
/// attributes), Y.mesh (Medit: subdomains, constrained facets), or Y.vtu
/// (ParaView: fields per vertex; subdomain and quality per cell).
inline void add_mesh_files(Output_files& files, const std::string& path, const Triangulation& tr, const Input& in)
{
  require_output_format(path);
  auto coordinates = std::make_shared<std::vector<std::array<double, 3>>>();
  for(const auto& p : in.points) coordinates->push_back({p.x(), p.y(), p.z()});
  // Where the points are now: smoothing moves interior ones.
  for(auto v : tr.finite_vertex_handles())
    if(v->info() < coordinates->size())
      (*coordinates)[v->info()] = {v->point().x(), v->point().y(), v->point().z()};
  auto cells = std::make_shared<std::vector<std::array<std::size_t, 4>>>();
  std::vector<int> subdomain;
  cells->reserve(tr.number_of_finite_cells());
  for(auto c : tr.finite_cell_handles())
  {
    cells->push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    // A point set or TetGen mesh has no subdomains: all of it is subdomain 1.
    subdomain.push_back(in.has_references ? c->info().subdomain : 1);
  }

  if(ends_with(path, ".ele"))
  {
    auto attributes = std::make_shared<std::vector<std::vector<double>>>(in.points.size());
    for(std::size_t k = 0; k < in.points.size(); ++k)
      for(const auto& f : in.fields) (*attributes)[k].push_back(f[k]);
    const int first = in.first_index;
    files.add(stem(path) + ".node", [coordinates, attributes, first](std::ostream& out) {
      IO::write_node_file(out, *coordinates, *attributes, first);
    });
    files.add(path, [cells, first](std::ostream& out) { IO::write_ele_file(out, *cells, first); });
  }
  else if(ends_with(path, ".mesh"))
  {
    auto m = std::make_shared<IO::Medit_mesh>();
    m->points = *coordinates;
    m->tetrahedra = *cells;
    m->tetrahedron_references = subdomain;
    // Each constrained facet once, seen from the cell whose sorted vertex
    // numbers come first (or from the finite side): independent of addresses.
    auto key = [&](Triangulation::Cell_handle c) {
      std::array<std::size_t, 4> k;
      for(int i = 0; i < 4; ++i) k[i] = tr.is_infinite(c->vertex(i)) ? std::size_t(-1) : c->vertex(i)->info();
      std::sort(k.begin(), k.end());
      return k;
    };
    for(auto c : tr.finite_cell_handles())
      for(int i = 0; i < 4; ++i)
      {
        if(c->info().facet_reference[i] == ES::Domain_cell_info::no_reference) continue;
        const auto n = c->neighbor(i);
        if(!tr.is_infinite(n) && !(key(c) < key(n))) continue;
        m->triangles.push_back({c->vertex((i + 1) & 3)->info(), c->vertex((i + 2) & 3)->info(), c->vertex((i + 3) & 3)->info()});
        m->triangle_references.push_back(c->info().facet_reference[i]);
      }
    files.add(path, [m](std::ostream& out) { IO::write_medit_file(out, *m); });
  }
  else
  {
    auto point_fields = std::make_shared<IO::Named_fields>();
    for(std::size_t f = 0; f < in.fields.size(); ++f) point_fields->emplace_back(in.field_names[f], in.fields[f]);
    auto cell_fields = std::make_shared<IO::Named_fields>();
    cell_fields->emplace_back("subdomain", std::vector<double>(subdomain.begin(), subdomain.end()));
    std::vector<double> edge_ratio, radius_ratio, min_angle, max_angle;
    for(auto c : tr.finite_cell_handles())
    {
      const auto& a = c->vertex(0)->point(); const auto& b = c->vertex(1)->point();
      const auto& d = c->vertex(2)->point(); const auto& e = c->vertex(3)->point();
      edge_ratio.push_back(ES::edge_length_ratio(a, b, d, e));
      radius_ratio.push_back(ES::radius_ratio(a, b, d, e));
      const auto angles = ES::dihedral_angles(a, b, d, e);
      min_angle.push_back(*std::min_element(angles.begin(), angles.end()));
      max_angle.push_back(*std::max_element(angles.begin(), angles.end()));
    }
    cell_fields->emplace_back("edge_length_ratio", edge_ratio);
    cell_fields->emplace_back("radius_ratio", radius_ratio);
    cell_fields->emplace_back("min_dihedral_angle", min_angle);
    cell_fields->emplace_back("max_dihedral_angle", max_angle);
    files.add(path, [coordinates, cells, point_fields, cell_fields](std::ostream& out) {
      IO::write_vtu_file(out, *coordinates, *cells, *point_fields, *cell_fields);
    });
  }
}

} // namespace edge_swap

#endif
