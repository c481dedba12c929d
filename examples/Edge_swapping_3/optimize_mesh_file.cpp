// SPDX-License-Identifier: GPL-3.0-or-later
// A user's mesh file, of a domain of any shape (here an L-shaped block that
// Gmsh meshed), optimized by the MinMax dihedral angle with the topological
// operations, its boundary, regions and vertices kept, and written back.
//
//   optimize_mesh_file [IN.mesh|IN.msh|IN.vtu|IN.ele [OUT]]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;
typedef ES::Numbered_domain_triangulation_3<K> Triangulation;
typedef ES::Mesh_with_fields<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : EDGE_SWAPPING_3_EXAMPLE_DATA "/l_shape.msh";
  const std::string output = argc > 2 ? argv[2] : "l_shape_optimized.msh";
  try
  {
    const Mesh mesh = ES::IO::read_mesh_with_fields<K::Point_3>(input);
    Triangulation tr;
    // A domain that is not its convex hull is completed outside, out of sight.
    const std::string problem = ES::build_numbered_mesh(tr, mesh);
    if(!problem.empty())
    {
      std::cerr << input << ": " << problem << '\n';
      return 2;
    }
    // Domain_constraints: the boundary, the interfaces and the regions stay.
    const ES::Quality_report report = ES::with_mesh_constraints(tr, mesh, [&](const auto& constraints) {
      return ES::improve_worst_tetrahedra(
          tr, ES::Min_max_dihedral_angle_criterion(),
          ES::parameters::operations(ES::TOPOLOGICAL_OPERATIONS, ES::parameters::mesh_constraints(constraints)));
    });
    std::cout << input << ": largest dihedral angle " << report.worst_before << " -> " << report.worst_after
              << " degrees; cells " << mesh.cells.size() << " -> " << ES::number_of_mesh_cells(tr) << '\n';
    // The domain's cells alone, with the mesh's points and references.
    ES::IO::write_mesh_with_fields(output, ES::numbered_mesh_snapshot(tr, mesh),
                                   [](const std::string& file, std::function<void(std::ostream&)> write) {
                                     std::ofstream out(file, std::ios::binary);
                                     write(out);
                                     if(!out) throw std::runtime_error("cannot write " + file);
                                   });
    std::cout << "written: " << output << '\n';
    return report.worst_after <= report.worst_before ? 0 : 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << '\n';
    return 2;
  }
}
