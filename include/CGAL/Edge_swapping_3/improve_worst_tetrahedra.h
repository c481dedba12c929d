// SPDX-License-Identifier: GPL-3.0-or-later
// The quality driver: hill climbing on the worst tetrahedra first. A queue
// holds the finite cells by the criterion's measure, worst first; the worst
// cell is taken and the operations are tried on it in a fixed order (edge
// removal on its six edges, multi-face removal at its four facets, the flip
// of each of its four facets, then, when asked, the smoothing of each of its
// vertices, the removal of each of its vertices and the insertion of a vertex
// in it); the first that improves the worst tetrahedron of its
// neighbourhood is made, and the cells whose operations that changed go into
// the queue. The run ends when the queue is empty (with smoothing, when a
// sweep over every cell moves no vertex): then no operation improves any
// cell, and a second run makes no change (with smoothing, none but moves of
// the vertices that used up their `maximum_moves_per_vertex`; with vertex
// insertion, it may insert in cells whose inserted vertices barred it).

#ifndef CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H
#define CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H

#include <CGAL/Edge_swapping_3/Dihedral_angle_guard.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Quality_report.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/internal/optimizer/Worst_first_optimizer.h>
#include <CGAL/Edge_swapping_3/internal/optimizer/partitioned_optimization.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {

/// The named parameters of `improve_worst_tetrahedra`, read once.
template <bool larger_is_worse, class Tr, class NamedParameters>
Worst_first_settings worst_first_settings(const Tr& tr, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Worst_first_settings s;
  s.operations = choose_parameter(get_parameter(np, internal_np::operations), unsigned(TOPOLOGICAL_OPERATIONS));
  s.maximum_ring = choose_parameter(get_parameter(np, internal_np::maximum_ring_size), 10);
  s.maximum_moves = choose_parameter(get_parameter(np, internal_np::maximum_moves_per_vertex), default_maximum_moves);
  const std::pair<double, double> change_angles =
      choose_parameter(get_parameter(np, internal_np::vertex_change_angles), std::pair<double, double>(30, 140));
  s.smallest_change_angle = change_angles.first;
  s.largest_change_angle = change_angles.second;
  const double target =
      choose_parameter(get_parameter(np, internal_np::quality_target), larger_is_worse ? -HUGE_VAL : HUGE_VAL);
  // Scores are larger-is-better: a cell scoring at least this needs no work.
  s.enough = larger_is_worse ? -target : target;
  s.maximum_operations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                          100 * tr.number_of_finite_cells());
  s.maximum_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), HUGE_VAL);
  s.stop = choose_parameter(get_parameter(np, internal_np::stop_flag), static_cast<const std::atomic<bool>*>(nullptr));
  return s;
}

} // namespace internal

/// Improves the worst tetrahedra of `tr` under `criterion` (any
/// `Worst_tetrahedron_criterion`: MinMax or MaxMin dihedral angle, an aspect
/// ratio) by hill climbing, worst first: edge removal (`remove_edge`) on each
/// edge of the worst cell, multi-face removal (`remove_faces`) at each of its
/// facets, the flip of each of its facets, then, with `SMOOTHING`, the
/// smoothing (`smooth_vertex`) of each of its vertices, with `VERTEX_REMOVAL`
/// the removal (`remove_vertex`) of each of its vertices and with
/// `VERTEX_INSERTION` the insertion of a vertex in it (`insert_vertex`), the
/// first that improves the worst tetrahedron where it acts. Every change improves
/// that worst value beyond the criterion's relative tolerance, so the worst
/// value over the mesh never gets worse and the run ends.
///
/// By default no change makes a dihedral angle smaller than the smallest of
/// the domain before the run, or larger than the largest
/// (`Dihedral_angle_guard.h`): a one-sided criterion such as MinMax would
/// otherwise trade small angles for large ones, and smoothing under it can
/// flatten cells.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{operations} bits of `Quality_operation` (default `TOPOLOGICAL_OPERATIONS`: no
///     point moves unless asked) \cgalParamNEnd
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{maximum_ring_size} the largest ring edge removal considers, and the most
///     triangles multi-face removal explores, default 10 \cgalParamNEnd
///   \cgalParamNBegin{maximum_moves_per_vertex} with `SMOOTHING`, the most times a vertex moves in a run,
///     default 200: smoothing a vertex to the best place of its star moves its neighbours' best places, so
///     the vertices near a fixed boundary move many times; the bound makes the run end (a lower one ends
///     it sooner, with worse cells left: user manual, "The quality driver") \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} the most operations made (smoothing moves included), default 100
///     times the number of cells \cgalParamNEnd
///   \cgalParamNBegin{quality_target} a value of the measure: only the cells worse than it are taken from the
///     queue (as TetGen's optimizer works only on the cells above its target angle); default: every cell, and
///     the run ends when no operation improves any cell \cgalParamNEnd
///   \cgalParamNBegin{keep_dihedral_angle_range} `bool`, default true: refuse every operation that makes a
///     dihedral angle outside the range of the domain's before the run \cgalParamNEnd
///   \cgalParamNBegin{vertex_change_angles} `std::pair<double, double>`, default (30, 140): with `VERTEX_REMOVAL`
///     or `VERTEX_INSERTION`, vertices are removed and inserted only at cells with a dihedral angle, in degrees,
///     below the first or above the second; no vertex is inserted in a cell that has a vertex inserted in the run
///     \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time} `double`, seconds, default no limit: the run ends after the operation
///     under way when this much time has passed since it began, with the ending `TIME_LIMIT_REACHED`; the mesh
///     is valid and each change made improved it \cgalParamNEnd
///   \cgalParamNBegin{stop_flag} `const std::atomic<bool>*`, default none: the run ends in the same way, with the
///     ending `INTERRUPTED`, once the flag reads true (set it from another thread or a signal handler) \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads} `unsigned`, default 1; 0: every core. With more than one, and a mesh of
///     at least 5,000 cells a thread under `No_constraints` or `Domain_constraints`, the mesh is cut into as many
///     parts, optimized at once with their frontiers frozen, glued back, and the band around the frontiers is
///     optimized last (`internal/optimizer/partitioned_optimization.h`). The result depends on the number of
///     threads, not on their timing (the same number gives the same mesh, cell for cell, with or without TBB);
///     the visitor is called by one part at a time, on the part's triangulation (a copy of `tr` for every part
///     but the first: data it writes in cells and vertices is carried back, handles it keeps are not). Memory:
///     a copy of the triangulation per thread beyond the first. Other constraints run on one thread \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor`: told of
///     every flip, removal (each step of a two-step removal), move, vertex insertion and vertex removal \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Quality_report improve_worst_tetrahedra(Tr& tr, const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool keep_range = choose_parameter(get_parameter(np, internal_np::keep_dihedral_angle_range), true);
  const internal::Worst_first_settings settings = internal::worst_first_settings<larger_is_worse>(tr, np);
  const auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  typedef std::decay_t<decltype(visitor)> Visitor;
  const unsigned threads = internal::threads_asked(choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u));
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    typedef std::decay_t<decltype(constraints)> Constraints;
    typedef Worst_tetrahedron_criterion<Measure, larger_is_worse> Criterion;
    auto optimize = [&](const auto& guarded) {
      typedef std::decay_t<decltype(guarded)> Guarded;
      const unsigned parts = internal::number_of_parts<Constraints>(tr, threads);
      if(parts > 1)
        return internal::optimize_in_parts(tr, guarded, criterion, constraints, visitor, settings, parts);
      return internal::Worst_first_optimizer<Tr, Guarded, Criterion, Constraints, Visitor>(tr, guarded, criterion,
                                                                                          constraints, visitor, settings)
          .run();
    };
    if(!keep_range) return optimize(criterion);
    const Dihedral_angle_range range = dihedral_angle_range(
        tr, [&](typename Tr::Cell_handle c) { return constraints.is_in_domain(tr, c); });
    // Reported in the criterion's own measure (the guard computes the
    // angles on the points in another order: the last bits may differ).
    return optimize(guarded_by_dihedral_angles(criterion, range));
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IMPROVE_WORST_TETRAHEDRA_H
