// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): meshes nobody here wrote (real_meshes.sh makes them
// from Gmsh's tutorials and demos, TetGen's example and CGAL's sample mesh),
// each optimized by ours and by the peers (quality_peers.h), all measured by
// one function on the domain's cells. Ours: MinMax with flips only, MinMax
// with the topological operations, the dihedral sine with smoothing. Peers:
// TetGen 1.5's optimizer (flips, then with smoothing), CGAL's
// Tetrahedral_remeshing flip step alone and with its smoothing step, Gmsh's
// optimizer. Ours run with the library's defaults (the input's dihedral
// angle range kept). Every
// output must keep the input's boundary and interface triangles (checked)
// and be a valid mesh (rebuilt by the package).
//
//   benchmark_real_meshes MESH...      (.mesh, .msh, .vtu or .ele)
//
// Columns: smallest / largest dihedral angle, cells below 10 and above 165
// degrees, the same among the cells with no vertex on a boundary or
// interface triangle ("in"), the 1st percentile of the radius ratio 3r/R,
// cells, seconds of the optimizer alone (ours: the library call, as for the
// peers). Then the program `edge_swap` (beside this benchmark) as a user runs
// it on the file, to each output format, its output checked and compared
// with the file.

#include <CGAL/Real_timer.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include "benchmark_common.h"
#include "quality_peers.h"
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

typedef ES::Numbered_domain_triangulation_3<K> Triangulation;
typedef ES::Mesh_with_fields<K::Point_3> Mesh;

namespace {

struct Quality_row
{
  double smallest = 180, largest = 0, radius_ratio_1st_percentile = 0;
  std::size_t below_10 = 0, above_165 = 0, cells = 0;
  std::size_t in_below_10 = 0, in_above_165 = 0; // the cells with no vertex on a kept triangle
};

// The boundary and interface triangles of the domain's cells (subdomain not
// 0), by point numbers, as sorted triples.
std::set<std::array<std::size_t, 3>> kept_triangles(const quality_peers::Cell_mesh& m)
{
  quality_peers::Cell_mesh domain;
  domain.points = m.points;
  for(std::size_t k = 0; k < m.cells.size(); ++k)
    if(m.subdomains[k] != 0)
    {
      domain.cells.push_back(m.cells[k]);
      domain.subdomains.push_back(m.subdomains[k]);
    }
  const auto b = quality_peers::boundary_triangles(domain);
  return {b.begin(), b.end()};
}

// The one measure of every row: the cells of the domain. "In": the cells
// with no vertex on a boundary or interface triangle of the mesh measured
// (the input's, where the boundary is kept: boundary smoothing slides its
// points and vertex removal renumbers them, so they are found again here).
Quality_row quality(const quality_peers::Cell_mesh& m)
{
  Quality_row q;
  std::vector<char> on_boundary(m.points.size(), 0);
  for(const auto& t : kept_triangles(m))
    for(std::size_t i : t) on_boundary[i] = 1;
  std::vector<double> ratios;
  for(std::size_t k = 0; k < m.cells.size(); ++k)
  {
    if(m.subdomains[k] == 0) continue;
    const auto& t = m.cells[k];
    const auto angles = ES::dihedral_angles(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
    const double lo = *std::min_element(angles.begin(), angles.end());
    const double hi = *std::max_element(angles.begin(), angles.end());
    const bool in = !on_boundary[t[0]] && !on_boundary[t[1]] && !on_boundary[t[2]] && !on_boundary[t[3]];
    q.smallest = std::min(q.smallest, lo);
    q.largest = std::max(q.largest, hi);
    q.below_10 += lo < 10;
    q.above_165 += hi > 165;
    q.in_below_10 += in && lo < 10;
    q.in_above_165 += in && hi > 165;
    ratios.push_back(3 / ES::circumradius_over_inradius(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
    ++q.cells;
  }
  std::sort(ratios.begin(), ratios.end());
  if(!ratios.empty()) q.radius_ratio_1st_percentile = ratios[ratios.size() / 100];
  return q;
}

// The same by their points, sorted.
std::set<std::array<K::Point_3, 3>> kept_triangle_points(const quality_peers::Cell_mesh& m)
{
  std::set<std::array<K::Point_3, 3>> kept;
  for(const auto& t : kept_triangles(m))
  {
    std::array<K::Point_3, 3> p = {m.points[t[0]], m.points[t[1]], m.points[t[2]]};
    std::sort(p.begin(), p.end());
    kept.insert(p);
  }
  return kept;
}

// Whether `out` keeps the boundary of `in`: the same triangles by number
// (boundary smoothing may slide their points within flat faces), or by
// points (vertex removal renumbers the points after a removed one).
bool same_boundary(const quality_peers::Cell_mesh& out, const quality_peers::Cell_mesh& in)
{
  return kept_triangles(out) == kept_triangles(in) || kept_triangle_points(out) == kept_triangle_points(in);
}

// An output rebuilt by the package (which checks it exactly), its boundary
// compared with the input's, and measured.
void row(const std::string& name, const quality_peers::Cell_mesh& input, const quality_peers::Peer_result& r)
{
  if(!r.error.empty())
  {
    std::printf("  %-34s failed: %s\n", name.c_str(), r.error.c_str());
    return;
  }
  Mesh m;
  m.is_mesh = m.has_references = true;
  m.points = r.mesh.points;
  for(std::size_t k = 0; k < r.mesh.cells.size(); ++k)
    if(r.mesh.subdomains[k] != 0)
    {
      m.cells.push_back(r.mesh.cells[k]);
      m.cell_references.push_back(r.mesh.subdomains[k]);
    }
  Triangulation tr;
  const std::string problem = ES::build_numbered_mesh(tr, m);
  const bool kept = same_boundary(r.mesh, input);
  const Quality_row q = quality(r.mesh);
  std::printf("  %-34s %6.2f / %6.2f %6zu %6zu %6zu %6zu %7.4f %8zu %8.2f %s%s\n", name.c_str(), q.smallest,
              q.largest, q.below_10, q.above_165, q.in_below_10, q.in_above_165, q.radius_ratio_1st_percentile, q.cells,
              r.seconds,
              problem.empty() ? "" : ("INVALID: " + problem).c_str(), kept ? "" : " BOUNDARY CHANGED");
  std::fflush(stdout);
}

// Ours, on the package's completed triangulation of the mesh.
template <class Criterion>
quality_peers::Peer_result ours(const Mesh& mesh, const Criterion& criterion, unsigned operations)
{
  quality_peers::Peer_result r;
  Triangulation tr;
  r.error = ES::build_numbered_mesh(tr, mesh);
  if(!r.error.empty()) return r;
  CGAL::Real_timer timer;
  timer.start();
  Mesh numbered = mesh; // vertex insertion numbers its vertices after the points
  ES::with_mesh_constraints(tr, mesh, [&](const auto& constraints) {
    return ES::improve_worst_tetrahedra(
        tr, criterion,
        ES::parameters::operations(operations, ES::parameters::mesh_constraints(constraints,
            CGAL::parameters::visitor(ES::Numbered_vertex_visitor<K::Point_3>(numbered)))));
  });
  r.seconds = timer.time();
  const Mesh out = ES::numbered_mesh_snapshot(tr, numbered);
  r.mesh = {out.points, out.cells, out.cell_references};
  return r;
}

// The mesh's tetrahedra and their references on the points they use, in
// the order met: Gmsh's optimizer drops the points no tetrahedron uses
// (OpenCASCADE keeps the geometry's construction points), and CGAL's
// triangulation cannot hold them.
Mesh domain_cells_only(const Mesh& in)
{
  Mesh out;
  out.is_mesh = out.has_references = true;
  std::vector<std::size_t> number(in.points.size(), std::size_t(-1));
  for(const auto& t : in.cells)
  {
    std::array<std::size_t, 4> u;
    for(int i = 0; i < 4; ++i)
    {
      if(number[t[i]] == std::size_t(-1))
      {
        number[t[i]] = out.points.size();
        out.points.push_back(in.points[t[i]]);
      }
      u[i] = number[t[i]];
    }
    out.cells.push_back(u);
  }
  out.cell_references = in.cell_references;
  return out;
}

// The exit code of a shell command.
int exit_code(const std::string& command)
{
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The program on the mesh file as it is, as a user runs it: `optimize
// --criterion minmax-dihedral --operations topological` to each format, then
// `check` on the output; the output read back must hold the file's points,
// the same boundary and interface triangles, and angles no worse.
void program_rows(const std::string& edge_swap, const std::string& path, const Mesh& file,
                  const std::filesystem::path& dir)
{
  auto cell_mesh = [](const Mesh& m) {
    quality_peers::Cell_mesh c{m.points, m.cells, m.cell_references};
    if(c.subdomains.empty()) c.subdomains.assign(c.cells.size(), 1);
    for(int& r : c.subdomains)
      if(r == 0) r = -1;
    return c;
  };
  const auto input = cell_mesh(file);
  const Quality_row before = quality(input);
  for(const std::string format : {"mesh", "msh", "vtu", "ele"})
  {
    const std::string out = (dir / ("program_out." + format)).string();
    const int optimized = exit_code("'" + edge_swap + "' optimize '" + path + "' --criterion minmax-dihedral "
                                    "--operations topological -q -o '" + out + "' > /dev/null 2>&1");
    const int checked = optimized == 0 ? exit_code("'" + edge_swap + "' check '" + out + "' > /dev/null 2>&1") : -1;
    std::string verdict;
    if(optimized != 0 || checked != 0)
      verdict = "optimize exit " + std::to_string(optimized) + ", check exit " + std::to_string(checked);
    else
    {
      const auto output = cell_mesh(ES::IO::read_mesh_with_fields<K::Point_3>(out));
      const Quality_row after = quality(output);
      char angles[96];
      std::snprintf(angles, sizeof angles, "%.2f / %.2f", after.smallest, after.largest);
      verdict = std::string("check ok, ") + (output.points == input.points ? "same points" : "POINTS CHANGED") + ", " +
                (same_boundary(output, input) ? "same boundary and interfaces" : "BOUNDARY CHANGED") +
                ", " + angles +
                (after.smallest >= before.smallest - 1e-9 && after.largest <= before.largest + 1e-9 ? "" : " WORSE");
    }
    std::printf("  edge_swap optimize -o X.%-4s        %s\n", format.c_str(), verdict.c_str());
  }
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: benchmark_real_meshes MESH... (see real_meshes.sh)\n");
    return 2;
  }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("edge_swapping_3_real_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  // The program beside this benchmark in the build's bin folder.
  const std::string edge_swap = (std::filesystem::absolute(argv[0]).parent_path() / "edge_swap").string();
  std::printf("%-36s %15s %6s %6s %6s %6s %7s %8s %8s\n", "", "min / max", "<10", ">165", "in<10", "in>165", "rr 1%",
              "cells", "seconds");
  for(int a = 1; a < argc; ++a)
  {
    const std::string path = argv[a];
    Mesh mesh;
    try
    {
      mesh = ES::IO::read_mesh_with_fields<K::Point_3>(path);
    }
    catch(const std::exception& e)
    {
      std::printf("%s: unreadable: %s\n", path.c_str(), e.what());
      continue;
    }
    if(mesh.cell_references.empty()) mesh.cell_references.assign(mesh.cells.size(), 1);
    const Mesh file = mesh;
    mesh = domain_cells_only(mesh);
    // Gmsh names volumes from 1; a reference 0 would be the outside for the peers.
    for(int& r : mesh.cell_references)
      if(r == 0) r = -1;
    mesh.has_references = true;
    const quality_peers::Cell_mesh input{mesh.points, mesh.cells, mesh.cell_references};
    std::printf("%s: %zu points (used by a tetrahedron), %zu tetrahedra\n",
                std::filesystem::path(path).filename().c_str(), mesh.points.size(), mesh.cells.size());
    quality_peers::Peer_result as_read;
    as_read.mesh = input;
    row("input", input, as_read);
    row("ours, MinMax, flips", input, ours(mesh, ES::Min_max_dihedral_angle_criterion(), ES::FLIPS));
    row("ours, MinMax, topological", input, ours(mesh, ES::Min_max_dihedral_angle_criterion(), ES::TOPOLOGICAL_OPERATIONS));
    row("ours, dihedral sine, all (smoothing)", input, ours(mesh, ES::Max_min_dihedral_sine_criterion(), ES::ALL_OPERATIONS));
    row("ours, dihedral sine, all + boundary smoothing", input,
        ours(mesh, ES::Max_min_dihedral_sine_criterion(), ES::ALL_OPERATIONS | ES::BOUNDARY_SMOOTHING));
    row("ours, dihedral sine, all + vertex removal and insertion", input,
        ours(mesh, ES::Max_min_dihedral_sine_criterion(), ES::ALL_WITH_VERTEX_CHANGES));
#ifdef EDGE_SWAPPING_3_WITH_TETGEN
    row("TetGen 1.5 flips (140 deg)", input, quality_peers::tetgen_optimizer(input, 1, 140));
    row("TetGen 1.5 flips + smoothing", input, quality_peers::tetgen_optimizer(input, 3, 140));
#endif
    // CGAL's flips depend on addresses: three runs of each.
    for(const char* run : {" #1", " #2", " #3"})
    {
      row((std::string("CGAL remeshing flips (10)") + run).c_str(), input,
          quality_peers::cgal_remeshing(input, quality_peers::CGAL_FLIPS, 10));
      row((std::string("CGAL remeshing flip + smooth (10)") + run).c_str(), input,
          quality_peers::cgal_remeshing(input, quality_peers::CGAL_FLIPS_THEN_SMOOTHING, 10));
    }
    row("Gmsh 4.8 optimizer", input, quality_peers::gmsh_optimizer(input, "/usr/bin/python3", GMSH_SCRIPT, dir.string()));
    program_rows(edge_swap, path, file, dir);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
