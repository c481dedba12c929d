// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the tests: the triangulation type, input families drawn from a
// printed seed, and exact comparisons of cell sets and volumes.

#ifndef EDGE_SWAPPING_3_TEST_COMMON_H
#define EDGE_SWAPPING_3_TEST_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_3<K> Tr;
namespace ES = CGAL::Edge_swapping_3;

typedef std::array<Point, 4> Cell_points;

/// The finite cells as sorted point quadruples: equal sets mean equal triangulations.
template <class T>
std::vector<Cell_points> cell_set(const T& tr)
{
  std::vector<Cell_points> cells;
  auto less = [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; };
  for(auto c : tr.finite_cell_handles())
  {
    Cell_points p = {c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point()};
    std::sort(p.begin(), p.end(), less);
    cells.push_back(p);
  }
  std::sort(cells.begin(), cells.end(), [&](const Cell_points& a, const Cell_points& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
  });
  return cells;
}

/// The exact volume of a tetrahedron (coordinates are doubles, so rationals are exact).
inline CGAL::Exact_rational exact_volume(const Point& o, const Point& a, const Point& b, const Point& c)
{
  typedef CGAL::Exact_rational Q;
  Q m[3][3];
  const Point* p[3] = {&a, &b, &c};
  for(int i = 0; i < 3; ++i)
  {
    m[i][0] = Q(p[i]->x()) - Q(o.x());
    m[i][1] = Q(p[i]->y()) - Q(o.y());
    m[i][2] = Q(p[i]->z()) - Q(o.z());
  }
  return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) / 6;
}

/// The exact total volume of the finite cells.
template <class T>
CGAL::Exact_rational exact_volume(const T& tr)
{
  CGAL::Exact_rational total = 0;
  for(auto c : tr.finite_cell_handles())
    total += exact_volume(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
  return total;
}

// --- Input families (the library's, point_families.h). Every random one is
// drawn from `seed`, which the tests print.

namespace pf = CGAL::Edge_swapping_3::point_families;
inline std::vector<Point> random_in_cube(std::size_t n, unsigned seed) { return pf::random_in_cube<Point>(n, seed); }
inline std::vector<Point> random_in_ball(std::size_t n, unsigned seed) { return pf::random_in_ball<Point>(n, seed); }
inline std::vector<Point> grid(int nx, int ny, int nz) { return pf::grid<Point>(nx, ny, nz); }
inline std::vector<Point> cospherical(int r2) { return pf::cospherical<Point>(r2); }
inline std::vector<Point> on_planes(std::size_t n, int planes, unsigned seed) { return pf::on_planes<Point>(n, planes, seed); }
inline std::vector<Point> clustered(std::size_t n, unsigned seed) { return pf::clustered<Point>(n, seed); }
inline std::vector<Point> nearly_flat(std::size_t n, unsigned seed) { return pf::nearly_flat<Point>(n, seed); }

struct Family
{
  std::string name;
  std::vector<Point> points;
};

/// The degenerate and random families of the exactness tests, for one seed.
inline std::vector<Family> families(unsigned seed)
{
  return {{"cube 5", random_in_cube(5, seed)},
          {"cube 300", random_in_cube(300, seed)},
          {"ball 500", random_in_ball(500, seed)},
          {"grid 2x2x2", grid(2, 2, 2)},
          {"grid 3x4x5", grid(3, 4, 5)},
          {"grid 6x6x6", grid(6, 6, 6)},
          {"cospherical 50", cospherical(50)},
          {"cospherical 27 + centre", [] { auto p = cospherical(27); p.emplace_back(0, 0, 0); return p; }()},
          {"planes 200", on_planes(200, 3, seed)},
          {"clustered 400", clustered(400, seed)},
          {"nearly flat 300", nearly_flat(300, seed)}};
}

} // namespace test

#endif
