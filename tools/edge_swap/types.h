// SPDX-License-Identifier: GPL-3.0-or-later
// The triangulation the program works on: each vertex remembers the number of
// its point, so that point i of the input is point i of the output (new
// points are numbered after the input's); each cell its subdomain and
// boundary references. The program's errors.

#ifndef EDGE_SWAP_TYPES_H
#define EDGE_SWAP_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/Mesh_with_fields.h>
#include <charconv>
#include <stdexcept>
#include <string>

namespace edge_swap {

namespace ES = CGAL::Edge_swapping_3;
namespace IO = CGAL::Edge_swapping_3::IO;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef ES::Numbered_domain_triangulation_3<K> Triangulation;
typedef ES::Mesh_with_fields<Point> Input;

/// Bad options or bad input: exit code 2, nothing written.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// `text` as a whole number from 0 to `largest`, or a Usage_error that names
/// `what` (an option, or a field of a file) and the text.
inline unsigned long long whole_number(const std::string& text, const std::string& what,
                                       unsigned long long largest = 1000000000ULL)
{
  unsigned long long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if(text.empty() || ec == std::errc::invalid_argument || ptr != end)
    throw Usage_error(what + " needs a whole number, not '" + text.substr(0, 40) + "'");
  if(ec == std::errc::result_out_of_range || value > largest)
    throw Usage_error(what + " is " + text.substr(0, 40) + ", more than " + std::to_string(largest));
  return value;
}

} // namespace edge_swap

#endif
