// SPDX-License-Identifier: GPL-3.0-or-later
// The edge_swap program, run as a user would: every bad input or option gives
// exit 2, a message that names the problem, and no output file at all.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <nlohmann/json.hpp>
#include "program_runner.h"

using namespace test;
namespace fs = std::filesystem;

namespace {

const std::string cube_node = "# the corners of a unit cube\n8 3 0 0\n"
                              "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 0 0 1\n6 1 0 1\n7 0 1 1\n8 1 1 1\n";

// Runs optimize on a .node text and expects a clean rejection naming `what`.
void expect_rejected_node(const std::string& node_text, const std::string& what)
{
  Workdir w;
  w.write("in.node", node_text);
  const Run r = w.run("optimize " + w.path("in.node") + " -o " + w.path("out.ele") + " --history " +
                      w.path("h.csv") + " --stats " + w.path("s.json"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find(what) != std::string::npos);
  REQUIRE(w.outputs({"in.node"}) == 0);
}

// Runs optimize and check on an .ele mesh (with the cube's .node).
void expect_rejected_mesh(const std::string& ele_text, const std::string& what)
{
  Workdir w;
  w.write("in.node", cube_node);
  w.write("in.ele", ele_text);
  const Run r = w.run("optimize " + w.path("in.ele") + " -o " + w.path("out.ele"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find(what) != std::string::npos);
  REQUIRE(w.outputs({"in.node", "in.ele"}) == 0);
  const Run c = w.run("check " + w.path("in.ele"));
  INFO("check stdout: " << c.out << " stderr: " << c.err);
  REQUIRE((c.exit_code == 1 || c.exit_code == 2));
}

} // namespace

TEST_CASE("Bad point sets are rejected with exit 2 - a message and no output", "[program]")
{
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 nan 0\n4 0 0 1\n", "not finite");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 inf 0\n4 0 0 1\n", "not finite");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1e999 0\n4 0 0 1\n", "not finite");
  expect_rejected_node("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 0\n", "duplicate points: point 1 and point 4");
  expect_rejected_node("3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n", "fewer than four points");
  expect_rejected_node("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 2 3 0\n", "coplanar");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 3 0 0\n", "collinear");
}

TEST_CASE("Malformed and inconsistent .node files are rejected", "[program]")
{
  expect_rejected_node("", "empty file");
  expect_rejected_node("4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n", "dimension is 2");
  expect_rejected_node("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "more than the rest of the file can hold");
  expect_rejected_node("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n# a comment that pads the file\n",
                       "the file ends after 4 of 5 points");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n", "more lines than");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 zero 0\n3 0 1 0\n4 0 0 1\n", "cannot read a coordinate");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n3 1 0 0\n2 0 1 0\n4 0 0 1\n", "out of sequence");
  expect_rejected_node("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0\n", "missing a coordinate");
  expect_rejected_node("4 3 0 0\n1 0 0 0 7\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "unexpected '7'");
}

TEST_CASE("Inverted - non-conforming and inconsistent meshes are rejected", "[program]")
{
  expect_rejected_mesh("1 4 0\n1 1 2 3 9\n", "not a point of the .node file");
  expect_rejected_mesh("2 4 0\n1 1 2 3 5\n", "more than the rest of the file can hold");
  expect_rejected_mesh("2 4 0\n1 1 2 3 5\n# a comment that pads the file\n", "the file ends after 1 of 2 tetrahedra");
  expect_rejected_mesh("1 4 0\n1 1 2 3 4\n", "coplanar"); // four coplanar corners, the only points used
  expect_rejected_mesh("1 10 0\n1 1 2 3 5 6 7 8 4 1 2\n", "only linear tetrahedra");
}

TEST_CASE("Points of no tetrahedron are kept in the mesh file, out of the triangulation", "[program]")
{
  Workdir w;
  w.write("in.node", cube_node);
  w.write("in.ele", "1 4 0\n1 1 2 3 5\n"); // covers a corner only
  REQUIRE(w.run("optimize " + w.path("in.ele") + " -o " + w.path("out.ele")).exit_code == 0);
  REQUIRE(Workdir::slurp(w.path("out.node")).find("8 1 1 1") != std::string::npos);
  REQUIRE(Workdir::slurp(w.path("out.ele")) == "1 4 0\n1 1 2 3 5\n");
}

TEST_CASE("Meshes with mixed orientation - overlaps or a non-convex boundary are rejected", "[program]")
{
  const std::vector<Point> corners = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0),
                                      Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1), Point(1, 1, 1)};
  // Start from CGAL's triangulation of the cube corners and spoil it.
  Tr dt;
  ES::insert_delaunay(dt, corners);
  std::vector<std::array<std::size_t, 4>> cells;
  auto index = [&](const Point& p) { return std::size_t(std::find(corners.begin(), corners.end(), p) - corners.begin()); };
  for(auto c : dt.finite_cell_handles())
    cells.push_back({index(c->vertex(0)->point()), index(c->vertex(1)->point()), index(c->vertex(2)->point()),
                     index(c->vertex(3)->point())});
  std::vector<Tr::Vertex_handle> vertices;
  // The builder in the file's order and in the Hilbert order of the points.
  const std::size_t hilbert_order_above = GENERATE(std::size_t(0), std::size_t(100000));
  CAPTURE(hilbert_order_above);
  auto build = [&](Tr& tr, const std::vector<Point>& points, const std::vector<std::array<std::size_t, 4>>& tets,
                   std::vector<Tr::Vertex_handle>& v) {
    std::vector<Tr::Cell_handle> handles;
    return ES::internal::build_triangulation_from_cells(tr, points, tets, v, handles, hilbert_order_above);
  };
  {
    Tr tr;
    REQUIRE(build(tr, corners, cells, vertices).empty());
    REQUIRE(ES::compare_with_delaunay(tr).identical);
  }
  {
    auto bad = cells;
    std::swap(bad[1][0], bad[1][1]);
    Tr tr;
    REQUIRE(build(tr, corners, bad, vertices).find("inverted") != std::string::npos);
    REQUIRE(tr.number_of_vertices() == 0);
  }
  {
    auto bad = cells;
    for(auto& t : bad) std::swap(t[0], t[1]); // all reversed: a consistent other convention, accepted
    Tr tr;
    REQUIRE(build(tr, corners, bad, vertices).empty());
  }
  {
    auto bad = cells;
    bad.push_back(bad.front()); // a facet shared by more than two tetrahedra
    Tr tr;
    const std::string why = build(tr, corners, bad, vertices);
    REQUIRE((why.find("more than two") != std::string::npos || why.find("repeated") != std::string::npos));
  }
  {
    // Two whole copies: every facet pairs up within its copy, so only the
    // second boundary surface gives them away.
    auto twice = cells;
    twice.insert(twice.end(), cells.begin(), cells.end());
    Tr tr;
    const std::string why = build(tr, corners, twice, vertices);
    INFO(why);
    REQUIRE((why.find("more than two") != std::string::npos || why.find("repeated") != std::string::npos));
  }
  {
    // Remove a corner tetrahedron touching the hull: the boundary is no longer convex
    // (or a point is left out).
    for(std::size_t k = 0; k < cells.size(); ++k)
    {
      auto bad = cells;
      bad.erase(bad.begin() + std::ptrdiff_t(k));
      Tr tr;
      const std::string why = build(tr, corners, bad, vertices);
      INFO("without tetrahedron " << k << ": " << why);
      REQUIRE_FALSE(why.empty());
    }
  }
  {
    // Overlap: a tetrahedron and its mirror image through a shared facet pointing the same way.
    const std::vector<Point> p = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(1, 1, 1)};
    Tr tr;
    const std::string why = build(tr, p, {{0, 1, 2, 3}, {0, 1, 2, 4}}, vertices);
    REQUIRE_FALSE(why.empty());
  }
}

TEST_CASE("Meshes built in the Hilbert order of their points are the meshes read", "[program]")
{
  const unsigned seed = 17;
  INFO("seed " << seed);
  const auto points = random_in_cube(3000, seed);
  Tr dt;
  const auto dv = ES::insert_delaunay(dt, points);
  std::map<Tr::Vertex_handle, std::size_t> index;
  for(std::size_t k = 0; k < dv.size(); ++k) index[dv[k]] = k;
  std::vector<std::array<std::size_t, 4>> cells;
  for(auto c : dt.finite_cell_handles())
    cells.push_back({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
  std::shuffle(cells.begin(), cells.end(), std::mt19937(seed));
  Tr tr;
  std::vector<Tr::Vertex_handle> vertices;
  std::vector<Tr::Cell_handle> handles;
  REQUIRE(ES::internal::build_triangulation_from_cells(tr, points, cells, vertices, handles, 0).empty());
  REQUIRE(tr.is_valid());
  REQUIRE(ES::compare_with_delaunay(tr).identical);
  // Each point has its vertex and each tetrahedron its cell, whatever the storage order.
  for(std::size_t v = 0; v < points.size(); ++v) REQUIRE(vertices[v]->point() == points[v]);
  for(std::size_t k = 0; k < cells.size(); ++k)
    for(std::size_t v : cells[k]) REQUIRE(handles[k]->has_vertex(vertices[v]));
  // The storage order is no longer the order given.
  bool same_order = true;
  std::size_t k = 0;
  for(Tr::Cell_handle c : tr.finite_cell_handles()) same_order = same_order && c == handles[k++];
  REQUIRE_FALSE(same_order);
}

TEST_CASE("Bad options are rejected with exit 2 and no output", "[program]")
{
  Workdir w;
  w.write("cube.node", cube_node);
  const std::string in = w.path("cube.node"), out = " -o " + w.path("out.ele");
  for(const std::string& args : std::vector<std::string>
      {"optimize " + in + out + " --criterion fastest", "optimize " + in + out + " --criterion minmax-dihedral --helper",
       "optimize " + in + out + " --start sideways", "optimize " + in + out + " --start scramble:x",
       "optimize " + in + out + " --order backwards", "optimize " + in + out + " --perturb maybe",
       "optimize " + in + " -o " + w.path("out.obj"), "optimize " + in + out + " --max-cycles -3",
       "optimize " + w.path("missing.node") + out, "optimize " + w.path("cube.txt") + out, "frobnicate",
       "check " + w.path("missing.ele"), "check " + in,
       "optimize " + in + out + " --operations flips",
       "optimize " + in + out + " --criterion minmax-dihedral --operations smoothing,paper-flips",
       "optimize " + in + out + " --criterion dihedral-sine --history " + w.path("h.csv"),
       "optimize " + in + out + " --criterion maxmin-dihedral --order random",
       "optimize " + in + out + " --criterion radius-ratio --max-cycles 5",
       "optimize " + in + out + " --criterion dihedral-sine --perturb none",
       "optimize " + in + out + " --criterion radius-ratio --operations topological --schedule cycles",
       "optimize " + in + out + " --criterion minmax-dihedral --operations flips,",
       "optimize " + in + out + " --criterion min-edges --operations edge-removal",
       "optimize " + in + out + " --criterion minmax-dihedral --operations multi-face",
       "optimize " + in + out + " --criterion radius-ratio --operations flips --history " + w.path("h.csv"),
       "optimize " + in + out + " --criterion minmax-dihedral --time-limit 0",
       "optimize " + in + out + " --criterion minmax-dihedral --time-limit -2",
       "optimize " + in + out + " --criterion minmax-dihedral --time-limit nan",
       "optimize " + in + out + " --criterion minmax-dihedral --time-limit soon",
       "optimize " + in + out + " --time-limit 5",
       "optimize " + in + out + " --criterion minmax-dihedral --operations paper-flips --time-limit 5",
       "optimize " + in + out + " --criterion minmax-dihedral --threads -1",
       "optimize " + in + out + " --criterion minmax-dihedral --threads many",
       "optimize " + in + out + " --criterion minmax-dihedral --threads 5000",
       "optimize " + in + out + " --threads 2",
       "optimize " + in + out + " --criterion dihedral-sine --moves-per-vertex 0",
       "optimize " + in + out + " --criterion dihedral-sine --moves-per-vertex many",
       "optimize " + in + out + " --criterion dihedral-sine --operations topological --moves-per-vertex 50",
       "optimize " + in + out + " --moves-per-vertex 50"})
  {
    INFO("edge_swap " << args);
    const Run r = w.run(args);
    REQUIRE(r.exit_code == 2);
    REQUIRE_FALSE(r.err.empty());
    REQUIRE(w.outputs({"cube.node"}) == 0);
  }
}

TEST_CASE("optimize writes a mesh that reads back exactly - and check agrees", "[program]")
{
  Workdir w;
  // Coordinates that need 17 digits to read back.
  std::ostringstream node;
  node.precision(17);
  const auto points = random_in_ball(300, 11);
  node << points.size() << " 3 1 0\n";
  for(std::size_t k = 0; k < points.size(); ++k)
    node << k << ' ' << points[k].x() << ' ' << points[k].y() << ' ' << points[k].z() << ' ' << 0.5 * double(k) << '\n';
  w.write("ball.node", node.str());

  Run r = w.run("optimize " + w.path("ball.node") + " -o " + w.path("out.ele") + " --helper --order random --seed 3 "
                "--history " + w.path("h.csv") + " --stats " + w.path("s.json"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const auto back = CGAL::Edge_swapping_3::IO::read_node_file(w.path("out.node"));
  REQUIRE(back.first_index == 0);
  REQUIRE(back.points.size() == points.size());
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    REQUIRE(back.points[k][0] == points[k].x());
    REQUIRE(back.points[k][1] == points[k].y());
    REQUIRE(back.points[k][2] == points[k].z());
    REQUIRE(back.attributes[k][0] == 0.5 * double(k)); // attributes are carried through
  }
  REQUIRE(Workdir::slurp(w.path("h.csv")).rfind("cycle,swaps_2_3,", 0) == 0);
  REQUIRE(Workdir::slurp(w.path("s.json")).find("\"ending\": \"converged\"") != std::string::npos);

  r = w.run("check " + w.path("out.ele"));
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("equal to CGAL's Delaunay triangulation: yes") != std::string::npos);

  // A placing start, optimized by another criterion, is valid but not Delaunay.
  r = w.run("optimize " + w.path("ball.node") + " -o " + w.path("minmax.ele") + " --criterion minmax-dihedral");
  REQUIRE(r.exit_code == 0);
  r = w.run("check " + w.path("minmax.ele"));
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("valid triangulation") != std::string::npos);

  // An .ele input is optimized in place of a start triangulation.
  r = w.run("optimize " + w.path("minmax.ele") + " -o " + w.path("again.ele") + " --criterion delaunay --perturb none");
  REQUIRE(r.exit_code == 0);
  r = w.run("optimize " + w.path("minmax.ele") + " -o " + w.path("x.ele") + " --start delaunay");
  REQUIRE(r.exit_code == 2);
}

namespace {
/// Writes `n` random points of the unit cube (seed `seed`) as the .node file `name`.
void write_random_node(const Workdir& w, const std::string& name, std::size_t n, unsigned seed)
{
  std::vector<std::array<double, 3>> points;
  for(const Point& p : random_in_cube(n, seed)) points.push_back({p.x(), p.y(), p.z()});
  std::ofstream node(w.path(name));
  CGAL::Edge_swapping_3::IO::write_node_file(node, points, {}, 0);
}
} // namespace

TEST_CASE("optimize --reading: readings the program cannot run as asked are refused before any work, the others run",
          "[program]")
{
  Workdir w;
  write_random_node(w, "p.node", 60, 7);
  const std::string base = "optimize " + w.path("p.node") + " -o " + w.path("x.ele") + " ";
  for(const auto& [args, what] : std::vector<std::pair<std::string, std::string>>{
          {"--reading never-cleared,pass-over,no-swap", "--reading sets the helper strategy's reading"},
          {"--helper --schedule cycles --reading never-cleared,pass-over", "is not a reading"},
          {"--helper --schedule cycles --reading until-destroyed,pass-over,no-swap,later", "is not a reading"},
          {"--helper --reading never-cleared,pass-over,no-swap", "runs on the paper's cycles: add --schedule cycles"},
          {"--helper --schedule cycles --order storage --reading until-destroyed,facet-cells,no-swap,same-cycle",
           "needs --order priority or random"},
          {"--helper --order fixed", "--order is storage, random or priority"},
          {"--criterion aspect-ratio --order priority", "--order and --schedule set the paper's flip driver"}})
    require_clean_rejection(w, base + args, what, {"p.node"});
  // The package's reading is the work queue's: no --schedule cycles needed. Without --order
  // the helper's order is random, which same-cycle takes.
  REQUIRE(w.run(base + "--helper --order priority --seed 3 --reading until-destroyed,pass-over,no-swap-no-tag").exit_code == 0);
  REQUIRE(w.run(base + "--helper --schedule cycles --reading until-destroyed,facet-cells,no-swap,same-cycle").exit_code == 0);
}

TEST_CASE("The program gives the same output with and without huge pages", "[program]")
{
  // edge_swap starts itself again with glibc.malloc.hugetlb=1 added to
  // GLIBC_TUNABLES, unless the variable names that tunable already.
  Workdir w;
  write_random_node(w, "cube.node", 400, 5);
  const std::string args = "optimize " + w.path("cube.node") + " --criterion minmax-dihedral -o ";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"unset GLIBC_TUNABLES;", "unset.ele"},
      {"export GLIBC_TUNABLES=glibc.malloc.hugetlb=0;", "off.ele"},
      {"export GLIBC_TUNABLES=glibc.malloc.check=0;", "other.ele"}};
  for(const auto& [prefix, output] : runs)
  {
    const Run r = w.run_with(prefix, args + w.path(output));
    INFO(prefix << " stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
  }
  const std::string first = Workdir::slurp(w.path("unset.ele"));
  REQUIRE(first.size() > 100);
  REQUIRE(Workdir::slurp(w.path("off.ele")) == first);
  REQUIRE(Workdir::slurp(w.path("other.ele")) == first);
  // Bad input is still refused the same way after the restart.
  const Run bad = w.run_with("unset GLIBC_TUNABLES;", "check " + w.path("missing.ele"));
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.find("missing.node") != std::string::npos);
}

TEST_CASE("optimize --operations runs the worst-first driver and writes a valid mesh", "[program]")
{
  Workdir w;
  write_random_node(w, "cube.node", 300, 13);
  // No --operations: the default, all of them.
  const std::pair<std::string, std::string> runs[] = {{"minmax-dihedral", "flips,edge-removal"},
                                                       {"radius-ratio", "multi-face-removal"},
                                                       {"maxmin-dihedral", "topological"},
                                                       {"minmax-dihedral", "edge-removal,two-step-edge-removal"},
                                                       {"dihedral-sine", "smoothing"},
                                                       {"volume-length", "flips,boundary-smoothing"},
                                                       {"aspect-ratio", ""}};
  for(const auto& [criterion, operations] : runs)
  {
    INFO(criterion << " " << operations);
    const Run r = w.run("optimize " + w.path("cube.node") + " --start delaunay --criterion " + criterion +
                        (operations.empty() ? "" : " --operations " + operations) + " -o " + w.path("out.ele") +
                        " --stats " + w.path("s.json"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("worst first (" + (operations.empty() ? "all" : operations) + "): converged") != std::string::npos);
    const bool smoothing = operations.empty() || operations.find("smoothing") != std::string::npos;
    REQUIRE((r.out.find("smoothing moves 0;") == std::string::npos) == smoothing);
    const std::string stats = Workdir::slurp(w.path("s.json"));
    REQUIRE(stats.find("\"edge_removals\"") != std::string::npos);
    REQUIRE(stats.find("\"multi_face_removals\"") != std::string::npos);
    const bool faces = operations.empty() || operations == "multi-face-removal" || operations == "topological";
    REQUIRE((stats.find("\"multi_face_removals\": 0,") == std::string::npos) == faces);
    REQUIRE(stats.find("\"driver\": \"worst first\"") != std::string::npos);
    const bool two_steps = operations.empty() || operations == "topological" ||
                           operations.find("two-step-edge-removal") != std::string::npos;
    REQUIRE((stats.find("\"two_step_edge_removals\": 0,") == std::string::npos) == two_steps);
    const Run c = w.run("check " + w.path("out.ele"));
    REQUIRE(c.exit_code == 0);
    REQUIRE(c.out.find("valid triangulation") != std::string::npos);
  }
  // --moves-per-vertex bounds the smoothing moves of each of the 300 vertices.
  auto smoothing_moves = [&](const std::string& bound) {
    const Run r = w.run("optimize " + w.path("cube.node") + " --start delaunay --criterion dihedral-sine "
                        "--operations smoothing" + bound + " -o " + w.path("moved.ele") + " --stats " + w.path("m.json"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string stats = Workdir::slurp(w.path("m.json"));
    const std::size_t at = stats.find("\"smoothing_moves\": ");
    REQUIRE(at != std::string::npos);
    return std::stol(stats.substr(at + 19));
  };
  const long one = smoothing_moves(" --moves-per-vertex 1"), bounded_by_default = smoothing_moves("");
  REQUIRE(one > 0);
  REQUIRE(one <= 300);
  REQUIRE(bounded_by_default > one);
  REQUIRE(Workdir::slurp(w.path("m.json")).find("\"moves_per_vertex\": 200") != std::string::npos);
  // The paper's driver, with its rounds.
  const Run r = w.run("optimize " + w.path("cube.node") + " --criterion minmax-dihedral --operations paper-flips -o " +
                      w.path("paper.ele") + " --history " + w.path("h.csv"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("minmax-dihedral: converged after") != std::string::npos);
  REQUIRE(Workdir::slurp(w.path("h.csv")).rfind("cycle,swaps_2_3,", 0) == 0);
}

TEST_CASE("optimize --threads: the same number of threads writes the same file - a valid mesh",
          "[program][threads]")
{
  Workdir w;
  const unsigned seed = 17;
  INFO("seed " << seed);
  write_random_node(w, "cube.node", 2000, seed);
  const std::string start = "optimize " + w.path("cube.node") +
                            " --start delaunay --criterion maxmin-dihedral --quality-target 20"
                            " --operations topological,vertex-removal,vertex-insertion";
  for(const std::string threads : {"1", "2"})
  {
    INFO("--threads " << threads);
    const std::string a = w.path("a" + threads + ".mesh"), b = w.path("b" + threads + ".mesh");
    const Run r = w.run(start + " --threads " + threads + " -o " + a + " --stats " + w.path("s.json"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("converged") != std::string::npos);
    REQUIRE(Workdir::slurp(w.path("s.json")).find("\"threads\": " + threads) != std::string::npos);
    REQUIRE(w.run(start + " --threads " + threads + " -o " + b).exit_code == 0);
    REQUIRE(Workdir::slurp(a) == Workdir::slurp(b));
    const Run c = w.run("check " + a);
    INFO(c.out << c.err);
    REQUIRE(c.exit_code == 0);
    REQUIRE(c.out.find("valid triangulation") != std::string::npos);
  }
  // Parts make a difference, and a run in parts inserted vertices here.
  REQUIRE(Workdir::slurp(w.path("a1.mesh")) != Workdir::slurp(w.path("a2.mesh")));
}

TEST_CASE("optimize --time-limit and Ctrl-C end the worst-first driver with the mesh so far - valid and written",
          "[program][time limit]")
{
  Workdir w;
  write_random_node(w, "cube.node", 300, 13);
  const std::string start = "optimize " + w.path("cube.node") + " --start delaunay --criterion minmax-dihedral -o ";
  {
    // A limit that has passed before the first visit: the start triangulation, written.
    const Run r = w.run(start + w.path("now.ele") + " --time-limit 1e-9 --stats " + w.path("s.json"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("worst first (all): time limit reached") != std::string::npos);
    const std::string stats = Workdir::slurp(w.path("s.json"));
    REQUIRE(stats.find("\"ending\": \"time limit reached\"") != std::string::npos);
    REQUIRE(stats.find("\"time_limit\": 1e-09") != std::string::npos);
    REQUIRE(w.run("check " + w.path("now.ele")).exit_code == 0);
  }
  {
    // A limit the run does not reach changes nothing.
    const Run limited = w.run(start + w.path("limited.ele") + " --time-limit 1000");
    const Run free = w.run(start + w.path("free.ele"));
    REQUIRE(limited.exit_code == 0);
    REQUIRE(free.exit_code == 0);
    REQUIRE(limited.out.find("converged") != std::string::npos);
    REQUIRE(Workdir::slurp(w.path("limited.ele")) == Workdir::slurp(w.path("free.ele")));
  }
  SECTION("Ctrl-C")
  {
    // 20,000 points with every operation run for many seconds: once the
    // driver says where it is, SIGINT ends it after the operation under way.
    const unsigned seed = 5;
    INFO("seed " << seed);
    write_random_node(w, "many.node", 20000, seed);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if(child == 0)
    {
      std::freopen(w.path("stdout").c_str(), "w", stdout);
      std::freopen(w.path("stderr").c_str(), "w", stderr);
      const std::string in = w.path("many.node"), out = w.path("cut.mesh");
      ::execl(EDGE_SWAP_BINARY, EDGE_SWAP_BINARY, "optimize", in.c_str(), "--criterion", "dihedral-sine", "-o",
              out.c_str(), static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    bool working = false;
    for(int k = 0; k < 1200 && !working; ++k) // two minutes at most
    {
      ::usleep(100000);
      working = Workdir::slurp(w.path("stderr")).find("worst first: ") != std::string::npos;
    }
    ::kill(child, SIGINT);
    int status = 0;
    ::waitpid(child, &status, 0);
    const std::string out = Workdir::slurp(w.path("stdout")), err = Workdir::slurp(w.path("stderr"));
    INFO("stdout: " << out << "\nstderr: " << err);
    REQUIRE(working);
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 130);
    REQUIRE(out.find("worst first (all): interrupted") != std::string::npos);
    const Run c = w.run("check " + w.path("cut.mesh"));
    INFO(c.out << c.err);
    REQUIRE(c.exit_code == 0);
    REQUIRE(c.out.find("valid triangulation") != std::string::npos);
  }
}

TEST_CASE("optimize's default criterion: the dihedral sine for a mesh - Delaunay for a point set - the helper and --paper",
          "[program]")
{
  Workdir w;
  write_random_node(w, "cube.node", 200, 17);
  // The point set: the Delaunay criterion from the paper's placing start.
  Run r = w.run("optimize " + w.path("cube.node") + " -o " + w.path("placed.ele"));
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("delaunay: converged") != std::string::npos);
  // A placing start kept as a mesh (no flip), then optimized as a mesh: the
  // dihedral sine with every operation, and its worst value never worse.
  r = w.run("optimize " + w.path("cube.node") + " --criterion min-edges --max-cycles 1 -o " + w.path("start.ele"));
  REQUIRE(r.exit_code == 0);
  for(const std::string out : {"better.ele", "better.mesh"})
  {
    r = w.run("optimize " + w.path("start.ele") + " -o " + w.path(out) + " --stats " + w.path("s.json"));
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("dihedral-sine, worst first (all): converged") != std::string::npos);
    const auto stats = nlohmann::json::parse(Workdir::slurp(w.path("s.json")));
    REQUIRE(stats["strategy"] == "dihedral-sine");
    REQUIRE(stats["worst_after"].get<double>() >= stats["worst_before"].get<double>());
    REQUIRE(w.run("check " + w.path(out)).exit_code == 0);
  }
  // The helper and --paper are the Delaunay criterion's, on a mesh too.
  r = w.run("optimize " + w.path("start.ele") + " --helper -o " + w.path("helper.ele"));
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("helper: ") != std::string::npos);
  r = w.run("optimize " + w.path("start.ele") + " --paper -o " + w.path("paper.ele"));
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("delaunay: ") != std::string::npos);
  // An option of the flip driver on a mesh says how to get it.
  require_clean_rejection(w, "optimize " + w.path("start.ele") + " --order random -o " + w.path("x.ele"),
                          "add --criterion delaunay for the flip driver",
                          {"cube.node", "placed.ele", "placed.node", "start.ele", "start.node", "better.ele",
                           "better.node", "better.mesh", "s.json", "helper.ele", "helper.node", "paper.ele",
                           "paper.node"});
  require_clean_rejection(w, "optimize " + w.path("start.ele") + " --max-cycles 5 -o " + w.path("x.ele"),
                          "add --criterion delaunay for the flip driver",
                          {"cube.node", "placed.ele", "placed.node", "start.ele", "start.node", "better.ele",
                           "better.node", "better.mesh", "s.json", "helper.ele", "helper.node", "paper.ele",
                           "paper.node"});
  r = w.run("optimize " + w.path("start.ele") + " --order random --max-cycles 5 --criterion delaunay -o " +
            w.path("x.ele"));
  REQUIRE(r.exit_code == 0);
}

TEST_CASE("optimize with vertex removal and insertion - new points get their fields - removed ones leave the output",
          "[program][vertex insertion]")
{
  // A point field equal to x: linear interpolation at a new vertex gives its
  // x again, up to rounding. Without smoothing, no old vertex moves.
  Workdir w;
  const unsigned seed = 19;
  INFO("seed " << seed);
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<double>> field;
  for(const Point& p : random_in_cube(200, seed))
  {
    points.push_back({p.x(), p.y(), p.z()});
    field.push_back({p.x()});
  }
  {
    std::ofstream node(w.path("cube.node"));
    CGAL::Edge_swapping_3::IO::write_node_file(node, points, field, 1);
  }
  // A placing start (an arbitrary triangulation, many bad cells), kept as a mesh.
  Run r = w.run("optimize " + w.path("cube.node") + " --criterion min-edges --max-cycles 1 -o " + w.path("start.ele"));
  REQUIRE(r.exit_code == 0);
  r = w.run("optimize " + w.path("start.ele") + " --operations topological,vertex-removal,vertex-insertion -o " +
            w.path("out.ele") + " --stats " + w.path("s.json"));
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto stats = nlohmann::json::parse(Workdir::slurp(w.path("s.json")));
  const std::size_t inserted = stats["vertex_insertions"], removed = stats["vertex_removals"];
  REQUIRE(inserted > 0);
  REQUIRE(removed > 0);
  REQUIRE(stats["worst_after"].get<double>() >= stats["worst_before"].get<double>());
  REQUIRE(r.out.find("(200 -> " + std::to_string(200 + inserted - removed) + ")") != std::string::npos);
  REQUIRE(w.run("check " + w.path("out.ele")).exit_code == 0);
  // The output's points: the kept ones and the new ones, each with its field.
  std::istringstream node(Workdir::slurp(w.path("out.node")));
  std::size_t n = 0, dimension = 0, attributes = 0, markers = 0;
  node >> n >> dimension >> attributes >> markers;
  REQUIRE(n == 200 + inserted - removed);
  REQUIRE(attributes == 1);
  std::size_t old_points = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    double index = 0, x = 0, y = 0, z = 0, value = 0;
    node >> index >> x >> y >> z >> value;
    REQUIRE(std::abs(value - x) <= 1e-12);
    old_points += std::find(points.begin(), points.end(), std::array<double, 3>{x, y, z}) != points.end();
  }
  // Removal may take inserted vertices too.
  REQUIRE(old_points >= 200 - removed);
  REQUIRE(n - old_points <= inserted);
  REQUIRE(n - old_points > 0);
  // The names of the operations are refused when misspelled.
  require_clean_rejection(w, "optimize " + w.path("start.ele") + " --operations vertex-insertions -o " + w.path("x.ele"),
                          "unknown operation 'vertex-insertions'",
                          {"cube.node", "start.ele", "start.node", "out.ele", "out.node", "s.json"});
}

TEST_CASE("The demo proves equality with CGAL and prints the paper's table", "[program]")
{
  Workdir w;
  const Run r = w.run("demo --points 1500 --seed 2");
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("cell for cell: yes") != std::string::npos);
  REQUIRE(r.out.find("Cells") != std::string::npos);
  REQUIRE(r.out.find("52800") != std::string::npos);
}

TEST_CASE("The program's version, help and unknown commands", "[program]")
{
  Workdir w;
  const Run version = w.run("--version");
  REQUIRE(version.exit_code == 0);
  REQUIRE(version.out.rfind("edge_swap ", 0) == 0);
  // A misspelled command is named, with the commands there are.
  const Run misspelled = w.run("optimise x.node -o y.ele");
  REQUIRE(misspelled.exit_code == 2);
  REQUIRE(misspelled.err.find("unknown command 'optimise'") != std::string::npos);
  REQUIRE(misspelled.err.find("optimize, check, insert") != std::string::npos);
  // Each option's help shows its default and, where there are some, its choices; optimize names every format.
  const Run help = w.run("optimize --help");
  REQUIRE(help.exit_code == 0);
  for(const std::string text : {"default: dihedral-sine for a mesh", "cgal|none", ".mesh", ".msh", ".vtu", ".ele", ".node"})
  {
    INFO(text);
    REQUIRE(help.out.find(text) != std::string::npos);
  }
}
