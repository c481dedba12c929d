// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL Mesh_3 meshes the flow region of the two-spheres case (the paper's
// Fig. 12), a box around two spheres on the flow axis. The box edges are
// protected as features, so the box stays a box; the spheres are seeded with
// points on their surfaces, then refined. The whole Mesh_3 triangulation is
// kept (cells outside the flow region, inside the spheres, get subdomain 0).

#ifndef CGAL_EDGE_SWAPPING_3_MAKE_TWO_SPHERES_MESH_H
#define CGAL_EDGE_SWAPPING_3_MAKE_TWO_SPHERES_MESH_H

#include <CGAL/Edge_swapping_3/Two_spheres_domain.h>
#include <CGAL/Edge_swapping_3/mesh_with_fields_from_complex.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {

// Points spread evenly over a sphere (a Fibonacci lattice) about `spacing` apart.
template <class Point>
std::vector<Point> points_on_sphere(const Point& center, double radius, double spacing)
{
  const int n = 8 + int(4 * CGAL_PI * radius * radius / (spacing * spacing));
  const double golden_angle = CGAL_PI * (3 - std::sqrt(5.0));
  std::vector<Point> points;
  for(int k = 0; k < n; ++k)
  {
    const double z = 1 - (2.0 * k + 1) / n, r = std::sqrt(1 - z * z), phi = k * golden_angle;
    points.emplace_back(center.x() + radius * r * std::cos(phi), center.y() + radius * r * std::sin(phi),
                        center.z() + radius * z);
  }
  return points;
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Domains
/// The Mesh_3 mesh of the flow region of `Two_spheres()` with edge, facet and
/// cell size `size` (0.35 gives about 5,000 vertices): subdomain 1 is the
/// flow region, 0 the rest of the convex hull (the spheres' insides);
/// boundary reference 1 on the box, 2 and 3 on the spheres.
/// \tparam K a kernel with exact predicates (`Exact_predicates_inexact_constructions_kernel`)
/// \pre `0.05 <= size <= 100` (else `std::invalid_argument`: below 0.05 the
/// mesh would have millions of vertices)
template <class K>
Mesh_with_fields<typename K::Point_3> make_two_spheres_mesh(double size)
{
  typedef CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K>> Domain;
  typedef typename CGAL::Mesh_triangulation_3<Domain>::type Mesh_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Mesh_tr, typename Domain::Corner_index,
                                                  typename Domain::Curve_index> C3t3;
  typedef CGAL::Mesh_criteria_3<Mesh_tr> Criteria;
  typedef typename K::Point_3 Point;
  if(!(size >= 0.05 && size <= 100)) throw std::invalid_argument("the two-spheres mesh size is from 0.05 to 100");
  const Two_spheres g;
  // The spheres are subdomains of their own while Mesh_3 runs, so that it
  // meshes both sides of their surfaces; they become holes (0) after.
  const auto region = [g](const Point& p) { return g.region(p); };
  const double margin = 0.5;
  Domain domain(region,
                typename K::Iso_cuboid_3(g.box_min[0] - margin, g.box_min[1] - margin, g.box_min[2] - margin,
                                         g.box_max[0] + margin, g.box_max[1] + margin, g.box_max[2] + margin),
                1e-6);
  // The twelve box edges, as polylines.
  std::vector<std::vector<Point>> edges;
  auto corner = [&](int i, int j, int k) {
    return Point(i ? g.box_max[0] : g.box_min[0], j ? g.box_max[1] : g.box_min[1], k ? g.box_max[2] : g.box_min[2]);
  };
  for(int a = 0; a < 2; ++a)
    for(int b = 0; b < 2; ++b)
    {
      edges.push_back({corner(0, a, b), corner(1, a, b)});
      edges.push_back({corner(a, 0, b), corner(a, 1, b)});
      edges.push_back({corner(a, b, 0), corner(a, b, 1)});
    }
  domain.add_features(edges.begin(), edges.end());

  namespace params = CGAL::parameters;
  const Criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                          params::facet_distance = size / 20, params::cell_radius_edge_ratio = 3,
                          params::cell_size = size);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  // Mesh_3 (CGAL 5.5) seeds surfaces with initial points only when the
  // protected features give no surface at all, and finds a surface later only
  // where a Voronoi edge happens to cross it: the small spheres are missed.
  // Seeding them with surface points, as for a custom initialization, and
  // refining again finds them.
  auto weighted = c3t3.triangulation().geom_traits().construct_weighted_point_3_object();
  for(int s = 0; s < 2; ++s)
    for(const auto& p : internal::points_on_sphere(Point(g.center_x[s], 0, 0), g.radius, size / 2))
    {
      const auto v = c3t3.triangulation().insert(weighted(p));
      if(v == typename Mesh_tr::Vertex_handle()) continue; // hidden by a protecting ball (the balls are on the box edges, far from the spheres)
      c3t3.set_dimension(v, 2);
      c3t3.set_index(v, domain.index_from_surface_patch_index(std::make_pair(1, 2 + s)));
    }
  CGAL::refine_mesh_3(c3t3, domain, criteria, params::no_perturb(), params::no_exude());
  // A facet's reference from the two labels it separates: 1 on the box (flow and outside), 2 and 3 on the spheres.
  return mesh_with_fields_from_complex(
      c3t3, [](int subdomain) { return subdomain == 1 ? 1 : 0; },
      [](const std::pair<int, int>& patch) { return (std::max)(patch.first, patch.second); });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MAKE_TWO_SPHERES_MESH_H
