// SPDX-License-Identifier: GPL-3.0-or-later
// The words on the command lines of the laboratory's programs
// (edge_swap_lab, experiment_priority_loops, experiment_adversarial_orders): whole numbers,
// and the point sets named random-integer:N:SET or family:NAME:N:SEED.

#ifndef EDGE_SWAPPING_3_LABORATORY_ARGUMENTS_H
#define EDGE_SWAPPING_3_LABORATORY_ARGUMENTS_H

#include <CGAL/Edge_swapping_3/point_families.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace laboratory_arguments {

/// `text` as a whole number of at most `most` in `value`; false when it is not
/// digits only ("12x", "-1", "") or larger.
inline bool whole_number(const std::string& text, std::size_t& value,
                         std::size_t most = std::numeric_limits<std::size_t>::max())
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  try
  {
    value = std::stoul(text);
  }
  catch(const std::out_of_range&)
  {
    return false;
  }
  return value <= most;
}

/// The points of `name` when it is random-integer:N:SET or family:NAME:N:SEED, and
/// true; false when it is neither form (a file, then). N is from 4 to 10^8, as
/// for `edge_swap_lab experiment --sizes`, SET and SEED at most 2^32 - 1. Throws
/// `std::invalid_argument` naming the problem for a malformed name, an unknown
/// family, a family refusing N, or points that cannot be triangulated.
template <class Point>
bool named_point_set(const std::string& name, std::vector<Point>& points)
{
  std::vector<std::string> part(1);
  for(char ch : name)
    if(ch == ':') part.emplace_back();
    else part.back() += ch;
  const bool family = part[0] == "family";
  if(!family && part[0] != "random-integer") return false;
  const std::string form = family ? "family:NAME:N:SEED" : "random-integer:N:SET";
  std::size_t n = 0, seed = 0;
  if(part.size() != (family ? 4u : 3u) || !whole_number(part[part.size() - 2], n) ||
     !whole_number(part.back(), seed, std::numeric_limits<unsigned>::max()))
    throw std::invalid_argument("'" + name + "' is not " + form + " with whole numbers N and " +
                                (family ? "SEED" : "SET") + " (at most 4294967295)");
  if(n < 4 || n > 100000000)
    throw std::invalid_argument("'" + name + "': N is from 4 to 100000000, not " + part[part.size() - 2]);
  points = family ? CGAL::Edge_swapping_3::make_point_family<Point>(part[1], n, unsigned(seed))
                  : CGAL::Edge_swapping_3::point_families::random_integer<Point>(n, unsigned(seed));
  const std::string problem = CGAL::Edge_swapping_3::point_set_problem(points);
  if(!problem.empty()) throw std::invalid_argument("'" + name + "': " + problem);
  return true;
}

} // namespace laboratory_arguments

#endif // EDGE_SWAPPING_3_LABORATORY_ARGUMENTS_H
