// SPDX-License-Identifier: GPL-3.0-or-later
// The attempts of a local operation (edge removal, multi-face removal,
// vertex smoothing) that failed, remembered with a signature of the cells
// they read, vertices and positions: the same cells at the same places give
// the same answer, and the quality driver, which tries the same edges,
// facets and vertices again and again as cells around them change, answers
// a second attempt on unchanged cells from here.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FAILED_ATTEMPTS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FAILED_ATTEMPTS_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/number_utils.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// A hash of a vertex and of its position: smoothing moves vertices, so the
/// handle alone does not say that a cell is unchanged. (The infinite
/// vertex has no position.)
template <class Tr>
std::uint64_t vertex_signature(const Tr& tr, typename Tr::Vertex_handle v)
{
  std::uint64_t h = mix_bits(std::uint64_t(address_of(v)));
  if(tr.is_infinite(v)) return h;
  const auto& p = internal::bare_point(v->point());
  for(double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())})
  {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = mix_bits(h ^ bits);
  }
  return h;
}

// The even slot of a fingerprint's pair among `pairs`: the high half of the
// product of a 32-bit hash and the number of pairs spreads over any number
// of pairs, so a table is the size asked for, not the next power of two.
inline std::size_t pair_of(std::uint64_t f, std::uint64_t pairs)
{
  return 2 * std::size_t(((mix_bits(f) >> 32) * pairs) >> 32);
}

/// Failed attempts in a fixed amount of memory: a table of fingerprints (the
/// key's hash mixed with the signature of the cells read, and the outcome),
/// two places per fingerprint, the older one overwritten when both are
/// taken. A failure that was overwritten is tried again. The attempt is a
/// function of what its signature covers (for two-step removal, the change
/// stamps of the edge's ends, with the ring starting at its smallest point),
/// so forgetting costs time and leaves the run as it was. Only the outcome
/// is kept: a remembered failure comes back as a report with its outcome
/// alone.
template <class Key, class Hash, class Report>
class Failure_cache
{
public:
  /// Room for `capacity` failures (rounded up to an even number, at least 2; 0: none, nothing is remembered).
  explicit Failure_cache(std::size_t capacity)
  {
    if(capacity == 0) return;
    // At most 2^32 pairs (`place`), 64 GiB: more than any mesh in memory needs.
    capacity = std::size_t((std::min)(std::uint64_t(capacity), std::uint64_t(1) << 33));
    slots_.assign((std::max)(std::size_t(2), capacity + (capacity & 1)), 0);
  }

  /// A report with the outcome of the failure at `key` when the cells read then had `signature`, else null.
  const Report* find(const Key& key, std::uint64_t signature)
  {
    if(slots_.empty()) return nullptr;
    const std::uint64_t f = fingerprint(key, signature);
    const std::size_t i = place(f);
    for(std::size_t k : {i, i ^ 1})
      if((slots_[k] & ~std::uint64_t(0xFF)) == f)
      {
        found_ = Report();
        found_.outcome = decltype(found_.outcome)((slots_[k] & 0xFF) - 1);
        return &found_;
      }
    return nullptr;
  }

  /// Records the outcome of an attempt: a failure is kept, a success forgets the key.
  void record(const Key& key, std::uint64_t signature, const Report& report, bool succeeded)
  {
    if(slots_.empty()) return;
    const std::uint64_t f = fingerprint(key, signature);
    const std::size_t i = place(f);
    for(std::size_t k : {i, i ^ 1})
      if((slots_[k] & ~std::uint64_t(0xFF)) == f)
      {
        slots_[k] = succeeded ? 0 : f | (std::uint64_t(report.outcome) + 1);
        return;
      }
    if(succeeded) return;
    // The empty place, else one of the two, in turn.
    const std::size_t k = slots_[i] == 0 ? i : (slots_[i ^ 1] == 0 ? i ^ 1 : (i ^ std::size_t(next_++ & 1)));
    slots_[k] = f | (std::uint64_t(report.outcome) + 1);
  }

private:
  static std::uint64_t fingerprint(const Key& key, std::uint64_t signature)
  {
    // The low byte holds the outcome; a fingerprint is never 0 (an empty place).
    return (mix_bits(signature ^ mix_bits(std::uint64_t(Hash()(key)))) & ~std::uint64_t(0xFF)) | 0x100;
  }
  std::size_t place(std::uint64_t f) const { return pair_of(f, slots_.size() / 2); }

  std::vector<std::uint64_t> slots_;
  Report found_;
  std::uint64_t next_ = 0;
};

// A value computed from the cells a signature covers (a bound on the best
// worst score of an edge's star, say), remembered in a fixed amount of
// memory, two places per fingerprint: a value forgotten is computed again.
template <class Key, class Hash>
class Value_cache
{
public:
  explicit Value_cache(std::size_t capacity)
  {
    if(capacity == 0) return;
    capacity = std::size_t((std::min)(std::uint64_t(capacity), std::uint64_t(1) << 33));
    slots_.assign((std::max)(std::size_t(2), capacity + (capacity & 1)), Slot{0, 0});
  }

  bool find(const Key& key, std::uint64_t signature, double& value) const
  {
    if(slots_.empty()) return false;
    const std::uint64_t f = fingerprint(key, signature);
    const std::size_t i = pair_of(f, slots_.size() / 2);
    for(std::size_t k : {i, i ^ 1})
      if(slots_[k].fingerprint == f)
      {
        value = slots_[k].value;
        return true;
      }
    return false;
  }

  void record(const Key& key, std::uint64_t signature, double value)
  {
    if(slots_.empty()) return;
    const std::uint64_t f = fingerprint(key, signature);
    const std::size_t i = pair_of(f, slots_.size() / 2);
    // The fingerprint's own place, else an empty one, else one of the two, in turn.
    std::size_t k = slots_[i ^ 1].fingerprint == f ? i ^ 1 : i;
    if(slots_[k].fingerprint != f && slots_[k].fingerprint != 0)
      k = slots_[i ^ 1].fingerprint == 0 ? i ^ 1 : (i ^ std::size_t(next_++ & 1));
    slots_[k] = Slot{f, value};
  }

private:
  struct Slot
  {
    std::uint64_t fingerprint; // 0: empty
    double value;
  };
  static std::uint64_t fingerprint(const Key& key, std::uint64_t signature)
  {
    return mix_bits(signature ^ mix_bits(std::uint64_t(Hash()(key)))) | 1;
  }

  std::vector<Slot> slots_;
  std::uint64_t next_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FAILED_ATTEMPTS_H
