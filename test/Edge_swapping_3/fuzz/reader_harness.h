// SPDX-License-Identifier: GPL-3.0-or-later
// The harness of each reader (readers.h names them), shared by the libFuzzer
// targets and by the mutation test of the suite: read `data` as the file
// `name`, and when it is accepted, go on as the program does (build and check
// the mesh). The outcome is either accepted (a valid mesh) or rejected with
// the error's message. Any other exception, a crash or a hang is a defect.

#ifndef EDGE_SWAPPING_3_FUZZ_READER_HARNESS_H
#define EDGE_SWAPPING_3_FUZZ_READER_HARNESS_H

#include "readers.h"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <algorithm>
#include <sstream>
#include <string>
#include <string_view>

namespace fuzz {

namespace ES = CGAL::Edge_swapping_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef ES::Numbered_domain_triangulation_3<K> Triangulation;
typedef ES::Mesh_with_fields<Point> Input;

namespace internal {

// Builds a mesh input as `edge_swap check` does; the problem is a rejection.
inline void build_mesh(const std::string& name, const Input& in, Outcome& o)
{
  Triangulation tr;
  const std::string problem = in.is_mesh ? ES::build_numbered_mesh(tr, in)
                                         : CGAL::Edge_swapping_3::point_set_problem(in.points);
  if(in.is_mesh)
  {
    // Large meshes are built in the Hilbert order of their points: that
    // order must give the same verdict as the file's.
    Triangulation file_order, hilbert_order;
    std::vector<Triangulation::Vertex_handle> vertices;
    std::vector<Triangulation::Cell_handle> cells;
    const bool in_file_order = ES::internal::build_triangulation_from_cells(file_order, in.points, in.cells, vertices, cells,
                                                                            in.cells.size()).empty();
    const bool in_hilbert_order =
        ES::internal::build_triangulation_from_cells(hilbert_order, in.points, in.cells, vertices, cells, 0).empty();
    if(in_file_order != in_hilbert_order) throw std::logic_error("the Hilbert order changed the verdict on a mesh");
    if(in_hilbert_order && !hilbert_order.is_valid()) throw std::logic_error("a mesh built in Hilbert order is not valid");
  }
  if(!problem.empty()) { o.message = name + ": " + problem; return; }
  if(in.is_mesh && !tr.is_valid()) throw std::logic_error("a mesh that was accepted is not valid");
  o.accepted = true;
}

} // namespace internal

/// Runs `reader` on `data`. For `Reader::ele`, the data is the text of the
/// .node, a NUL byte, and the text of the .ele (no NUL: the .node is empty).
inline Outcome run(Reader reader, std::string_view data)
{
  Outcome o;
  const std::string name = file_name(reader);
  try
  {
    switch(reader)
    {
    case Reader::node:
    case Reader::medit:
    case Reader::msh:
    case Reader::vtu:
      internal::build_mesh(name, ES::IO::mesh_with_fields_from_text<Point>(name, data), o);
      break;
    case Reader::ele:
    {
      const std::size_t nul = data.find('\0');
      const std::string_view node = nul == std::string_view::npos ? std::string_view() : data.substr(0, nul);
      const std::string_view ele = nul == std::string_view::npos ? data : data.substr(nul + 1);
      internal::build_mesh(name, ES::IO::mesh_with_fields_from_text<Point>(name, ele, node), o);
      break;
    }
    }
  }
  catch(const CGAL::Edge_swapping_3::IO::Input_error& e)
  {
    o.message = e.what();
  }
  catch(const std::invalid_argument& e)
  {
    o.message = e.what();
  }
  return o;
}

} // namespace fuzz

#endif
