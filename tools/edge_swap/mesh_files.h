// SPDX-License-Identifier: GPL-3.0-or-later
// The program's mesh input and output: the library reads and writes
// (IO/mesh_with_fields.h); here the outputs join the files written all or
// nothing, and a bad path is a usage error.

#ifndef EDGE_SWAP_MESH_FILES_H
#define EDGE_SWAP_MESH_FILES_H

#include "types.h"
#include <CGAL/Edge_swapping_3/IO/output_files.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <string>
#include <vector>

namespace edge_swap {

using IO::check_output_paths;
using IO::Output_files;

/// Reads the input file `path` (and the .node beside an .ele).
inline Input read_input(const std::string& path)
{
  try
  {
    return IO::read_mesh_with_fields<Point>(path);
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(e.what());
  }
}

/// Throws IO::Input_error unless the points can be triangulated in 3-D.
inline void require_valid_point_set(const Input& in, const std::string& path)
{
  const std::string problem = ES::point_set_problem(in.points);
  if(!problem.empty()) throw IO::Input_error(path + ": " + problem);
}

/// The files a mesh output `path` writes: Y.ele comes with Y.node.
inline std::vector<std::string> mesh_output_paths(const std::string& path)
{
  try
  {
    return IO::mesh_file_paths(path);
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(e.what());
  }
}

/// How mesh outputs are encoded (`--msh-format`).
inline IO::Mesh_file_options mesh_file_options;

/// Adds the files of the output `path` of `tr`, numbered as `in`; a VTK
/// file also gets the quality of each cell (for ParaView).
inline void add_mesh_files(Output_files& files, const std::string& path, const Triangulation& tr, const Input& in)
{
  Input mesh = ES::numbered_mesh_snapshot(tr, in);
  if(IO::has_extension(path, ".vtu")) ES::add_quality_cell_fields(mesh);
  IO::write_mesh_with_fields(path, std::move(mesh),
                             [&files](const std::string& file, std::function<void(std::ostream&)> writer) {
                               files.add(file, std::move(writer));
                             },
                             mesh_file_options);
}

} // namespace edge_swap

#endif
