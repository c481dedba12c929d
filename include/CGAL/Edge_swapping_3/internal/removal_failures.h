// The attempts of a removal (edge or multi-face) that failed, remembered with
// a hash of the cells they read: the points never move, so the same cells
// give the same answer, and the quality driver, which tries the same edges
// and facets again and again as cells around them change, answers a second
// attempt on unchanged cells from here.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_REMOVAL_FAILURES_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_REMOVAL_FAILURES_H

#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <cstdint>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Key, class Hash, class Report>
class Removal_failures
{
public:
  /// The report of the failure at `key` when the cells read then hash to `signature`, else null.
  const Report* find(const Key& key, std::uint64_t signature) const
  {
    const Failure* known = failures_.find(key);
    return (known != nullptr && known->signature == signature) ? &known->report : nullptr;
  }

  /// Records the outcome of an attempt: a failure is kept, a removal forgets the key.
  void record(const Key& key, std::uint64_t signature, const Report& report)
  {
    if(report.removed()) failures_.erase(key);
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

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_REMOVAL_FAILURES_H
