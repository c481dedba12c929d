// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap check: is a mesh a valid triangulation, how Delaunay is it, and
// is it CGAL's Delaunay triangulation.

#ifndef EDGE_SWAP_CHECK_COMMAND_H
#define EDGE_SWAP_CHECK_COMMAND_H

#include "mesh_files.h"
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <set>

namespace edge_swap {

/// 0: valid; 1: not a valid mesh; read errors throw (2).
inline int run_check(const std::string& path)
{
  const Input in = read_input(path);
  if(!in.is_mesh) throw Usage_error("check reads a mesh (.ele, .mesh, .msh or .vtu), not the point set '" + path + "'");
  Triangulation tr;
  const std::string problem = ES::build_numbered_mesh(tr, in);
  if(!problem.empty())
  {
    std::cout << path << ": invalid: " << problem << '\n';
    return 1;
  }
  if(ES::is_completed_domain(tr))
  {
    // A domain that is not its convex hull: valid as checked, once filled
    // outside to a box and checked exactly as one triangulation of it.
    std::size_t vertices = 0, cells = 0, boundary = 0;
    for(auto v : tr.finite_vertex_handles()) vertices += v->info() < in.points.size();
    std::set<int> subdomains;
    for(auto c : tr.finite_cell_handles())
    {
      if(c->info().subdomain == ES::Domain_cell_info::completion) continue;
      ++cells;
      subdomains.insert(c->info().subdomain);
      for(int i = 0; i < 4; ++i) boundary += c->neighbor(i)->info().subdomain == ES::Domain_cell_info::completion;
    }
    std::cout << path << ": valid mesh of a domain that is not its convex hull (orientation, conformity, no overlap)\n"
              << "  vertices " << vertices << ", cells " << cells << ", boundary faces " << boundary
              << ", subdomains " << subdomains.size() << '\n'
              << "  not compared with CGAL's Delaunay triangulation, which covers the convex hull\n";
    return 0;
  }
  // A valid triangulation of the convex hull whose every face is locally
  // Delaunay under CGAL's perturbation is the perturbed Delaunay
  // triangulation, which is unique: CGAL's. Only a mesh that is not
  // Delaunay is compared cell for cell (a second triangulation in memory).

  const std::size_t non_delaunay = ES::number_of_non_delaunay_facets(tr);
  ES::Delaunay_comparison cmp;
  if(non_delaunay == 0)
  {
    cmp.identical = true;
    cmp.cells = cmp.delaunay_cells = tr.number_of_finite_cells();
  }
  else
    cmp = ES::compare_with_delaunay(tr);
  std::cout << path << ": valid triangulation of the convex hull (orientation, conformity, convex boundary)\n"
            << "  vertices " << tr.number_of_vertices() << ", cells " << cmp.cells << '\n'
            << "  faces not locally Delaunay: " << non_delaunay << '\n'
            << "  equal to CGAL's Delaunay triangulation: " << (cmp.identical ? "yes" : "no");
  if(cmp.identical) std::cout << " (every face locally Delaunay, so it is the unique perturbed Delaunay triangulation)";
  if(!cmp.identical)
    std::cout << " (" << cmp.cells_not_in_delaunay << " cells not in it, " << cmp.delaunay_cells_missing
              << " of its " << cmp.delaunay_cells << " cells missing)";
  std::cout << '\n';
  return 0;
}

} // namespace edge_swap

#endif
