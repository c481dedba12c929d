// Options of the swap drivers (one struct: CGAL 5.5 cannot add named
// parameters from outside the library) and the report they return.

#ifndef CGAL_EDGE_SWAPPING_3_SWAP_OPTIONS_H
#define CGAL_EDGE_SWAPPING_3_SWAP_OPTIONS_H

#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// The order in which a cycle visits the interior facets.
enum Face_order
{
  STORAGE_ORDER, ///< the order of the cells in the triangulation's container
  RANDOM_ORDER   ///< a new random permutation each cycle, drawn from `random_seed`
};

/// What one cycle over the facets did.
struct Cycle_record
{
  std::size_t cycle = 0;                                  ///< 1 for the first cycle
  std::array<std::size_t, number_of_flip_kinds> swaps{};  ///< indexed by `Flip_kind`
  std::size_t cells = 0;                                  ///< finite cells after the cycle
  long long non_delaunay_facets = -1;                     ///< after the cycle; -1 if not recorded

  std::size_t total_swaps() const { return swaps[0] + swaps[1] + swaps[2] + swaps[3]; }
};

struct Swap_options
{
  /// Random by default: in storage order the helper strategy can cycle (doc/Edge_swapping_3/findings.md).
  Face_order face_order = RANDOM_ORDER;
  unsigned int random_seed = 0;
  /// The driver stops after this many cycles and reports CYCLE_LIMIT_REACHED.
  std::size_t max_cycles = 1000;
  /// Count the facets that are not locally Delaunay after each cycle (a full pass).
  bool record_non_delaunay_facets = false;
  /// The tie-breaking of the Delaunay tests of the helper strategy and of the
  /// final test that tells CONVERGED from STUCK.
  Perturbation perturbation = CGAL_PERTURBATION;
  /// Called after each cycle (progress, history).
  std::function<void(const Cycle_record&)> cycle_visitor;
};

enum Swap_ending
{
  CONVERGED,           ///< a cycle made no swap (for Delaunay: and every facet is Delaunay)
  STUCK,               ///< Delaunay only: no swap possible, but some facet is not Delaunay
  CYCLE_LIMIT_REACHED  ///< still swapping after `max_cycles` cycles (possibly cycling)
};

inline const char* swap_ending_name(Swap_ending e)
{
  static const char* names[] = {"converged", "stuck", "cycle limit reached"};
  return names[e];
}

struct Swap_report
{
  std::vector<Cycle_record> cycles;
  Swap_ending ending = CONVERGED;
  /// Facets not locally Delaunay at the end (Delaunay criterion and helper only; else -1).
  long long non_delaunay_facets = -1;
  double seconds = 0;

  std::size_t number_of_cycles() const { return cycles.size(); }
  std::array<std::size_t, number_of_flip_kinds> total_swaps() const
  {
    std::array<std::size_t, number_of_flip_kinds> t{};
    for(const auto& c : cycles)
      for(int k = 0; k < number_of_flip_kinds; ++k) t[k] += c.swaps[k];
    return t;
  }
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_SWAP_OPTIONS_H
