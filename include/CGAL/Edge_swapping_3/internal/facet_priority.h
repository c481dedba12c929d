// SPDX-License-Identifier: GPL-3.0-or-later
// The fixed face order PRIORITY_ORDER: a priority for each facet computed
// from its three points and a seed alone, so that an independent program can
// compute the same order (the definition is in laboratory/doc/traces.md).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_PRIORITY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_PRIORITY_H

#include <CGAL/number_utils.h>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// SplitMix64's finalizer.
inline std::uint64_t splitmix64(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// The bits of `d` as an IEEE double, with -0 read as +0.
inline std::uint64_t double_bits(double d)
{
  d += 0.0;
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

/// The key of one point: its coordinates as doubles, chained through SplitMix64 from the seed.
template <class Point>
std::uint64_t point_priority_key(std::uint64_t seed, const Point& p)
{
  std::uint64_t h = splitmix64(seed ^ double_bits(CGAL::to_double(p.x())));
  h = splitmix64(h ^ double_bits(CGAL::to_double(p.y())));
  return splitmix64(h ^ double_bits(CGAL::to_double(p.z())));
}

/// The priority of the facet of points `p`, `q`, `r` (in any order): smaller is visited first.
/// Equal priorities (a chance of 2^-64 per pair) are ordered by the sorted points.
template <class Point>
std::uint64_t facet_priority(std::uint64_t seed, const Point& p, const Point& q, const Point& r)
{
  return splitmix64(point_priority_key(seed, p) + point_priority_key(seed, q) + point_priority_key(seed, r));
}

/// The seed of cycle `cycle`'s sweep in random order when the facets made
/// during a cycle are visited in it (same-cycle): SplitMix64 of the run's seed,
/// plus the cycle, through SplitMix64 again. With SplitMix64(`seed` + `cycle`)
/// (older traces' seeds) seed s + 1 would draw in cycle k the sweep of seed s
/// in cycle k + 1: runs of nearby seeds that met in one state would go on
/// alike, shifted by a cycle, and would not be independent samples.
inline std::uint64_t random_sweep_seed(std::uint64_t seed, std::uint64_t cycle)
{
  return splitmix64(splitmix64(seed) + cycle);
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_PRIORITY_H
