// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile input: each defect found by fuzzing and fault injection, as a case
// that failed before. Bad input means exit 2, a message that names the file,
// the line or the option and the problem, and no output file.

#include "test_common.h"
#include "program_runner.h"
#include <CGAL/Edge_swapping_3/IO/output_files.h>
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/IO/vtu.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <csignal>
#include <fstream>
#include <sstream>

using namespace test;
namespace IO = CGAL::Edge_swapping_3::IO;
namespace fs = std::filesystem;

namespace {

const std::string cube_node = "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 0 0 1\n6 1 0 1\n7 0 1 1\n8 1 1 1\n";
const std::string tet_mesh = "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
                             "Tetrahedra\n1\n1 2 3 4 1\nEnd\n";

std::string vtu(const std::string& piece, const std::string& body)
{
  return "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece " + piece + ">" + body +
         "</Piece></UnstructuredGrid></VTKFile>\n";
}

// A .vtu of one tetrahedron with a cell field "subdomain" of value `subdomain`.
std::string tet_vtu(const std::string& subdomain)
{
  return vtu("NumberOfPoints=\"4\" NumberOfCells=\"1\"",
             "<CellData><DataArray type=\"Float64\" Name=\"subdomain\" format=\"ascii\">" + subdomain +
                 "</DataArray></CellData><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
                 "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points><Cells>"
                 "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>"
                 "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
                 "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>");
}


} // namespace

TEST_CASE("Defect 1: cell indices out of range are errors wherever cells come from", "[hostile]")
{
  const std::vector<Point> p = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(1, 1, 1)};
  std::vector<Tr::Vertex_handle> vertices;
  Tr tr;
  REQUIRE(ES::build_triangulation_from_cells(tr, p, {{0, 1, 2, 3}, {1, 2, 3, 99}}, vertices) ==
          "tetrahedron 1 names point 99, but there are only 5 points");
  REQUIRE(ES::build_triangulation_from_cells(tr, p, {{0, 1, 2, std::size_t(-1)}}, vertices) ==
          "tetrahedron 0 names point 18446744073709551615, but there are only 5 points");
  REQUIRE(ES::build_triangulation_from_cells(tr, p, {{0, 1, 1, 3}}, vertices) == "tetrahedron 0 names point 1 twice");
  REQUIRE(tr.number_of_vertices() == 0);
}

TEST_CASE("Defect 2: a count the file cannot back is an error - not an allocation", "[hostile]")
{
  auto rejects = [](auto read, const std::string& text, const std::string& what) {
    INFO(text.substr(0, 200));
    REQUIRE_THROWS_WITH(read(text), Catch::Contains("x:") && Catch::Contains(what));
  };
  auto node = [](const std::string& t) { return IO::read_node_text("x", t); };
  auto ele = [](const std::string& t) { return IO::read_ele_text("x", t, 8, 1); };
  auto medit = [](const std::string& t) { return IO::read_medit_text("x", t); };
  auto vtu_file = [](const std::string& t) { return IO::read_vtu_text("x", t); };
  rejects(node, "1000000000000000000 3 0 0\n1 0 0 0\n", "more than the rest of the file can hold");
  rejects(node, "99999999999999999999 3 0 0\n", "out of range");
  rejects(node, "2 3 900 0\n1 0 0 0\n2 0 0 0\n", "more than the rest of the file can hold"); // attributes count too
  rejects(ele, "4611686018427387904 4 0\n1 1 2 3 4\n", "more than the rest of the file can hold");
  rejects(medit, "MeshVersionFormatted 1\nDimension 3\nVertices\n6148914691236517206\n0 0 0 1\n", "more than the rest");
  // 3 * NumberOfPoints wraps to 2 in 64 bits.
  rejects(vtu_file, vtu("NumberOfPoints=\"6148914691236517206\" NumberOfCells=\"0\"", ""), "more than the file can hold");
  rejects(vtu_file, vtu("NumberOfPoints=\"4\" NumberOfCells=\"4611686018427387904\"", ""), "more than the file can hold");
  rejects(vtu_file, vtu("NumberOfPoints=\"-4\" NumberOfCells=\"0\"", ""), "without a whole NumberOfPoints");
  // An array with more values than the piece announces stops at the first extra one.
  rejects(vtu_file, vtu("NumberOfPoints=\"1\" NumberOfCells=\"0\"", "<Points><DataArray format=\"ascii\">0 0 0 1</DataArray></Points>"),
          "has more than 3 values");
}

TEST_CASE("Defect 3: reading a .vtu is linear: 100,000 data arrays", "[hostile]")
{
  // The old reader searched back through the whole text for each array: 20,000
  // arrays took over a minute. This file has 100,000 (a hang guard, not a timing).
  std::string body = "<PointData>";
  for(int k = 0; k < 100000; ++k) body += "<DataArray Name=\"f" + std::to_string(k) + "\" format=\"ascii\"></DataArray>";
  body += "</PointData>";
  const auto m = IO::read_vtu_text("x.vtu", vtu("NumberOfPoints=\"0\" NumberOfCells=\"0\"", body));
  REQUIRE(m.point_fields.size() == 100000);
  REQUIRE_THROWS_WITH(IO::read_vtu_text("x.vtu", vtu("NumberOfPoints=\"0\" NumberOfCells=\"0\"", body + body)),
                      Catch::Contains("two fields named 'f0'"));
}


TEST_CASE("Large point families: distinct integer points drawn in n log n and the smallest sphere as defined", "[hostile]")
{
  namespace pf = CGAL::Edge_swapping_3::point_families;
  // A point drawn again is looked up in a set, not in the points so far (a linear
  // lookup made the draw take time n^2): a million points are drawn here.
  for(const std::string name : {"random-integer", "planes"})
  {
    INFO(name << ", seed 1");
    std::vector<Point> p = ES::make_point_family<Point>(name, 1000000, 1);
    REQUIRE(p.size() == 1000000);
    REQUIRE(std::all_of(p.begin(), p.end(), [](const Point& q) { return q.x() >= 0 && q.y() >= 0 && q.z() >= 0; }));
    std::sort(p.begin(), p.end());
    REQUIRE(std::adjacent_find(p.begin(), p.end()) == p.end());
  }
  // The sphere of `cospherical_subset` is the smallest r2 >= 3 with at least max(n, 8) integer
  // points, counted here point by point in the cube about each sphere.
  const auto points_on = [](long r2) {
    std::size_t count = 0;
    const long r = long(std::sqrt(double(r2))) + 1;
    for(long x = -r; x <= r; ++x)
      for(long y = -r; y <= r; ++y)
        for(long z = -r; z <= r; ++z) count += x * x + y * y + z * z == r2;
    return count;
  };
  long r2 = 3;
  for(std::size_t n = 8; n <= 400; ++n)
  {
    while(points_on(r2) < n) ++r2;
    INFO(n << " points");
    REQUIRE(pf::smallest_sphere_with(n) == r2);
    REQUIRE(pf::cospherical<Point>(r2).size() == points_on(r2));
  }
  const auto big = pf::cospherical_subset<Point>(pf::cospherical_max_points, 1);
  REQUIRE(big.size() == 20000);
  REQUIRE(std::all_of(big.begin(), big.end(),
                      [](const Point& q) { return q.x() * q.x() + q.y() * q.y() + q.z() * q.z() == 644474; }));
  REQUIRE_THROWS_WITH(pf::cospherical_subset<Point>(20001, 1), Catch::Contains("at most 20000 points"));
}




TEST_CASE("Defect 7: all outputs appear or none - a folder is not an output file", "[hostile]")
{
  Workdir w;
  w.write("cube.node", cube_node);
  fs::create_directories(w.path("dir"));
  const std::vector<std::string> inputs = {"cube.node", "dir"};
  const std::string in = w.path("cube.node") + " -o " + w.path("y.ele");
  require_clean_rejection(w, "optimize " + in + " --stats " + w.path("dir"), "output '" + w.path("dir") + "' is a directory", inputs);
  require_clean_rejection(w, "optimize " + in + " --history " + w.path("dir"), "is a directory", inputs);
  require_clean_rejection(w, "optimize " + w.path("cube.node") + " -o " + w.path("dir"), "not an .ele", inputs);
  require_clean_rejection(w, "optimize " + w.path("cube.node") + " -o " + w.path("no/such/y.ele"), "does not exist", inputs);
  require_clean_rejection(w, "optimize " + in + " --stats " + w.path("y.node"), "named twice", inputs);
  require_clean_rejection(w, "optimize " + in + " --stats " + w.path("h.csv") + " --history " + w.path("h.csv"), "named twice", inputs);
  require_clean_rejection(w, "stats " + w.path("y.ele") + " --json " + w.path("dir"), "is a directory", inputs);
  require_clean_rejection(w, "mesh-domain two-spheres -o " + w.path("dir/"), "not an .ele", inputs);

  // A rename that fails after another succeeded puts the replaced file back.
  w.write("a.txt", "old");
  fs::create_directories(w.path("gone"));
  ES::IO::Output_files files;
  files.add(w.path("a.txt"), [](std::ostream& os) { os << "new"; });
  files.add(w.path("gone/b.txt"), [](std::ostream& os) { os << "new"; });
  fs::remove(w.path("gone"));
  REQUIRE_THROWS_WITH(files.commit(), Catch::Contains("cannot write '" + w.path("gone/b.txt") + "'"));
  REQUIRE(Workdir::slurp(w.path("a.txt")) == "old");
  REQUIRE(w.outputs({"cube.node", "dir", "a.txt"}) == 0);

  // A writer refuses a value that is not finite: nothing is written, no partial file stays.
  ES::IO::Output_files nan_files;
  nan_files.add(w.path("b.txt"), [](std::ostream& os) { os << "complete"; });
  nan_files.add(w.path("n.vtu"), [](std::ostream& os) {
    IO::write_vtu_file(os, {{0, 0, 0}}, {}, {{"f", {std::nan("")}}}, {});
  });
  REQUIRE_THROWS_WITH(nan_files.commit(), Catch::Contains("cannot write '" + w.path("n.vtu") +
                                                          "': a value of field 'f' is not a finite number"));
  REQUIRE(w.outputs({"cube.node", "dir", "a.txt"}) == 0);
}

TEST_CASE("Defect 8: a full disk is an error - every write and close is checked", "[hostile]")
{
  // A file size limit of 512 bytes, with SIGXFSZ ignored: writes fail with EFBIG, as on a full disk.
  Workdir w;
  w.write("cube.node", cube_node);
  const std::string limit = "trap '' XFSZ; ulimit -f 1;";
  const Run r = w.run_with(limit, "mesh-domain two-spheres -o " + w.path("big.vtu"));
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find("cannot write '" + w.path("big.vtu") + "'") != std::string::npos);
  REQUIRE(!fs::exists(w.path("big.vtu")));
  REQUIRE(w.outputs({"cube.node"}) == 0); // no partial file left
}

TEST_CASE("Coordinates: any finite double within the supported extent is accepted, others are rejected, and no "
          "output holds nan or inf", "[hostile]")
{
  Workdir w;
  for(const std::string x : {"1e400", "1e-400"})
  {
    w.write("p.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 " + x + " 0\n4 0 0 1\n");
    const std::string what = x == "1e400" ? "not finite" : "too small for a double";
    require_clean_rejection(w, "optimize " + w.path("p.node") + " -o " + w.path("o.ele"), "p.node:4: ", {"p.node"});
    require_clean_rejection(w, "optimize " + w.path("p.node") + " -o " + w.path("o.ele"), what, {"p.node"});
  }
  // The extent, not the size of one coordinate, limits the arithmetic.
  for(const std::string x : {"1e307", "-1.5e30"})
  {
    w.write("p.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 " + x + " 0\n4 0 0 1\n");
    require_clean_rejection(w, "optimize " + w.path("p.node") + " -o " + w.path("o.ele"),
                            "p.node: the points span " + std::string(x == "1e307" ? "1e+307" : "1.5e+30") + " along y",
                            {"p.node"});
  }
  w.write("p.node", "4 3 0 0\n1 1e-31 1e-31 0\n2 1e-32 1e-32 1e-32\n3 2e-31 3e-31 1e-31\n4 1e-31 0 2e-31\n");
  require_clean_rejection(w, "optimize " + w.path("p.node") + " -o " + w.path("o.ele"),
                          "p.node: the points span only 3e-31 along their longest axis", {"p.node"});
  // Rounding zeros of a CAD kernel beside coordinates of size 1, and a mesh placed far from the origin.
  for(const std::string x : {"1e-31", "-1.1998078261295e-31", "1e-320", "0"})
    for(const std::string offset : {"0", "1e20"})
    {
      INFO(x << ", offset " << offset);
      w.write("p.node", "6 3 0 0\n1 " + offset + " 0 0\n2 1 0 0\n3 " + x + " 1 0\n4 0 0 1\n5 1 1 1\n6 0.5 " + x + " 0.5\n");
      REQUIRE(w.run("optimize " + w.path("p.node") + " --criterion minmax-dihedral -o " + w.path("o.vtu")).exit_code == 0);
      const std::string text = Workdir::slurp(w.path("o.vtu"));
      REQUIRE(text.find("nan") == std::string::npos);
      REQUIRE(text.find("inf") == std::string::npos);
      fs::remove(w.path("o.vtu"));
    }
  // Vertex fields are at most 1e100 in magnitude: their gradients stay finite.
  w.write("a.node", "4 3 1 0\n1 0 0 0 1\n2 1 0 0 2\n3 0 1 0 -1e200\n4 0 0 1 4\n");
  require_clean_rejection(w, "optimize " + w.path("a.node") + " -o " + w.path("o.vtu"),
                          "a.node: field 'attribute1' at point 2 is larger than 1e100", {"p.node", "a.node"});
  w.write("m.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1e307 0 0 1\n0 1 0 1\n0 0 1 1\n"
                    "Tetrahedra\n1\n1 2 3 4 1\nEnd\n");
  require_clean_rejection(w, "stats " + w.path("m.mesh"), "m.mesh: the points span 1e+307 along x", {"p.node", "a.node", "m.mesh"});

  // At both ends of the range, and for tetrahedra too flat for double precision,
  // every measure is a finite number.
  for(double s : {1e30, 1e-30, 1.0})
  {
    const Point a(0, 0, 0), b(s, 0, 0), c(0, s, 0), d(s * 0.25, s * 0.25, s * 1e-16);
    INFO("scale " << s);
    for(double x : ES::dihedral_angles(a, b, c, d)) REQUIRE(std::isfinite(x));
    REQUIRE(std::isfinite(ES::circumradius_over_inradius(a, b, c, d)));
    REQUIRE(std::isfinite(ES::edge_length_ratio(a, b, c, d)));
    // Scale invariant: the same corner tetrahedron has the same ratio at every scale.
    REQUIRE(ES::circumradius_over_inradius(a, b, c, Point(0, 0, s)) ==
            Approx(ES::circumradius_over_inradius(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1))));
  }
  // A mesh at the top of the range, with a sliver: stats and a .vtu without nan or inf.
  w.write("big.node", "5 3 0 0\n1 0 0 0\n2 1e30 0 0\n3 0 1e30 0\n4 0 0 1e30\n5 3e29 3e29 1e14\n");
  REQUIRE(w.run("optimize " + w.path("big.node") + " -o " + w.path("big.vtu")).exit_code == 0);
  const Run r = w.run("stats " + w.path("big.vtu") + " --json " + w.path("big.json"));
  REQUIRE(r.exit_code == 0);
  for(const std::string f : {"big.vtu", "big.json"})
  {
    const std::string text = Workdir::slurp(w.path(f)) + r.out;
    INFO(f);
    REQUIRE(text.find("nan") == std::string::npos);
    REQUIRE(text.find("inf") == std::string::npos);
    REQUIRE(text.find("null") == std::string::npos);
  }
}

TEST_CASE("Defect 10: every message names the option or the file", "[hostile]")
{
  Workdir w;
  w.write("cube.node", cube_node);
  fs::create_directories(w.path("d.node"));
  fs::create_directories(w.path("d.mesh"));
  w.write("t.mesh", tet_mesh);
  REQUIRE(::mkfifo(w.path("fifo.node").c_str(), 0600) == 0); // reading it would wait forever
  const std::vector<std::string> inputs = {"cube.node", "d.node", "d.mesh", "t.mesh", "fifo.node"};
  const std::string out = " -o " + w.path("o.ele");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"optimize " + w.path("cube.node") + out + " --start scramble:99999999999999999999", "--start scramble:K is 99999999999999999999"},
      {"optimize " + w.path("cube.node") + out + " --start scramble:-3", "--start scramble:K needs a whole number, not '-3'"},
      {"refine " + w.path("t.mesh") + " --by gradient --field flow-speed --sites 99999999999999999999" + out, "--sites"},
      {"optimize " + w.path("d.node") + out, "d.node: is a directory"},
      {"stats " + w.path("d.mesh"), "d.mesh: is a directory"},
      {"insert " + w.path("t.mesh") + " --points " + w.path("d.node") + out, "d.node: is a directory"},
      {"optimize " + w.path("fifo.node") + out, "fifo.node: is not a regular file"},
      {"mesh-domain two-spheres --size 1e-9 -o " + w.path("o.mesh"), "--size is from 0.05 to 100"}};
  for(const auto& [args, what] : cases) require_clean_rejection(w, args, what, inputs);
}

TEST_CASE("Defect 11: subdomain values and section counts are checked", "[hostile]")
{
  Workdir w;
  for(const std::string v : {"1e300", "2.5", "-3e9"})
  {
    w.write("s.vtu", tet_vtu(v));
    require_clean_rejection(w, "stats " + w.path("s.vtu"), "s.vtu: cell field 'subdomain': the value of cell 0 is not a whole number",
                    {"s.vtu"});
  }
  w.write("s.vtu", tet_vtu("7"));
  REQUIRE(w.run("stats " + w.path("s.vtu")).exit_code == 0);
  // Section counts times entries per section would wrap: rejected before any loop.
  for(const std::string section : {"Edges", "Corners", "Quadrilaterals", "Tetrahedra", "Triangles"})
  {
    w.write("c.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n" + section +
                          "\n6148914691236517206\n1 2 3\n");
    require_clean_rejection(w, "stats " + w.path("c.mesh"), "c.mesh:10: number of", {"s.vtu", "c.mesh"});
  }
  // A reference larger than an int is a clear error.
  w.write("r.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
                    "Tetrahedra\n1\n1 2 3 4 99999999999\nEnd\n");
  require_clean_rejection(w, "stats " + w.path("r.mesh"), "r.mesh:11: a tetrahedron reference is out of range", {"s.vtu", "c.mesh", "r.mesh"});
}

TEST_CASE("Defect 12: partial files are recognisable and stale ones go on the next run", "[hostile]")
{
  Workdir w;
  w.write("cube.node", cube_node);
  // A process that has ended: its partial files are stale.
  const pid_t child = ::fork();
  if(child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  const std::string stale = "y.ele.edge_swap-partial-" + std::to_string(child);
  const std::string stale_node = "y.node.edge_swap-partial-" + std::to_string(child);
  const std::string live = "y.ele.edge_swap-partial-" + std::to_string(::getpid()); // this process: not stale
  const std::string other = "z.ele.edge_swap-partial-" + std::to_string(child);    // another output's
  for(const auto& f : {stale, stale_node, live, other}) w.write(f, "partial");
  const Run r = w.run("optimize " + w.path("cube.node") + " -o " + w.path("y.ele"));
  REQUIRE(r.exit_code == 0);
  REQUIRE(!fs::exists(w.path(stale)));
  REQUIRE(!fs::exists(w.path(stale_node)));
  REQUIRE(fs::exists(w.path(live)));
  REQUIRE(fs::exists(w.path(other)));
  REQUIRE(w.outputs({"cube.node", "y.ele", "y.node", live, other}) == 0);
}
