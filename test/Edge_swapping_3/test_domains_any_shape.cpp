// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes as users have them. Domains of any shape (non-convex, with
// cavities, several regions, several parts, coordinates as CAD kernels write
// them): accepted, completed outside to a convex region, optimized, and
// written back with exactly the domain's cells, the same vertices,
// boundaries, interfaces and references, checked exactly through the library
// and through the program. Files as Gmsh and VTK (ParaView) write them.

#include "test_common.h"
#include "program_runner.h"
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>

using namespace test;

namespace {

typedef ES::Numbered_domain_triangulation_3<K> Numbered;
typedef ES::Mesh_with_fields<Point> Mesh;
typedef std::array<std::size_t, 3> Triple;

// The cubes of an nx x ny x nz grid of unit cubes for which `region(i, j, k)`
// is not 0, each split into the six tetrahedra around its main diagonal (the
// same diagonal everywhere, so the tetrahedra of neighbouring cubes conform);
// `x_of` gives the x coordinate of a grid plane. Only used points are kept.
// Boundary triangles (reference 1) and interface triangles (reference 2)
// are listed, as Medit files list them.
Mesh cube_grid_mesh(int nx, int ny, int nz, const std::function<int(int, int, int)>& region,
                    const std::function<Point(int, int, int)>& point_of = [](int i, int j, int k) { return Point(i, j, k); })
{
  Mesh m;
  m.is_mesh = m.has_references = true;
  std::map<std::array<int, 3>, std::size_t> number;
  auto vertex = [&](int i, int j, int k) {
    const auto it = number.emplace(std::array<int, 3>{i, j, k}, m.points.size());
    if(it.second) m.points.push_back(point_of(i, j, k));
    return it.first->second;
  };
  // The six paths from corner 000 to 111, one axis at a time.
  static const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j)
      for(int k = 0; k < nz; ++k)
      {
        const int r = region(i, j, k);
        if(r == 0) continue;
        for(const auto& path : paths)
        {
          std::array<int, 3> c = {i, j, k};
          std::array<std::size_t, 4> t;
          t[0] = vertex(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++c[path[s]];
            t[s + 1] = vertex(c[0], c[1], c[2]);
          }
          // Positively oriented, as meshers write them.
          if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) == CGAL::NEGATIVE)
            std::swap(t[0], t[1]);
          m.cells.push_back(t);
          m.cell_references.push_back(r);
        }
      }
  // Facets of one cell, or of two cells of different regions.
  std::map<Triple, std::vector<int>> facets;
  for(std::size_t c = 0; c < m.cells.size(); ++c)
    for(int i = 0; i < 4; ++i)
    {
      Triple f = {m.cells[c][(i + 1) & 3], m.cells[c][(i + 2) & 3], m.cells[c][(i + 3) & 3]};
      std::sort(f.begin(), f.end());
      facets[f].push_back(m.cell_references[c]);
    }
  for(const auto& [f, regions] : facets)
    if(regions.size() == 1 || regions[0] != regions[1])
    {
      m.triangles.push_back(f);
      m.triangle_references.push_back(regions.size() == 1 ? 1 : 2);
    }
  return m;
}

// What must be identical before and after: the facets of one cell (the
// boundary), the facets between two regions with the regions (interfaces),
// the listed triangles with their references, and each region's exact volume.
struct Domain_shape
{
  std::set<Triple> boundary;
  std::set<std::pair<Triple, std::pair<int, int>>> interfaces;
  std::multiset<std::pair<Triple, int>> triangles;
  std::map<int, CGAL::Exact_rational> volumes;
  bool operator==(const Domain_shape& o) const
  {
    return boundary == o.boundary && interfaces == o.interfaces && triangles == o.triangles && volumes == o.volumes;
  }
};

Domain_shape shape_of(const Mesh& m)
{
  Domain_shape s;
  std::map<Triple, std::vector<int>> facets;
  for(std::size_t c = 0; c < m.cells.size(); ++c)
  {
    const int r = m.cell_references.empty() ? 1 : m.cell_references[c];
    const auto& t = m.cells[c];
    s.volumes[r] += CGAL::abs(exact_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
    for(int i = 0; i < 4; ++i)
    {
      Triple f = {t[(i + 1) & 3], t[(i + 2) & 3], t[(i + 3) & 3]};
      std::sort(f.begin(), f.end());
      facets[f].push_back(r);
    }
  }
  for(const auto& [f, regions] : facets)
  {
    REQUIRE(regions.size() <= 2);
    if(regions.size() == 1) s.boundary.insert(f);
    else if(regions[0] != regions[1])
      s.interfaces.insert({f, {(std::min)(regions[0], regions[1]), (std::max)(regions[0], regions[1])}});
  }
  for(std::size_t k = 0; k < m.triangles.size(); ++k)
  {
    Triple f = m.triangles[k];
    std::sort(f.begin(), f.end());
    s.triangles.insert({f, m.triangle_references[k]});
  }
  return s;
}

// The extreme dihedral angles of the mesh's cells.
std::pair<double, double> dihedral_extremes(const Mesh& m)
{
  double low = 180, high = 0;
  for(const auto& t : m.cells)
    for(double a : ES::dihedral_angles(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]))
    {
      low = (std::min)(low, a);
      high = (std::max)(high, a);
    }
  return {low, high};
}

// Builds `m`, checks it is completed (or not) and that a snapshot gives it
// back as it is; optimizes it by MinMax with the topological operations and
// checks the domain is kept exactly and no extreme angle got worse.
void require_domain_kept(const Mesh& m, bool completed)
{
  Numbered tr;
  REQUIRE(ES::build_numbered_mesh(tr, m) == "");
  REQUIRE(tr.is_valid());
  REQUIRE(ES::is_completed_domain(tr) == completed);
  REQUIRE(ES::number_of_mesh_cells(tr) == m.cells.size());
  const Mesh same = ES::numbered_mesh_snapshot(tr, m);
  REQUIRE(same.points == m.points);
  REQUIRE(same.cells.size() == m.cells.size());
  REQUIRE(shape_of(same) == shape_of(m));

  const auto before = dihedral_extremes(m);
  const auto report = ES::with_mesh_constraints(tr, m, [&](const auto& constraints) {
    return ES::improve_worst_tetrahedra(
        tr, ES::Min_max_dihedral_angle_criterion(),
        ES::parameters::operations(ES::TOPOLOGICAL_OPERATIONS, ES::parameters::mesh_constraints(constraints)));
  });
  INFO("operations " << report.edge_removals << " edge removals, " << report.face_removals << " face removals");
  REQUIRE(tr.is_valid());
  const Mesh out = ES::numbered_mesh_snapshot(tr, m);
  REQUIRE(out.points == m.points);
  REQUIRE(shape_of(out) == shape_of(m));
  const auto after = dihedral_extremes(out);
  REQUIRE(after.second <= before.second);
  REQUIRE(after.first >= before.first - 1e-9);

  // Smoothing too: the vertices of the boundary and the interfaces stay where they are.
  ES::with_mesh_constraints(tr, m, [&](const auto& constraints) {
    return ES::improve_worst_tetrahedra(
        tr, ES::Max_min_dihedral_sine_criterion(),
        ES::parameters::operations(ES::ALL_OPERATIONS, ES::parameters::mesh_constraints(constraints)));
  });
  const Mesh smoothed = ES::numbered_mesh_snapshot(tr, m);
  REQUIRE(shape_of(smoothed).boundary == shape_of(m).boundary);
  REQUIRE(shape_of(smoothed).interfaces == shape_of(m).interfaces);
  REQUIRE(shape_of(smoothed).triangles == shape_of(m).triangles);
  const auto shape = shape_of(m);
  for(const auto& f : shape.boundary)
    for(auto v : f) REQUIRE(smoothed.points[v] == m.points[v]);
  for(const auto& [f, regions] : shape.interfaces)
    for(auto v : f) REQUIRE(smoothed.points[v] == m.points[v]);
  // Written and read back as a Medit file, it builds again.
  Numbered again;
  REQUIRE(ES::build_numbered_mesh(again, smoothed) == "");
  REQUIRE(ES::number_of_mesh_cells(again) == smoothed.cells.size());
}

} // namespace

TEST_CASE("Domains of any shape: an L-shape, a cube with a cavity, two regions, two parts", "[domain][any shape]")
{
  SECTION("a convex domain is not completed")
  {
    require_domain_kept(cube_grid_mesh(3, 2, 2, [](int, int, int) { return 1; }), false);
  }
  SECTION("an L-shape (not convex)")
  {
    require_domain_kept(cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : 1; }), true);
  }
  SECTION("a cube with a cavity (two boundary surfaces)")
  {
    require_domain_kept(cube_grid_mesh(4, 4, 4, [](int i, int j, int k) {
                          return (i == 1 || i == 2) && (j == 1 || j == 2) && (k == 1 || k == 2) ? 0 : 1;
                        }),
                        true);
  }
  SECTION("two regions with an interface, in an L-shape")
  {
    require_domain_kept(cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : i < 2 ? 1 : 7; }),
                        true);
  }
  SECTION("two disjoint parts")
  {
    require_domain_kept(cube_grid_mesh(5, 2, 2, [](int i, int, int) { return i == 0 || i == 1 ? 1 : i == 4 ? 2 : 0; }),
                        true);
  }
  SECTION("two parts that touch along an edge")
  {
    require_domain_kept(cube_grid_mesh(2, 2, 1, [](int i, int j, int) { return i == j ? 1 : 0; }), true);
  }
  SECTION("coordinates as a CAD kernel writes them: rounding zeros of 1e-31 beside 1, far from the origin")
  {
    for(double offset : {0.0, 1e12})
    {
      INFO("offset " << offset);
      const auto point_of = [offset](int i, int j, int k) {
        // Each plane x = 0 point is off by a rounding zero, alternately of each sign.
        const double x = i == 0 ? ((j + k) % 2 ? -1.1998078261295e-31 : 3e-32) : double(i);
        return Point(offset + x, j, k);
      };
      const Mesh m = cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : 1; }, point_of);
      if(offset == 0) require_domain_kept(m, true);
      else
      {
        Numbered tr; // at 1e12 the rounding zeros vanish into offset + 0: the points are the grid's
        REQUIRE(ES::build_numbered_mesh(tr, m) == "");
        REQUIRE(ES::number_of_mesh_cells(tr) == m.cells.size());
      }
    }
  }
}

TEST_CASE("Domains of any shape: two spherical cavities in a box (Mesh_3's mesh without its subdomain 0)",
          "[domain][any shape]")
{
  // Mesh_3's mesh of the two-spheres domain (make_two_spheres_mesh), made by
  // the program: this file then compiles no Mesh_3.
  Workdir w;
  REQUIRE(w.run("mesh-domain two-spheres --size 0.7 --quiet -o " + w.path("two_spheres.mesh")).exit_code == 0);
  const Mesh full = ES::IO::read_mesh_with_fields<Point>(w.path("two_spheres.mesh"));
  // Keep the cells of the flow region and the points they use, renumbered.
  Mesh m;
  m.is_mesh = m.has_references = true;
  std::vector<std::size_t> number(full.points.size(), std::size_t(-1));
  for(std::size_t c = 0; c < full.cells.size(); ++c)
  {
    if(full.cell_references[c] == 0) continue;
    std::array<std::size_t, 4> t;
    for(int i = 0; i < 4; ++i)
    {
      std::size_t& n = number[full.cells[c][i]];
      if(n == std::size_t(-1))
      {
        n = m.points.size();
        m.points.push_back(full.points[full.cells[c][i]]);
      }
      t[i] = n;
    }
    m.cells.push_back(t);
    m.cell_references.push_back(full.cell_references[c]);
  }
  for(std::size_t k = 0; k < full.triangles.size(); ++k)
  {
    Triple t;
    bool kept = true;
    for(int i = 0; i < 3; ++i) kept = kept && (t[i] = number[full.triangles[k][i]]) != std::size_t(-1);
    if(!kept) continue;
    m.triangles.push_back(t);
    m.triangle_references.push_back(full.triangle_references[k]);
  }
  REQUIRE(m.cells.size() < full.cells.size());
  require_domain_kept(m, true);
}

TEST_CASE("Meshes that are not valid domains are refused with what is wrong", "[domain][any shape][hostile]")
{
  const Mesh l_shape = cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : 1; });
  SECTION("a tetrahedron repeated as a third one on a facet")
  {
    Mesh m = l_shape;
    // A third tetrahedron on a facet inside the first cube (of two already).
    const auto t = m.cells[0];
    m.points.push_back(Point(0.9, 0.6, 0.3));
    std::array<std::size_t, 4> third = {t[1], t[2], t[3], m.points.size() - 1};
    if(CGAL::orientation(m.points[third[0]], m.points[third[1]], m.points[third[2]], m.points[third[3]]) == CGAL::NEGATIVE)
      std::swap(third[0], third[1]);
    m.cells.push_back(third);
    m.cell_references.push_back(1);
    Numbered tr;
    const std::string problem = ES::build_numbered_mesh(tr, m);
    INFO(problem);
    REQUIRE(!problem.empty());
    REQUIRE(tr.number_of_vertices() == 0);
  }
  SECTION("messages name the points as the file does, points on no tetrahedron counted")
  {
    // Two tetrahedra on the same side of their common facet 1 2 3, after a
    // point that no tetrahedron uses (left out of the triangulation).
    Mesh m;
    m.is_mesh = m.has_references = true;
    m.points = {Point(9, 9, 9), Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0.2, 0.2, 0.5)};
    m.cells = {{1, 2, 3, 4}, {1, 2, 3, 5}};
    m.cell_references = {1, 1};
    Numbered tr;
    const std::string problem = ES::build_numbered_mesh(tr, m);
    INFO(problem);
    REQUIRE(problem.find("facet 1 2 3") != std::string::npos);
  }
  SECTION("two overlapping parts")
  {
    // The L-shape and a copy of one of its cubes shifted by half a cube: the boundaries cross.
    Mesh m = l_shape;
    const Mesh shifted = cube_grid_mesh(1, 1, 1, [](int, int, int) { return 1; },
                                        [](int i, int j, int k) { return Point(i + 0.5, j + 0.25, k + 0.125); });
    const std::size_t base = m.points.size();
    m.points.insert(m.points.end(), shifted.points.begin(), shifted.points.end());
    for(auto t : shifted.cells)
    {
      for(auto& v : t) v += base;
      m.cells.push_back(t);
      m.cell_references.push_back(1);
    }
    m.triangles.clear();
    m.triangle_references.clear();
    Numbered tr;
    const std::string problem = ES::build_numbered_mesh(tr, m);
    INFO(problem);
    REQUIRE(!problem.empty());
    REQUIRE(tr.number_of_vertices() == 0);
  }
  SECTION("a tetrahedron too flat for double precision (a fuzzer's mutant of the L-shape, on which TetGen ran without end)")
  {
    const Mesh m = ES::IO::read_mesh_with_fields<Point>(std::string(EDGE_SWAPPING_3_FIXTURES) + "/nearly_flat_tetrahedron.ele");
    Numbered tr;
    const std::string problem = ES::build_numbered_mesh(tr, m);
    INFO(problem);
    REQUIRE(problem.find("is too flat for double precision") != std::string::npos);
  }
  SECTION("the reserved reference")
  {
    Mesh m = l_shape;
    m.cell_references[3] = ES::Domain_cell_info::completion;
    Numbered tr;
    REQUIRE(ES::build_numbered_mesh(tr, m).find("is reserved") != std::string::npos);
  }
}

namespace {

// Writes `m` to `path` in `w` (the format of its extension).
void write_mesh(const Workdir& w, const std::string& name, const Mesh& m,
                ES::IO::Gmsh_format msh = ES::IO::MSH_4_1_ASCII, ES::IO::Vtu_encoding vtu = ES::IO::VTU_ASCII)
{
  ES::IO::Mesh_file_options options;
  options.msh = msh;
  options.vtu = vtu;
  ES::IO::write_mesh_with_fields(w.path(name), m, [&](const std::string& file, std::function<void(std::ostream&)> write) {
    std::ofstream out(file, std::ios::binary);
    write(out);
  }, options);
}

Mesh read_mesh(const Workdir& w, const std::string& name) { return ES::IO::read_mesh_with_fields<Point>(w.path(name)); }

// The shape of a mesh read back from a format that keeps fewer things:
// TetGen and VTK files no boundary triangles (TetGen's .ele keeps the
// regions as the tetrahedra's attribute).
Domain_shape comparable(Domain_shape s, const std::string& format)
{
  if(format == "ele" || format == "vtu") s.triangles.clear();
  return s;
}

} // namespace

TEST_CASE("edge_swap on domains of any shape: check, stats and optimize keep the domain in every format",
          "[domain][any shape][program]")
{
  Workdir w;
  const std::map<std::string, Mesh> meshes = {
      {"l_shape_two_regions", cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : i < 2 ? 1 : 7; })},
      {"cavity", cube_grid_mesh(4, 4, 4, [](int i, int j, int k) {
         return (i == 1 || i == 2) && (j == 1 || j == 2) && (k == 1 || k == 2) ? 0 : 1;
       })},
      {"two_parts", cube_grid_mesh(5, 2, 2, [](int i, int, int) { return i <= 1 ? 1 : i == 4 ? 2 : 0; })},
      {"tiny_coordinates", cube_grid_mesh(4, 4, 2, [](int i, int j, int) { return i >= 2 && j >= 2 ? 0 : 1; },
                                          [](int i, int j, int k) {
                                            return Point(i == 0 ? ((j + k) % 2 ? -1.1998078261295e-31 : 3e-32) : i, j, k);
                                          })}};
  for(const auto& [name, m] : meshes)
    for(const std::string in_format : {"mesh", "msh", "vtu", "ele"})
    {
      const std::string input = name + "." + in_format;
      write_mesh(w, input, m);
      INFO(input);
      const Run check = w.run("check " + w.path(input));
      INFO(check.out << check.err);
      REQUIRE(check.exit_code == 0);
      REQUIRE(check.out.find("valid mesh of a domain that is not its convex hull") != std::string::npos);
      REQUIRE(check.out.find("cells " + std::to_string(m.cells.size())) != std::string::npos);
      const Run stats = w.run("stats " + w.path(input));
      REQUIRE(stats.exit_code == 0);
      REQUIRE(stats.out.find("cells " + std::to_string(m.cells.size()) + " (in the domain: " +
                             std::to_string(m.cells.size()) + ")") != std::string::npos);
      const auto before = dihedral_extremes(m);
      for(const std::string out_format : {"mesh", "msh", "vtu", "ele"})
      {
        INFO("to ." << out_format);
        const std::string output = name + "_out." + out_format;
        const Run r = w.run("optimize " + w.path(input) + " --criterion minmax-dihedral --operations topological -o " +
                            w.path(output));
        INFO(r.out << r.err);
        REQUIRE(r.exit_code == 0);
        const Mesh out = read_mesh(w, output);
        REQUIRE(out.points == m.points);
        REQUIRE(comparable(comparable(shape_of(out), out_format), in_format) ==
                comparable(comparable(shape_of(m), out_format), in_format));
        const auto after = dihedral_extremes(out);
        REQUIRE(after.second <= before.second);
        REQUIRE(after.first >= before.first - 1e-9);
      }
    }
}

TEST_CASE("edge_swap refine on a completed domain counts the domain's vertices only", "[domain][any shape][program]")
{
  Workdir w;
  // An L-shape whose inner grid points are moved a little (on the regular
  // grid every circumcenter is on an edge: nothing to refine).
  const Mesh m = cube_grid_mesh(5, 5, 3, [](int i, int j, int) { return i >= 3 && j >= 3 ? 0 : 1; },
                                [](int i, int j, int k) {
                                  const bool inner = i > 0 && i < 5 && j > 0 && j < 5 && k > 0 && k < 3;
                                  const double d = inner ? 0.05 * ((i * 7 + j * 3 + k * 5) % 5 - 2) : 0;
                                  return Point(i + d, j - d, k + 0.5 * d);
                                });
  write_mesh(w, "l.mesh", m);
  const Run r = w.run("refine " + w.path("l.mesh") + " --by aspect-ratio --target 1.5 --max-sites 20 --history " +
                      w.path("h.csv") + " -o " + w.path("out.mesh"));
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const Mesh out = read_mesh(w, "out.mesh");
  REQUIRE(out.points.size() > m.points.size());
  REQUIRE(r.out.find("vertices " + std::to_string(out.points.size()) + ",") != std::string::npos);
  std::ifstream history(w.path("h.csv"));
  std::string line, last;
  while(std::getline(history, line))
    if(!line.empty()) last = line;
  // round,sites_inserted,vertices,...
  const std::size_t first = last.find(','), second = last.find(',', first + 1);
  REQUIRE(last.substr(second + 1, last.find(',', second + 1) - second - 1) == std::to_string(out.points.size()));
}

TEST_CASE("TetGen regions: the first attribute of an .ele file is the tetrahedron's region, read and written",
          "[files][tetgen]")
{
  Workdir w;
  // Two cubes of six tetrahedra each, regions 3 and -10, as `tetgen -A` writes them.
  const Mesh m = cube_grid_mesh(2, 1, 1, [](int i, int, int) { return i == 0 ? 3 : -10; });
  write_mesh(w, "two.ele", m);
  std::ifstream ele(w.path("two.ele"));
  std::string header;
  std::getline(ele, header);
  REQUIRE(header == "12 4 1");
  const Mesh back = read_mesh(w, "two.ele");
  REQUIRE(back.has_references);
  REQUIRE(back.cell_references == m.cell_references);
  REQUIRE(shape_of(back).interfaces == shape_of(m).interfaces);
  // The program keeps both regions and their interface through an .ele.
  const Run r = w.run("optimize " + w.path("two.ele") + " --criterion minmax-dihedral --operations topological -o " +
                      w.path("out.ele"));
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const Mesh out = read_mesh(w, "out.ele");
  REQUIRE(shape_of(out).interfaces == shape_of(m).interfaces);
  REQUIRE(shape_of(out).volumes == shape_of(m).volumes);
  // A region that is not a whole number is refused with its line.
  {
    std::ofstream bad(w.path("bad.ele"));
    bad << "1 4 1\n1 1 2 3 4 1.5\n";
    std::ofstream node(w.path("bad.node"));
    node << "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  }
  require_clean_rejection(w, "check " + w.path("bad.ele"), "bad.ele:2:", {"two.ele", "two.node", "out.ele", "out.node",
                                                                      "bad.ele", "bad.node"});
  const Run bad = w.run("check " + w.path("bad.ele"));
  REQUIRE(bad.err.find("the region attribute 1.5 is not a whole number") != std::string::npos);
}

TEST_CASE("The optimizer keeps the extreme dihedral angles of a Gmsh mesh unless told otherwise",
          "[domain][quality driver][angle range]")
{
  // Gmsh 4.8's OpenCASCADE demo `boolean` (Debian's gmsh-doc), meshed as its
  // docs run it: gmsh -3 boolean.geo -o gmsh_boolean_demo.msh. Under MinMax
  // alone the topological operations trade its smallest angle (7.62 degrees)
  // for smaller ones, and the dihedral sine with smoothing its largest.
  const std::string file = std::string(EDGE_SWAPPING_3_FIXTURES) + "/gmsh_boolean_demo.msh";
  const Mesh m = ES::IO::read_mesh_with_fields<Point>(file);
  REQUIRE(m.cells.size() == 1170);
  const auto before = dihedral_extremes(m);
  INFO("input: " << before.first << " / " << before.second << " degrees");
  auto optimized = [&](bool minmax, bool keep) {
    Numbered tr;
    REQUIRE(ES::build_numbered_mesh(tr, m) == "");
    namespace np = ES::parameters;
    ES::with_mesh_constraints(tr, m, [&](const auto& constraints) {
      const auto settings = np::keep_dihedral_angle_range(
          keep, np::operations(minmax ? unsigned(ES::TOPOLOGICAL_OPERATIONS) : unsigned(ES::ALL_OPERATIONS),
                               np::mesh_constraints(constraints)));
      return minmax ? ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(), settings)
                    : ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_sine_criterion(), settings);
    });
    REQUIRE(tr.is_valid());
    const Mesh out = ES::numbered_mesh_snapshot(tr, m);
    REQUIRE(shape_of(out).boundary == shape_of(m).boundary);
    return dihedral_extremes(out);
  };
  // The angles are computed in another vertex order here than by the guard:
  // the last bits may differ.
  const double rounding = 1e-9;
  SECTION("MinMax, topological operations")
  {
    const auto kept = optimized(true, true);
    INFO("kept: " << kept.first << " / " << kept.second);
    REQUIRE(kept.first >= before.first - rounding);
    REQUIRE(kept.second < before.second - 1);
    const auto free = optimized(true, false);
    INFO("free: " << free.first << " / " << free.second);
    REQUIRE(free.first < before.first - 1); // what the guard prevents
  }
  SECTION("the dihedral sine with smoothing")
  {
    const auto kept = optimized(false, true);
    INFO("kept: " << kept.first << " / " << kept.second);
    REQUIRE(kept.first >= before.first - rounding);
    REQUIRE(kept.second <= before.second + rounding);
    const auto free = optimized(false, false);
    INFO("free: " << free.first << " / " << free.second);
    REQUIRE(free.second > before.second + 1); // what the guard prevents
  }
  SECTION("the program: --angle-range keep by default, free on request")
  {
    Workdir w;
    const Run kept = w.run("optimize " + file + " --criterion minmax-dihedral --operations topological -o " +
                           w.path("kept.msh") + " --stats " + w.path("kept.json"));
    INFO(kept.out << kept.err);
    REQUIRE(kept.exit_code == 0);
    const auto k = dihedral_extremes(read_mesh(w, "kept.msh"));
    REQUIRE(k.first >= before.first - rounding);
    REQUIRE(k.second < before.second - 1);
    std::ifstream json(w.path("kept.json"));
    const std::string stats((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
    REQUIRE(stats.find("\"angle_range\": \"keep\"") != std::string::npos);
    const Run free = w.run("optimize " + file + " --criterion minmax-dihedral --operations topological "
                           "--angle-range free -o " + w.path("free.msh"));
    REQUIRE(free.exit_code == 0);
    REQUIRE(dihedral_extremes(read_mesh(w, "free.msh")).first < before.first - 1);
    require_clean_rejection(w, "optimize " + file + " --criterion minmax-dihedral --angle-range wide -o " +
                                   w.path("o.msh"), "--angle-range", {"kept.msh", "kept.json", "free.msh"});
    require_clean_rejection(w, "optimize " + file + " --criterion delaunay --angle-range keep -o " + w.path("o.msh"),
                            "--angle-range sets the worst-first driver", {"kept.msh", "kept.json", "free.msh"});
  }
}

TEST_CASE("Gmsh files: 4.1 and 2.2, ASCII and binary, read as Gmsh wrote them and written back", "[files][gmsh]")
{
  // An L-shaped block meshed by Gmsh 4.8 (OpenCASCADE), saved in the four encodings.
  const std::string dir = std::string(EDGE_SWAPPING_3_FIXTURES) + "/../fuzz/corpus/msh/";
  std::vector<Mesh> meshes;
  for(const std::string file : {"l_shape_41.msh", "l_shape_41_binary.msh", "l_shape_22.msh", "l_shape_22_binary.msh"})
  {
    INFO(file);
    meshes.push_back(ES::IO::read_mesh_with_fields<Point>(dir + file));
    const Mesh& m = meshes.back();
    REQUIRE(m.cells.size() == 99);
    REQUIRE(m.points.size() == m.point_tags.size());
    REQUIRE(std::set<int>(m.cell_references.begin(), m.cell_references.end()) == std::set<int>{7});
    REQUIRE(std::set<int>(m.triangle_references.begin(), m.triangle_references.end()) == std::set<int>{3});
    REQUIRE(shape_of(m).boundary.size() == m.triangles.size()); // every boundary triangle listed, no other
    REQUIRE(m.cells == meshes.front().cells);
    REQUIRE(m.point_tags == meshes.front().point_tags);
    // Gmsh writes 16 significant digits in ASCII, every bit in binary.
    REQUIRE(m.points.size() == meshes.front().points.size());
    for(std::size_t k = 0; k < m.points.size(); ++k)
      REQUIRE(CGAL::squared_distance(m.points[k], meshes.front().points[k]) < 1e-28);
  }
  REQUIRE(meshes[0].points == meshes[2].points); // 4.1 and 2.2 in ASCII
  REQUIRE(meshes[1].points == meshes[3].points); // and in binary
  // Written in each encoding and read back: the same mesh, node tags included.
  Workdir w;
  const Mesh& m = meshes.front();
  for(auto format : {ES::IO::MSH_4_1_ASCII, ES::IO::MSH_4_1_BINARY, ES::IO::MSH_2_2_ASCII, ES::IO::MSH_2_2_BINARY})
  {
    INFO("format " << int(format));
    write_mesh(w, "back.msh", m, format);
    const Mesh back = read_mesh(w, "back.msh");
    REQUIRE(back.points == m.points);
    REQUIRE(back.point_tags == m.point_tags);
    REQUIRE(shape_of(back) == shape_of(m));
  }
  // The program: optimized in a binary output, node tags kept.
  REQUIRE(w.run("optimize " + dir + "l_shape_22_binary.msh --criterion minmax-dihedral --operations topological "
                "--msh-format 4.1-binary -o " + w.path("o.msh")).exit_code == 0);
  const Mesh out = read_mesh(w, "o.msh");
  REQUIRE(out.point_tags == m.point_tags);
  REQUIRE(shape_of(out).boundary == shape_of(m).boundary);
}

TEST_CASE("Bad Gmsh files are refused with the file, the place and the problem, exit 2 and no output",
          "[files][gmsh][hostile]")
{
  Workdir w;
  const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "MSH version '3.0' is not supported"},
      {"hello", "not a Gmsh MSH file"},
      {head + nodes, "no $Elements section"},
      {head + nodes + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 9\n$EndElements\n", "node 9, which is not in $Nodes"},
      {head + nodes + "$Elements\n1 1 1 1\n3 1 5 1\n1 1 2 3 4 1 2 3 4\n$EndElements\n", "only linear tetrahedra"},
      {head + "$Nodes\n1 1000000000 1 4\n3 1 0 4\n1\n$EndNodes\n", "more than the rest of the file can hold"},
      {head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n1\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n", "node tag 1 is repeated"},
      {head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\nnan 0 0\n0 1 0\n0 0 1\n$EndNodes\n", "a coordinate"},
      {head + nodes + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n$PartitionedEntities\n", "partitioned"},
  };
  for(const auto& [text, what] : cases)
  {
    w.write("bad.msh", text);
    require_clean_rejection(w, "optimize " + w.path("bad.msh") + " --criterion minmax-dihedral -o " + w.path("o.msh"),
                            what, {"bad.msh"});
    require_clean_rejection(w, "check " + w.path("bad.msh"), "bad.msh:", {"bad.msh"});
  }
  // A valid one for contrast.
  w.write("good.msh", head + nodes + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n");
  REQUIRE(w.run("check " + w.path("good.msh")).exit_code == 0);
}

TEST_CASE("VTK files as VTK and ParaView write them: inline or appended, raw or base64, zlib or not", "[files][vtu]")
{
  // The L-shaped mesh that Gmsh wrote, and the same written by VTK 9.1's own
  // XML writer in five encodings (fixtures/make_vtk_fixtures.py).
  const std::string dir = std::string(EDGE_SWAPPING_3_FIXTURES) + "/../fuzz/corpus/";
  const Mesh gmsh = ES::IO::read_mesh_with_fields<Point>(dir + "msh/l_shape_22.msh");
  for(const std::string file : {"l_shape_appended_raw_zlib.vtu", "l_shape_appended_base64_zlib.vtu",
                                "l_shape_binary_zlib.vtu", "l_shape_binary_uint32.vtu", "l_shape_appended_raw_uint32.vtu"})
  {
    INFO(file);
    const Mesh m = ES::IO::read_mesh_with_fields<Point>(dir + "vtu/" + file);
    REQUIRE(m.points == gmsh.points);
    REQUIRE(m.cells == gmsh.cells);
    REQUIRE(m.cell_references == std::vector<int>(gmsh.cells.size(), 7));
    REQUIRE(m.field_index("x") == 0);
    for(std::size_t k = 0; k < m.points.size(); ++k) REQUIRE(m.fields[0][k] == m.points[k].x());
  }
  // Ours in binary (as ParaView writes by default), read back: the same.
  Workdir w;
  Mesh with_field = gmsh;
  with_field.field_names = {"x"};
  with_field.fields = {{}};
  for(const auto& p : gmsh.points) with_field.fields[0].push_back(p.x());
  with_field.cell_field_names = {"subdomain"};
  with_field.cell_fields = {std::vector<double>(gmsh.cells.size(), 7.0)};
  write_mesh(w, "b.vtu", with_field, ES::IO::MSH_4_1_ASCII, ES::IO::VTU_BINARY_ZLIB);
  REQUIRE(Workdir::slurp(w.path("b.vtu")).find("<AppendedData encoding=\"raw\">") != std::string::npos);
  const Mesh back = read_mesh(w, "b.vtu");
  REQUIRE(back.points == gmsh.points);
  REQUIRE(back.cells == gmsh.cells);
  REQUIRE(back.cell_references == std::vector<int>(gmsh.cells.size(), 7));
  REQUIRE(back.fields == with_field.fields);
  // The program too, with --vtu-format binary.
  const Run r = w.run("optimize " + dir + "vtu/l_shape_appended_raw_zlib.vtu --criterion minmax-dihedral "
                      "--operations topological --vtu-format binary -o " + w.path("o.vtu"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Mesh out = read_mesh(w, "o.vtu");
  REQUIRE(out.points == gmsh.points);
  REQUIRE(shape_of(out).boundary == shape_of(gmsh).boundary);
}

TEST_CASE("Bad binary VTK files are refused with the file and the problem, exit 2 and no output",
          "[files][vtu][hostile]")
{
  Workdir w;
  const std::string good = Workdir::slurp(std::string(EDGE_SWAPPING_3_FIXTURES) +
                                          "/../fuzz/corpus/vtu/l_shape_appended_raw_zlib.vtu");
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {replaced("compressor=\"vtkZLibDataCompressor\"", "compressor=\"vtkLZ4DataCompressor\""), "is not supported"},
      {replaced("byte_order=\"LittleEndian\"", "byte_order=\"BigEndian\""), "only LittleEndian"},
      {replaced("header_type=\"UInt64\"", "header_type=\"UInt16\""), "is not UInt32 or UInt64"},
      {replaced("NumberOfPoints=\"44\"", "NumberOfPoints=\"45\""), "bytes, not"},
      {good.substr(0, good.size() - 400), "data array"},
      {replaced("encoding=\"raw\"", "encoding=\"hex\""), "not raw or base64"},
      {replaced("offset=\"125\"", "offset=\"999999\""), "beyond the appended data"},
  };
  for(const auto& [text, what] : cases)
  {
    w.write("bad.vtu", text);
    require_clean_rejection(w, "stats " + w.path("bad.vtu"), what, {"bad.vtu"});
    require_clean_rejection(w, "optimize " + w.path("bad.vtu") + " -o " + w.path("o.vtu"), "bad.vtu", {"bad.vtu"});
  }
}
