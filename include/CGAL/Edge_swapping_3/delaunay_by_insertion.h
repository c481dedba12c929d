// SPDX-License-Identifier: GPL-3.0-or-later
// A Delaunay triangulation built from scratch by flip-based insertion: points
// in CGAL's spatial order (Hilbert with BRIO), each located by walking from
// the previous one, split in, and flipped outward (paper section 5).

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/point_insertion.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/Regular_criterion.h>
#include <CGAL/Edge_swapping_3/internal/split_with_data.h>
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
    auto at = [&](std::size_t m) -> const Point& { return points[seq[m]]; };
    const auto& q = at(k);
    bool independent = true;
    if(found >= 1) independent = (q != at(basis[0]));
    if(found >= 2 && independent) independent = !gt.collinear_3_object()(at(basis[0]), at(basis[1]), q);
    if(found == 3 && independent)
      independent = gt.orientation_3_object()(at(basis[0]), at(basis[1]), at(basis[2]), q) != COPLANAR;
    if(independent) basis[found++] = k;
  }
  for(std::size_t m = 0; m < found; ++m)
    std::rotate(seq.begin() + m, seq.begin() + basis[m], seq.begin() + basis[m] + 1);
  return seq;
}

} // namespace internal

/// The order in which the insertion functions take `points`: the
/// `insertion_order` (default `SPATIAL_ORDER`, CGAL's spatial sort), with the
/// first four affinely independent points moved to the front, so that one
/// tetrahedron, its own Delaunay and regular triangulation, starts. Weighted
/// points are ordered by their bare points. Named parameter `geom_traits`
/// (default: the points' kernel).
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t> insertion_sequence(const std::vector<Point>& points,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::decay_t<decltype(internal::bare_point(std::declval<const Point&>()))> Bare_point;
  typedef typename CGAL::Kernel_traits<Bare_point>::Kernel Kernel;
  const auto gt = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Kernel());
  const Insertion_order order = choose_parameter(get_parameter(np, internal_np::insertion_order), SPATIAL_ORDER);
  std::vector<Bare_point> bare;
  bare.reserve(points.size());
  for(const Point& p : points) bare.push_back(internal::bare_point(p));
  return internal::basis_first(bare, gt, internal::insertion_sequence<std::decay_t<decltype(gt)>>(bare, order));
}

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

namespace internal {

// Inserts `points` into the empty `tr` one at a time by flip insertion under
// the Delaunay or the regular criterion, in `insertion_sequence` order; the
// first four affinely independent points make one tetrahedron.
template <class Tr, class Criterion, class NamedParameters>
Insertion_report<Tr> build_by_insertion(Tr& tr, const std::vector<typename Tr::Point>& points,
                                        const Criterion& criterion, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Plain_triangulation_of<Tr>::type Base;
  CGAL_precondition(tr.number_of_vertices() == 0);
  const Insertion_order order = choose_parameter(get_parameter(np, internal_np::insertion_order), SPATIAL_ORDER);
  const Perturbation perturbation = choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION);
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<std::size_t> seq =
      insertion_sequence(points, parameters::insertion_order(order, CGAL::parameters::geom_traits(tr.geom_traits())));

  Insertion_report<Tr> report;
  report.vertices.resize(points.size());
  typename Tr::Cell_handle hint;
  std::size_t removed = 0;
  for(std::size_t k : seq)
  {
    if(tr.dimension() < 3)
    {
      report.vertices[k] = static_cast<Base&>(tr).insert(points[k], hint);
      hint = report.vertices[k]->cell();
      continue;
    }
    const auto r = insert_by_swapping(tr, points[k], criterion, hint, No_constraints(), perturbation, 0);
    report.vertices[k] = r.vertex;
    if(r.vertex != Vertex_handle()) hint = r.vertex->cell();
    for(int f = 0; f < number_of_flip_kinds; ++f) report.swaps[f] += r.swaps[f];
    report.stuck_facets += r.stuck_facets;
    removed += r.removed_vertices;
  }
  if(removed > 0)
    // A vertex removed later is dead, or its slot holds another point now.
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      Vertex_handle& v = report.vertices[k];
      if(v != Vertex_handle() && (!tr.tds().vertices().is_used(v) || !(v->point() == points[k]))) v = Vertex_handle();
    }
  report.seconds = timer.time();
  return report;
}

} // namespace internal

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
  return internal::build_by_insertion(tr, points, Delaunay_criterion(), np);
}

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Makes the empty `tr` the regular triangulation of the weighted
/// `points` by inserting them one at a time with `insert_by_swapping()` and
/// `Regular_criterion` (Edelsbrunner and Shah's flips: 2-3, 3-2, the coplanar
/// ones, and 4-1 for a vertex made redundant).
///
/// The result is meant to equal CGAL's `Regular_triangulation_3` of the points,
/// cell for cell, redundant points left out. The first four affinely
/// independent points (in the insertion order) start the triangulation.
///
/// \tparam Tr a `CGAL::Regular_triangulation_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr an empty triangulation
/// \param points the weighted points
/// \param np `insertion_order` (default `SPATIAL_ORDER`) and `perturbation`, as for `delaunay_by_insertion()`
/// \pre `tr.number_of_vertices() == 0`
/// \return the vertex of each point (the default handle for a redundant one, or for one a later point
///   made redundant), the swaps, the stuck facets (0 when the result is regular) and the time
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
Insertion_report<Tr> regular_by_insertion(Tr& tr, const std::vector<typename Tr::Point>& points,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::build_by_insertion(tr, points, Regular_criterion(), np);
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
