// SPDX-License-Identifier: GPL-3.0-or-later
// Medit .mesh files (ASCII, as written by CGAL's Mesh_3 and read by Gmsh,
// MMG and ParaView): vertices, boundary triangles and tetrahedra, each with a
// reference (the subdomain of a tetrahedron, the surface patch of a triangle).
//
// Reading accepts the sections Vertices, Triangles, Tetrahedra, and skips
// Edges, Corners, Ridges, RequiredVertices, RequiredEdges, Quadrilaterals;
// any other keyword is an error that names it. Indices are 1-based.

#ifndef CGAL_EDGE_SWAPPING_3_IO_MEDIT_H
#define CGAL_EDGE_SWAPPING_3_IO_MEDIT_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/text_output.h>
#include <array>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// The sections of a Medit `.mesh` file that the package reads.
struct Medit_mesh
{
  std::vector<std::array<double, 3>> points;           ///< `Vertices`
  std::vector<int> point_references;                   ///< their references
  std::vector<std::array<std::size_t, 3>> triangles;   ///< `Triangles`, 0-based point indices
  std::vector<int> triangle_references;                ///< their references (boundary markers)
  std::vector<std::array<std::size_t, 4>> tetrahedra;  ///< `Tetrahedra`, 0-based point indices
  std::vector<int> tetrahedron_references;             ///< their references (subdomains)
};

/// Reads the text of a Medit file; `name` is the file name used in messages.
inline Medit_mesh read_medit_text(const std::string& name, std::string_view text)
{
  internal::Text_scanner r(name, text);
  Medit_mesh m;
  std::string_view keyword;
  bool dimension_seen = false, vertices_seen = false;
  auto token = [&](std::string_view what) {
    std::string_view t;
    if(!r.next_token(t)) r.fail("the file ends before " + std::string(what));
    return t;
  };
  auto read_int = [&](std::string_view what) { return r.number<int>(token(what), what); };
  auto index = [&]() {
    const std::string_view t = token("a vertex index");
    const long long i = r.number<long long>(t, "a vertex index");
    if(i < 1 || i > (long long)m.points.size())
      r.fail("vertex index " + std::to_string(i) + " is not one of the " + std::to_string(m.points.size()) + " vertices");
    return std::size_t(i - 1);
  };
  // A count of entries of `numbers` numbers each: each takes at least 2 bytes a number.
  auto count = [&](std::string_view what, std::size_t numbers) {
    return r.count(token(what), what, 2 * numbers);
  };
  // The sections skipped, with the number of numbers per entry.
  auto skipped_numbers = [](std::string_view k) -> std::size_t {
    if(k == "Edges") return 3;
    if(k == "Corners" || k == "Ridges" || k == "RequiredVertices" || k == "RequiredEdges") return 1;
    if(k == "Quadrilaterals") return 5;
    return 0;
  };

  if(!r.next_token(keyword)) r.fail("empty file");
  if(keyword != "MeshVersionFormatted") r.fail("not a Medit file: it starts with " + quote_token(keyword));
  read_int("the format version");
  while(r.next_token(keyword))
  {
    if(keyword == "End") break;
    if(keyword == "Dimension")
    {
      if(dimension_seen) r.fail("a second Dimension");
      const int d = read_int("the dimension");
      if(d != 3) r.fail("the dimension is " + std::to_string(d) + ", not 3");
      dimension_seen = true;
    }
    else if(keyword == "Vertices")
    {
      if(vertices_seen) r.fail("a second Vertices section");
      const std::size_t n = count("number of vertices", 4);
      m.points.reserve(n);
      m.point_references.reserve(n);
      for(std::size_t k = 0; k < n; ++k)
      {
        std::array<double, 3> p;
        for(auto& x : p)
        {
          x = r.number<double>(token("a coordinate"), "a coordinate");
          const std::string problem = coordinate_problem(x);
          if(!problem.empty()) r.fail(problem);
        }
        m.points.push_back(p);
        m.point_references.push_back(read_int("a vertex reference"));
      }
      vertices_seen = true;
    }
    else if(keyword == "Triangles" || keyword == "Tetrahedra")
    {
      if(!vertices_seen) r.fail(std::string(keyword) + " before Vertices");
      const bool tets = (keyword == "Tetrahedra");
      if(tets ? !m.tetrahedra.empty() : !m.triangles.empty()) r.fail("a second " + std::string(keyword) + " section");
      const std::size_t n = tets ? count("number of tetrahedra", 5) : count("number of triangles", 4);
      (tets ? m.tetrahedron_references : m.triangle_references).reserve(n);
      if(tets) m.tetrahedra.reserve(n); else m.triangles.reserve(n);
      for(std::size_t k = 0; k < n; ++k)
      {
        if(tets)
        {
          std::array<std::size_t, 4> t;
          for(auto& v : t) v = index();
          m.tetrahedra.push_back(t);
          m.tetrahedron_references.push_back(read_int("a tetrahedron reference"));
        }
        else
        {
          std::array<std::size_t, 3> t;
          for(auto& v : t) v = index();
          m.triangles.push_back(t);
          m.triangle_references.push_back(read_int("a triangle reference"));
        }
      }
    }
    else if(const std::size_t numbers = skipped_numbers(keyword))
    {
      const std::size_t n = count("number of entries", numbers);
      for(std::size_t k = 0; k < n * numbers; ++k) r.number<double>(token("an entry"), "an entry");
    }
    else
      r.fail("unknown or unsupported section " + quote_token(keyword));
  }
  if(!dimension_seen) r.fail("no Dimension");
  if(!vertices_seen) r.fail("no Vertices");
  return m;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads a Medit `.mesh` file; a bad file throws an error that names it, the line and the problem.
inline Medit_mesh read_medit_file(const std::string& path) { return read_medit_text(path, read_text_file(path)); }

/// Writes a Medit file (each coordinate in the shortest text that reads back exactly).
inline void write_medit_file(std::ostream& stream, const Medit_mesh& m)
{
  Text_sink out(stream); // to_chars: shortest text that reads back the same double
  out << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << m.points.size() << '\n';
  for(std::size_t k = 0; k < m.points.size(); ++k)
    out << finite_value(m.points[k][0], "a coordinate") << ' ' << finite_value(m.points[k][1], "a coordinate") << ' '
        << finite_value(m.points[k][2], "a coordinate") << ' '
        << (m.point_references.empty() ? 0 : m.point_references[k]) << '\n';
  out << "Triangles\n" << m.triangles.size() << '\n';
  for(std::size_t k = 0; k < m.triangles.size(); ++k)
    out << m.triangles[k][0] + 1 << ' ' << m.triangles[k][1] + 1 << ' ' << m.triangles[k][2] + 1 << ' '
        << m.triangle_references[k] << '\n';
  out << "Tetrahedra\n" << m.tetrahedra.size() << '\n';
  for(std::size_t k = 0; k < m.tetrahedra.size(); ++k)
    out << m.tetrahedra[k][0] + 1 << ' ' << m.tetrahedra[k][1] + 1 << ' ' << m.tetrahedra[k][2] + 1 << ' '
        << m.tetrahedra[k][3] + 1 << ' ' << m.tetrahedron_references[k] << '\n';
  out << "End\n";
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_MEDIT_H
