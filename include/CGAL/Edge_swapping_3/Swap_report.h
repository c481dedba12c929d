// SPDX-License-Identifier: GPL-3.0-or-later
// What a swap driver reports: the rounds it made, how it ended, and, for the
// Delaunay repair, which path it took.

#ifndef CGAL_EDGE_SWAPPING_3_SWAP_REPORT_H
#define CGAL_EDGE_SWAPPING_3_SWAP_REPORT_H

#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// How a driver finds the facets to visit.
enum Schedule
{
  /// Visits every interior facet once, then only the facets whose
  /// configuration (or, for the helper, the tags of whose cells) changed since
  /// their last visit. A round ends when the facets queued before it are done.
  WORK_QUEUE,
  /// The paper's cycles: every round visits every interior facet that existed
  /// when it began and still exists when its turn comes.
  PAPER_CYCLES
};

/// The order of the visits within a round.
enum Face_order
{
  STORAGE_ORDER, ///< the order of the cells in the triangulation's container, then of the queue
  RANDOM_ORDER,  ///< a uniform random permutation of each round, drawn from `random_seed`
  /// A fixed total order on facets by their three points, drawn from
  /// `random_seed` and the same in every round (`facet_priority()`): the
  /// order is a function of the triangulation, so a run that comes back to a
  /// state at a round's end repeats itself from there.
  PRIORITY_ORDER
};

/// \ingroup PkgEdgeSwapping3Reports
/// "storage", "random" or "priority", as files and options name the orders.
inline const char* face_order_name(Face_order o)
{
  static const char* names[] = {"storage", "random", "priority"};
  return names[o];
}

/// \ingroup PkgEdgeSwapping3Reports
/// The face order named `name` ("storage", "random", "priority") in `o`; false for another name.
inline bool face_order_from_name(const std::string& name, Face_order& o)
{
  for(Face_order k : {STORAGE_ORDER, RANDOM_ORDER, PRIORITY_ORDER})
    if(name == face_order_name(k))
    {
      o = k;
      return true;
    }
  return false;
}

/// The rule a round applied at each facet it visited.
enum Round_rule
{
  PLAIN_RULE,  ///< Algorithm 2 under the criterion (for Delaunay: plain flips)
  HELPER_RULE  ///< Algorithm 4, the helper strategy
};

/// The name of `r`, for reports.
inline const char* round_rule_name(Round_rule r)
{
  static const char* names[] = {"plain", "helper"};
  return names[r];
}

/// What one round (one cycle of the paper) did.
struct Cycle_record
{
  std::size_t cycle = 0;                                  ///< 1 for the first round
  Round_rule rule = PLAIN_RULE;                           ///< the rule of the round
  std::array<std::size_t, number_of_flip_kinds> swaps{};  ///< indexed by `Flip_kind`
  std::size_t visits = 0;                                 ///< facets visited
  std::size_t new_tags = 0;                               ///< helper: cells tagged in this round
  std::size_t cells = 0;                                  ///< finite cells after the round
  long long non_delaunay_facets = -1;                     ///< after the round; -1 if not recorded

  /// The swaps of every kind in the round.
  std::size_t total_swaps() const { return swaps[0] + swaps[1] + swaps[2] + swaps[3]; }
};

/// \ingroup PkgEdgeSwapping3Reports
/// How a swap driver ended.
enum Swap_ending
{
  CONVERGED,           ///< nothing left to do (for Delaunay: and every facet is Delaunay)
  STUCK,               ///< Delaunay only: no swap possible, but some facet is not Delaunay
  CYCLE_LIMIT_REACHED, ///< still swapping after `number_of_iterations` rounds (possibly cycling)
  /// `improve_worst_tetrahedra` only: still improving when `maximum_running_time` ran out
  TIME_LIMIT_REACHED,
  INTERRUPTED          ///< `improve_worst_tetrahedra` only: its `stop_flag` was set
};

/// The name of `e`, for reports.
inline const char* swap_ending_name(Swap_ending e)
{
  static const char* names[] = {"converged", "stuck", "cycle limit reached", "time limit reached", "interrupted"};
  return names[e];
}

/// The steps of the Delaunay repair of `swap_edges`, in the order it tries them.
/// A repair that did not converge names its last step.
enum Delaunay_repair_path
{
  PLAIN_FLIPS,              ///< Algorithm 3 with the Delaunay criterion reached the Delaunay triangulation
  HELPER_FLIPS,             ///< plain flips were stuck; a round of the helper strategy finished the work
  PLAIN_FLIPS_AFTER_HELPER, ///< plain flips were stuck; after the helper's rounds, plain flips finished the work
  REBUILT                   ///< the helper had not converged within its bound; the cells were rebuilt
};

/// The name of `p`, for reports.
inline const char* delaunay_repair_path_name(Delaunay_repair_path p)
{
  static const char* names[] = {"plain flips", "helper flips", "plain flips after helper", "rebuilt"};
  return names[p];
}

/// \ingroup PkgEdgeSwapping3Reports
/// What a swap driver (`swap_edges()`, `swap_edges_with_helper()`) did and how it ended.
struct Swap_report
{
  std::vector<Cycle_record> cycles; ///< one record per round (the paper's cycle)
  Swap_ending ending = CONVERGED;   ///< converged, stuck, or the round limit reached
  /// Facets not locally Delaunay at the end (Delaunay criterion and helper only; else -1).
  long long non_delaunay_facets = -1;
  double seconds = 0; ///< the time of the run

  /// Delaunay repair only: the step that finished the work (the last one taken if none did).
  Delaunay_repair_path repair_path = PLAIN_FLIPS;
  long long stuck_after_plain_flips = 0; ///< Delaunay repair: the non-Delaunay facets plain flips left
  /// Delaunay repair: the rounds of the helper strategy (not those of plain
  /// flips between them, see `swap_edges()`).
  std::size_t helper_rounds = 0;
  std::size_t first_helper_round = 0;    ///< Delaunay repair: the number of the helper's first round (0: none)
  std::size_t rebuilt_cells = 0;         ///< Delaunay repair: the finite cells the rebuild replaced (0 if not needed)
  /// Helper in the fixed face order (`PRIORITY_ORDER`), when the driver found a state
  /// (cells and tags) come back, compared exactly, so that the run loops and the rounds
  /// after were added up, not run: the first round whose state is that of `loop_period`
  /// rounds before, and the loop's period, both placed by a 64-bit hash of each round's
  /// state (states equal by chance would misplace them, not make a loop). 0 if no state
  /// came back (or the driver did not look: a visitor, another order).
  std::size_t loop_round = 0;
  std::size_t loop_period = 0; ///< see `loop_round`

  /// The number of rounds.
  std::size_t number_of_cycles() const { return cycles.size(); }
  /// The facets visited in all rounds.
  std::size_t number_of_visits() const
  {
    std::size_t n = 0;
    for(const auto& c : cycles) n += c.visits;
    return n;
  }
  /// The swaps of all rounds, by kind (indexed by `Flip_kind`).
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

#endif // CGAL_EDGE_SWAPPING_3_SWAP_REPORT_H
