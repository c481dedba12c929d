// The triangulation the program works on: each vertex remembers the number of
// its point, so that point i of the input is point i of the output (new
// points are numbered after the input's).

#ifndef EDGE_SWAP_TYPES_H
#define EDGE_SWAP_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>

namespace edge_swap {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K> Vb;
// Cells carry a subdomain index and boundary references (Medit input).
typedef CGAL::Triangulation_cell_base_with_info_3<CGAL::Edge_swapping_3::Domain_cell_info, K> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Triangulation_3<K, Tds> Triangulation;

/// Bad options or bad input: exit code 2, nothing written.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace edge_swap

#endif
