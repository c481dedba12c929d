// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh optimization by the MinMax dihedral-angle criterion (paper section 4):
// the largest dihedral angle of the mesh never grows.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_3<K> Triangulation;
namespace ES = CGAL::Edge_swapping_3;

int main()
{
  CGAL::Random rng(3);
  std::vector<K::Point_3> points;
  for(int i = 0; i < 500; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  Triangulation tr;
  ES::insert_delaunay(tr, points);

  const ES::Mesh_statistics before = ES::mesh_statistics(tr);
  const ES::Swap_report report = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion());
  const ES::Mesh_statistics after = ES::mesh_statistics(tr);
  const auto swaps = report.total_swaps();
  std::cout << "MinMax from Delaunay: largest dihedral angle " << before.max_dihedral_angle << " -> "
            << after.max_dihedral_angle << " degrees; " << swaps[ES::FLIP_2_3] << " 2-3 and " << swaps[ES::FLIP_3_2]
            << " 3-2 swaps; cells " << before.cells << " -> " << after.cells << '\n';
  return (tr.is_valid() && after.max_dihedral_angle <= before.max_dihedral_angle) ? 0 : 1;
}
