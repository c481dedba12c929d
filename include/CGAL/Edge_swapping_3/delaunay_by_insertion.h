// SPDX-License-Identifier: GPL-3.0-or-later
// A Delaunay triangulation built from scratch by flip-based insertion: points
// in CGAL's spatial order (Hilbert with BRIO), each located by walking from
// the previous one, split in, and flipped outward (paper section 5).

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H

#include <CGAL/Real_timer.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/point_insertion.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <algorithm>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {

// The insertion sequence `seq` with the first four affinely independent points
// (in its order) moved to the front: one tetrahedron is its own Delaunay
// triangulation. Left as it is if there are none.
template <class Point, class Gt>
std::vector<std::size_t> basis_first(const std::vector<Point>& points, const Gt& gt, std::vector<std::size_t> seq)
{
  std::size_t basis[4], found = 0;
  for(std::size_t k = 0; k < seq.size() && found < 4; ++k)
  {
    const auto& q = points[seq[k]];
    bool independent = true;
    if(found >= 1) independent = (q != points[seq[basis[0]]]);
    if(found >= 2 && independent) independent = !gt.collinear_3_object()(points[seq[basis[0]]], points[seq[basis[1]]], q);
    if(found == 3 && independent)
      independent = gt.orientation_3_object()(points[seq[basis[0]]], points[seq[basis[1]]],
                                              points[seq[basis[2]]], q) != COPLANAR;
    if(independent) basis[found++] = k;
  }
  for(std::size_t m = 0; m < found; ++m)
    std::rotate(seq.begin() + m, seq.begin() + basis[m], seq.begin() + basis[m] + 1);
  return seq;
}

} // namespace internal

/// What `delaunay_by_insertion` did, over all points.
template <class Tr>
struct Insertion_report
{
  /// The vertex of each point, in the order of the input (equal points share one).
  std::vector<typename Tr::Vertex_handle> vertices;
  std::array<std::size_t, number_of_flip_kinds> swaps{}; ///< the swaps of all insertions, by kind
  std::size_t stuck_facets = 0;                          ///< should stay 0 (Joe 1991)
  double seconds = 0;                                    ///< the time of the run
};

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Makes the empty `tr` the Delaunay triangulation of `points` by
/// inserting them one at a time with plain flips (no helper).
///
/// With `CGAL_PERTURBATION` the result is CGAL's `Delaunay_triangulation_3`,
/// cell for cell. The first four affinely independent points (in the
/// insertion order) start the triangulation; if there are none (all points
/// coplanar) `tr` is left of lower dimension and is not Delaunay.
///
/// \tparam Tr a `CGAL::Triangulation_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr an empty triangulation
/// \param points the points
/// \param np an optional sequence of named parameters among the ones listed below
/// \pre `tr.number_of_vertices() == 0`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{insertion_order}
///     \cgalParamDescription{the order in which the points are inserted}
///     \cgalParamType{`Edge_swapping_3::Insertion_order`}
///     \cgalParamDefault{`Edge_swapping_3::SPATIAL_ORDER`}
///   \cgalParamNEnd
///   \cgalParamNBegin{perturbation}
///     \cgalParamDescription{how cospherical ties are broken}
///     \cgalParamType{`Edge_swapping_3::Perturbation`}
///     \cgalParamDefault{`Edge_swapping_3::CGAL_PERTURBATION`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the vertex of each point, the swaps made, the stuck facets (0) and the time
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
Insertion_report<Tr> delaunay_by_insertion(Tr& tr, const std::vector<typename Tr::Point>& points,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Tr::Vertex_handle Vertex_handle;
  CGAL_precondition(tr.number_of_vertices() == 0);
  const Insertion_order order = choose_parameter(get_parameter(np, internal_np::insertion_order), SPATIAL_ORDER);
  const Perturbation perturbation = choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION);
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<std::size_t> seq = internal::basis_first(
      points, tr.geom_traits(), internal::insertion_sequence<typename Tr::Geom_traits>(points, order));

  Insertion_report<Tr> report;
  report.vertices.resize(points.size());
  Vertex_handle hint;
  for(std::size_t k : seq)
  {
    if(tr.dimension() < 3)
      hint = report.vertices[k] =
        tr.insert(points[k], hint == Vertex_handle() ? typename Tr::Cell_handle() : hint->cell());
    else
    {
      const auto r = internal::insert_by_swapping(tr, points[k], Delaunay_criterion(), hint->cell(), No_constraints(),
                                                  perturbation, 0);
      hint = report.vertices[k] = r.vertex;
      for(int f = 0; f < number_of_flip_kinds; ++f) report.swaps[f] += r.swaps[f];
      report.stuck_facets += r.stuck_facets;
    }
  }
  report.seconds = timer.time();
  return report;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
