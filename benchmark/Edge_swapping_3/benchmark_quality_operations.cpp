// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): the quality operations on three inputs, beside
// the peers on the same meshes (quality_peers.h). Inputs: the
// two-spheres domain mesh (`edge_swap mesh-domain two-spheres`, measured on
// its flow region, boundaries and subdomains kept), and the Delaunay and the
// placing triangulation of 8,000 random points (the hull fixed). Rows: the
// input, the flip driver (`swap_edges`, MinMax), the worst-first driver
// (`improve_worst_tetrahedra`) for MinMax with each set of operations, two
// rows with a quality target, then with the topological operations, with
// smoothing too, and with smoothing on flat boundary faces and straight
// boundary edges, for MaxMin, the radius ratio, the dihedral sine and the
// volume-length ratio; then TetGen's optimizer, CGAL's remeshing and Gmsh's
// optimizer. Columns: smallest and largest dihedral angle, cells below 10
// and above 165 and 175 degrees, the same first two counts on the cells with
// no vertex on the boundary (the hull, or a facet between subdomains), the
// 1st percentile of the radius ratio 3 r / R (1 for a regular tetrahedron),
// the time (the optimizer alone), the cells below 10 or above 165 degrees by
// their number of vertices on the boundary (0 to 4), and the operations. Each output is
// validated (rebuilt, orientations checked) and its boundary triangles
// compared with the input's.
//
//   benchmark_quality_operations [two-spheres|delaunay|placing [ROW [SCALE]]]
//
// (default: all three inputs; with ROW, only the rows whose name contains
// it, or one of the parts separated by '|', the input's row always; SCALE: the two-spheres mesh's size, default
// 0.35, or the number of random points, default 8,000).

#include <CGAL/Real_timer.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include "benchmark_common.h"
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include "quality_peers.h"
#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

typedef ES::Numbered_domain_triangulation_3<K> Triangulation;

namespace {

typedef std::function<bool(Triangulation::Cell_handle)> Cell_filter;

// The rows asked for (parts of their names; empty: every row).
std::string selected_rows;
// ROW may list several parts, separated by '|': a row is run when its name
// contains one of them.
bool selected(const std::string& row)
{
  std::size_t begin = 0;
  for(;;)
  {
    const std::size_t end = std::min(selected_rows.find('|', begin), selected_rows.size());
    if(row.find(selected_rows.substr(begin, end - begin)) != std::string::npos) return true;
    if(end == selected_rows.size()) return false;
    begin = end + 1;
  }
}

// The runs of each CGAL row.
constexpr int cgal_runs = 5;

struct Quality_row
{
  double smallest = 180, largest = 0, radius_ratio_1st_percentile = 0;
  std::size_t below_10 = 0, above_165 = 0, above_175 = 0, cells = 0;
  // The same counts on the cells with no vertex on the boundary.
  std::size_t interior_below_10 = 0, interior_above_165 = 0;
  double interior_smallest = 180, interior_largest = 0;
  // The cells below 10 or above 165 degrees by their number of vertices on
  // the boundary (0 to 4): where the bad cells are.
  std::array<std::size_t, 5> bad_by_boundary_vertices{};
};

// The points of the input's boundary triangles (facets between two
// subdomains, or on the hull): every optimizer keeps them where they are.
std::set<K::Point_3> boundary_points;

void set_boundary_points(const quality_peers::Cell_mesh& input)
{
  boundary_points.clear();
  for(const auto& t : quality_peers::boundary_triangles(input))
    for(std::size_t v : t) boundary_points.insert(input.points[v]);
}

// The vertices of `tr` at a point of the input's boundary: taken before an
// optimizer of ours runs (ours may move them within flat boundary faces), or
// on a peer's output (the peers keep them where they are).
std::set<Triangulation::Vertex_handle> boundary_vertices(const Triangulation& tr)
{
  std::set<Triangulation::Vertex_handle> on;
  for(auto v : tr.finite_vertex_handles())
    if(boundary_points.count(v->point())) on.insert(v);
  return on;
}

// The quality of the cells `counted` selects, and of those of them with no
// vertex in `boundary`.
Quality_row quality(const Triangulation& tr, const Cell_filter& counted,
                    const std::set<Triangulation::Vertex_handle>& boundary)
{
  Quality_row q;
  std::vector<double> ratios;
  for(auto c : tr.finite_cell_handles())
  {
    if(!counted(c)) continue;
    const auto& p0 = c->vertex(0)->point();
    const auto& p1 = c->vertex(1)->point();
    const auto& p2 = c->vertex(2)->point();
    const auto& p3 = c->vertex(3)->point();
    const auto angles = ES::dihedral_angles(p0, p1, p2, p3);
    const double lo = *std::min_element(angles.begin(), angles.end());
    const double hi = *std::max_element(angles.begin(), angles.end());
    q.smallest = std::min(q.smallest, lo);
    q.largest = std::max(q.largest, hi);
    q.below_10 += lo < 10;
    q.above_165 += hi > 165;
    q.above_175 += hi > 175;
    int on_boundary = 0;
    for(int i = 0; i < 4; ++i) on_boundary += int(boundary.count(c->vertex(i)));
    const bool interior = on_boundary == 0;
    if(lo < 10 || hi > 165) ++q.bad_by_boundary_vertices[std::size_t(on_boundary)];
    q.interior_below_10 += interior && lo < 10;
    q.interior_above_165 += interior && hi > 165;
    if(interior)
    {
      q.interior_smallest = std::min(q.interior_smallest, lo);
      q.interior_largest = std::max(q.interior_largest, hi);
    }
    ratios.push_back(3 / ES::circumradius_over_inradius(p0, p1, p2, p3));
    ++q.cells;
  }
  std::sort(ratios.begin(), ratios.end());
  if(!ratios.empty()) q.radius_ratio_1st_percentile = ratios[ratios.size() / 100];
  return q;
}

void print(const char* name, const Quality_row& q, double seconds, const std::string& operations)
{
  const auto& b = q.bad_by_boundary_vertices;
  std::printf("%-44s %6.2f / %6.2f %6zu %6zu %6zu %6zu %6zu %8.4f %8zu %8.2f  in %6.2f / %6.2f  %zu/%zu/%zu/%zu/%zu  %s\n",
              name, q.smallest, q.largest, q.below_10, q.above_165, q.above_175, q.interior_below_10,
              q.interior_above_165, q.radius_ratio_1st_percentile, q.cells, seconds, q.interior_smallest,
              q.interior_largest, b[0], b[1], b[2], b[3], b[4], operations.c_str());
  std::fflush(stdout);
}

// The vertices of `tr` that are not where a point of `input` is.
std::size_t moved_vertices(const Triangulation& tr, const quality_peers::Cell_mesh& input)
{
  const std::set<K::Point_3> at(input.points.begin(), input.points.end());
  std::size_t moved = 0;
  for(auto v : tr.finite_vertex_handles()) moved += !at.count(v->point());
  return moved;
}

std::string operations_of(const ES::Quality_report& r)
{
  return std::to_string(r.edge_removals) + " edge removals, " + std::to_string(r.two_step_removals) +
         " two-step, " + std::to_string(r.face_removals) + " multi-face (" +
         std::to_string(r.faces_removed) + " faces), " + std::to_string(r.flips[ES::FLIP_2_3]) + " 2-3, " +
         std::to_string(r.flips[ES::FLIP_3_2]) + " 3-2, " + std::to_string(r.flips[ES::FLIP_4_4] + r.flips[ES::FLIP_2_2]) +
         " 4-4/2-2, " + std::to_string(r.smoothing_moves) + " smoothing moves" +
         (r.vertex_removals + r.vertex_insertions == 0
              ? std::string()
              : ", " + std::to_string(r.vertex_removals) + " vertices removed, " +
                    std::to_string(r.vertex_insertions) + " inserted");
}

// A peer's result, rebuilt as our triangulation (which validates it) and
// measured by the same code; it must keep the input's boundary triangles.
void peer_row(const char* name, const std::function<quality_peers::Peer_result()>& run,
              const quality_peers::Cell_mesh& input, const std::function<Cell_filter(const Triangulation&)>& counted)
{
  if(!selected(name)) return;
  const quality_peers::Peer_result r = run();
  if(!r.error.empty())
  {
    std::printf("%-44s failed: %s\n", name, r.error.c_str());
    return;
  }
  Triangulation tr;
  std::vector<Triangulation::Vertex_handle> vertices;
  std::vector<Triangulation::Cell_handle> cells;
  const std::string problem = ES::build_triangulation_from_cells(tr, r.mesh.points, r.mesh.cells, vertices, cells);
  if(!problem.empty())
  {
    std::printf("%-44s invalid output: %s\n", name, problem.c_str());
    return;
  }
  ES::mark_point_set_domain(tr);
  for(std::size_t k = 0; k < cells.size(); ++k) cells[k]->info().subdomain = r.mesh.subdomains[k];
  // By their points: a peer that adds or removes vertices numbers them anew.
  auto by_points = [](const quality_peers::Cell_mesh& m) {
    std::set<std::array<K::Point_3, 3>> triangles;
    for(const auto& t : quality_peers::boundary_triangles(m))
    {
      std::array<K::Point_3, 3> p = {m.points[t[0]], m.points[t[1]], m.points[t[2]]};
      std::sort(p.begin(), p.end());
      triangles.insert(p);
    }
    return triangles;
  };
  const bool kept = by_points(r.mesh) == by_points(input);
  print(name, quality(tr, counted(tr), boundary_vertices(tr)), r.seconds,
        std::to_string(r.moved) + " points moved, boundary " + (kept ? "kept" : "CHANGED"));
}

// Every row on a fresh copy of the input (`make`), measured on the cells that
// `counted(tr)` selects; then the peers on the same mesh (`input`).
template <class Constraints>
void rows(const std::function<void(Triangulation&)>& make, const Constraints& constraints,
          const std::function<Cell_filter(const Triangulation&)>& counted, const quality_peers::Cell_mesh& input)
{
  set_boundary_points(input);
  std::printf("%-44s %15s %6s %6s %6s %6s %6s %8s %8s %8s  %18s  %s  %s\n", "optimizer", "min / max deg", "<10", ">165",
              ">175", "in<10", "in>165", "rr 1%", "cells", "s", "in min / max deg",
              "bad by boundary vertices 0/1/2/3/4", "operations");
  {
    Triangulation tr;
    make(tr);
    const auto boundary = boundary_vertices(tr);
    print("input", quality(tr, counted(tr), boundary), 0, "");
  }
  if(selected("swap_edges MinMax (flips)"))
  {
    Triangulation tr;
    make(tr);
    const auto boundary = boundary_vertices(tr);
    const auto r = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion(), ES::parameters::mesh_constraints(constraints));
    const auto s = r.total_swaps();
    print("swap_edges MinMax (flips)", quality(tr, counted(tr), boundary), r.seconds,
          std::to_string(s[0]) + " 2-3, " + std::to_string(s[1]) + " 3-2, " + std::to_string(s[2] + s[3]) + " 4-4/2-2");
  }
  const std::pair<const char*, unsigned> variants[] = {
      {"flips", ES::FLIPS},
      {"edge removal", ES::EDGE_REMOVAL},
      {"multi-face removal", ES::MULTI_FACE_REMOVAL},
      {"edge removal, one or two steps", ES::EDGE_REMOVAL | ES::TWO_STEP_EDGE_REMOVAL},
      {"edge + multi-face removal", ES::EDGE_REMOVAL | ES::MULTI_FACE_REMOVAL},
      {"topological", ES::TOPOLOGICAL_OPERATIONS},
      {"topological + smoothing", ES::ALL_OPERATIONS}};
  for(const auto& [name, operations] : variants)
  {
    if(!selected(std::string("worst first MinMax, ") + name)) continue;
    Triangulation tr;
    make(tr);
    const auto boundary = boundary_vertices(tr);
    const auto np = ES::parameters::operations(operations, ES::parameters::mesh_constraints(constraints));
    const auto r = ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(), np);
    print((std::string("worst first MinMax, ") + name).c_str(), quality(tr, counted(tr), boundary), r.seconds,
          operations_of(r) + " (" + std::to_string(moved_vertices(tr, input)) + " points moved)");
  }
  // The other measures, with the topological operations, then with smoothing.
  auto other = [&](const auto& criterion, const char* measure) {
    for(const unsigned operations : {unsigned(ES::TOPOLOGICAL_OPERATIONS), unsigned(ES::ALL_OPERATIONS),
                                     unsigned(ES::ALL_OPERATIONS | ES::BOUNDARY_SMOOTHING),
                                     unsigned(ES::ALL_WITH_VERTEX_CHANGES)})
    {
      const std::string row = std::string("worst first ") + measure +
                              (operations == ES::TOPOLOGICAL_OPERATIONS ? ", topological"
                               : operations == ES::ALL_OPERATIONS      ? ", topological + smoothing"
                               : operations == ES::ALL_WITH_VERTEX_CHANGES
                                   ? ", topological + smoothing + vertex removal and insertion"
                                   : ", topological + boundary smoothing");
      if(!selected(row)) continue;
      Triangulation tr;
      make(tr);
      const auto boundary = boundary_vertices(tr);
      const auto np = ES::parameters::operations(operations, ES::parameters::mesh_constraints(constraints));
      const auto r = ES::improve_worst_tetrahedra(tr, criterion, np);
      print(row.c_str(), quality(tr, counted(tr), boundary), r.seconds,
            operations_of(r) + " (" + std::to_string(moved_vertices(tr, input)) + " points moved)");
    }
  };
  // With a quality target, as TetGen works only on the cells above its 140
  // degrees: only the cells worse than the target are taken.
  auto targeted = [&](const auto& criterion, unsigned operations, double target, const std::string& row) {
    if(!selected(row)) return;
    Triangulation tr;
    make(tr);
    const auto boundary = boundary_vertices(tr);
    const auto np = ES::parameters::quality_target(
        target, ES::parameters::operations(operations, ES::parameters::mesh_constraints(constraints)));
    const auto r = ES::improve_worst_tetrahedra(tr, criterion, np);
    print(row.c_str(), quality(tr, counted(tr), boundary), r.seconds,
          operations_of(r) + " (" + std::to_string(moved_vertices(tr, input)) + " points moved)");
  };
  targeted(ES::Min_max_dihedral_angle_criterion(), ES::TOPOLOGICAL_OPERATIONS, 140,
           "worst first MinMax, topological, target 140 deg");
  targeted(ES::Min_max_dihedral_angle_criterion(), ES::FLIPS | ES::EDGE_REMOVAL, 140,
           "worst first MinMax, flips + edge removal, target 140 deg");
  targeted(ES::Min_max_dihedral_angle_criterion(), ES::EDGE_REMOVAL | ES::MULTI_FACE_REMOVAL, 140,
           "worst first MinMax, edge + multi-face removal, target 140 deg");
  targeted(ES::Max_min_radius_ratio_criterion(), ES::ALL_OPERATIONS, 0.5,
           "worst first radius ratio, topological + smoothing, target 0.5");
  other(ES::Max_min_dihedral_angle_criterion(), "MaxMin");
  other(ES::Max_min_radius_ratio_criterion(), "radius ratio");
  other(ES::Max_min_dihedral_sine_criterion(), "dihedral sine");
  other(ES::Max_min_volume_length_criterion(), "volume-length");

  // The peers. TetGen aims at a largest dihedral angle of 140 degrees (optmaxdihedral).
#ifdef EDGE_SWAPPING_3_WITH_TETGEN
  peer_row("TetGen 1.5 flips (140 deg)", [&] { return quality_peers::tetgen_optimizer(input, 1, 140); }, input, counted);
  peer_row("TetGen 1.5 flips + smoothing", [&] { return quality_peers::tetgen_optimizer(input, 3, 140); }, input,
           counted);
#else
  std::printf("TetGen: libtet was not found when this benchmark was built\n");
#endif
  // CGAL's remeshing keeps its candidate edges in sets ordered by handles,
  // that is by addresses: each run gives another result. Five runs each.
  for(int run = 1; run <= cgal_runs; ++run)
  {
    const std::string at = " #" + std::to_string(run);
    peer_row(("CGAL remeshing flips (10 passes)" + at).c_str(),
             [&] { return quality_peers::cgal_remeshing(input, quality_peers::CGAL_FLIPS, 10); }, input, counted);
    peer_row(("CGAL remeshing flip + smooth (10 passes)" + at).c_str(),
             [&] { return quality_peers::cgal_remeshing(input, quality_peers::CGAL_FLIPS_THEN_SMOOTHING, 10); }, input,
             counted);
    peer_row(("CGAL isotropic remeshing (its defaults)" + at).c_str(),
             [&] { return quality_peers::cgal_remeshing(input, quality_peers::CGAL_ISOTROPIC_REMESHING, 0); }, input,
             counted);
  }
  peer_row("Gmsh 4.8 optimize (swaps, relocation)",
           [&] {
             const auto dir = std::filesystem::temp_directory_path() / ("edge_swapping_3_gmsh_" + std::to_string(getpid()));
             std::filesystem::create_directories(dir);
             const auto r = quality_peers::gmsh_optimizer(input, "/usr/bin/python3", GMSH_SCRIPT, dir.string());
             std::filesystem::remove_all(dir);
             return r;
           },
           input, counted);
}

/// The cells of our triangulation, with its own points numbered.
quality_peers::Cell_mesh cell_mesh_of(const Triangulation& tr)
{
  std::map<Triangulation::Vertex_handle, std::size_t> index;
  std::vector<K::Point_3> points;
  for(auto v : tr.finite_vertex_handles())
  {
    index[v] = points.size();
    points.push_back(v->point());
  }
  return quality_peers::cell_mesh_of(tr, points, [&](Triangulation::Vertex_handle v) { return index.at(v); },
                                     [](Triangulation::Cell_handle c) { return c->info().subdomain; });
}

/// Our triangulation of `m`, a point set's domain (subdomain 1, no constraint).
void build_point_set_mesh(Triangulation& tr, const quality_peers::Cell_mesh& m)
{
  std::vector<Triangulation::Vertex_handle> vertices;
  std::vector<Triangulation::Cell_handle> cells;
  const std::string problem = ES::build_triangulation_from_cells(tr, m.points, m.cells, vertices, cells);
  if(!problem.empty()) throw std::runtime_error(problem);
  ES::mark_point_set_domain(tr);
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  const std::string only = argc > 1 ? argv[1] : "";
  if(argc > 2) selected_rows = argv[2];
  // The scale: the two-spheres mesh's size, or the number of random points.
  const double scale = argc > 3 ? std::atof(argv[3]) : 0;
  if(argc > 3 && !(scale > 0))
  {
    std::fprintf(stderr, "the scale '%s' is not a positive number\n", argv[3]);
    return 2;
  }
  auto wanted = [&](const char* input) { return only.empty() || only == input; };
  if(!only.empty() && !wanted("two-spheres") && !wanted("delaunay") && !wanted("placing"))
  {
    std::fprintf(stderr, "unknown input '%s' (two-spheres, delaunay, placing)\n", only.c_str());
    return 2;
  }
  const std::string dir = (std::filesystem::temp_directory_path() / ("edge_swapping_3_quality_" + std::to_string(getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string mesh = dir + "/two_spheres.mesh";
  const std::string size = (scale > 0 && only == "two-spheres") ? std::string(argv[3]) : std::string("0.35");
  run_program({EDGE_SWAP_BINARY, "mesh-domain", "two-spheres", "--size", size, "-o", mesh});
  const auto two_spheres = ES::IO::read_mesh_with_fields<K::Point_3>(mesh);
  std::filesystem::remove_all(dir);

  quality_peers::Cell_mesh two_spheres_cells{two_spheres.points, two_spheres.cells, two_spheres.cell_references};
  if(wanted("two-spheres"))
  {
    std::printf("\nTwo-spheres domain mesh of size %s, flow region (subdomain 1; in: its cells with no vertex on "
                "a boundary); boundaries and subdomains kept\n", size.c_str());
    std::printf("(%zu boundary triangles in the file, %zu facets between subdomains or on the hull)\n",
                two_spheres.triangles.size(), quality_peers::boundary_triangles(two_spheres_cells).size());
    rows([&](Triangulation& tr) { ES::build_numbered_mesh(tr, two_spheres); }, ES::Domain_constraints(),
         [](const Triangulation&) {
           return Cell_filter([](Triangulation::Cell_handle c) { return c->info().subdomain == 1; });
         },
         two_spheres_cells);
  }

  const std::size_t n = (scale > 0 && only != "two-spheres") ? std::size_t(scale) : 8000;
  const auto points = random_points(n);
  quality_peers::Cell_mesh delaunay, placing;
  {
    Triangulation tr;
    ES::insert_delaunay(tr, points);
    ES::mark_point_set_domain(tr);
    delaunay = cell_mesh_of(tr);
  }
  {
    Triangulation tr;
    ES::insert_by_placing(tr, points);
    ES::mark_point_set_domain(tr);
    placing = cell_mesh_of(tr);
  }
  for(const auto* input : {&delaunay, &placing})
  {
    if(!wanted(input == &delaunay ? "delaunay" : "placing")) continue;
    std::printf("\n%s of %zu random points (in: cells with no vertex on the hull)\n",
                input == &delaunay ? "Delaunay triangulation" : "Placing triangulation (no flip)", n);
    rows([&](Triangulation& tr) { build_point_set_mesh(tr, *input); }, ES::No_constraints(),
         [](const Triangulation&) { return Cell_filter([](Triangulation::Cell_handle) { return true; }); }, *input);
  }
  return 0;
}
