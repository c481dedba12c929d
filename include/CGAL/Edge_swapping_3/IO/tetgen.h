// SPDX-License-Identifier: GPL-3.0-or-later
// TetGen .node and .ele files: reading with clear errors, writing so that
// coordinates read back to the same doubles.
//
// .node: "<#points> <dim=3> <#attributes> <#markers 0|1>", then
//        "<index> <x> <y> <z> [attributes] [marker]".
// .ele:  "<#tets> <nodes per tet=4> <#attributes>", then "<index> <n1> <n2> <n3> <n4> [attributes]";
//        the first attribute is the region (`tetgen -A`), a whole number.
// '#' starts a comment; indices start at 0 or 1 (the first point decides), as in TetGen.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TETGEN_H
#define CGAL_EDGE_SWAPPING_3_IO_TETGEN_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/text_output.h>
#include <array>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// A TetGen `.node` file: points and their attributes.
struct Node_file
{
  std::vector<std::array<double, 3>> points;   ///< in the file's order
  std::vector<std::vector<double>> attributes; ///< per point, possibly empty
  int first_index = 1;                         ///< the number of the first point (0 or 1)
};

namespace internal {

// TetGen's files are line based: one header line, then one line per entry.
class Line_reader
{
public:
  Line_reader(const std::string& name, std::string_view text) : scan_(name, text) {}

  bool next_line() { return scan_.next_line(); }

  template <class T>
  T read(std::string_view what)
  {
    std::string_view token;
    if(!scan_.next_token_in_line(token)) fail("missing " + std::string(what));
    return scan_.number<T>(token, what);
  }

  bool more() { return scan_.line_has_more(); }

  void expect_end()
  {
    std::string_view extra;
    if(scan_.next_token_in_line(extra)) fail("unexpected " + quote_token(extra) + " at the end of the line");
  }

  /// A header count whose entries each take at least `min_bytes` of the rest.
  std::size_t count(const std::string& what, std::size_t min_bytes)
  {
    std::string_view token;
    if(!scan_.next_token_in_line(token)) fail("missing " + what);
    return scan_.count(token, what, min_bytes);
  }

  /// Fails unless `n` entries of at least `min_bytes` each fit in the rest.
  void require_room(std::size_t n, const std::string& what, std::size_t min_bytes) const
  {
    if(!scan_.has_room(n, min_bytes))
      fail(what + " is " + std::to_string(n) + ", more than the rest of the file can hold (" +
           std::to_string(scan_.remaining_bytes()) + " bytes)");
  }

  [[noreturn]] void fail(const std::string& what) const { scan_.fail(what); }

private:
  Text_scanner scan_;
};

} // namespace internal

/// Reads the text of a .node file; `name` is the file name used in messages.
inline Node_file read_node_text(const std::string& name, std::string_view text)
{
  internal::Line_reader r(name, text);
  if(!r.next_line()) r.fail("empty file: no header line");
  // A point line holds at least an index and three coordinates: 8 bytes.
  const std::size_t n = r.count("the number of points", 8);
  const int dim = r.read<int>("the dimension");
  const int n_attr = r.more() ? r.read<int>("the number of attributes") : 0;
  const int n_mark = r.more() ? r.read<int>("the number of boundary markers") : 0;
  r.expect_end();
  if(dim != 3) r.fail("the dimension is " + std::to_string(dim) + ", not 3");
  if(n_attr < 0 || n_attr > 1000 || (n_mark != 0 && n_mark != 1)) r.fail("bad attribute or marker count");
  r.require_room(n, "the number of points", 2 * std::size_t(4 + n_attr + n_mark));

  Node_file f;
  f.points.reserve(n);
  f.attributes.reserve(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    if(!r.next_line()) r.fail("the file ends after " + std::to_string(k) + " of " + std::to_string(n) + " points");
    const long long index = r.read<long long>("the point index");
    if(k == 0)
    {
      if(index != 0 && index != 1) r.fail("the first point index is " + std::to_string(index) + ", not 0 or 1");
      f.first_index = int(index);
    }
    else if(index != f.first_index + (long long)k)
      r.fail("point index " + std::to_string(index) + " out of sequence (expected " +
             std::to_string(f.first_index + (long long)k) + ")");
    std::array<double, 3> p;
    for(int c = 0; c < 3; ++c)
    {
      p[c] = r.read<double>("a coordinate");
      const std::string problem = coordinate_problem(p[c]);
      if(!problem.empty()) r.fail(problem);
    }
    std::vector<double> attributes(static_cast<std::size_t>(n_attr));
    for(auto& a : attributes) a = r.read<double>("an attribute");
    if(n_mark) r.read<double>("the boundary marker");
    r.expect_end();
    f.points.push_back(p);
    f.attributes.push_back(std::move(attributes));
  }
  if(r.next_line()) r.fail("more lines than the " + std::to_string(n) + " points the header announces");
  return f;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads a TetGen `.node` file; a bad file throws an error that names it, the line and the problem.
inline Node_file read_node_file(const std::string& path) { return read_node_text(path, read_text_file(path)); }

/// Reads the text of an .ele file: tetrahedra as 0-based point indices.
/// `number_of_points` and `first_index` come from the matching .node file.
/// With `regions`, the first attribute of each tetrahedron (its region, as
/// `tetgen -A` writes it) is put there when the file has attributes.
inline std::vector<std::array<std::size_t, 4>>
read_ele_text(const std::string& name, std::string_view text, std::size_t number_of_points, int first_index,
              std::vector<int>* regions = nullptr)
{
  internal::Line_reader r(name, text);
  if(!r.next_line()) r.fail("empty file: no header line");
  // A tetrahedron line holds at least five numbers: 10 bytes.
  const std::size_t n = r.count("the number of tetrahedra", 10);
  const int per = r.more() ? r.read<int>("the number of nodes per tetrahedron") : 4;
  const int n_attr = r.more() ? r.read<int>("the number of attributes") : 0;
  r.expect_end();
  if(per != 4) r.fail("only linear tetrahedra (4 nodes) are supported, not " + std::to_string(per));
  if(n_attr < 0 || n_attr > 1000) r.fail("bad number of attributes");
  r.require_room(n, "the number of tetrahedra", 2 * std::size_t(5 + n_attr));

  std::vector<std::array<std::size_t, 4>> cells;
  cells.reserve(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    if(!r.next_line()) r.fail("the file ends after " + std::to_string(k) + " of " + std::to_string(n) + " tetrahedra");
    r.read<long long>("the tetrahedron index");
    std::array<std::size_t, 4> t;
    for(auto& v : t)
    {
      const long long i = r.read<long long>("a node index");
      if(i < first_index || i - first_index >= (long long)number_of_points)
        r.fail("node index " + std::to_string(i) + " is not a point of the .node file");
      v = std::size_t(i - first_index);
    }
    for(int a = 0; a < n_attr; ++a)
    {
      const double value = r.read<double>("an attribute");
      if(a > 0 || regions == nullptr) continue;
      if(!(value == std::floor(value) && std::abs(value) <= 2147483647.0))
      {
        std::ostringstream text;
        text.precision(17);
        text << value;
        r.fail("the region attribute " + text.str() + " is not a whole number: regions are read as integer references");
      }
      regions->push_back(int(value));
    }
    r.expect_end();
    cells.push_back(t);
  }
  if(r.next_line()) r.fail("more lines than the " + std::to_string(n) + " tetrahedra the header announces");
  return cells;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads a TetGen `.ele` file of `number_of_points` points numbered from `first_index`: its
/// tetrahedra as 0-based point indices; a bad file throws an error that names it, the line and the problem.
inline std::vector<std::array<std::size_t, 4>>
read_ele_file(const std::string& path, std::size_t number_of_points, int first_index)
{
  return read_ele_text(path, read_text_file(path), number_of_points, first_index);
}

/// Writes a .node file (each coordinate in the shortest text that reads back exactly).
inline void write_node_file(std::ostream& stream, const std::vector<std::array<double, 3>>& points,
                            const std::vector<std::vector<double>>& attributes, int first_index)
{
  const std::size_t n_attr = attributes.empty() ? 0 : attributes.front().size();
  Text_sink out(stream); // to_chars: shortest text that reads back the same double
  out << points.size() << " 3 " << n_attr << " 0\n";
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    out << k + first_index << ' ' << finite_value(points[k][0], "a coordinate") << ' '
        << finite_value(points[k][1], "a coordinate") << ' ' << finite_value(points[k][2], "a coordinate");
    for(std::size_t a = 0; a < n_attr; ++a) out << ' ' << finite_value(attributes[k][a], "an attribute");
    out << '\n';
  }
}

/// Writes an .ele file; each tetrahedron positively oriented (TetGen's convention too).
/// With `regions` (one per tetrahedron), each is written as the tetrahedron's
/// attribute, as `tetgen -A` writes regions.
inline void write_ele_file(std::ostream& stream, const std::vector<std::array<std::size_t, 4>>& cells,
                           int first_index, const std::vector<int>* regions = nullptr)
{
  Text_sink out(stream);
  const bool with_regions = regions != nullptr && regions->size() == cells.size();
  out << cells.size() << (with_regions ? " 4 1\n" : " 4 0\n");
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    out << k + first_index << ' ' << cells[k][0] + first_index << ' ' << cells[k][1] + first_index << ' '
        << cells[k][2] + first_index << ' ' << cells[k][3] + first_index;
    if(with_regions) out << ' ' << (*regions)[k];
    out << '\n';
  }
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TETGEN_H
