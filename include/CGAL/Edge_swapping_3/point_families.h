// SPDX-License-Identifier: GPL-3.0-or-later
// Point sets for experiments and tests: random ones drawn from a seed, and
// degenerate ones (grids, exactly cospherical and coplanar sets, clusters,
// jittered grids), the inputs on which the paper's conjectures are tested.

#ifndef CGAL_EDGE_SWAPPING_3_POINT_FAMILIES_H
#define CGAL_EDGE_SWAPPING_3_POINT_FAMILIES_H

#include <CGAL/Random.h>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace point_families {

/// `n` points uniform in the unit cube, from `seed`.
template <class Point>
std::vector<Point> random_in_cube(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  for(std::size_t k = 0; k < n; ++k) p.emplace_back(r.get_double(), r.get_double(), r.get_double());
  return p;
}

/// `n` points uniform in the unit ball, from `seed`.
template <class Point>
std::vector<Point> random_in_ball(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  while(p.size() < n)
  {
    const double x = r.get_double(-1, 1), y = r.get_double(-1, 1), z = r.get_double(-1, 1);
    if(x * x + y * y + z * z <= 1) p.emplace_back(x, y, z);
  }
  return p;
}

/// Random points on the unit sphere (rounded: nearly, not exactly, cospherical).
template <class Point>
std::vector<Point> on_sphere(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  while(p.size() < n)
  {
    const double x = r.get_double(-1, 1), y = r.get_double(-1, 1), z = r.get_double(-1, 1);
    const double l = std::sqrt(x * x + y * y + z * z);
    if(l > 0.1 && l <= 1) p.emplace_back(x / l, y / l, z / l);
  }
  return p;
}

/// The `nx` by `ny` by `nz` integer grid.
template <class Point>
std::vector<Point> grid(int nx, int ny, int nz)
{
  std::vector<Point> p;
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j)
      for(int k = 0; k < nz; ++k) p.emplace_back(i, j, k);
  return p;
}

/// A k x k x k grid moved by at most `amount` (relative) per coordinate.
template <class Point>
std::vector<Point> jittered_grid(int k, double amount, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  for(const Point& q : grid<Point>(k, k, k))
    p.emplace_back(q.x() + amount * r.get_double(-1, 1), q.y() + amount * r.get_double(-1, 1),
                   q.z() + amount * r.get_double(-1, 1));
  return p;
}

/// Integer points exactly on the sphere x^2 + y^2 + z^2 = r2: all cospherical,
/// ordered by x, then y, then z.
template <class Point>
std::vector<Point> cospherical(long r2)
{
  std::vector<Point> p;
  const long r = long(std::sqrt(double(r2))) + 1;
  for(long x = -r; x <= r; ++x)
    for(long y = -r; y <= r; ++y)
    {
      const long rest = r2 - x * x - y * y; // z^2
      if(rest < 0) continue;
      long z = long(std::sqrt(double(rest)));
      while(z * z > rest) --z;
      while((z + 1) * (z + 1) <= rest) ++z;
      if(z * z != rest) continue;
      if(z > 0) p.emplace_back(int(x), int(y), int(-z));
      p.emplace_back(int(x), int(y), int(z));
    }
  return p;
}

/// The most points `cospherical_subset` gives. The sphere for 20,000 has
/// r2 = 644,474; the points of a sphere grow only as the root of r2 on average,
/// so the sphere for many more would not be found in reasonable time.
constexpr std::size_t cospherical_max_points = 20000;

/// The smallest r2 >= 3 whose sphere x^2 + y^2 + z^2 = r2 has at least `n`
/// integer points.
inline long smallest_sphere_with(std::size_t n)
{
  // Every sphere up to `most` counted in one pass over the ball's points with
  // x, y, z >= 0 (each stands for its sign changes), `most` doubled until one
  // has n: not a search of the cube for each sphere.
  for(long most = 64;; most *= 2)
  {
    std::vector<std::size_t> count(std::size_t(most) + 1, 0);
    for(long x = 0; x * x <= most; ++x)
      for(long y = 0; x * x + y * y <= most; ++y)
        for(long z = 0; x * x + y * y + z * z <= most; ++z)
          count[std::size_t(x * x + y * y + z * z)] += (x > 0 ? 2 : 1) * (y > 0 ? 2 : 1) * (z > 0 ? 2 : 1);
    for(long r2 = 3; r2 <= most; ++r2)
      if(count[std::size_t(r2)] >= n) return r2;
  }
}

/// `n` of the integer points of the smallest sphere about the origin that has
/// at least `n` and at least 8 (so not flat), drawn from `seed`: exactly
/// cospherical. Throws `std::invalid_argument` for more than
/// `cospherical_max_points`.
template <class Point>
std::vector<Point> cospherical_subset(std::size_t n, unsigned seed)
{
  if(n > cospherical_max_points)
    throw std::invalid_argument("cospherical: at most " + std::to_string(cospherical_max_points) +
                                " points (the integer points of one sphere), not " + std::to_string(n));
  std::vector<Point> p = cospherical<Point>(smallest_sphere_with(std::max<std::size_t>(n, 8)));
  CGAL::Random r(seed);
  for(std::size_t k = 0; k < n; ++k) std::swap(p[k], p[k + std::size_t(r.get_int(0, int(p.size() - k)))]);
  p.resize(n);
  return p;
}

template <class Point>
std::vector<Point> two_concentric_spheres(std::size_t n, unsigned seed)
{
  if(n > 2 * cospherical_max_points)
    throw std::invalid_argument("two-spheres: at most " + std::to_string(2 * cospherical_max_points) +
                                " points (those of two spheres), not " + std::to_string(n));
  std::vector<Point> p = cospherical_subset<Point>(n / 2, seed);
  for(const Point& q : cospherical_subset<Point>(n - n / 2, seed + 1)) p.emplace_back(3 * q.x(), 3 * q.y(), 3 * q.z());
  return p;
}

/// Random integer points on a few parallel planes: many coplanar and cocircular subsets.
template <class Point>
std::vector<Point> on_planes(std::size_t n, int planes, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  std::set<Point> drawn; // a point drawn again is skipped, in time n log n
  const int side = std::max(20, 2 + int(std::sqrt(double(n))));
  while(p.size() < n)
  {
    Point q(r.get_int(0, side), r.get_int(0, side), r.get_int(0, planes));
    if(drawn.insert(q).second) p.push_back(q);
  }
  return p;
}

/// Tight clusters around five centres.
template <class Point>
std::vector<Point> clustered(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> centres;
  for(int k = 0; k < 5; ++k) centres.emplace_back(r.get_double(), r.get_double(), r.get_double());
  std::vector<Point> p;
  for(std::size_t k = 0; k < n; ++k)
  {
    const Point& c = centres[k % centres.size()];
    p.emplace_back(c.x() + 1e-3 * r.get_double(), c.y() + 1e-3 * r.get_double(), c.z() + 1e-3 * r.get_double());
  }
  return p;
}

/// Nearly flat: a unit square, 1e-6 thick.
template <class Point>
std::vector<Point> nearly_flat(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  for(std::size_t k = 0; k < n; ++k) p.emplace_back(r.get_double(), r.get_double(), 1e-6 * r.get_double());
  return p;
}

/// Distinct random integer points in [0, 1000]^3 (general position with high
/// probability; integer, so TOPCOM can read them).
template <class Point>
std::vector<Point> random_integer(std::size_t n, unsigned seed)
{
  CGAL::Random r(seed);
  std::vector<Point> p;
  std::set<Point> drawn; // a point drawn again is skipped, in time n log n
  while(p.size() < n)
  {
    Point q(r.get_int(0, 1001), r.get_int(0, 1001), r.get_int(0, 1001));
    if(drawn.insert(q).second) p.push_back(q);
  }
  return p;
}

/// The corners of the cube [0,2]^3, with its centre (1,1,1) if asked.
template <class Point>
std::vector<Point> cube_corners(bool with_centre)
{
  std::vector<Point> p;
  for(const Point& q : grid<Point>(2, 2, 2)) p.emplace_back(2 * q.x(), 2 * q.y(), 2 * q.z());
  if(with_centre) p.emplace_back(1, 1, 1);
  return p;
}

/// The corners of the cube [0,2]^3, its centre and the centres of its six faces (15 points).
template <class Point>
std::vector<Point> cube_with_centre_and_face_centres()
{
  std::vector<Point> p = cube_corners<Point>(true);
  for(int axis = 0; axis < 3; ++axis)
    for(int side : {0, 2})
    {
      int c[3] = {1, 1, 1};
      c[axis] = side;
      p.emplace_back(c[0], c[1], c[2]);
    }
  return p;
}

/// `n` integer points on two concentric spheres about the origin: about half
/// on the inner (as `cospherical_subset`), the rest on a sphere three times
/// as large, each drawn from `seed`.
template <class Point>
std::vector<Point> two_concentric_spheres(std::size_t n, unsigned seed);

/// The octahedron (+-1,0,0), (0,+-1,0), (0,0,+-1), with its centre if asked.
template <class Point>
std::vector<Point> octahedron(bool with_centre)
{
  std::vector<Point> p = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                          Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  if(with_centre) p.emplace_back(0, 0, 0);
  return p;
}

} // namespace point_families

/// The names `make_point_family` knows, for experiments.
inline std::vector<std::string> point_family_names()
{
  return {"random-cube", "random-ball", "sphere",   "grid",     "cospherical", "planes",   "clusters",
          "jittered-grid", "nearly-flat", "random-integer", "cube-corners", "cube-centre", "octahedron",
          "octahedron-centre", "cube-face-centres", "grid-2x2x3", "grid-3x3x2", "two-spheres"};
}

/// The family `name` with about `n` points (grids: the nearest k x k x k;
/// cube, octahedron and the fixed grids: their own size), drawn from `seed`. Throws
/// `std::invalid_argument` for an unknown name, and for more points than `cospherical`
/// (`cospherical_max_points`) or `two-spheres` (twice that) give.
template <class Point>
std::vector<Point> make_point_family(const std::string& name, std::size_t n, unsigned seed)
{
  namespace pf = point_families;
  const int k = std::max(2, int(std::lround(std::cbrt(double(n)))));
  if(name == "random-cube") return pf::random_in_cube<Point>(n, seed);
  if(name == "random-ball") return pf::random_in_ball<Point>(n, seed);
  if(name == "sphere") return pf::on_sphere<Point>(n, seed);
  if(name == "grid") return pf::grid<Point>(k, k, k);
  if(name == "cospherical") return pf::cospherical_subset<Point>(n, seed);
  if(name == "planes") return pf::on_planes<Point>(n, 3, seed);
  if(name == "clusters") return pf::clustered<Point>(n, seed);
  if(name == "jittered-grid") return pf::jittered_grid<Point>(k, 1e-9, seed);
  if(name == "nearly-flat") return pf::nearly_flat<Point>(n, seed);
  if(name == "random-integer") return pf::random_integer<Point>(n, seed);
  if(name == "cube-corners") return pf::cube_corners<Point>(false);
  if(name == "cube-centre") return pf::cube_corners<Point>(true);
  if(name == "octahedron") return pf::octahedron<Point>(false);
  if(name == "octahedron-centre") return pf::octahedron<Point>(true);
  if(name == "cube-face-centres") return pf::cube_with_centre_and_face_centres<Point>();
  if(name == "grid-2x2x3") return pf::grid<Point>(2, 2, 3);
  if(name == "grid-3x3x2") return pf::grid<Point>(3, 3, 2);
  if(name == "two-spheres") return pf::two_concentric_spheres<Point>(n, seed);
  throw std::invalid_argument("unknown point family '" + name + "'");
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_POINT_FAMILIES_H
