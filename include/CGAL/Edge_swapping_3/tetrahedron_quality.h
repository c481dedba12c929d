// SPDX-License-Identifier: GPL-3.0-or-later
// Quality measures of a tetrahedron: dihedral angles, the paper's two
// aspect ratios, the smallest dihedral sine and the volume-length ratio. Constructions in double precision: approximate by nature.
// Every measure is scale invariant, so it is computed on the edge vectors
// scaled to at most 1 (no overflow or underflow whatever the coordinates),
// and it is always a finite number: a tetrahedron too flat for double
// precision gets the largest double as its aspect ratio.

#ifndef CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H
#define CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H

#include <CGAL/number_utils.h>
#include <algorithm>
#include <array>
#include <cfloat>
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

// The vertices relative to the first, divided by the largest coordinate
// difference: each component is at most 1 in magnitude.
template <class Point>
std::array<Vec, 4> to_vecs(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  auto v = [](const Point& p) {
    return Vec{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  const Vec o = v(p0);
  std::array<Vec, 4> r = {Vec{0, 0, 0}, sub(v(p1), o), sub(v(p2), o), sub(v(p3), o)};
  double largest = 0;
  for(const Vec& d : r) largest = (std::max)({largest, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  if(largest > 0 && std::isfinite(largest))
    for(Vec& d : r) d = Vec{d.x / largest, d.y / largest, d.z / largest};
  return r;
}

// A ratio that is not a finite number (a tetrahedron too flat for double
// precision) becomes the largest double.
inline double finite_ratio(double r) { return (r >= 0 && r <= DBL_MAX) ? r : DBL_MAX; }
} // namespace internal

namespace internal {
// The cosines of the six dihedral angles of a non-degenerate tetrahedron.
template <class Point>
std::array<double, 6> dihedral_cosines(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
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
  std::array<double, 4> lengths;
  for(int k = 0; k < 4; ++k) lengths[k] = norm(n[k]);
  static const int faces[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  std::array<double, 6> cosines;
  for(int e = 0; e < 6; ++e)
  {
    const Vec& a = n[faces[e][0]];
    const Vec& b = n[faces[e][1]];
    const double length = lengths[faces[e][0]] * lengths[faces[e][1]];
    // A face too thin for double precision has no normal: call its angles 0.
    const double c = length > 0 ? -dot(a, b) / length : 1.0;
    cosines[e] = std::isfinite(c) ? (std::max)(-1.0, (std::min)(1.0, c)) : 1.0;
  }
  return cosines;
}

inline double degrees_of_cosine(double c) { return std::acos(c) * (180.0 / 3.14159265358979323846); }
} // namespace internal

/// The six dihedral angles, in degrees, of a non-degenerate tetrahedron.
template <class Point>
std::array<double, 6> dihedral_angles(const Point& p0, const Point& p1,
                                      const Point& p2, const Point& p3)
{
  const auto cosines = internal::dihedral_cosines(p0, p1, p2, p3);
  std::array<double, 6> angles;
  for(int e = 0; e < 6; ++e) angles[e] = internal::degrees_of_cosine(cosines[e]);
  return angles;
}

/// The largest dihedral angle, in degrees, with one `acos` (the angle
/// decreases with its cosine).
template <class Point>
double largest_dihedral_angle(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const auto cosines = internal::dihedral_cosines(p0, p1, p2, p3);
  return internal::degrees_of_cosine(*std::min_element(cosines.begin(), cosines.end()));
}

/// The smallest dihedral angle, in degrees, with one `acos`.
template <class Point>
double smallest_dihedral_angle(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const auto cosines = internal::dihedral_cosines(p0, p1, p2, p3);
  return internal::degrees_of_cosine(*std::max_element(cosines.begin(), cosines.end()));
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
  return finite_ratio(std::sqrt(hi / lo));
}

/// Circumradius over inradius (the paper's second aspect ratio; 3 for a
/// regular tetrahedron; the largest double for one too flat for double precision).
template <class Point>
double circumradius_over_inradius(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  const Vec a = sub(v[1], v[0]), b = sub(v[2], v[0]), c = sub(v[3], v[0]);
  const double six_volume = std::abs(dot(a, cross(b, c)));
  if(!(six_volume > 0)) return DBL_MAX;
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
  return finite_ratio(circumradius / inradius);
}

/// The smallest sine of the six dihedral angles, divided by that of a
/// regular tetrahedron (2 sqrt(2) / 3): 1 for a regular tetrahedron, 0 for a
/// flat one. Small for both small and large angles, with no `acos`: the sine
/// of the angle at edge ij is |n_k x n_l| / (|n_k| |n_l|), n_k and n_l the
/// normals of the two faces on that edge.
template <class Point>
double minimum_dihedral_sine(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  std::array<Vec, 4> n;
  for(int k = 0; k < 4; ++k)
    n[k] = cross(sub(v[(k + 2) & 3], v[(k + 1) & 3]), sub(v[(k + 3) & 3], v[(k + 1) & 3]));
  std::array<double, 4> lengths;
  for(int k = 0; k < 4; ++k) lengths[k] = norm(n[k]);
  double smallest = HUGE_VAL;
  for(int k = 0; k < 4; ++k)
    for(int l = k + 1; l < 4; ++l)
    {
      const double length = lengths[k] * lengths[l];
      const double s = length > 0 ? norm(cross(n[k], n[l])) / length : 0.0;
      smallest = (std::min)(smallest, std::isfinite(s) ? s : 0.0);
    }
  return smallest / (2 * std::sqrt(2.0) / 3);
}

/// The volume over the cube of the root mean square edge length, times
/// 6 sqrt(2): 1 for a regular tetrahedron, 0 for a flat one.
template <class Point>
double volume_length_ratio(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  using namespace internal;
  const auto v = to_vecs(p0, p1, p2, p3);
  const double volume = std::abs(dot(v[1], cross(v[2], v[3]))) / 6;
  double squares = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) squares += dot(sub(v[i], v[j]), sub(v[i], v[j]));
  const double rms = std::sqrt(squares / 6);
  const double r = rms > 0 ? 6 * std::sqrt(2.0) * volume / (rms * rms * rms) : 0.0;
  return std::isfinite(r) ? r : 0.0;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TETRAHEDRON_QUALITY_H
