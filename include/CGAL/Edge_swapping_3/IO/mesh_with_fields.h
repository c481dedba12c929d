// SPDX-License-Identifier: GPL-3.0-or-later
// A `Mesh_with_fields` read from and written to the formats the package
// knows, chosen by the file's extension: TetGen .node (a point set) and .ele
// (a mesh, with the .node beside it), Medit .mesh and Gmsh .msh (subdomains
// and boundary triangles) and VTK .vtu (point and cell fields).

#ifndef CGAL_EDGE_SWAPPING_3_IO_MESH_WITH_FIELDS_H
#define CGAL_EDGE_SWAPPING_3_IO_MESH_WITH_FIELDS_H

#include <CGAL/Edge_swapping_3/IO/gmsh.h>
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/vtu.h>
#include <CGAL/Edge_swapping_3/Mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// Whether `path` ends with `end`.
inline bool has_extension(const std::string& path, const std::string& end)
{
  return path.size() >= end.size() && path.compare(path.size() - end.size(), end.size(), end) == 0;
}

/// \ingroup PkgEdgeSwapping3IO
/// `path` without its extension.
inline std::string path_stem(const std::string& path) { return path.substr(0, path.rfind('.')); }

namespace internal {

/// Drops the triangles with a point that no tetrahedron has: those of a
/// surface meshed alone, bounding no volume (Gmsh writes them), which are not
/// part of the volume mesh.
template <class Point>
void drop_triangles_off_the_tetrahedra(Mesh_with_fields<Point>& m, std::size_t points)
{
  std::vector<char> used(points, 0);
  for(const auto& t : m.cells)
    for(auto v : t)
      if(v < points) used[v] = 1;
  std::size_t kept = 0;
  for(std::size_t k = 0; k < m.triangles.size(); ++k)
  {
    const auto& t = m.triangles[k];
    if(!(t[0] < points && t[1] < points && t[2] < points && used[t[0]] && used[t[1]] && used[t[2]])) continue;
    m.triangles[kept] = t;
    m.triangle_references[kept++] = m.triangle_references[k];
  }
  m.triangles.resize(kept);
  m.triangle_references.resize(kept);
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3IO
/// The mesh or point set in `text`, the content of the file `path` (its
/// extension says the format); for an `.ele` file, `node_text` is the content
/// of the `.node` beside it. Throws `Input_error` naming the file (and line)
/// for bad content, `std::invalid_argument` for an unknown extension.
template <class Point>
Mesh_with_fields<Point> mesh_with_fields_from_text(const std::string& path, std::string_view text,
                                                   std::string_view node_text = {})
{
  Mesh_with_fields<Point> in;
  std::vector<std::array<double, 3>> coordinates;
  if(has_extension(path, ".node") || has_extension(path, ".ele"))
  {
    const bool ele = has_extension(path, ".ele");
    Node_file node = ele ? read_node_text(path_stem(path) + ".node", node_text) : read_node_text(path, text);
    coordinates = std::move(node.points);
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
      in.cells = read_ele_text(path, text, coordinates.size(), node.first_index, &in.cell_references);
      in.is_mesh = true;
      in.has_references = !in.cell_references.empty();
    }
  }
  else if(has_extension(path, ".mesh") || has_extension(path, ".msh"))
  {
    // Medit and Gmsh files: tetrahedra and triangles with their references.
    auto take = [&](auto&& m, const char* no_tetrahedra) {
      coordinates = std::move(m.points);
      in.cells = std::move(m.tetrahedra);
      in.cell_references = std::move(m.tetrahedron_references);
      in.triangles = std::move(m.triangles);
      in.triangle_references = std::move(m.triangle_references);
      in.is_mesh = in.has_references = true;
      if(in.cells.empty()) throw Input_error(path + ": " + no_tetrahedra);
      internal::drop_triangles_off_the_tetrahedra(in, coordinates.size());
    };
    if(has_extension(path, ".mesh")) take(read_medit_text(path, text), "no Tetrahedra");
    else
    {
      Gmsh_mesh m = read_gmsh_text(path, text);
      in.point_tags = std::move(m.point_tags);
      take(std::move(m), "no linear tetrahedra (element type 4)");
    }
  }
  else if(has_extension(path, ".vtu"))
  {
    Vtu_mesh m = read_vtu_text(path, text);
    coordinates = std::move(m.points);
    in.cells = std::move(m.tetrahedra);
    in.is_mesh = !in.cells.empty();
    for(auto& [name, values] : m.point_fields)
    {
      in.field_names.push_back(name);
      in.fields.push_back(std::move(values));
    }
    // Only the subdomains are read back; the quality fields describe the mesh that was written.
    for(const auto& [name, values] : m.cell_fields)
      if(name == "subdomain")
      {
        in.has_references = true;
        for(std::size_t k = 0; k < values.size(); ++k)
        {
          const double v = values[k];
          if(!(v == std::floor(v) && std::abs(v) <= 1e9))
            throw Input_error(path + ": cell field 'subdomain': the value of cell " + std::to_string(k) +
                              " is not a whole number of at most 1e9 in magnitude");
          in.cell_references.push_back(int(v));
        }
      }
  }
  else
    throw std::invalid_argument("input '" + path + "' is not a .node, .ele, .mesh, .msh or .vtu file");
  for(std::size_t f = 0; f < in.fields.size(); ++f)
    for(std::size_t k = 0; k < in.fields[f].size(); ++k)
      if(!(std::abs(in.fields[f][k]) <= max_field_value))
        throw Input_error(path + ": field '" + in.field_names[f] + "' at point " + std::to_string(k) +
                          " is larger than 1e100 in magnitude, the largest field value supported");
  in.points.reserve(coordinates.size());
  for(const auto& p : coordinates) in.points.emplace_back(p[0], p[1], p[2]);
  return in;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads the file `path` (and the `.node` beside an `.ele`); see `mesh_with_fields_from_text()`.
template <class Point>
Mesh_with_fields<Point> read_mesh_with_fields(const std::string& path)
{
  if(!has_extension(path, ".node") && !has_extension(path, ".ele") && !has_extension(path, ".mesh") &&
     !has_extension(path, ".msh") && !has_extension(path, ".vtu"))
    throw std::invalid_argument("input '" + path + "' is not a .node, .ele, .mesh, .msh or .vtu file");
  if(has_extension(path, ".ele"))
  {
    const std::string node_text = read_text_file(path_stem(path) + ".node");
    return mesh_with_fields_from_text<Point>(path, read_text_file(path), node_text);
  }
  return mesh_with_fields_from_text<Point>(path, read_text_file(path));
}

/// \ingroup PkgEdgeSwapping3IO
/// The files that writing a mesh to `path` makes: `Y.ele` comes with `Y.node`.
/// Throws `std::invalid_argument` unless `path` is an `.ele`, `.mesh`, `.msh` or `.vtu` file.
inline std::vector<std::string> mesh_file_paths(const std::string& path)
{
  if(has_extension(path, ".ele")) return {path, path_stem(path) + ".node"};
  if(has_extension(path, ".mesh") || has_extension(path, ".msh") || has_extension(path, ".vtu")) return {path};
  throw std::invalid_argument("output '" + path + "' is not an .ele, .mesh, .msh or .vtu file");
}

/// \ingroup PkgEdgeSwapping3IO
/// How `write_mesh_with_fields()` encodes the formats that have choices.
struct Mesh_file_options
{
  Gmsh_format msh = MSH_4_1_ASCII; ///< `.msh`: version and encoding
  Vtu_encoding vtu = VTU_ASCII;    ///< `.vtu`: ASCII or binary (zlib)
};

/// \ingroup PkgEdgeSwapping3IO
/// Writes `mesh` in the format of `path`: for each file of
/// `mesh_file_paths(path)`, calls `add_file(file, writer)`, where `writer` is
/// a `std::function<void(std::ostream&)>` that writes the file's content
/// (and throws for a value that is not finite). So a caller chooses how the
/// files are opened (all or nothing, in memory). `Y.ele` with `Y.node`
/// (point fields as attributes), `Y.mesh` (Medit: subdomains, boundary
/// triangles), `Y.msh` (Gmsh: the same as physical tags, node tags kept;
/// version and encoding from `options`) or `Y.vtu` (point fields and cell fields).
/// \param path the file to write; its extension chooses the format
/// \param mesh the mesh (for example `numbered_mesh_snapshot()` of a triangulation)
/// \param add_file a callable `void(const std::string&, std::function<void(std::ostream&)>)`
/// \param options the encoding of the formats that have choices
template <class Point, class Add_file>
void write_mesh_with_fields(const std::string& path, Mesh_with_fields<Point> mesh, Add_file add_file,
                            const Mesh_file_options& options = Mesh_file_options())
{
  mesh_file_paths(path); // throws for an unknown format
  auto m = std::make_shared<const Mesh_with_fields<Point>>(std::move(mesh));
  auto coordinates = [m]() {
    std::vector<std::array<double, 3>> c;
    c.reserve(m->points.size());
    for(const auto& p : m->points) c.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    return c;
  };
  if(has_extension(path, ".ele"))
  {
    add_file(path_stem(path) + ".node", std::function<void(std::ostream&)>([m, coordinates](std::ostream& out) {
               std::vector<std::vector<double>> attributes(m->points.size());
               for(std::size_t k = 0; k < m->points.size(); ++k)
                 for(const auto& f : m->fields) attributes[k].push_back(f[k]);
               write_node_file(out, coordinates(), attributes, m->first_index);
             }));
    add_file(path, std::function<void(std::ostream&)>(
                       [m](std::ostream& out) {
                         write_ele_file(out, m->cells, m->first_index,
                                        m->has_references ? &m->cell_references : nullptr);
                       }));
  }
  else if(has_extension(path, ".mesh"))
    add_file(path, std::function<void(std::ostream&)>([m, coordinates](std::ostream& out) {
               Medit_mesh medit;
               medit.points = coordinates();
               medit.tetrahedra = m->cells;
               medit.tetrahedron_references = m->cell_references;
               if(medit.tetrahedron_references.empty()) medit.tetrahedron_references.assign(m->cells.size(), 1);
               medit.triangles = m->triangles;
               medit.triangle_references = m->triangle_references;
               write_medit_file(out, medit);
             }));
  else if(has_extension(path, ".msh"))
    add_file(path, std::function<void(std::ostream&)>([m, coordinates, options](std::ostream& out) {
               Gmsh_mesh gmsh;
               gmsh.points = coordinates();
               // Points added since reading take the tags after the largest one.
               if(!m->point_tags.empty())
               {
                 gmsh.point_tags = m->point_tags;
                 std::size_t next = *std::max_element(gmsh.point_tags.begin(), gmsh.point_tags.end());
                 while(gmsh.point_tags.size() < gmsh.points.size()) gmsh.point_tags.push_back(++next);
               }
               gmsh.tetrahedra = m->cells;
               gmsh.tetrahedron_references = m->cell_references;
               gmsh.triangles = m->triangles;
               gmsh.triangle_references = m->triangle_references;
               write_gmsh_file(out, gmsh, options.msh);
             }));
  else
    add_file(path, std::function<void(std::ostream&)>([m, coordinates, options](std::ostream& out) {
               Named_fields point_fields, cell_fields;
               for(std::size_t f = 0; f < m->fields.size(); ++f) point_fields.emplace_back(m->field_names[f], m->fields[f]);
               for(std::size_t f = 0; f < m->cell_fields.size(); ++f)
                 cell_fields.emplace_back(m->cell_field_names[f], m->cell_fields[f]);
               // The references as the cell field the reader takes them from, unless given.
               const bool given = std::find(m->cell_field_names.begin(), m->cell_field_names.end(), "subdomain") !=
                                  m->cell_field_names.end();
               if(m->has_references && !given && m->cell_references.size() == m->cells.size())
                 cell_fields.emplace_back("subdomain",
                                          std::vector<double>(m->cell_references.begin(), m->cell_references.end()));
               write_vtu_file(out, coordinates(), m->cells, point_fields, cell_fields, options.vtu);
             }));
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_MESH_WITH_FIELDS_H
