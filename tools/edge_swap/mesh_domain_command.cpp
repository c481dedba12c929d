// edge_swap mesh-domain two-spheres: CGAL Mesh_3 meshes the flow region of
// the paper's Fig. 12 case, a box around two spheres on the flow axis. The
// box edges are protected as features, so the box stays a box; the whole
// Mesh_3 triangulation is kept (cells outside the flow region, inside the
// spheres, get subdomain 0), so the result triangulates the convex hull and
// the swap and insertion functions can work on it.

#include "mesh_domain_command.h"
#include "flow_field.h"
#include "mesh_files.h"
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <iostream>

namespace edge_swap {

namespace {

typedef CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K>> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Mesh_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Mesh_tr, Domain::Corner_index, Domain::Curve_index> C3t3;
typedef CGAL::Mesh_criteria_3<Mesh_tr> Criteria;

// 1 in the flow region, 2 and 3 inside the spheres, 0 outside the box. The
// spheres are meshed as subdomains of their own so that Mesh_3 refines
// their inside and cannot miss their surfaces; they become holes (0) after.
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

// The boundary reference of a facet of the flow region: 1 on the box,
// 2 and 3 on the first and second sphere.
int boundary_reference(const Two_spheres& g, const std::array<K::Point_3, 3>& p)
{
  const K::Point_3 c = CGAL::centroid(p[0], p[1], p[2]);
  const double d0 = std::sqrt(CGAL::squared_distance(c, K::Point_3(g.center_x[0], 0, 0)));
  const double d1 = std::sqrt(CGAL::squared_distance(c, K::Point_3(g.center_x[1], 0, 0)));
  if(std::min(d0, d1) > 2 * g.radius) return 1;
  return d0 < d1 ? 2 : 3;
}

} // namespace

int run_mesh_domain(const std::string& name, const std::string& output, double size)
{
  if(name != "two-spheres") throw Usage_error("unknown domain '" + name + "' (known: two-spheres)");
  if(!(size > 0)) throw Usage_error("--size must be positive");
  require_output_format(output);
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
  // A great circle on each sphere (closed polyline): Mesh_3 finds a surface
  // only where its refinement meets it, and the spheres are small.
  for(double cx : g.center_x)
  {
    std::vector<K::Point_3> circle;
    const int n = 256;
    for(int k = 0; k <= n; ++k)
    {
      const double t = 2 * CGAL_PI * (k % n) / n;
      circle.emplace_back(cx + g.radius * std::cos(t), g.radius * std::sin(t), 0);
    }
    edges.push_back(circle);
  }
  domain.add_features(edges.begin(), edges.end());

  namespace params = CGAL::parameters;
  const Criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                          params::facet_distance = size / 20, params::cell_radius_edge_ratio = 3,
                          params::cell_size = size);
  std::cerr << "mesh-domain: meshing two-spheres with size " << size << " (CGAL Mesh_3)\n";
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
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
    std::array<K::Point_3, 3> p;
    for(int k = 0; k < 3; ++k)
    {
      t[k] = index[f.first->vertex((f.second + 1 + k) & 3)];
      p[k] = in.points[t[k]];
    }
    in.triangles.push_back(t);
    in.triangle_references.push_back(boundary_reference(g, p));
  }
  Triangulation tr;
  const std::string problem = build_mesh(tr, in);
  if(!problem.empty()) throw std::runtime_error("the Mesh_3 triangulation did not convert: " + problem);

  Atomic_files files;
  add_mesh_files(files, output, tr, in);
  files.commit();
  std::size_t flow_cells = 0;
  for(auto r : in.cell_references) flow_cells += (r == 1);
  std::cout << "two-spheres: " << tr.number_of_vertices() << " vertices, " << flow_cells << " cells in the flow region ("
            << tr.number_of_finite_cells() << " in all), " << in.triangles.size() << " boundary triangles\n";
  return 0;
}

} // namespace edge_swap
