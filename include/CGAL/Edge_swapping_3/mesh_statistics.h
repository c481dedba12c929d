// SPDX-License-Identifier: GPL-3.0-or-later
// Counts and quality extremes of a triangulation, as the paper reports them.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H
#define CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// The counts of the paper's tables and the extreme qualities of a mesh (`mesh_statistics()`).
struct Mesh_statistics
{
  std::size_t vertices = 0;             ///< finite vertices
  std::size_t edges = 0;                ///< finite edges, hull included
  std::size_t faces = 0;                ///< finite facets, hull included
  std::size_t cells = 0;                ///< finite cells
  double min_dihedral_angle = HUGE_VAL; ///< degrees
  double max_dihedral_angle = 0;        ///< degrees
  double max_edge_length_ratio = 0;     ///< longest over shortest edge, worst cell
  double max_circumradius_over_inradius = 0;          ///< circumradius over inradius, worst cell
};

/// \ingroup PkgEdgeSwapping3Functions
/// The counts and extreme qualities of the finite part of `tr` in the domain.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints}
///     \cgalParamDescription{a model of `MeshConstraints_3`: only the cells `is_in_domain`, and the vertices,
///       edges and faces of such cells, are counted}
///     \cgalParamDefault{`No_constraints`: the whole finite part}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_statistics mesh_statistics(const Tr& tr, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto constraints = choose_parameter(get_parameter(np, internal_np::mesh_constraints), No_constraints());
  constexpr bool everything = std::is_same<std::decay_t<decltype(constraints)>, No_constraints>::value;
  Mesh_statistics s;
  auto in_domain = [&](typename Tr::Cell_handle c) { return everything || constraints.is_in_domain(tr, c); };
  if(everything)
  {
    s.vertices = tr.number_of_vertices();
    s.edges = tr.number_of_finite_edges();
    s.faces = tr.number_of_finite_facets();
    s.cells = tr.number_of_finite_cells();
  }
  else
  {
    for(auto v : tr.finite_vertex_handles())
    {
      std::vector<typename Tr::Cell_handle> around;
      tr.finite_incident_cells(v, std::back_inserter(around));
      s.vertices += std::any_of(around.begin(), around.end(), in_domain);
    }
    for(auto e : tr.finite_edges())
    {
      auto c = tr.incident_cells(e), done = c;
      bool found = false;
      do found = found || (!tr.is_infinite(c) && in_domain(c)); while(!found && ++c != done);
      s.edges += found;
    }
    for(auto f : tr.finite_facets())
    {
      const auto n = f.first->neighbor(f.second);
      s.faces += (!tr.is_infinite(f.first) && in_domain(f.first)) || (!tr.is_infinite(n) && in_domain(n));
    }
  }
  for(auto c : tr.finite_cell_handles())
  {
    if(!in_domain(c)) continue;
    if(!everything) ++s.cells;
    const auto& p0 = internal::bare_point(c->vertex(0)->point());
    const auto& p1 = internal::bare_point(c->vertex(1)->point());
    const auto& p2 = internal::bare_point(c->vertex(2)->point());
    const auto& p3 = internal::bare_point(c->vertex(3)->point());
    for(double a : dihedral_angles(p0, p1, p2, p3))
    {
      s.min_dihedral_angle = (std::min)(s.min_dihedral_angle, a);
      s.max_dihedral_angle = (std::max)(s.max_dihedral_angle, a);
    }
    s.max_edge_length_ratio = (std::max)(s.max_edge_length_ratio, edge_length_ratio(p0, p1, p2, p3));
    s.max_circumradius_over_inradius = (std::max)(s.max_circumradius_over_inradius, circumradius_over_inradius(p0, p1, p2, p3));
  }
  return s;
}

/// \ingroup PkgEdgeSwapping3Reports
/// One quality measure over the cells of a domain: its extremes and a histogram.
struct Quality_histogram
{
  double min = HUGE_VAL;           ///< the smallest value
  double max = -HUGE_VAL;          ///< the largest value
  double bin_start = 0;            ///< the lower end of the first bin
  double bin_width = 1;            ///< the width of every bin
  std::vector<std::size_t> counts; ///< values per bin; the values beyond the last bins are counted in the end bins

  /// Counts `value`.
  void add(double value)
  {
    min = (std::min)(min, value);
    max = (std::max)(max, value);
    const double bin = (value - bin_start) / bin_width;
    counts[std::size_t((std::min)(double(counts.size() - 1), (std::max)(0.0, bin)))]++;
  }
};

/// \ingroup PkgEdgeSwapping3Reports
/// The quality of the cells of a domain (`quality_histograms()`).
struct Quality_histograms
{
  std::size_t cells = 0;                                       ///< cells in the domain
  Quality_histogram dihedral_angle{HUGE_VAL, -HUGE_VAL, 0, 5, std::vector<std::size_t>(36)};     ///< degrees, 5-degree bins
  Quality_histogram edge_length_ratio{HUGE_VAL, -HUGE_VAL, 1, 0.25, std::vector<std::size_t>(40)}; ///< 1 to 11
  Quality_histogram circumradius_over_inradius{HUGE_VAL, -HUGE_VAL, 3, 1, std::vector<std::size_t>(40)};     ///< 3 (regular) to 43
};

/// \ingroup PkgEdgeSwapping3Functions
/// The extremes and histograms of the dihedral angles, edge length ratios
/// and radius ratios of the finite cells of `tr` in the domain.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints}
///     \cgalParamDescription{a model of `MeshConstraints_3`: only the cells `is_in_domain` are counted}
///     \cgalParamDefault{`No_constraints`: every finite cell}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class NamedParameters = CGAL::parameters::Default_named_parameters>
Quality_histograms quality_histograms(const Tr& tr, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto constraints = choose_parameter(get_parameter(np, internal_np::mesh_constraints), No_constraints());
  Quality_histograms h;
  for(auto c : tr.finite_cell_handles())
  {
    if(!constraints.is_in_domain(tr, c)) continue;
    ++h.cells;
    const auto& p0 = internal::bare_point(c->vertex(0)->point());
    const auto& p1 = internal::bare_point(c->vertex(1)->point());
    const auto& p2 = internal::bare_point(c->vertex(2)->point());
    const auto& p3 = internal::bare_point(c->vertex(3)->point());
    for(double a : dihedral_angles(p0, p1, p2, p3)) h.dihedral_angle.add(a);
    h.edge_length_ratio.add(Edge_swapping_3::edge_length_ratio(p0, p1, p2, p3));
    h.circumradius_over_inradius.add(Edge_swapping_3::circumradius_over_inradius(p0, p1, p2, p3));
  }
  return h;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MESH_STATISTICS_H
