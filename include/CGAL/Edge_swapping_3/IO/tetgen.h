// TetGen .node and .ele files: reading with clear errors, writing so that
// coordinates read back to the same doubles.
//
// .node: "<#points> <dim=3> <#attributes> <#markers 0|1>", then
//        "<index> <x> <y> <z> [attributes] [marker]".
// .ele:  "<#tets> <nodes per tet=4> <#attributes>", then "<index> <n1> <n2> <n3> <n4> [attributes]".
// '#' starts a comment; indices start at 0 or 1 (the first point decides), as in TetGen.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TETGEN_H
#define CGAL_EDGE_SWAPPING_3_IO_TETGEN_H

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// A file that cannot be read as what it claims to be. The message names the
/// file, the line and the problem.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Node_file
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<double>> attributes; ///< per point, possibly empty
  int first_index = 1;
};

namespace internal {

// Reads a number from `token`; `fail(message)` must throw. NaN and
// infinities are named, not reported as garbage.
template <class T, class Fail>
T parse_token(const std::string& token, const char* what, const Fail& fail)
{
  std::istringstream t(token);
  T value;
  if(!(t >> value) || t.rdbuf()->in_avail() != 0)
  {
    if constexpr(std::is_floating_point<T>::value)
    {
      const double d = std::strtod(token.c_str(), nullptr);
      if(std::isnan(d) || std::isinf(d)) fail(std::string(what) + " is not finite: " + token);
    }
    fail(std::string("cannot read ") + what + " from '" + token + "'");
  }
  return value;
}

class Line_reader
{
public:
  explicit Line_reader(const std::string& path) : path_(path), in_(path)
  {
    if(!in_) throw Input_error(path + ": cannot open the file");
  }

  /// The next line with content, comments removed; false at the end.
  bool next(std::istringstream& line)
  {
    std::string s;
    while(std::getline(in_, s))
    {
      ++number_;
      const auto hash = s.find('#');
      if(hash != std::string::npos) s.erase(hash);
      if(s.find_first_not_of(" \t\r") == std::string::npos) continue;
      line.clear();
      line.str(s);
      return true;
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Input_error(path_ + ":" + std::to_string(number_) + ": " + what);
  }

  template <class T>
  T read(std::istringstream& line, const char* what)
  {
    std::string token;
    if(!(line >> token)) fail(std::string("missing ") + what);
    return parse_token<T>(token, what, [this](const std::string& m) { fail(m); });
  }

  static bool more(std::istringstream& line)
  {
    line >> std::ws;
    return !line.eof();
  }

  void expect_end(std::istringstream& line)
  {
    std::string extra;
    if(line >> extra) fail("unexpected '" + extra + "' at the end of the line");
  }

private:
  std::string path_;
  std::ifstream in_;
  std::size_t number_ = 0;
};

} // namespace internal

inline Node_file read_node_file(const std::string& path)
{
  internal::Line_reader r(path);
  std::istringstream line;
  if(!r.next(line)) r.fail("empty file: no header line");
  const long long n = r.read<long long>(line, "the number of points");
  const int dim = r.read<int>(line, "the dimension");
  const int n_attr = r.more(line) ? r.read<int>(line, "the number of attributes") : 0;
  const int n_mark = r.more(line) ? r.read<int>(line, "the number of boundary markers") : 0;
  r.expect_end(line);
  if(n < 0) r.fail("negative number of points");
  if(dim != 3) r.fail("the dimension is " + std::to_string(dim) + ", not 3");
  if(n_attr < 0 || (n_mark != 0 && n_mark != 1)) r.fail("bad attribute or marker count");

  Node_file f;
  f.points.reserve(std::size_t(n));
  for(long long k = 0; k < n; ++k)
  {
    if(!r.next(line)) r.fail("the file ends after " + std::to_string(k) + " of " + std::to_string(n) + " points");
    const long long index = r.read<long long>(line, "the point index");
    if(k == 0)
    {
      if(index != 0 && index != 1) r.fail("the first point index is " + std::to_string(index) + ", not 0 or 1");
      f.first_index = int(index);
    }
    else if(index != f.first_index + k)
      r.fail("point index " + std::to_string(index) + " out of sequence (expected " +
             std::to_string(f.first_index + k) + ")");
    std::array<double, 3> p;
    for(int c = 0; c < 3; ++c)
    {
      p[c] = r.read<double>(line, "a coordinate");
      if(!std::isfinite(p[c])) r.fail("a coordinate is not finite");
    }
    std::vector<double> attributes(static_cast<std::size_t>(n_attr));
    for(auto& a : attributes) a = r.read<double>(line, "an attribute");
    if(n_mark) r.read<double>(line, "the boundary marker");
    r.expect_end(line);
    f.points.push_back(p);
    f.attributes.push_back(std::move(attributes));
  }
  if(r.next(line)) r.fail("more lines than the " + std::to_string(n) + " points the header announces");
  return f;
}

/// Reads the tetrahedra of an .ele file, as 0-based point indices. `number_of_points`
/// and `first_index` come from the matching .node file.
inline std::vector<std::array<std::size_t, 4>>
read_ele_file(const std::string& path, std::size_t number_of_points, int first_index)
{
  internal::Line_reader r(path);
  std::istringstream line;
  if(!r.next(line)) r.fail("empty file: no header line");
  const long long n = r.read<long long>(line, "the number of tetrahedra");
  const int per = r.more(line) ? r.read<int>(line, "the number of nodes per tetrahedron") : 4;
  const int n_attr = r.more(line) ? r.read<int>(line, "the number of attributes") : 0;
  r.expect_end(line);
  if(n < 0) r.fail("negative number of tetrahedra");
  if(per != 4) r.fail("only linear tetrahedra (4 nodes) are supported, not " + std::to_string(per));
  if(n_attr < 0) r.fail("negative number of attributes");

  std::vector<std::array<std::size_t, 4>> cells;
  cells.reserve(std::size_t(n));
  for(long long k = 0; k < n; ++k)
  {
    if(!r.next(line)) r.fail("the file ends after " + std::to_string(k) + " of " + std::to_string(n) + " tetrahedra");
    r.read<long long>(line, "the tetrahedron index");
    std::array<std::size_t, 4> t;
    for(auto& v : t)
    {
      const long long i = r.read<long long>(line, "a node index");
      if(i < first_index || i >= first_index + (long long)number_of_points)
        r.fail("node index " + std::to_string(i) + " is not a point of the .node file");
      v = std::size_t(i - first_index);
    }
    for(int a = 0; a < n_attr; ++a) r.read<double>(line, "an attribute");
    r.expect_end(line);
    cells.push_back(t);
  }
  if(r.next(line)) r.fail("more lines than the " + std::to_string(n) + " tetrahedra the header announces");
  return cells;
}

/// Writes a .node file (17 significant digits: coordinates read back exactly).
inline void write_node_file(std::ostream& out, const std::vector<std::array<double, 3>>& points,
                            const std::vector<std::vector<double>>& attributes, int first_index)
{
  const std::size_t n_attr = attributes.empty() ? 0 : attributes.front().size();
  out.precision(17);
  out << points.size() << " 3 " << n_attr << " 0\n";
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    out << k + first_index << ' ' << points[k][0] << ' ' << points[k][1] << ' ' << points[k][2];
    for(std::size_t a = 0; a < n_attr; ++a) out << ' ' << attributes[k][a];
    out << '\n';
  }
}

/// Writes an .ele file; each tetrahedron positively oriented (TetGen's convention too).
inline void write_ele_file(std::ostream& out, const std::vector<std::array<std::size_t, 4>>& cells,
                           int first_index)
{
  out << cells.size() << " 4 0\n";
  for(std::size_t k = 0; k < cells.size(); ++k)
    out << k + first_index << ' ' << cells[k][0] + first_index << ' ' << cells[k][1] + first_index << ' '
        << cells[k][2] + first_index << ' ' << cells[k][3] + first_index << '\n';
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TETGEN_H
