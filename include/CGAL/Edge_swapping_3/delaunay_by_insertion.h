// SPDX-License-Identifier: GPL-3.0-or-later
// A Delaunay triangulation built from scratch by flip-based insertion: points
// in CGAL's spatial order (Hilbert with BRIO), each located by walking from
// the previous one, split in, and flipped outward (paper section 5).

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H

#include <CGAL/Real_timer.h>
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
struct Insertion_totals
{
  std::array<std::size_t, number_of_flip_kinds> swaps{};
  std::size_t stuck_facets = 0; ///< should stay 0 (Joe 1991)
  double seconds = 0;
};

/// Makes the empty `tr` the Delaunay triangulation of `points` by inserting
/// them one at a time with plain flips (no helper), in `order`. With
/// `CGAL_PERTURBATION` the result is CGAL's Delaunay_triangulation_3, cell for
/// cell. The first four affinely independent points (in that order) start the
/// triangulation; if there are none (all points coplanar) `tr` is left of
/// lower dimension and is not Delaunay. Returns the vertex of each point
/// (equal points share one).
template <class Tr>
std::vector<typename Tr::Vertex_handle>
delaunay_by_insertion(Tr& tr, const std::vector<typename Tr::Point>& points,
                      Insertion_totals* totals = nullptr,
                      Insertion_order order = SPATIAL_ORDER,
                      Perturbation perturbation = CGAL_PERTURBATION)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  CGAL_precondition(tr.number_of_vertices() == 0);
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<std::size_t> seq = internal::basis_first(
      points, tr.geom_traits(), internal::insertion_sequence<typename Tr::Geom_traits>(points, order));

  std::vector<Vertex_handle> vertices(points.size());
  Insertion_totals local;
  Vertex_handle hint;
  const Delaunay_criterion criterion(perturbation);
  for(std::size_t k : seq)
  {
    if(tr.dimension() < 3)
      hint = vertices[k] = tr.insert(points[k], hint == Vertex_handle() ? typename Tr::Cell_handle() : hint->cell());
    else
    {
      const auto r = insert_by_swapping(tr, points[k], criterion, hint->cell());
      hint = vertices[k] = r.vertex;
      for(int f = 0; f < number_of_flip_kinds; ++f) local.swaps[f] += r.swaps[f];
      local.stuck_facets += r.stuck_facets;
    }
  }
  local.seconds = timer.time();
  if(totals) *totals = local;
  return vertices;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_BY_INSERTION_H
