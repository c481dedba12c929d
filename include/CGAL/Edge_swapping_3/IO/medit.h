// Medit .mesh files (ASCII, as written by CGAL's Mesh_3 and read by Gmsh,
// MMG and ParaView): vertices, boundary triangles and tetrahedra, each with a
// reference (the subdomain of a tetrahedron, the surface patch of a triangle).
//
// Reading accepts the sections Vertices, Triangles, Tetrahedra, and skips
// Edges, Corners, Ridges, RequiredVertices, RequiredEdges, Quadrilaterals;
// any other keyword is an error that names it. Indices are 1-based.

#ifndef CGAL_EDGE_SWAPPING_3_IO_MEDIT_H
#define CGAL_EDGE_SWAPPING_3_IO_MEDIT_H

#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

struct Medit_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<int> point_references;
  std::vector<std::array<std::size_t, 3>> triangles;   ///< 0-based point indices
  std::vector<int> triangle_references;
  std::vector<std::array<std::size_t, 4>> tetrahedra;  ///< 0-based point indices
  std::vector<int> tetrahedron_references;
};

namespace internal {

// Whitespace-separated tokens with the line each comes from.
class Token_reader
{
public:
  explicit Token_reader(const std::string& path) : path_(path), in_(path)
  {
    if(!in_) throw Input_error(path + ": cannot open the file");
  }

  bool next(std::string& token)
  {
    while(!(line_ >> token))
    {
      std::string s;
      if(!std::getline(in_, s)) return false;
      ++number_;
      const auto hash = s.find('#');
      if(hash != std::string::npos) s.erase(hash);
      line_.clear();
      line_.str(s);
    }
    return true;
  }

  template <class T>
  T read(const char* what)
  {
    std::string token;
    if(!next(token)) fail(std::string("the file ends before ") + what);
    return parse_token<T>(token, what, [this](const std::string& m) { fail(m); });
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Input_error(path_ + ":" + std::to_string(number_) + ": " + what);
  }

private:
  std::string path_;
  std::ifstream in_;
  std::istringstream line_;
  std::size_t number_ = 0;
};

} // namespace internal

inline Medit_mesh read_medit_file(const std::string& path)
{
  internal::Token_reader r(path);
  Medit_mesh m;
  std::string keyword;
  bool dimension_seen = false, vertices_seen = false;
  // The sections skipped, with the number of numbers per entry.
  const std::map<std::string, int> skipped = {{"Edges", 3}, {"Corners", 1}, {"Ridges", 1},
                                              {"RequiredVertices", 1}, {"RequiredEdges", 1},
                                              {"Quadrilaterals", 5}};
  auto index = [&](std::size_t n_points) {
    const long long i = r.read<long long>("a vertex index");
    if(i < 1 || i > (long long)n_points)
      r.fail("vertex index " + std::to_string(i) + " is not one of the " + std::to_string(n_points) + " vertices");
    return std::size_t(i - 1);
  };
  auto count = [&](const char* what) {
    const long long n = r.read<long long>(what);
    if(n < 0) r.fail(std::string("negative ") + what);
    return std::size_t(n);
  };

  if(!r.next(keyword)) r.fail("empty file");
  if(keyword != "MeshVersionFormatted") r.fail("not a Medit file: it starts with '" + keyword + "'");
  r.read<int>("the format version");
  while(r.next(keyword))
  {
    if(keyword == "End") break;
    if(keyword == "Dimension")
    {
      const int d = r.read<int>("the dimension");
      if(d != 3) r.fail("the dimension is " + std::to_string(d) + ", not 3");
      dimension_seen = true;
    }
    else if(keyword == "Vertices")
    {
      const std::size_t n = count("number of vertices");
      for(std::size_t k = 0; k < n; ++k)
      {
        std::array<double, 3> p;
        for(auto& x : p)
        {
          x = r.read<double>("a coordinate");
          if(!std::isfinite(x)) r.fail("a coordinate is not finite");
        }
        m.points.push_back(p);
        m.point_references.push_back(r.read<int>("a vertex reference"));
      }
      vertices_seen = true;
    }
    else if(keyword == "Triangles" || keyword == "Tetrahedra")
    {
      if(!vertices_seen) r.fail(keyword + " before Vertices");
      const bool tets = (keyword == "Tetrahedra");
      const std::size_t n = count(tets ? "number of tetrahedra" : "number of triangles");
      for(std::size_t k = 0; k < n; ++k)
      {
        if(tets)
        {
          std::array<std::size_t, 4> t;
          for(auto& v : t) v = index(m.points.size());
          m.tetrahedra.push_back(t);
          m.tetrahedron_references.push_back(r.read<int>("a tetrahedron reference"));
        }
        else
        {
          std::array<std::size_t, 3> t;
          for(auto& v : t) v = index(m.points.size());
          m.triangles.push_back(t);
          m.triangle_references.push_back(r.read<int>("a triangle reference"));
        }
      }
    }
    else if(skipped.count(keyword))
    {
      const std::size_t n = count("number of entries");
      for(std::size_t k = 0; k < n * std::size_t(skipped.at(keyword)); ++k) r.read<double>("an entry");
    }
    else
      r.fail("unknown or unsupported section '" + keyword + "'");
  }
  if(!dimension_seen) r.fail("no Dimension");
  if(!vertices_seen) r.fail("no Vertices");
  return m;
}

/// Writes a Medit file (17 significant digits: coordinates read back exactly).
inline void write_medit_file(std::ostream& out, const Medit_mesh& m)
{
  out.precision(17);
  out << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << m.points.size() << '\n';
  for(std::size_t k = 0; k < m.points.size(); ++k)
    out << m.points[k][0] << ' ' << m.points[k][1] << ' ' << m.points[k][2] << ' '
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
