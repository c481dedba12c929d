// SPDX-License-Identifier: GPL-3.0-or-later
// TOPCOM's text formats (Rambau's Triangulations Of Point Configurations and
// Oriented Matroids): a point configuration in homogeneous coordinates,
// `[[x,y,z,1],...]`, and the triangulations it enumerates, one per line,
// `T[...] := {{a,b,c,d},...};` with 0-based point indices.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TOPCOM_H
#define CGAL_EDGE_SWAPPING_3_IO_TOPCOM_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/number_utils.h>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// Writes `points` as a TOPCOM point configuration. TOPCOM reads exact
/// rationals; every coordinate here must be an integer (throws otherwise).
template <class Point>
void write_topcom_points(std::ostream& os, const std::vector<Point>& points)
{
  os << '[';
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    os << (k ? "," : "") << '[';
    for(int c = 0; c < 3; ++c)
    {
      const double x = CGAL::to_double(points[k][c]);
      if(!(std::floor(x) == x) || std::abs(x) > 1e15)
        throw std::invalid_argument("TOPCOM input needs integer coordinates; point " + std::to_string(k) +
                                    " has " + std::to_string(x));
      os << (long long)x << ',';
    }
    os << "1]";
  }
  os << "]\n";
}

/// Reads one line that TOPCOM printed (`points2allfinetriangs` and the
/// like) into `cells`: false for a line that is not a triangulation (it is
/// skipped); a malformed triangulation line throws, naming `line_number`.
inline bool read_topcom_triangulation_line(const std::string& line, std::size_t line_number,
                                           std::vector<std::array<std::size_t, 4>>& cells)
{
  const auto assign = line.find(":=");
  if(line.rfind("T[", 0) != 0 || assign == std::string::npos) return false;
  auto fail = [&](const std::string& what) {
    throw Input_error("TOPCOM output line " + std::to_string(line_number) + ": " + what);
  };
  cells.clear();
  std::size_t pos = line.find('{', assign);
  if(pos == std::string::npos) fail("no '{'");
  ++pos;
  for(;;)
  {
    pos = line.find_first_not_of(" ,", pos);
    if(pos == std::string::npos) fail("unterminated");
    if(line[pos] == '}') break;
    if(line[pos] != '{') fail("expected '{' at column " + std::to_string(pos + 1));
    const std::size_t close = line.find('}', pos);
    if(close == std::string::npos) fail("unterminated simplex");
    std::array<std::size_t, 4> cell{};
    std::size_t count = 0, k = pos + 1;
    while(k < close)
    {
      k = line.find_first_not_of(" ,", k);
      if(k >= close) break;
      // A point index: digits only (no sign), in range of std::size_t.
      const std::size_t stop = std::min(close, line.find_first_of(" ,", k));
      std::size_t value = 0;
      const auto [ptr, ec] = std::from_chars(line.data() + k, line.data() + stop, value);
      if(ec != std::errc() || ptr != line.data() + stop || line[k] == '-' || line[k] == '+')
        fail("bad index at column " + std::to_string(k + 1));
      if(count == 4) fail("a simplex with more than four points");
      cell[count++] = value;
      k = stop;
    }
    if(count != 4) fail("a simplex with " + std::to_string(count) + " points");
    cells.push_back(cell);
    pos = close + 1;
  }
  return true;
}

/// Reads every triangulation TOPCOM printed (see `read_topcom_triangulation_line()`).
inline std::vector<std::vector<std::array<std::size_t, 4>>> read_topcom_triangulations(std::istream& is)
{
  std::vector<std::vector<std::array<std::size_t, 4>>> result;
  std::vector<std::array<std::size_t, 4>> cells;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(is, line))
    if(read_topcom_triangulation_line(line, ++line_number, cells)) result.push_back(cells);
  return result;
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TOPCOM_H
