// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL Mesh_3's mesh of a shell (the ball of radius 1 less the ball of
// radius 0.5: a cavity), optimized in memory by the MinMax dihedral angle
// with the topological operations. The complex's own indices are the
// constraints: its surface facets and subdomains stay as they are.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/edge_swapping_3.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
namespace ES = CGAL::Edge_swapping_3;

int shell(const K::Point_3& p)
{
  const double r2 = CGAL::to_double(CGAL::squared_distance(p, K::Point_3(CGAL::ORIGIN)));
  return r2 < 1 && r2 > 0.25 ? 1 : 0;
}

int main()
{
  namespace params = CGAL::parameters;
  const Domain domain(std::function<int(const K::Point_3&)>(shell), K::Sphere_3(CGAL::ORIGIN, 4.), 1e-6);
  const CGAL::Mesh_criteria_3<Tr> criteria(params::facet_angle = 25, params::facet_size = 0.2,
                                           params::facet_distance = 0.02, params::cell_radius_edge_ratio = 3,
                                           params::cell_size = 0.2);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  const std::size_t facets = c3t3.number_of_facets_in_complex();
  const ES::Quality_report report =
      ES::improve_worst_tetrahedra(c3t3.triangulation(), ES::Min_max_dihedral_angle_criterion(),
                                   ES::parameters::operations(ES::TOPOLOGICAL_OPERATIONS));
  c3t3.rescan_after_load_of_triangulation(); // the complex counts its cells and facets again
  std::cout << "Mesh_3 shell: largest dihedral angle in the domain " << report.worst_before << " -> "
            << report.worst_after << " degrees; surface facets " << facets << " -> "
            << c3t3.number_of_facets_in_complex() << '\n';
  return report.worst_after <= report.worst_before && c3t3.number_of_facets_in_complex() == facets ? 0 : 1;
}
