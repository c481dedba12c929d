// SPDX-License-Identifier: GPL-3.0-or-later
// The facets of a mesh being glued that have met one tetrahedron so far,
// keyed by their sorted point indices. Each slot (16 bytes) holds the key and
// where the facet was seen, so that a probe touches one cache line; the
// generic Flat_hash_map keeps its flags apart and its keys wider, and gluing
// a mesh is mostly such probes (measured: 22% of `check` at 10^5 points).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPEN_FACET_TABLE_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPEN_FACET_TABLE_H

#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

class Open_facet_table
{
public:
  /// Indices and places must be below 2^32 (the builder checks).
  static constexpr std::uint64_t limit = std::uint64_t(1) << 32;

  explicit Open_facet_table(std::size_t expected = 0)
  {
    std::size_t capacity = 64;
    while(3 * capacity < 4 * expected) capacity *= 2;
    slots_.assign(capacity, Slot());
    mask_ = capacity - 1;
  }

  std::size_t size() const { return size_; }

  /// The facet `a < b < c` seen at `place`: if it was open, closes it and
  /// returns where it was seen first; otherwise opens it and returns -1.
  std::int64_t close_or_open(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t place)
  {
    const std::uint64_t ab = (std::uint64_t(a) << 32) | b;
    std::size_t s = slot_of(ab, c);
    for(; slots_[s].place != 0; s = (s + 1) & mask_)
      if(slots_[s].ab == ab && slots_[s].c == c)
      {
        const std::int64_t first = std::int64_t(slots_[s].place) - 1;
        erase_at(s);
        return first;
      }
    if(4 * (size_ + 1) > 3 * slots_.size())
    {
      grow();
      return close_or_open(a, b, c, place);
    }
    slots_[s] = {ab, c, place + 1};
    ++size_;
    return -1;
  }

  /// Asks the processor for the slot of facet `a < b < c`, some probes ahead.
  void prefetch(std::uint32_t a, std::uint32_t b, std::uint32_t c) const
  {
#if defined(__GNUC__)
    __builtin_prefetch(&slots_[slot_of((std::uint64_t(a) << 32) | b, c)]);
#else
    (void)a, (void)b, (void)c;
#endif
  }

private:
  struct Slot
  {
    std::uint64_t ab = 0;
    std::uint32_t c = 0;
    std::uint32_t place = 0; ///< where seen, plus one; 0: empty
  };

  std::size_t slot_of(std::uint64_t ab, std::uint32_t c) const
  {
    return std::size_t(mix_bits(ab ^ (std::uint64_t(c) * 0x9e3779b97f4a7c15ull))) & mask_;
  }

  void erase_at(std::size_t s)
  {
    // Backward shift: later entries of the run move into the hole when their home allows.
    for(std::size_t next = (s + 1) & mask_; slots_[next].place != 0; next = (next + 1) & mask_)
    {
      const std::size_t home = slot_of(slots_[next].ab, slots_[next].c);
      if(((next - home) & mask_) >= ((next - s) & mask_))
      {
        slots_[s] = slots_[next];
        s = next;
      }
    }
    slots_[s] = Slot();
    --size_;
  }

  void grow()
  {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    mask_ = slots_.size() - 1;
    for(const Slot& slot : old)
      if(slot.place != 0)
      {
        std::size_t s = slot_of(slot.ab, slot.c);
        while(slots_[s].place != 0) s = (s + 1) & mask_;
        slots_[s] = slot;
      }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0, size_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPEN_FACET_TABLE_H
