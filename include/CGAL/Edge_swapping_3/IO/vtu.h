// VTK XML unstructured grid (.vtu, ASCII) for ParaView: tetrahedra with
// named scalar fields per point and per cell.

#ifndef CGAL_EDGE_SWAPPING_3_IO_VTU_H
#define CGAL_EDGE_SWAPPING_3_IO_VTU_H

#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <array>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

typedef std::vector<std::pair<std::string, std::vector<double>>> Named_fields;

inline void write_vtu_file(std::ostream& out, const std::vector<std::array<double, 3>>& points,
                           const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                           const Named_fields& point_fields, const Named_fields& cell_fields)
{
  out.precision(17);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << tetrahedra.size() << "\">\n";
  auto fields = [&](const char* tag, const Named_fields& f) {
    out << "<" << tag << ">\n";
    for(const auto& [name, values] : f)
    {
      out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for(double v : values) out << v << '\n';
      out << "</DataArray>\n";
    }
    out << "</" << tag << ">\n";
  };
  fields("PointData", point_fields);
  fields("CellData", cell_fields);
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const auto& t : tetrahedra) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t k = 1; k <= tetrahedra.size(); ++k) out << 4 * k << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t k = 0; k < tetrahedra.size(); ++k) out << "10\n"; // VTK_TETRA
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

/// What `read_vtu_file` returns.
struct Vtu_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tetrahedra;
  Named_fields point_fields, cell_fields;
};

/// Reads the ASCII .vtu files that `write_vtu_file` writes (tetrahedra only,
/// ASCII data arrays); anything else is an Input_error naming the problem.
inline Vtu_mesh read_vtu_file(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Input_error(path + ": cannot open the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  auto fail = [&](const std::string& what) -> void { throw Input_error(path + ": " + what); };
  auto attribute = [&](const std::string& tag, const std::string& name) {
    const std::string key = name + "=\"";
    const auto at = tag.find(key);
    if(at == std::string::npos) return std::string();
    const auto end = tag.find('"', at + key.size());
    return tag.substr(at + key.size(), end - at - key.size());
  };
  if(text.find("<VTKFile") == std::string::npos || text.find("UnstructuredGrid") == std::string::npos)
    fail("not a VTK unstructured grid (.vtu) file");
  const auto piece = text.find("<Piece");
  if(piece == std::string::npos) fail("no <Piece>");
  const std::string piece_tag = text.substr(piece, text.find('>', piece) - piece);
  long long n_points = -1, n_cells = -1;
  try { n_points = std::stoll(attribute(piece_tag, "NumberOfPoints")); n_cells = std::stoll(attribute(piece_tag, "NumberOfCells")); }
  catch(const std::exception&) { fail("<Piece> without NumberOfPoints and NumberOfCells"); }
  if(n_points < 0 || n_cells < 0) fail("negative NumberOfPoints or NumberOfCells");

  Vtu_mesh m;
  std::vector<double> connectivity, offsets, types, coordinates;
  for(std::size_t at = text.find("<DataArray", piece); at != std::string::npos; at = text.find("<DataArray", at + 1))
  {
    const auto close = text.find('>', at);
    const std::string tag = text.substr(at, close - at);
    if(attribute(tag, "format") != "ascii") fail("data array '" + attribute(tag, "Name") + "' is not ASCII");
    const auto end = text.find("</DataArray>", close);
    if(end == std::string::npos) fail("unterminated <DataArray>");
    std::istringstream numbers(text.substr(close + 1, end - close - 1));
    std::vector<double> values;
    std::string token;
    while(numbers >> token)
    {
      char* stop = nullptr;
      const double d = std::strtod(token.c_str(), &stop);
      if(*stop != 0) fail("cannot read a number from '" + token + "' in '" + attribute(tag, "Name") + "'");
      if(!std::isfinite(d)) fail("a value of '" + attribute(tag, "Name") + "' is not finite: " + token);
      values.push_back(d);
    }
    // Which section holds this array: the last section tag opened before it.
    const auto section = [&](const char* s) { const auto p = text.rfind(s, at); return p == std::string::npos ? 0 : p + 1; };
    const std::size_t in_points = section("<Points>"), in_cells = section("<Cells>"),
                      in_pdata = section("<PointData"), in_cdata = section("<CellData");
    const std::size_t latest = (std::max)((std::max)(in_points, in_cells), (std::max)(in_pdata, in_cdata));
    const std::string name = attribute(tag, "Name");
    if(latest == 0) fail("data array '" + name + "' outside Points, Cells, PointData and CellData");
    if(latest == in_points) coordinates = values;
    else if(latest == in_cells)
    {
      if(name == "connectivity") connectivity = values;
      else if(name == "offsets") offsets = values;
      else if(name == "types") types = values;
    }
    else if(latest == in_pdata)
    {
      if(values.size() != std::size_t(n_points)) fail("point field '" + name + "' has " + std::to_string(values.size()) + " values, not " + std::to_string(n_points));
      m.point_fields.emplace_back(name, values);
    }
    else
    {
      if(values.size() != std::size_t(n_cells)) fail("cell field '" + name + "' has " + std::to_string(values.size()) + " values, not " + std::to_string(n_cells));
      m.cell_fields.emplace_back(name, values);
    }
  }
  if(coordinates.size() != 3 * std::size_t(n_points)) fail("the points do not have 3 coordinates each");
  if(connectivity.size() != 4 * std::size_t(n_cells) || offsets.size() != std::size_t(n_cells) ||
     types.size() != std::size_t(n_cells))
    fail("the cells are not all tetrahedra (4 points each, VTK type 10)");
  for(std::size_t k = 0; k < std::size_t(n_points); ++k)
    m.points.push_back({coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]});
  for(std::size_t k = 0; k < std::size_t(n_cells); ++k)
  {
    if(types[k] != 10 || offsets[k] != double(4 * (k + 1))) fail("cell " + std::to_string(k) + " is not a tetrahedron");
    std::array<std::size_t, 4> t;
    for(int i = 0; i < 4; ++i)
    {
      const double v = connectivity[4 * k + i];
      if(v < 0 || v >= double(n_points) || v != std::floor(v)) fail("cell " + std::to_string(k) + " names a point that does not exist");
      t[i] = std::size_t(v);
    }
    m.tetrahedra.push_back(t);
  }
  return m;
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_VTU_H
