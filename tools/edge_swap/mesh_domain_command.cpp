// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap mesh-domain two-spheres: CGAL Mesh_3 meshes the flow region of
// the paper's Fig. 12 case, a box around two spheres on the flow axis. The
// box edges are protected as features, so the box stays a box; the spheres
// are seeded with points on their surfaces, then refined. The whole Mesh_3
// triangulation is kept (cells outside the flow region, inside the spheres,
// get subdomain 0), so the result triangulates the convex hull and the swap
// and insertion functions can work on it.

#include "mesh_domain_command.h"
#include "flow_field.h"
#include "mesh_files.h"
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>
#include <iostream>

namespace edge_swap {

namespace {

typedef CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K>> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Mesh_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Mesh_tr, Domain::Corner_index, Domain::Curve_index> C3t3;
typedef CGAL::Mesh_criteria_3<Mesh_tr> Criteria;

// 1 in the flow region, 2 and 3 inside the spheres, 0 outside the box. The
// spheres are subdomains of their own while Mesh_3 runs, so that it meshes
// both sides of their surfaces; they become holes (0) after.
struct Flow_region
{
  Two_spheres g;
  int operator()(const K::Point_3& p) const
  {
    for(int c = 0; c < 3; ++c)
      if(p[c] < g.box_min[c] || p[c] > g.box_max[c]) return 0;
    for(int s = 0; s < 2; ++s)
      if(CGAL::squared_distance(p, K::Point_3(g.center_x[s], 0, 0)) < g.radius * g.radius) return 2 + s;
    return 1;
  }
};

// The boundary reference of a facet of the flow region, from the two labels
// it separates: 1 on the box (flow and outside), 2 and 3 on the spheres.
int boundary_reference(const std::pair<int, int>& patch)
{
  return std::max(patch.first, patch.second);
}

// Points spread evenly over a sphere (a Fibonacci lattice) about `spacing` apart.
std::vector<K::Point_3> points_on_sphere(const K::Point_3& center, double radius, double spacing)
{
  const int n = 8 + int(4 * CGAL_PI * radius * radius / (spacing * spacing));
  const double golden_angle = CGAL_PI * (3 - std::sqrt(5.0));
  std::vector<K::Point_3> points;
  for(int k = 0; k < n; ++k)
  {
    const double z = 1 - (2.0 * k + 1) / n, r = std::sqrt(1 - z * z), phi = k * golden_angle;
    points.emplace_back(center.x() + radius * r * std::cos(phi), center.y() + radius * r * std::sin(phi),
                        center.z() + radius * z);
  }
  return points;
}

} // namespace

int run_mesh_domain(const std::string& name, const std::string& output, double size)
{
  if(name != "two-spheres") throw Usage_error("unknown domain '" + name + "' (known: two-spheres)");
  // Below 0.05 the mesh would have millions of vertices: a typo, not a wish.
  if(!(size >= 0.05 && size <= 100)) throw Usage_error("--size is from 0.05 to 100");
  check_output_paths(mesh_output_paths(output));
  const Two_spheres g;
  const double margin = 0.5;
  Domain domain(Flow_region{g},
                K::Iso_cuboid_3(g.box_min[0] - margin, g.box_min[1] - margin, g.box_min[2] - margin,
                                g.box_max[0] + margin, g.box_max[1] + margin, g.box_max[2] + margin),
                1e-6);
  // The twelve box edges, as polylines.
  std::vector<std::vector<K::Point_3>> edges;
  auto corner = [&](int i, int j, int k) {
    return K::Point_3(i ? g.box_max[0] : g.box_min[0], j ? g.box_max[1] : g.box_min[1], k ? g.box_max[2] : g.box_min[2]);
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
  std::cerr << "mesh-domain: meshing two-spheres with size " << size << " (CGAL Mesh_3)\n";
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  // Mesh_3 (CGAL 5.5) seeds surfaces with initial points only when the
  // protected features give no surface at all, and finds a surface later only
  // where a Voronoi edge happens to cross it: the small spheres are missed.
  // Seeding them with surface points, as for a custom initialization, and
  // refining again finds them.
  auto weighted = c3t3.triangulation().geom_traits().construct_weighted_point_3_object();
  for(int s = 0; s < 2; ++s)
    for(const auto& p : points_on_sphere(K::Point_3(g.center_x[s], 0, 0), g.radius, size / 2))
    {
      const auto v = c3t3.triangulation().insert(weighted(p));
      if(v == Mesh_tr::Vertex_handle()) continue; // hidden by a protecting ball (never near the spheres)
      c3t3.set_dimension(v, 2);
      c3t3.set_index(v, domain.index_from_surface_patch_index(std::make_pair(1, 2 + s)));
    }
  CGAL::refine_mesh_3(c3t3, domain, criteria, params::no_perturb(), params::no_exude());
  const Mesh_tr& mtr = c3t3.triangulation();
  std::map<int, int> by_label;
  for(auto c : mtr.finite_cell_handles()) by_label[c3t3.subdomain_index(c)]++;
  for(auto [l, n] : by_label) std::cerr << "label " << l << ": " << n << " cells\n";

  // The whole triangulation, bare points (protecting balls' weights dropped).
  Input in;
  in.is_mesh = in.has_references = true;
  std::map<Mesh_tr::Vertex_handle, std::size_t> index;
  for(auto v : mtr.finite_vertex_handles())
  {
    index[v] = in.points.size();
    const auto& wp = v->point();
    in.points.emplace_back(wp.x(), wp.y(), wp.z());
  }
  for(auto c : mtr.finite_cell_handles())
  {
    in.cells.push_back({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
    in.cell_references.push_back(c3t3.subdomain_index(c) == 1 ? 1 : 0);
  }
  for(auto it = c3t3.facets_in_complex_begin(); it != c3t3.facets_in_complex_end(); ++it)
  {
    const auto& f = *it;
    std::array<std::size_t, 3> t;
    for(int k = 0; k < 3; ++k) t[k] = index[f.first->vertex((f.second + 1 + k) & 3)];
    in.triangles.push_back(t);
    in.triangle_references.push_back(boundary_reference(c3t3.surface_patch_index(f)));
  }
  Triangulation tr;
  const std::string problem = build_mesh(tr, in);
  if(!problem.empty()) throw std::runtime_error("the Mesh_3 triangulation did not convert: " + problem);

  Output_files files;
  add_mesh_files(files, output, tr, in);
  files.commit();
  std::size_t flow_cells = 0;
  for(auto r : in.cell_references) flow_cells += (r == 1);
  std::cout << "two-spheres: " << tr.number_of_vertices() << " vertices, " << flow_cells << " cells in the flow region ("
            << tr.number_of_finite_cells() << " in all), " << in.triangles.size() << " boundary triangles\n";
  return 0;
}

} // namespace edge_swap
