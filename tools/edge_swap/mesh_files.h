// Reading the program's input (a TetGen point set or mesh) and writing its
// outputs all or nothing: each file goes to a temporary name first and is
// renamed only when every file is complete.

#ifndef EDGE_SWAP_MESH_FILES_H
#define EDGE_SWAP_MESH_FILES_H

#include "types.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>

namespace edge_swap {

namespace IO = CGAL::Edge_swapping_3::IO;

inline bool ends_with(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

inline std::string stem(const std::string& path) { return path.substr(0, path.rfind('.')); }

/// What a TetGen input holds: points (with attributes) and, for an .ele file, tetrahedra.
struct Input
{
  std::vector<Point> points;
  IO::Node_file node;
  std::vector<std::array<std::size_t, 4>> cells;
  bool is_mesh = false;
};

inline Input read_input(const std::string& path)
{
  Input in;
  if(ends_with(path, ".node"))
    in.node = IO::read_node_file(path);
  else if(ends_with(path, ".ele"))
  {
    in.node = IO::read_node_file(stem(path) + ".node");
    in.cells = IO::read_ele_file(path, in.node.points.size(), in.node.first_index);
    in.is_mesh = true;
  }
  else
    throw Usage_error("input '" + path + "' is neither a .node nor an .ele file");
  for(const auto& p : in.node.points) in.points.emplace_back(p[0], p[1], p[2]);
  return in;
}

/// Throws IO::Input_error unless the points can be triangulated in 3-D.
inline void require_valid_point_set(const Input& in, const std::string& path)
{
  const std::string problem = CGAL::Edge_swapping_3::point_set_problem(in.points, K());
  if(!problem.empty()) throw IO::Input_error(path + ": " + problem);
}

/// Builds the mesh of an .ele input; an empty string, or what is wrong with it.
inline std::string build_mesh(Triangulation& tr, const Input& in)
{
  std::vector<Triangulation::Vertex_handle> vertices;
  const std::string problem =
      CGAL::Edge_swapping_3::build_triangulation_from_cells(tr, in.points, in.cells, vertices);
  for(std::size_t k = 0; k < vertices.size(); ++k) vertices[k]->info() = k;
  return problem;
}

/// Writes several files all or nothing. Each writer fills a stream.
class Atomic_files
{
public:
  void add(const std::string& path, std::function<void(std::ostream&)> writer)
  {
    files_.push_back({path, std::move(writer)});
  }

  void commit()
  {
    std::vector<std::string> temporary;
    auto discard = [&] { for(const auto& t : temporary) std::remove(t.c_str()); };
    for(const auto& f : files_)
    {
      const std::string tmp = f.path + ".tmp" + std::to_string(::getpid());
      temporary.push_back(tmp);
      std::ofstream out(tmp);
      if(out) f.writer(out);
      out.close();
      if(!out) { discard(); throw Usage_error("cannot write '" + f.path + "'"); }
    }
    for(std::size_t k = 0; k < files_.size(); ++k)
      if(std::rename(temporary[k].c_str(), files_[k].path.c_str()) != 0)
      {
        discard();
        throw Usage_error("cannot write '" + files_[k].path + "'");
      }
  }

private:
  struct File { std::string path; std::function<void(std::ostream&)> writer; };
  std::vector<File> files_;
};

/// Adds Y.node and Y.ele for the output Y.ele.
inline void add_mesh_files(Atomic_files& files, const std::string& ele_path, const Triangulation& tr,
                           const Input& in)
{
  std::vector<std::array<std::size_t, 4>> cells;
  cells.reserve(tr.number_of_finite_cells());
  for(auto c : tr.finite_cell_handles())
    cells.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  files.add(stem(ele_path) + ".node", [&in](std::ostream& out) {
    IO::write_node_file(out, in.node.points, in.node.attributes, in.node.first_index);
  });
  files.add(ele_path, [cells = std::move(cells), &in](std::ostream& out) { IO::write_ele_file(out, cells, in.node.first_index); });
}

} // namespace edge_swap

#endif
