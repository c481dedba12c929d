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
#include <cstring>

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

template <class Key, class Hash, class Report>
class Failed_attempts
{
public:
  /// The report of the failure at `key` when the cells read then have `signature`, else null.
  const Report* find(const Key& key, std::uint64_t signature) const
  {
    const Failure* known = failures_.find(key);
    return (known != nullptr && known->signature == signature) ? &known->report : nullptr;
  }

  /// Records the outcome of an attempt: a failure is kept, a success forgets the key.
  void record(const Key& key, std::uint64_t signature, const Report& report, bool succeeded)
  {
    if(succeeded) failures_.erase(key);
    else failures_[key] = {signature, report};
  }

private:
  struct Failure
  {
    std::uint64_t signature;
    Report report;
  };
  Flat_hash_map<Key, Failure, Hash> failures_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FAILED_ATTEMPTS_H
