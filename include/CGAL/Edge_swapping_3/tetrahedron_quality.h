// Quality measures of a tetrahedron: dihedral angles and the paper's two
// aspect ratios. Constructions in double precision: approximate by nature.

#ifndef CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H
#define CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H

#include <CGAL/number_utils.h>
#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Edge_swapping_3 {

namespace internal {
struct Vec { double x, y, z; };
inline Vec sub(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec cross(const Vec& a, const Vec& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

template <class Point>
std::array<Vec, 4> to_vecs(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  auto v = [](const Point& p) {
    return Vec{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  return {v(p0), v(p1), v(p2), v(p3)};
}
} // namespace internal

/// The six dihedral angles, in degrees, of a non-degenerate tetrahedron.
template <class Point>
std::array<double, 6> dihedral_angles(const Point& p0, const Point& p1,
                                      const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  // Outward normal of the face opposite vertex k.
  std::array<Vec, 4> n;
  for(int k = 0; k < 4; ++k)
  {
    const Vec& a = v[(k + 1) & 3];
    const Vec& b = v[(k + 2) & 3];
    const Vec& c = v[(k + 3) & 3];
    Vec nk = cross(sub(b, a), sub(c, a));
    if(dot(nk, sub(v[k], a)) > 0) nk = Vec{-nk.x, -nk.y, -nk.z};
    n[k] = nk;
  }
  static const int faces[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  std::array<double, 6> angles;
  const double to_degrees = 180.0 / 3.14159265358979323846;
  for(int e = 0; e < 6; ++e)
  {
    const Vec& a = n[faces[e][0]];
    const Vec& b = n[faces[e][1]];
    double c = -dot(a, b) / (norm(a) * norm(b));
    c = (std::max)(-1.0, (std::min)(1.0, c));
    angles[e] = std::acos(c) * to_degrees;
  }
  return angles;
}

/// Longest over shortest edge (the paper's first aspect ratio; 1 for a regular tetrahedron).
template <class Point>
double edge_length_ratio(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  double lo = HUGE_VAL, hi = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      const Vec d = sub(v[i], v[j]);
      lo = (std::min)(lo, dot(d, d));
      hi = (std::max)(hi, dot(d, d));
    }
  return std::sqrt(hi / lo);
}

/// Circumradius over inradius (the paper's second aspect ratio; 3 for a
/// regular tetrahedron, infinite for a flat one).
template <class Point>
double radius_ratio(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  const Vec a = sub(v[1], v[0]), b = sub(v[2], v[0]), c = sub(v[3], v[0]);
  const double six_volume = std::abs(dot(a, cross(b, c)));
  if(six_volume == 0) return HUGE_VAL;
  // Circumcentre relative to v0: (|a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b)) / (2 a.(b x c)).
  const Vec bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  const double la = dot(a, a), lb = dot(b, b), lc = dot(c, c);
  const Vec o{la * bc.x + lb * ca.x + lc * ab.x, la * bc.y + lb * ca.y + lc * ab.y,
              la * bc.z + lb * ca.z + lc * ab.z};
  const double circumradius = norm(o) / (2 * six_volume);
  double area2 = 0; // twice the total face area
  for(int k = 0; k < 4; ++k)
    area2 += norm(cross(sub(v[(k + 2) & 3], v[(k + 1) & 3]), sub(v[(k + 3) & 3], v[(k + 1) & 3])));
  const double inradius = six_volume / area2; // 3V / A
  return circumradius / inradius;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H
