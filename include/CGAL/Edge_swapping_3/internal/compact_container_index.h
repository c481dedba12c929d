// SPDX-License-Identifier: GPL-3.0-or-later
// A dense index for the items of a CGAL::Compact_container (the cells of a
// TDS), so that a driver keeps its per-cell state in plain arrays instead of
// hash tables keyed by handles. The index of an item is its slot number, the
// one `Compact_container::operator[]` takes: it stays the same while the item
// lives, and a freed slot's number is given to the next item stored there.
//
// `Compact_container::index()` scans every block (O(sqrt(capacity))). Here the
// blocks are found once through the container's public slot interface and
// kept sorted by address, so a lookup is a binary search over a few hundred
// blocks (or none, when the previous lookup's block holds the item). Blocks
// the container allocates later are found on the first lookup that misses.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_COMPACT_CONTAINER_INDEX_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_COMPACT_CONTAINER_INDEX_H

#include <CGAL/Compact_container.h>
#include <CGAL/assertions.h>
#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The rule for block sizes of a Compact_container (a private type of it).
template <class Container>
struct Increment_policy_of;
template <class T, class Allocator, class Policy, class Stamper>
struct Increment_policy_of<Compact_container<T, Allocator, Policy, Stamper>>
{
  typedef typename Default::Get<Policy, Addition_size_policy<CGAL_INIT_COMPACT_CONTAINER_BLOCK_SIZE,
                                                             CGAL_INCREMENT_COMPACT_CONTAINER_BLOCK_SIZE>>::type type;
};

template <class Container>
class Compact_container_index
{
public:
  typedef typename Container::value_type Item;
  typedef typename Container::size_type size_type;

  explicit Compact_container_index(const Container& items) : items_(items) {}

  /// The slot number of the live item `p`.
  std::size_t index(const Item* p)
  {
    if(!blocks_.empty())
    {
      const Block& b = blocks_[last_];
      if(b.first <= p && p < b.first + b.size) return b.first_index + std::size_t(p - b.first);
      if(const Block* found = block_of(p)) return found->first_index + std::size_t(p - found->first);
    }
    find_new_blocks();
    const Block* found = block_of(p);
    CGAL_assertion_msg(found != nullptr, "the item is not in the container");
    return found->first_index + std::size_t(p - found->first);
  }

  template <class Handle>
  std::size_t operator()(Handle h) { return index(&*h); }

  /// The live item in slot `k`, or null when the slot is free.
  Item* item(std::size_t k) const
  {
    if(k >= items_.capacity() || !items_.is_used(size_type(k))) return nullptr;
    return const_cast<Item*>(&items_[size_type(k)]);
  }

  /// One more than the largest slot number: the size of a per-item array.
  std::size_t number_of_slots() const { return items_.capacity(); }

private:
  struct Block
  {
    const Item* first; ///< the item in the block's first slot
    std::size_t size;
    std::size_t first_index;
  };

  const Block* block_of(const Item* p)
  {
    // The last block whose first item is not above p, by a binary search
    // without branches on the data (the lookups come in no predictable order).
    const Block* base = blocks_.data();
    std::size_t n = blocks_.size();
    if(p < base->first) return nullptr;
    while(n > 1)
    {
      const std::size_t half = n / 2;
      base = (base[half].first <= p) ? base + half : base;
      n -= half;
    }
    if(p >= base->first + base->size) return nullptr;
    last_ = std::size_t(base - blocks_.data());
    return base;
  }

  /// Adds every block not known yet that has a live item (a block without
  /// one holds nothing to look up).
  void find_new_blocks()
  {
    const std::size_t capacity = items_.capacity();
    bool added = false;
    for(std::size_t start = 0; start < capacity;)
    {
      const std::size_t end = block_end(start, capacity);
      const std::size_t block = block_number(start);
      if(block >= known_.size()) known_.resize(block + 1, false);
      if(!known_[block])
        for(std::size_t k = start; k < end; ++k)
          if(items_.is_used(size_type(k)))
          {
            blocks_.push_back({&items_[size_type(k)] - (k - start), end - start, start});
            known_[block] = true;
            added = true;
            break;
          }
      start = end;
    }
    if(added)
    {
      std::sort(blocks_.begin(), blocks_.end(), [](const Block& a, const Block& b) { return a.first < b.first; });
      last_ = 0;
    }
  }

  /// One past the last slot of the block that starts at slot `start`, from
  /// the container's own rule for block sizes.
  std::size_t block_end(std::size_t start, std::size_t capacity) const
  {
    const std::size_t block = block_number(start);
    // Blocks only grow, so the first slot of another block is found by doubling, then halving.
    std::size_t step = 1, inside = start;
    while(inside + step < capacity && block_number(inside + step) == block)
    {
      inside += step;
      step *= 2;
    }
    for(; step > 0; step /= 2)
      if(inside + step < capacity && block_number(inside + step) == block) inside += step;
    return inside + 1;
  }

  static std::size_t block_number(std::size_t k)
  {
    size_type in_block = 0, block = 0;
    Increment_policy_of<Container>::type::template get_index_and_block<Container>(size_type(k), in_block, block);
    return std::size_t(block);
  }

  const Container& items_;
  std::vector<Block> blocks_;            // sorted by address
  std::vector<bool> known_; // by block number
  std::size_t last_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_COMPACT_CONTAINER_INDEX_H
