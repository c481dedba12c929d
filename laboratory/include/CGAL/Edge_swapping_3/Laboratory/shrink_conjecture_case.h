// SPDX-License-Identifier: GPL-3.0-or-later
// Shrinking a case of the conjecture laboratory: fewer points, the same
// failure (a stuck plain run, or a counterexample), so that it can be read.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_SHRINK_CONJECTURE_CASE_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_SHRINK_CONJECTURE_CASE_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <algorithm>
#include <stdexcept>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Laboratory
/// What `shrink_conjecture_case()` keeps.
enum Shrink_target
{
  KEEP_STUCK,         ///< plain swapping still ends stuck
  KEEP_COUNTEREXAMPLE ///< the end is still not CGAL's Delaunay triangulation
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// Removes points from `c`, in halves, quarters, ... down to single points,
/// as long as the case still fails as `target` says; returns the smaller
/// case. The start must not be `GIVEN_CELLS_START` (its cells name the points).
/// \pre `c` fails as `target` says (else `std::invalid_argument`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{called with the number of points after each removal that kept the failure}
///     \cgalParamType{a callable `void(std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
Conjecture_case<Point> shrink_conjecture_case(Conjecture_case<Point> c, Shrink_target target,
                                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), [](std::size_t) {});
  if(c.start == GIVEN_CELLS_START) throw std::invalid_argument("a case with an explicit start triangulation cannot be shrunk");
  auto fails = [&](const Conjecture_case<Point>& k) {
    if(!point_set_problem(k.points).empty()) return false;
    const auto o = run_conjecture_case(k);
    return target == KEEP_STUCK ? (!o.bad_start && o.ending == STUCK) : !o.equal_to_cgal;
  };
  if(!fails(c))
    throw std::invalid_argument(std::string("the case does not fail as '") +
                                (target == KEEP_STUCK ? "stuck" : "failure") + "' to begin with");
  for(std::size_t chunk = c.points.size() / 2; chunk >= 1;)
  {
    bool removed = false;
    for(std::size_t from = 0; from < c.points.size() && c.points.size() > 4;)
    {
      Conjecture_case<Point> smaller = c;
      const std::size_t to = (std::min)(from + chunk, smaller.points.size());
      smaller.points.erase(smaller.points.begin() + std::ptrdiff_t(from), smaller.points.begin() + std::ptrdiff_t(to));
      if(smaller.points.size() >= 4 && fails(smaller))
      {
        c = std::move(smaller);
        removed = true;
        visitor(c.points.size());
      }
      else
        from = to;
    }
    if(!removed) chunk /= 2;
  }
  return c;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_SHRINK_CONJECTURE_CASE_H
