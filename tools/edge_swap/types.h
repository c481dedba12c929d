// SPDX-License-Identifier: GPL-3.0-or-later
// The triangulation the program works on: each vertex remembers the number of
// its point, so that point i of the input is point i of the output (new
// points are numbered after the input's).

#ifndef EDGE_SWAP_TYPES_H
#define EDGE_SWAP_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <charconv>
#include <stdexcept>
#include <string>

namespace edge_swap {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K> Vb;
// Cells carry a subdomain index and boundary references (Medit input).
typedef CGAL::Triangulation_cell_base_with_info_3<CGAL::Edge_swapping_3::Domain_cell_info, K> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Triangulation_3<K, Tds> Triangulation;

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
