// SPDX-License-Identifier: GPL-3.0-or-later
// Start triangulations for experiments: placing (no flip at all), CGAL's
// Delaunay triangulation, and a Delaunay triangulation scrambled by random flips.

#ifndef CGAL_EDGE_SWAPPING_3_START_TRIANGULATIONS_H
#define CGAL_EDGE_SWAPPING_3_START_TRIANGULATIONS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// The order in which points are inserted.
enum Insertion_order
{
  SPATIAL_ORDER, ///< CGAL's spatial_sort (Hilbert order with BRIO): fast
  INPUT_ORDER    ///< the order of the input
};

namespace internal {
template <class Gt>
std::vector<std::size_t> insertion_sequence(const std::vector<typename Gt::Point_3>& points,
                                            Insertion_order order)
{
  std::vector<std::size_t> seq(points.size());
  std::iota(seq.begin(), seq.end(), std::size_t(0));
  if(order == SPATIAL_ORDER)
  {
    typedef CGAL::Spatial_sort_traits_adapter_3<
        Gt, typename CGAL::Pointer_property_map<typename Gt::Point_3>::const_type> Traits;
    CGAL::spatial_sort(seq.begin(), seq.end(), Traits(CGAL::make_property_map(points)));
  }
  return seq;
}
} // namespace internal

/// Inserts `points` into the empty `tr` with Triangulation_3::insert: each point
/// splits the cell it falls in, or is joined to the hull facets it sees; no
/// flip at all, so the result is an arbitrary (usually poor) triangulation.
/// Returns the vertex of each point (equal points share one vertex).
/// Named parameter: `insertion_order` (default `SPATIAL_ORDER`).
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename Tr::Vertex_handle>
insert_by_placing(Tr& tr, const std::vector<typename Tr::Point>& points,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Insertion_order order = choose_parameter(get_parameter(np, internal_np::insertion_order), SPATIAL_ORDER);
  std::vector<typename Tr::Vertex_handle> vertices(points.size());
  typename Tr::Vertex_handle hint;
  for(std::size_t k : internal::insertion_sequence<typename Tr::Geom_traits>(points, order))
    hint = vertices[k] = tr.insert(points[k], hint == typename Tr::Vertex_handle() ? typename Tr::Cell_handle() : hint->cell());
  return vertices;
}

/// Makes the empty `tr` CGAL's Delaunay triangulation of `points` (built by
/// Delaunay_triangulation_3 on the same data structure, then moved in).
/// Returns the vertex of each point.
template <class Tr>
std::vector<typename Tr::Vertex_handle> insert_delaunay(Tr& tr, const std::vector<typename Tr::Point>& points)
{
  typedef typename Tr::Geom_traits Gt;
  typedef typename Tr::Vertex_handle Vertex_handle;
  CGAL::Delaunay_triangulation_3<Gt, typename Tr::Triangulation_data_structure> dt;
  std::vector<Vertex_handle> vertices(points.size());
  Vertex_handle hint;
  for(std::size_t k : internal::insertion_sequence<Gt>(points, SPATIAL_ORDER))
    hint = vertices[k] = dt.insert(points[k], hint == Vertex_handle() ? typename Tr::Cell_handle() : hint->cell());
  const Vertex_handle infinite = tr.infinite_vertex();
  tr.tds().swap(dt.tds());
  tr.set_infinite_vertex(dt.infinite_vertex());
  dt.set_infinite_vertex(infinite);
  return vertices;
}

/// Applies `number_of_flips` random valid flips of any kind (2-3, 3-2, 2-2,
/// 4-4) to `tr`, drawn from `seed`. Returns the number of each kind made.
template <class Tr>
std::array<std::size_t, number_of_flip_kinds> scramble(Tr& tr, std::size_t number_of_flips,
                                                       unsigned int seed)
{
  typedef typename Tr::Cell_handle Cell_handle;
  CGAL::Random rng(seed);
  std::vector<Cell_handle> cells;
  for(auto c : tr.finite_cell_handles()) cells.push_back(c);
  std::array<std::size_t, number_of_flip_kinds> made{};
  std::array<Cell_handle, 4> created;
  std::size_t done = 0, attempts = 0;
  // Candidates: a random cell of the pool, a random facet. Stale handles
  // (cells freed by a flip) are dropped when drawn; new cells join the pool.
  while(done < number_of_flips && !cells.empty() && attempts < 100 * number_of_flips + 1000)
  {
    ++attempts;
    const std::size_t k = std::size_t(rng.get_int(0, int(cells.size())));
    const Cell_handle c = cells[k];
    if(!tr.tds().cells().is_used(c) || tr.is_infinite(c))
    {
      cells[k] = cells.back();
      cells.pop_back();
      continue;
    }
    const auto conf = classify_facet(tr, c, rng.get_int(0, 4));
    if(!conf.is_swappable()) continue;
    const int n = flip(tr, conf, created);
    for(int m = 0; m < n; ++m) cells.push_back(created[m]);
    ++made[conf.flip_kind()];
    ++done;
  }
  return made;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_START_TRIANGULATIONS_H
