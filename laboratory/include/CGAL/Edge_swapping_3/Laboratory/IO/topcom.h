// SPDX-License-Identifier: GPL-3.0-or-later
// TOPCOM's text formats (Rambau's Triangulations Of Point Configurations and
// Oriented Matroids): a point configuration in homogeneous coordinates,
// `[[x,y,z,1],...]`, and the triangulations it enumerates, one per line,
// `T[...] := {{a,b,c,d},...};` with 0-based point indices.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_H

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
#include <string_view>
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
inline bool read_topcom_triangulation_line(std::string_view line, std::size_t line_number,
                                           std::vector<std::array<std::size_t, 4>>& cells)
{
  const auto assign = line.find(":=");
  if(line.substr(0, 2) != "T[" || assign == std::string_view::npos) return false;
  auto fail = [&](const std::string& what) {
    throw Input_error("TOPCOM output line " + std::to_string(line_number) + ": " + what);
  };
  // One pass over the characters: a streamed enumeration reads millions of these lines.
  const char* const begin = line.data();
  const char* const end = begin + line.size();
  const auto column = [&](const char* at) { return std::to_string(at - begin + 1); };
  const auto separator = [](char ch) { return ch == ' ' || ch == ','; };
  cells.clear();
  const char* p = begin + assign;
  while(p != end && *p != '{') ++p;
  if(p == end) fail("no '{'");
  ++p;
  for(;;)
  {
    while(p != end && separator(*p)) ++p;
    if(p == end) fail("unterminated");
    if(*p == '}') break;
    if(*p != '{') fail("expected '{' at column " + column(p));
    const char* close = p;
    while(close != end && *close != '}') ++close;
    if(close == end) fail("unterminated simplex");
    std::array<std::size_t, 4> cell{};
    std::size_t count = 0;
    for(const char* k = p + 1; k < close;)
    {
      while(k < close && separator(*k)) ++k;
      if(k == close) break;
      // A point index: digits only (no sign), in range of std::size_t.
      const char* stop = k;
      while(stop < close && !separator(*stop)) ++stop;
      std::size_t value = 0;
      const auto [ptr, ec] = std::from_chars(k, stop, value);
      if(ec != std::errc() || ptr != stop || *k == '-' || *k == '+') fail("bad index at column " + column(k));
      if(count == 4) fail("a simplex with more than four points");
      cell[count++] = value;
      k = stop;
    }
    if(count != 4) fail("a simplex with " + std::to_string(count) + " points");
    cells.push_back(cell);
    p = close + 1;
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

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_H
