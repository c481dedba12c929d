// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes of domains of any shape (non-convex, with cavities, several regions,
// several parts, coordinates as CAD kernels write them): accepted, completed
// outside to a convex region, optimized, and written back with exactly the
// domain's cells, the same vertices, boundaries, interfaces and references.
// Checked exactly, through the library and through the program.

#include "test_common.h"
#include "program_runner.h"
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/make_two_spheres_mesh.h>
#include <functional>
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
    for(double offset : {0.0, 1e20})
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
        Numbered tr; // at 1e20 the rounding zeros vanish into offset + 0: the points are the grid's
        REQUIRE(ES::build_numbered_mesh(tr, m) == "");
        REQUIRE(ES::number_of_mesh_cells(tr) == m.cells.size());
      }
    }
  }
}

TEST_CASE("Domains of any shape: two spherical cavities in a box (Mesh_3's mesh without its subdomain 0)",
          "[domain][any shape]")
{
  const Mesh full = ES::make_two_spheres_mesh<K>(0.7);
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
    // A tetrahedron on the far side of a shared facet: three on that facet.
    const auto t = m.cells[0];
    m.points.push_back(Point(-0.5, -0.5, -0.5));
    m.cells.push_back({t[1], t[0], t[2], m.points.size() - 1});
    m.cell_references.push_back(1);
    Numbered tr;
    const std::string problem = ES::build_numbered_mesh(tr, m);
    INFO(problem);
    REQUIRE(!problem.empty());
    REQUIRE(tr.number_of_vertices() == 0);
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
  SECTION("the reserved reference")
  {
    Mesh m = l_shape;
    m.cell_references[3] = ES::Domain_cell_info::completion;
    Numbered tr;
    REQUIRE(ES::build_numbered_mesh(tr, m).find("is reserved") != std::string::npos);
  }
}
