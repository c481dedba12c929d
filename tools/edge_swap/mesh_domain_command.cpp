// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap mesh-domain two-spheres: the library's Mesh_3 mesh of the
// two-spheres domain (make_two_spheres_mesh.h), written as a mesh file. In a
// translation unit of its own: Mesh_3 compiles in parallel with main.cpp.

#include "mesh_domain_command.h"
#include "mesh_files.h"
#include <CGAL/Edge_swapping_3/make_two_spheres_mesh.h>
#include <iostream>

namespace edge_swap {

int run_mesh_domain(const std::string& name, const std::string& output, double size)
{
  if(name != "two-spheres") throw Usage_error("unknown domain '" + name + "' (known: two-spheres)");
  // Below 0.05 the mesh would have millions of vertices: a typo, not a wish.
  if(!(size >= 0.05 && size <= 100)) throw Usage_error("--size is from 0.05 to 100");
  check_output_paths(mesh_output_paths(output));
  std::cerr << "mesh-domain: meshing two-spheres with size " << size << " (CGAL Mesh_3)\n";
  const Input in = ES::make_two_spheres_mesh<K>(size);
  Triangulation tr;
  const std::string problem = ES::build_numbered_mesh(tr, in);
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
