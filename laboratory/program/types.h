// SPDX-License-Identifier: GPL-3.0-or-later
// The laboratory program's kernel and points, its errors, and how it reads
// whole numbers from options.

#ifndef EDGE_SWAP_LAB_TYPES_H
#define EDGE_SWAP_LAB_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include "laboratory_arguments.h"
#include <CGAL/Edge_swapping_3/IO/output_files.h>
#include <stdexcept>
#include <string>

namespace edge_swap_lab {

namespace ES = CGAL::Edge_swapping_3;
namespace IO = CGAL::Edge_swapping_3::IO;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
using IO::check_output_paths;
using IO::Output_files;

/// Bad options or bad input: exit code 2, nothing written.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// `--quiet`: no progress lines.
inline bool quiet = false;

/// `text` as a whole number from 0 to `largest`, or a Usage_error that names
/// `what` (an option, or a part of one) and the text.
inline unsigned long long whole_number(const std::string& text, const std::string& what,
                                       unsigned long long largest = 1000000000ULL)
{
  std::size_t value = 0;
  if(laboratory_arguments::whole_number(text, value, largest)) return value;
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error(what + " needs a whole number, not '" + text.substr(0, 40) + "'");
  throw Usage_error(what + " is " + text.substr(0, 40) + ", more than " + std::to_string(largest));
}

} // namespace edge_swap_lab

#endif
