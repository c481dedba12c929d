// SPDX-License-Identifier: GPL-3.0-or-later
// The program's insertion, refinement, statistics and domain commands, and
// the Medit, VTK and TetGen-attribute files: round trips, domain integrity
// (boundary triangles and flow region unchanged, sites inside), bad files.

#include "test_common.h"
#include "program_runner.h"
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/IO/vtu.h>
#include <map>
#include <set>

using namespace test;
namespace IO = CGAL::Edge_swapping_3::IO;

namespace {

typedef std::array<double, 3> P3;

// Boundary triangles as sorted coordinate triples with their reference.
std::multiset<std::pair<std::array<P3, 3>, int>> boundary(const IO::Medit_mesh& m)
{
  std::multiset<std::pair<std::array<P3, 3>, int>> s;
  for(std::size_t k = 0; k < m.triangles.size(); ++k)
  {
    std::array<P3, 3> t = {m.points[m.triangles[k][0]], m.points[m.triangles[k][1]], m.points[m.triangles[k][2]]};
    std::sort(t.begin(), t.end());
    s.insert({t, m.triangle_references[k]});
  }
  return s;
}

CGAL::Exact_rational volume_of(const IO::Medit_mesh& m, int reference)
{
  CGAL::Exact_rational v = 0;
  for(std::size_t k = 0; k < m.tetrahedra.size(); ++k)
    if(m.tetrahedron_references[k] == reference)
    {
      std::array<Point, 4> p;
      for(int i = 0; i < 4; ++i) { const auto& q = m.points[m.tetrahedra[k][i]]; p[i] = Point(q[0], q[1], q[2]); }
      v += CGAL::abs(exact_volume(p[0], p[1], p[2], p[3]));
    }
  return v;
}

// Strictly inside the box of CGAL/Edge_swapping_3/Two_spheres_domain.h.
bool in_box(const P3& p)
{
  return p[0] > -3 && p[0] < 7 && std::abs(p[1]) < 2.5 && std::abs(p[2]) < 2.5;
}

Point point_of(const P3& p) { return Point(p[0], p[1], p[2]); }

// Whether p lies in or on a tetrahedron of reference 0 (a hole) of m (exact).
bool in_a_hole(const IO::Medit_mesh& m, const P3& p)
{
  const Point q = point_of(p);
  for(std::size_t k = 0; k < m.tetrahedra.size(); ++k)
  {
    if(m.tetrahedron_references[k] != 0) continue;
    std::array<Point, 4> t;
    for(int i = 0; i < 4; ++i) t[i] = point_of(m.points[m.tetrahedra[k][i]]);
    const auto o = CGAL::orientation(t[0], t[1], t[2], t[3]);
    bool inside = true;
    for(int i = 0; i < 4 && inside; ++i)
    {
      auto u = t;
      u[i] = q;
      inside = CGAL::orientation(u[0], u[1], u[2], u[3]) != -o;
    }
    if(inside) return true;
  }
  return false;
}

// Whether p lies strictly inside the diametral ball of a boundary triangle of m.
bool encroaches_boundary(const IO::Medit_mesh& m, const P3& p)
{
  for(const auto& t : m.triangles)
    if(CGAL::side_of_bounded_sphere(point_of(m.points[t[0]]), point_of(m.points[t[1]]), point_of(m.points[t[2]]),
                                    point_of(p)) == CGAL::ON_BOUNDED_SIDE)
      return true;
  return false;
}

// A site of the flow region: inside the box, in no hole, and encroaching upon
// no boundary triangle.
bool in_flow_region(const IO::Medit_mesh& m, const P3& p)
{
  return in_box(p) && !in_a_hole(m, p) && !encroaches_boundary(m, p);
}

} // namespace

TEST_CASE("Two-spheres domain: refinement keeps the boundary and the flow region and inserts inside", "[program][domain]")
{
  Workdir w;
  Run r = w.run("mesh-domain two-spheres -o " + w.path("ts.mesh"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const IO::Medit_mesh before = IO::read_medit_file(w.path("ts.mesh"));
  REQUIRE(before.tetrahedra.size() > 1000);
  REQUIRE(std::set<int>(before.triangle_references.begin(), before.triangle_references.end()) == std::set<int>{1, 2, 3});
  REQUIRE(w.run("check " + w.path("ts.mesh")).exit_code == 0);
  // Each sphere is a closed surface (every edge in two of its triangles), and
  // the holes fill most of the two balls (an inscribed polyhedron is smaller).
  for(int sphere : {2, 3})
  {
    INFO("sphere reference " << sphere);
    std::map<std::pair<std::size_t, std::size_t>, int> edge_uses;
    for(std::size_t k = 0; k < before.triangles.size(); ++k)
      if(before.triangle_references[k] == sphere)
        for(int i = 0; i < 3; ++i)
        {
          const auto a = before.triangles[k][i], b = before.triangles[k][(i + 1) % 3];
          edge_uses[std::minmax(a, b)]++;
        }
    REQUIRE(edge_uses.size() >= 12);
    for(const auto& e : edge_uses) REQUIRE(e.second == 2);
  }
  const double holes = CGAL::to_double(volume_of(before, 0)), balls = 2 * 4.0 / 3.0 * CGAL_PI * 0.125;
  CHECK(holes > 0.7 * balls);
  CHECK(holes < balls);

  r = w.run("refine " + w.path("ts.mesh") + " --by aspect-ratio --target 2 -o " + w.path("ar.mesh") +
            " --history " + w.path("ar.csv"));
  INFO("stdout: " << r.out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("(target met)") != std::string::npos);
  const IO::Medit_mesh after = IO::read_medit_file(w.path("ar.mesh"));
  REQUIRE(after.points.size() > before.points.size());
  for(std::size_t k = before.points.size(); k < after.points.size(); ++k) REQUIRE(in_flow_region(before, after.points[k]));
  REQUIRE(boundary(after) == boundary(before));
  REQUIRE(volume_of(after, 1) == volume_of(before, 1));
  REQUIRE(w.run("check " + w.path("ar.mesh")).exit_code == 0);

  // Gradient refinement by the synthetic field, two rounds.
  r = w.run("refine " + w.path("ts.mesh") + " --by gradient --field flow-density --sites 300,200 -o " + w.path("g.mesh"));
  REQUIRE(r.exit_code == 0);
  const IO::Medit_mesh g = IO::read_medit_file(w.path("g.mesh"));
  REQUIRE(g.points.size() == before.points.size() + 500);
  for(std::size_t k = before.points.size(); k < g.points.size(); ++k) REQUIRE(in_flow_region(before, g.points[k]));
  REQUIRE(boundary(g) == boundary(before));
  REQUIRE(volume_of(g, 1) == volume_of(before, 1));

  r = w.run("stats " + w.path("g.mesh") + " --json " + w.path("s.json"));
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("dihedral angle histogram") != std::string::npos);
  REQUIRE(Workdir::slurp(w.path("s.json")).find("\"histogram\"") != std::string::npos);
}

TEST_CASE("Each file format round-trips - write then read then write gives the same file", "[program][files]")
{
  Workdir w;
  REQUIRE(w.run("mesh-domain two-spheres --size 0.9 -o " + w.path("a.mesh")).exit_code == 0);
  w.write("none.node", "0 3 0 0\n");
  for(const std::string ext : {".mesh", ".msh", ".vtu", ".ele"})
  {
    INFO("format " << ext);
    REQUIRE(w.run("insert " + w.path("a.mesh") + " --points " + w.path("none.node") + " -o " + w.path("b" + ext)).exit_code == 0);
    REQUIRE(w.run("insert " + w.path("b" + ext) + " --points " + w.path("none.node") + " -o " + w.path("c" + ext)).exit_code == 0);
    REQUIRE(Workdir::slurp(w.path("b" + ext)) == Workdir::slurp(w.path("c" + ext)));
  }
  // The Medit copy is the input, point for point and cell for cell.
  const IO::Medit_mesh a = IO::read_medit_file(w.path("a.mesh")), b = IO::read_medit_file(w.path("b.mesh"));
  REQUIRE(a.points == b.points);
  REQUIRE(boundary(a) == boundary(b));
  REQUIRE(volume_of(a, 1) == volume_of(b, 1));
  const IO::Vtu_mesh v = IO::read_vtu_file(w.path("b.vtu"));
  REQUIRE(v.points == a.points);
  REQUIRE(v.tetrahedra.size() == a.tetrahedra.size());
}

TEST_CASE("Node attributes are vertex fields - interpolated at new sites and written back", "[program][files]")
{
  Workdir w;
  // A Delaunay mesh of random points with the linear field 1 + x + 2y: linear
  // interpolation reproduces it at every new site.
  std::ostringstream node;
  node.precision(17);
  const auto points = random_in_cube(300, 21);
  node << points.size() << " 3 1 0\n";
  for(std::size_t k = 0; k < points.size(); ++k)
    node << k + 1 << ' ' << points[k].x() << ' ' << points[k].y() << ' ' << points[k].z() << ' '
         << 1 + points[k].x() + 2 * points[k].y() << '\n';
  w.write("p.node", node.str());
  REQUIRE(w.run("optimize " + w.path("p.node") + " --start delaunay -o " + w.path("m.ele")).exit_code == 0);
  const Run r = w.run("refine " + w.path("m.ele") + " --by gradient --field attribute1 --sites 100 -o " + w.path("r.ele"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const auto back = IO::read_node_file(w.path("r.node"));
  REQUIRE(back.points.size() == 400);
  for(std::size_t k = 0; k < back.points.size(); ++k)
    REQUIRE(std::abs(back.attributes[k][0] - (1 + back.points[k][0] + 2 * back.points[k][1])) < 1e-12);
  REQUIRE(w.run("refine " + w.path("m.ele") + " --by gradient --field attribute1 --sites 10 -o " + w.path("r.vtu")).exit_code == 0);
  const auto vtu = IO::read_vtu_file(w.path("r.vtu"));
  REQUIRE(vtu.point_fields.size() == 1);
  REQUIRE(vtu.point_fields[0].first == "attribute1");
  REQUIRE(vtu.cell_fields.size() == 6); // subdomain and the five quality fields
}

TEST_CASE("insert: points anywhere end on CGAL's Delaunay triangulation", "[program][insertion]")
{
  Workdir w;
  std::ostringstream a, b;
  a << "27 3 0 0\n";
  int k = 0;
  for(const Point& p : grid(3, 3, 3)) a << ++k << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  w.write("grid.node", a.str());
  REQUIRE(w.run("optimize " + w.path("grid.node") + " --start delaunay -o " + w.path("g.ele")).exit_code == 0);
  // Inside, on a grid edge, on a vertex, outside, coplanar with a hull face.
  w.write("new.node", "5 3 0 0\n1 0.3 0.2 0.1\n2 0.5 0 0\n3 1 1 1\n4 3 1.2 0.7\n5 7 -3 0\n");
  const Run r = w.run("insert " + w.path("g.ele") + " --points " + w.path("new.node") + " -o " + w.path("i.ele"));
  INFO("stdout: " << r.out << " stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("inserted 4 points (1 on existing vertices, 0 refused") != std::string::npos);
  const Run c = w.run("check " + w.path("i.ele"));
  REQUIRE(c.out.find("equal to CGAL's Delaunay triangulation: yes") != std::string::npos);
}

TEST_CASE("Bad Medit and VTK files and refine options are rejected with exit 2 and no output", "[program][files]")
{
  Workdir w;
  const std::string head = "MeshVersionFormatted 1\nDimension 3\n";
  const std::string tet = "Vertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n";
  struct Bad { const char* name; std::string text; const char* what; };
  const std::vector<Bad> bad = {
      {"x.mesh", "Hello\n", "not a Medit file"},
      {"x.mesh", head + "Vertices\n2\n0 0 0 1\n", "more than the rest of the file can hold"},
      {"x.mesh", head + "Vertices\n2\n0 0 0 1\n# a comment that pads the file\n", "the file ends before"},
      {"x.mesh", head + "Vertices\n1\n0 nan 0 1\n", "not finite"},
      {"x.mesh", head + tet + "Tetrahedra\n1\n1 2 3 9 1\n", "vertex index 9"},
      {"x.mesh", head + tet + "Hexahedra\n0\n", "unknown or unsupported section 'Hexahedra'"},
      {"x.mesh", "MeshVersionFormatted 1\nDimension 2\n", "the dimension is 2"},
      {"x.mesh", head + tet + "Tetrahedra\n1\n1 2 3 4 1\nTriangles\n1\n1 2 2 1\n", "triangle 1 is not a facet"},
      {"x.mesh", head + tet + "Tetrahedra\n2\n1 2 3 4 1\n1 2 3 4 1\n", "tetrahedron"},
      {"x.vtu", "<html></html>\n", "not a VTK unstructured grid"},
      {"x.vtu", "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">"
                "<Points><DataArray type=\"Float64\" format=\"binary\">AAAA</DataArray></Points></Piece></UnstructuredGrid></VTKFile>",
       "the binary data is cut short"},
      {"x.vtu", "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">"
                "<Points><DataArray type=\"Float64\" format=\"ascii\">0 inf 0</DataArray></Points></Piece></UnstructuredGrid></VTKFile>",
       "not finite"}};
  for(const auto& b : bad)
  {
    INFO(b.text);
    w.write(b.name, b.text);
    require_clean_rejection(w, "stats " + w.path(b.name), b.what, {"x.mesh", "x.vtu"});
    require_clean_rejection(w, "refine " + w.path(b.name) + " --by aspect-ratio --target 2 -o " + w.path("o.mesh"), b.what,
                            {"x.mesh", "x.vtu"});
  }
  // Well-formed, but a bad command line.
  w.write("t.mesh", head + tet + "Tetrahedra\n1\n1 2 3 4 1\n");
  const std::vector<std::string> inputs = {"t.mesh", "x.mesh", "x.vtu"};
  require_clean_rejection(w, "refine " + w.path("t.mesh") + " --by curvature -o " + w.path("o.mesh"), "--by is", inputs);
  require_clean_rejection(w, "refine " + w.path("t.mesh") + " --by aspect-ratio --target 0.5 -o " + w.path("o.mesh"), "--target", inputs);
  require_clean_rejection(w, "refine " + w.path("t.mesh") + " --by gradient --field nothing --sites 10 -o " + w.path("o.mesh"), "no field 'nothing'", inputs);
  require_clean_rejection(w, "refine " + w.path("t.mesh") + " --by gradient --field flow-speed --sites 10,x -o " + w.path("o.mesh"), "--sites", inputs);
  require_clean_rejection(w, "refine " + w.path("t.mesh") + " --by aspect-ratio --target 2 -o " + w.path("o.obj"), "not an .ele", inputs);
  require_clean_rejection(w, "mesh-domain three-cubes -o " + w.path("o.mesh"), "unknown domain", inputs);
  require_clean_rejection(w, "mesh-domain two-spheres --size -1 -o " + w.path("o.mesh"), "--size", inputs);
}
