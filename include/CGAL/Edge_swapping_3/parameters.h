// SPDX-License-Identifier: GPL-3.0-or-later
// The package's own named parameters. CGAL's (`number_of_iterations`,
// `random_seed`, `visitor`, ...) are used as they are; these add the
// package's settings in the same convention, each in two forms:
//   ES::parameters::face_order(ES::RANDOM_ORDER).random_seed(3)
//   ES::parameters::face_order(ES::RANDOM_ORDER, CGAL::parameters::random_seed(3))

#ifndef CGAL_EDGE_SWAPPING_3_PARAMETERS_H
#define CGAL_EDGE_SWAPPING_3_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal_np {

enum schedule_t { schedule };
enum face_order_t { face_order };
enum perturbation_t { perturbation };
enum record_non_delaunay_facets_t { record_non_delaunay_facets };
enum cycle_visitor_t { cycle_visitor };
enum mesh_constraints_t { mesh_constraints };
enum delaunay_repair_t { delaunay_repair };
enum helper_rounds_before_rebuild_t { helper_rounds_before_rebuild };
enum maximum_ring_size_t { maximum_ring_size };
enum operations_t { operations };
enum maximum_moves_per_vertex_t { maximum_moves_per_vertex };
enum quality_target_t { quality_target };
enum keep_dihedral_angle_range_t { keep_dihedral_angle_range };
enum move_on_flat_boundary_t { move_on_flat_boundary };
enum vertex_change_angles_t { vertex_change_angles };
enum hint_t { hint };
enum maximum_swaps_t { maximum_swaps };
enum insertion_order_t { insertion_order };
enum aspect_ratio_definition_t { aspect_ratio_definition };
enum maximum_sites_t { maximum_sites };
enum new_vertex_visitor_t { new_vertex_visitor };
enum round_visitor_t { round_visitor };
enum number_of_threads_t { number_of_threads };
enum visit_visitor_t { visit_visitor };
enum helper_reading_t { helper_reading };
enum stop_flag_t { stop_flag };

} // namespace internal_np

namespace parameters {

#define CGAL_EDGE_SWAPPING_3_PARAMETER(NAME)                                                                 \
  template <class T>                                                                                       \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)                          \
  {                                                                                                        \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(value);                              \
  }                                                                                                        \
  template <class T, class T2, class Tag, class Base>                                                     \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t, CGAL::Named_function_parameters<T2, Tag, Base>> \
  NAME(const T& value, const CGAL::Named_function_parameters<T2, Tag, Base>& np)                          \
  {                                                                                                        \
    return {value, np};                                                                                    \
  }

/// `Schedule`: the work queue (default) or the paper's cycles.
CGAL_EDGE_SWAPPING_3_PARAMETER(schedule)
/// `Face_order`: the order of visits within a round (default `STORAGE_ORDER`).
CGAL_EDGE_SWAPPING_3_PARAMETER(face_order)
/// `Perturbation`: how a Delaunay criterion, the helper and Delaunay
/// insertion break cospherical ties (default `CGAL_PERTURBATION`). Its only home.
CGAL_EDGE_SWAPPING_3_PARAMETER(perturbation)
/// `bool`: count the non-Delaunay facets after each round (a full pass; default false).
CGAL_EDGE_SWAPPING_3_PARAMETER(record_non_delaunay_facets)
/// A callable `void(const Cycle_record&)`, called after each round.
CGAL_EDGE_SWAPPING_3_PARAMETER(cycle_visitor)
/// A visit visitor (`No_visit_visitor` documents the two calls), called after
/// every visit of a facet with a `Visit_record` and after every round: the
/// traces of the laboratory. Copied, like `visitor`: pass `std::ref`.
CGAL_EDGE_SWAPPING_3_PARAMETER(visit_visitor)
/// `Helper_reading`: the reading of Algorithm 4 (default: the package's);
/// another reading needs `schedule(PAPER_CYCLES)`.
CGAL_EDGE_SWAPPING_3_PARAMETER(helper_reading)
/// A model of `MeshConstraints_3` (default `No_constraints`).
CGAL_EDGE_SWAPPING_3_PARAMETER(mesh_constraints)
/// `bool`: whether `swap_edges` with the Delaunay criterion goes on from a
/// stuck state to the helper and then to a rebuild (default true); false
/// gives the paper's Algorithm 3 alone.
CGAL_EDGE_SWAPPING_3_PARAMETER(delaunay_repair)
/// `std::size_t`: the rounds the helper step of the Delaunay repair may take
/// before the rebuild (default 100).
CGAL_EDGE_SWAPPING_3_PARAMETER(helper_rounds_before_rebuild)
/// `int`: the largest number of tetrahedra around an edge that `remove_edge`
/// considers (default 10).
CGAL_EDGE_SWAPPING_3_PARAMETER(maximum_ring_size)
/// `unsigned`: the operations of `improve_worst_tetrahedra`, bits of
/// `Quality_operation` (default `TOPOLOGICAL_OPERATIONS`).
CGAL_EDGE_SWAPPING_3_PARAMETER(operations)
/// `int`: how many times smoothing may move one vertex in a run of
/// `improve_worst_tetrahedra` (default 200).
CGAL_EDGE_SWAPPING_3_PARAMETER(maximum_moves_per_vertex)
/// `double`: `improve_worst_tetrahedra` works only on the cells whose measure
/// is worse than this value (default: on every cell).
CGAL_EDGE_SWAPPING_3_PARAMETER(quality_target)
/// `bool`: whether `improve_worst_tetrahedra` refuses every operation that
/// makes a dihedral angle smaller than the smallest before the run or larger
/// than the largest (default true).
CGAL_EDGE_SWAPPING_3_PARAMETER(keep_dihedral_angle_range)
/// `bool`: `smooth_vertex` may move a vertex within a flat patch or along a
/// straight edge of the boundary (default false).
CGAL_EDGE_SWAPPING_3_PARAMETER(move_on_flat_boundary)
/// `std::pair<double, double>`: `improve_worst_tetrahedra` removes or inserts
/// vertices only at cells with a dihedral angle, in degrees, below the first
/// or above the second (default 30 and 140, as Stellar's results are read).
CGAL_EDGE_SWAPPING_3_PARAMETER(vertex_change_angles)

/// `const std::atomic<bool>*`: `improve_worst_tetrahedra` ends after the
/// operation under way once the flag reads true (default: no flag).
CGAL_EDGE_SWAPPING_3_PARAMETER(stop_flag)

/// `Tr::Cell_handle`: where the walk of `insert_by_swapping` starts (default: anywhere).
CGAL_EDGE_SWAPPING_3_PARAMETER(hint)
/// `std::size_t`: the most swaps `insert_by_swapping` makes after a split
/// under a criterion other than Delaunay (default 100000).
CGAL_EDGE_SWAPPING_3_PARAMETER(maximum_swaps)
/// `Insertion_order`: the order in which `delaunay_by_insertion` inserts the
/// points (default `SPATIAL_ORDER`).
CGAL_EDGE_SWAPPING_3_PARAMETER(insertion_order)
/// `Aspect_ratio_definition`: the measure `refine_by_aspect_ratio` refines
/// by (default `EDGE_LENGTH_RATIO`).
CGAL_EDGE_SWAPPING_3_PARAMETER(aspect_ratio_definition)
/// `std::size_t`: the most sites `refine_by_aspect_ratio` inserts (default: no limit).
CGAL_EDGE_SWAPPING_3_PARAMETER(maximum_sites)
/// A callable `void(Tr::Vertex_handle, const Site_location<Tr>&)`, called by
/// the refinement functions for each new vertex before the next site is
/// chosen: set its data (index, field values) there.
CGAL_EDGE_SWAPPING_3_PARAMETER(new_vertex_visitor)
/// A callable `void(const Refinement_round&)`, called by the refinement
/// functions after each round.
CGAL_EDGE_SWAPPING_3_PARAMETER(round_visitor)
/// `unsigned`: the threads of `run_conjecture_experiment` (default 0: every
/// core), of the first round's scan of `swap_edges` with a Delaunay
/// criterion (default 1), and the parts of `improve_worst_tetrahedra` (default 1).
CGAL_EDGE_SWAPPING_3_PARAMETER(number_of_threads)

#undef CGAL_EDGE_SWAPPING_3_PARAMETER

} // namespace parameters
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_PARAMETERS_H
