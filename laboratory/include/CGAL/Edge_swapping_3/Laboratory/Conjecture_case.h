// SPDX-License-Identifier: GPL-3.0-or-later
// One case of the conjecture laboratory: points, a start triangulation, a
// strategy (plain Algorithm 3, the helper strategy, or insertion one point at
// a time with plain swaps after each) and a face order; running it exactly
// and comparing the end with CGAL's Delaunay triangulation. The laboratory
// runs the paper's method as the paper states it: its cycles over all
// facets, and no repair after a stuck state. Files of cases are in
// Laboratory/IO/conjecture_json.h.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_CASE_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_CASE_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Helper_reading.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/swap_edges.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <CGAL/Edge_swapping_3/Laboratory/Visit_trace.h>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Laboratory
/// What a case runs.
enum Conjecture_strategy
{
  PLAIN_SWAPS,               ///< Algorithm 3 with the Delaunay criterion (stuck states are counted)
  HELPER_STRATEGY,           ///< Algorithm 4 (Conjecture 1)
  INSERTION_WITH_PLAIN_SWAPS ///< each point split in, then plain swaps over all facets (Conjecture 2)
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// The start triangulation of a case.
enum Conjecture_start
{
  PLACING_START,            ///< each point, in the case's order, splits the cell it falls in (no flip)
  SCRAMBLED_DELAUNAY_START, ///< the Delaunay triangulation with `scramble_flips` random flips
  GIVEN_CELLS_START,        ///< the case's `cells` (a TOPCOM triangulation)
  NO_START                  ///< insertion: the points are inserted one at a time
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// Everything that fixes a run of the laboratory.
template <class Point>
struct Conjecture_case
{
  std::vector<Point> points;                     ///< placing and insertion: in insertion order
  Conjecture_start start = PLACING_START;        ///< the start triangulation
  std::size_t scramble_flips = 0;                ///< `SCRAMBLED_DELAUNAY_START`: the random flips
  std::vector<std::array<std::size_t, 4>> cells; ///< `GIVEN_CELLS_START`: the tetrahedra
  Conjecture_strategy strategy = HELPER_STRATEGY; ///< what runs
  Face_order order = RANDOM_ORDER;               ///< the face order of every cycle
  unsigned seed = 1;                             ///< of the face order and the scrambling flips
  std::size_t max_cycles = 1000;                 ///< the cycle limit of each run
  Helper_reading reading;                        ///< the helper strategy's reading of Algorithm 4
  /// The paper's cycles (the laboratory's), or the work queue (the package's
  /// default for users; the package's reading only). Insertion runs cycles.
  Schedule schedule = PAPER_CYCLES;
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// What running a case gave.
struct Conjecture_outcome
{
  bool bad_start = false;           ///< the given cells are not a triangulation (`start_problem` says why)
  std::string start_problem;        ///< what is wrong with the given cells
  Swap_ending ending = CONVERGED;   ///< insertion: stuck if any insertion's swaps were
  std::size_t cycles = 0;           ///< all runs together
  std::array<std::size_t, number_of_flip_kinds> swaps{}; ///< by `Flip_kind`
  bool equal_to_cgal = false;       ///< the end is CGAL's Delaunay triangulation, cell for cell
  bool valid = false;               ///< the end passes `is_valid()`
  long long non_delaunay_facets = -1; ///< at the end (-1: not counted)
  std::size_t insertions_not_converged = 0; ///< insertion: insertions whose swaps did not converge
  /// Helper in the fixed order, untraced: the run loops, and its state after cycle
  /// `loop_round` is first that of `loop_period` cycles before (`Swap_report::loop_round`);
  /// 0: no loop found.
  std::size_t loop_round = 0;
  std::size_t loop_period = 0; ///< see `loop_round`
  double seconds = 0;               ///< the run's time
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// The names of strategies, starts and face orders in files and options.
inline const char* conjecture_strategy_name(Conjecture_strategy s)
{
  static const char* names[] = {"plain", "helper", "insertion"};
  return names[s];
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The strategy named `name` ("plain", "helper", "insertion") in `s`; false for another name.
inline bool conjecture_strategy_from_name(const std::string& name, Conjecture_strategy& s)
{
  for(Conjecture_strategy k : {PLAIN_SWAPS, HELPER_STRATEGY, INSERTION_WITH_PLAIN_SWAPS})
    if(name == conjecture_strategy_name(k))
    {
      s = k;
      return true;
    }
  return false;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The start of `c` as files name it: "placing", "scramble:K", "cells" or "-" (insertion).
template <class Point>
std::string conjecture_start_name(const Conjecture_case<Point>& c)
{
  switch(c.start)
  {
    case PLACING_START: return "placing";
    case SCRAMBLED_DELAUNAY_START: return "scramble:" + std::to_string(c.scramble_flips);
    case GIVEN_CELLS_START: return "cells";
    default: return "-";
  }
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The ending as results files name it: `swap_ending_name()`, or "bad start: " and the problem.
inline std::string conjecture_ending_name(const Conjecture_outcome& o)
{
  return o.bad_start ? "bad start: " + o.start_problem : std::string(swap_ending_name(o.ending));
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Whether `o` is a counterexample to a conjecture: the helper strategy, or
/// insertion with plain swaps, did not end on CGAL's Delaunay triangulation.
template <class Point>
bool is_counterexample(const Conjecture_case<Point>& c, const Conjecture_outcome& o)
{
  return c.strategy != PLAIN_SWAPS && !o.bad_start && !o.equal_to_cgal;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The cells with their vertices ordered so that each is positively oriented
/// (TOPCOM gives unordered sets); a flat one, or one naming a point that does
/// not exist, is left as it is.
template <class Point>
std::vector<std::array<std::size_t, 4>> oriented_cells(const std::vector<Point>& points,
                                                       std::vector<std::array<std::size_t, 4>> cells)
{
  const auto orientation = typename CGAL::Kernel_traits<Point>::Kernel().orientation_3_object();
  for(auto& t : cells)
    if(t[0] < points.size() && t[1] < points.size() && t[2] < points.size() && t[3] < points.size() &&
       orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[0], t[1]);
  return cells;
}

namespace internal {

template <class Point>
auto laboratory_swap_parameters(const Conjecture_case<Point>& c)
{
  namespace np = Edge_swapping_3::parameters;
  return np::schedule(c.schedule,
                      np::face_order(c.order, np::helper_reading(c.reading,
                                                                 np::delaunay_repair(false, CGAL::parameters::random_seed(c.seed)
                                                                           .number_of_iterations(c.max_cycles)))));
}

inline void add_swap_report(Conjecture_outcome& o, const Swap_report& r)
{
  o.cycles += r.number_of_cycles();
  const auto t = r.total_swaps();
  for(int k = 0; k < number_of_flip_kinds; ++k) o.swaps[k] += t[k];
}

// Conjecture 2: each point is split in (or joined to the hull) and plain
// swaps over all facets, in the case's face order, follow. The first four
// affinely independent points start (one tetrahedron is Delaunay).
template <class Tr, class Point>
void run_insertion_case(Tr& tr, const Conjecture_case<Point>& c, Conjecture_outcome& o)
{
  const auto sequence = Edge_swapping_3::insertion_sequence(c.points, parameters::insertion_order(INPUT_ORDER));
  const auto settings = laboratory_swap_parameters(c);
  typename Tr::Vertex_handle hint;
  for(std::size_t k : sequence)
  {
    const auto cell = hint == typename Tr::Vertex_handle() ? typename Tr::Cell_handle() : hint->cell();
    hint = tr.insert(c.points[k], cell);
    if(tr.dimension() < 3 || tr.number_of_vertices() < 5) continue;
    const auto r = CGAL::swap_edges(tr, Delaunay_criterion(), settings);
    add_swap_report(o, r);
    if(r.ending != CONVERGED) ++o.insertions_not_converged;
  }
  o.ending = o.insertions_not_converged == 0 ? CONVERGED : STUCK;
}

} // namespace internal

namespace internal {

// Runs case `c`; with a trace writer, the plain and helper strategies write their trace.
template <class Point>
Conjecture_outcome run_conjecture_case(const Conjecture_case<Point>& c, Visit_trace_writer<Point>* trace)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef CGAL::Triangulation_3<K> Tr;
  const std::string problem = point_set_problem(c.points);
  if(!problem.empty()) throw std::invalid_argument(problem);
  if(trace != nullptr && c.strategy == INSERTION_WITH_PLAIN_SWAPS)
    throw std::invalid_argument("traces are written for the plain and helper strategies, not for insertion");
  if(c.schedule == WORK_QUEUE && (c.strategy == INSERTION_WITH_PLAIN_SWAPS || !c.reading.is_default()))
    throw std::invalid_argument("the work queue runs plain swapping and the helper's default reading only");
  Conjecture_outcome o;
  CGAL::Real_timer timer;
  timer.start();
  Tr tr;
  if(c.strategy == INSERTION_WITH_PLAIN_SWAPS)
    run_insertion_case(tr, c, o);
  else
  {
    switch(c.start)
    {
      case PLACING_START: insert_by_placing(tr, c.points, parameters::insertion_order(INPUT_ORDER)); break;
      case SCRAMBLED_DELAUNAY_START:
        insert_delaunay(tr, c.points);
        scramble(tr, c.scramble_flips, c.seed);
        break;
      case GIVEN_CELLS_START:
      {
        std::vector<typename Tr::Vertex_handle> vertices;
        o.start_problem = Edge_swapping_3::build_triangulation_from_cells(tr, c.points, c.cells, vertices);
        if(!o.start_problem.empty())
        {
          o.bad_start = true;
          return o;
        }
        break;
      }
      default: throw std::invalid_argument("the plain and helper strategies need a start triangulation");
    }
    const auto settings = laboratory_swap_parameters(c);
    auto run = [&](const auto& np) {
      return c.strategy == PLAIN_SWAPS ? CGAL::swap_edges(tr, Delaunay_criterion(), np)
                                       : CGAL::swap_edges_with_helper(tr, np);
    };
    Swap_report r;
    if(trace != nullptr)
    {
      trace->start(tr, {{"strategy", conjecture_strategy_name(c.strategy)},
                        {"schedule", c.schedule == WORK_QUEUE ? "queue" : "cycles"},
                        {"order", face_order_name(c.order)},
                        {"seed", c.seed},
                        {"reading", helper_reading_name(c.reading)},
                        {"max_rounds", c.max_cycles}});
      r = run(parameters::visit_visitor(std::ref(*trace), settings));
      trace->finish(swap_ending_name(r.ending), r.number_of_cycles());
    }
    else
      r = run(settings);
    add_swap_report(o, r);
    o.ending = r.ending;
    o.non_delaunay_facets = r.non_delaunay_facets;
    o.loop_round = r.loop_round;
    o.loop_period = r.loop_period;
  }
  o.valid = tr.is_valid();
  o.equal_to_cgal = o.valid && compare_with_delaunay(tr).identical;
  o.seconds = timer.time();
  return o;
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Laboratory
/// Runs the case `c` exactly (on a `Triangulation_3` of the points' kernel)
/// and compares the end with CGAL's Delaunay triangulation.
/// \pre the points can be triangulated in 3-D (else `std::invalid_argument`
/// with `point_set_problem()`'s message)
template <class Point>
Conjecture_outcome run_conjecture_case(const Conjecture_case<Point>& c)
{
  return internal::run_conjecture_case<Point>(c, nullptr);
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Runs the case `c` as `run_conjecture_case()` does and writes its trace to
/// `out` (`Visit_trace_writer`): every visit and the state after every cycle.
/// \pre the strategy is plain or helper (else `std::invalid_argument`)
template <class Point>
Conjecture_outcome trace_conjecture_case(const Conjecture_case<Point>& c, std::ostream& out)
{
  Visit_trace_writer<Point> writer(out, c.points);
  return internal::run_conjecture_case<Point>(c, &writer);
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_CASE_H
