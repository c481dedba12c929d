// SPDX-License-Identifier: GPL-3.0-or-later
// VTK XML unstructured grid (.vtu, ASCII) for ParaView: tetrahedra with
// named scalar fields per point and per cell.

#ifndef CGAL_EDGE_SWAPPING_3_IO_VTU_H
#define CGAL_EDGE_SWAPPING_3_IO_VTU_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/text_output.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <string_view>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// Arrays of values by name, one value per point or per cell.
typedef std::vector<std::pair<std::string, std::vector<double>>> Named_fields;

/// \ingroup PkgEdgeSwapping3IO
/// Writes a VTK unstructured grid (`.vtu`, ASCII) of tetrahedra with point and cell fields.
inline void write_vtu_file(std::ostream& stream, const std::vector<std::array<double, 3>>& points,
                           const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                           const Named_fields& point_fields, const Named_fields& cell_fields)
{
  Text_sink out(stream); // to_chars: shortest text that reads back the same double
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << tetrahedra.size() << "\">\n";
  auto fields = [&](const char* tag, const Named_fields& f) {
    out << "<" << tag << ">\n";
    for(const auto& [name, values] : f)
    {
      out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for(double v : values) out << finite_value(v, "a value", &name) << '\n';
      out << "</DataArray>\n";
    }
    out << "</" << tag << ">\n";
  };
  fields("PointData", point_fields);
  fields("CellData", cell_fields);
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : points)
    out << finite_value(p[0], "a coordinate") << ' ' << finite_value(p[1], "a coordinate") << ' '
        << finite_value(p[2], "a coordinate") << '\n';
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
  std::vector<std::array<double, 3>> points;          ///< the points
  std::vector<std::array<std::size_t, 4>> tetrahedra; ///< 0-based point indices
  Named_fields point_fields;                          ///< the `PointData` arrays of one component
  Named_fields cell_fields;                           ///< the `CellData` arrays of one component
};

namespace internal {

// The attributes of an XML start tag, `name="value"` or `name='value'`;
// `fail(message)` throws.
template <class Fail>
class Xml_attributes
{
public:
  Xml_attributes(std::string_view tag, const Fail& fail) : tag_(tag), where_(fail) {}

  /// The value of attribute `key`, or `none` if the tag has no such attribute.
  std::string_view get(std::string_view key, std::string_view none = std::string_view()) const
  {
    std::size_t at = tag_.find_first_of(" \t\r\n");
    while(at != std::string_view::npos && at < tag_.size())
    {
      at = tag_.find_first_not_of(" \t\r\n/", at);
      if(at == std::string_view::npos) break;
      const std::size_t eq = tag_.find('=', at);
      if(eq == std::string_view::npos) where_("malformed attribute in " + quote_token(tag_));
      std::string_view name = tag_.substr(at, eq - at);
      while(!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.remove_suffix(1);
      const std::size_t open = tag_.find_first_not_of(" \t\r\n", eq + 1);
      if(open == std::string_view::npos || (tag_[open] != '"' && tag_[open] != '\''))
        where_("attribute " + quote_token(name) + " without a quoted value");
      const std::size_t close = tag_.find(tag_[open], open + 1);
      if(close == std::string_view::npos) where_("attribute " + quote_token(name) + " with an unterminated value");
      if(name == key) return tag_.substr(open + 1, close - open - 1);
      at = close + 1;
    }
    return none;
  }

private:
  std::string_view tag_;
  const Fail& where_;
};

} // namespace internal

/// Reads the text of an ASCII .vtu file (tetrahedra only, ASCII data arrays,
/// one Piece); anything else is an Input_error naming the file, the line and
/// the problem. One pass over the text: linear in its size.
inline Vtu_mesh read_vtu_text(const std::string& name, std::string_view text)
{
  std::size_t line = 1, counted_to = 0;
  auto fail_at = [&](std::size_t pos, const std::string& what) {
    for(; counted_to < pos && counted_to < text.size(); ++counted_to) line += text[counted_to] == '\n';
    throw Input_error(name + ":" + std::to_string(line) + ": " + what);
  };

  enum Section { NONE, POINTS, CELLS, POINT_DATA, CELL_DATA };
  Section section = NONE;
  bool vtk_file = false, piece_seen = false, piece_open = false;
  std::size_t n_points = 0, n_cells = 0;
  std::vector<double> connectivity, offsets, types, coordinates;
  bool have_connectivity = false, have_offsets = false, have_types = false, have_points = false;
  Vtu_mesh m;
  std::unordered_set<std::string> point_names, cell_names;
  auto field_name_ok = [](std::string_view s) {
    if(s.empty() || s.size() > 256) return false;
    for(char ch : s)
      if(ch < 32 || ch >= 127 || ch == '<' || ch == '>' || ch == '&' || ch == '"' || ch == '\'') return false;
    return true;
  };

  std::size_t pos = 0;
  while((pos = text.find('<', pos)) != std::string_view::npos)
  {
    if(text.compare(pos, 4, "<!--") == 0)
    {
      const std::size_t end = text.find("-->", pos + 4);
      if(end == std::string_view::npos) fail_at(pos, "unterminated comment");
      pos = end + 3;
      continue;
    }
    const std::size_t close = text.find('>', pos);
    if(close == std::string_view::npos) fail_at(pos, "unterminated tag");
    const std::string_view tag = text.substr(pos + 1, close - pos - 1);
    const std::size_t tag_start = pos;
    pos = close + 1;
    if(!tag.empty() && (tag[0] == '?' || tag[0] == '!')) continue; // declaration
    const bool closing = !tag.empty() && tag[0] == '/';
    const std::string_view body = closing ? tag.substr(1) : tag;
    const std::string_view element = body.substr(0, body.find_first_of(" \t\r\n/"));
    auto fail = [&](const std::string& what) { fail_at(tag_start, what); };
    const internal::Xml_attributes<decltype(fail)> attributes(tag, fail);

    if(element == "VTKFile")
    {
      if(closing) continue;
      if(attributes.get("type") != "UnstructuredGrid") fail("not a VTK unstructured grid (.vtu) file");
      vtk_file = true;
    }
    else if(element == "Piece")
    {
      if(closing) { piece_open = false; continue; }
      if(!vtk_file) fail("<Piece> outside <VTKFile type=\"UnstructuredGrid\">");
      if(piece_seen) fail("more than one <Piece> (only one is supported)");
      piece_seen = piece_open = true;
      long long np = -1, nc = -1;
      if(internal::parse_number(attributes.get("NumberOfPoints"), np) != internal::Number_status::ok ||
         internal::parse_number(attributes.get("NumberOfCells"), nc) != internal::Number_status::ok || np < 0 || nc < 0)
        fail("<Piece> without a whole NumberOfPoints and NumberOfCells");
      // Each point takes at least 6 bytes (3 numbers), each cell 12 (6 numbers).
      if(std::size_t(np) > text.size() / 6 || std::size_t(nc) > text.size() / 12)
        fail("NumberOfPoints " + std::to_string(np) + " and NumberOfCells " + std::to_string(nc) +
             " are more than the file can hold (" + std::to_string(text.size()) + " bytes)");
      n_points = std::size_t(np);
      n_cells = std::size_t(nc);
    }
    else if(element == "Points" || element == "Cells" || element == "PointData" || element == "CellData")
    {
      if(closing) { section = NONE; continue; }
      if(!piece_open) fail("<" + std::string(element) + "> outside <Piece>");
      if(section != NONE) fail("<" + std::string(element) + "> inside another section");
      section = element == "Points" ? POINTS : element == "Cells" ? CELLS : element == "PointData" ? POINT_DATA : CELL_DATA;
      if(!body.empty() && body.back() == '/') section = NONE; // an empty section: <PointData/>
    }
    else if(element == "DataArray")
    {
      if(closing) fail("</DataArray> without <DataArray>");
      const std::string array_name(attributes.get("Name"));
      if(section == NONE) fail("data array " + quote_token(array_name) + " outside Points, Cells, PointData and CellData");
      if(attributes.get("format") != "ascii") fail("data array " + quote_token(array_name) + " is not ASCII");
      const std::string_view components = attributes.get("NumberOfComponents", section == POINTS ? "3" : "1");
      if(components != (section == POINTS ? "3" : "1"))
        fail("data array " + quote_token(array_name) + " has NumberOfComponents " + quote_token(components));
      // How many values it must hold, and where they go.
      std::vector<double>* values = nullptr;
      std::vector<double> field;
      std::size_t expected = 0;
      if(section == POINTS)
      {
        if(have_points) fail("a second data array in <Points>");
        have_points = true;
        values = &coordinates;
        expected = 3 * n_points;
      }
      else if(section == CELLS)
      {
        bool* have = array_name == "connectivity" ? &have_connectivity : array_name == "offsets" ? &have_offsets
                     : array_name == "types" ? &have_types : nullptr;
        if(have == nullptr) fail("unknown cell array " + quote_token(array_name));
        if(*have) fail("a second " + quote_token(array_name) + " array");
        *have = true;
        values = array_name == "connectivity" ? &connectivity : array_name == "offsets" ? &offsets : &types;
        expected = array_name == "connectivity" ? 4 * n_cells : n_cells;
      }
      else
      {
        if(!field_name_ok(array_name)) fail("field name " + quote_token(array_name) + " is empty, too long or has characters that are not supported");
        if(!(section == POINT_DATA ? point_names : cell_names).insert(array_name).second)
          fail("two fields named " + quote_token(array_name));
        values = &field;
        expected = section == POINT_DATA ? n_points : n_cells;
      }
      values->reserve(expected);
      // The numbers up to the closing tag.
      const std::size_t end = text.find('<', pos);
      if(end == std::string_view::npos || text.compare(end, 12, "</DataArray>") != 0)
        fail("data array " + quote_token(array_name) + " is not closed by </DataArray>");
      for(std::size_t at = pos;;)
      {
        at = text.find_first_not_of(" \t\r\n", at);
        if(at >= end) break;
        const std::size_t stop = std::min(end, text.find_first_of(" \t\r\n", at));
        const std::string_view token = text.substr(at, stop - at);
        at = stop;
        if(values->size() == expected)
          fail("data array " + quote_token(array_name) + " has more than " + std::to_string(expected) + " values");
        double d = 0;
        const auto status = internal::parse_number(token, d);
        if(status != internal::Number_status::ok)
          fail("cannot read a number from " + quote_token(token) + " in " + quote_token(array_name));
        if(!std::isfinite(d)) fail("a value of " + quote_token(array_name) + " is not finite: " + quote_token(token));
        if(section == POINTS)
        {
          const std::string problem = coordinate_problem(d);
          if(!problem.empty()) fail(problem);
        }
        values->push_back(d);
      }
      if(values->size() != expected)
        fail("data array " + quote_token(array_name) + " has " + std::to_string(values->size()) + " values, not " +
             std::to_string(expected));
      if(section == POINT_DATA) m.point_fields.emplace_back(array_name, std::move(field));
      if(section == CELL_DATA) m.cell_fields.emplace_back(array_name, std::move(field));
      pos = end + 12;
    }
  }
  if(!vtk_file) fail_at(0, "not a VTK unstructured grid (.vtu) file");
  if(!piece_seen) fail_at(text.size(), "no <Piece>");
  if(!have_points && n_points > 0) fail_at(text.size(), "no <Points> data array");
  if(n_cells > 0 && !(have_connectivity && have_offsets && have_types))
    fail_at(text.size(), "the cells need connectivity, offsets and types arrays");
  m.points.reserve(n_points);
  for(std::size_t k = 0; k < n_points; ++k)
    m.points.push_back({coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]});
  m.tetrahedra.reserve(n_cells);
  for(std::size_t k = 0; k < n_cells; ++k)
  {
    if(types[k] != 10 || offsets[k] != double(4 * (k + 1)))
      fail_at(text.size(), "cell " + std::to_string(k) + " is not a tetrahedron (VTK type 10, 4 points)");
    std::array<std::size_t, 4> t;
    for(int i = 0; i < 4; ++i)
    {
      const double v = connectivity[4 * k + i];
      if(!(v >= 0 && v < double(n_points)) || v != std::floor(v))
        fail_at(text.size(), "cell " + std::to_string(k) + " names a point that does not exist");
      t[i] = std::size_t(v);
    }
    m.tetrahedra.push_back(t);
  }
  return m;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads a `.vtu` file of tetrahedra; a bad file throws an error that names it and the problem.
inline Vtu_mesh read_vtu_file(const std::string& path) { return read_vtu_text(path, read_text_file(path)); }

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_VTU_H
