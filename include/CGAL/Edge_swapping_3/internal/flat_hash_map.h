// SPDX-License-Identifier: GPL-3.0-or-later
// A hash map with open addressing (linear probing, deletion by backward
// shift) for the drivers' per-cell and per-facet state. Node-based maps
// allocate on every insertion; a driver inserts and erases a few dozen keys
// per flip, so their allocations dominated its time. Boost's flat map
// (unordered_flat_map, Boost 1.81) cannot be had beside Debian 12's CGAL:
// libcgal-dev depends on libboost-dev (1.74), which libboost1.81-dev
// conflicts with. `benchmark_library_choices` measures this map beside
// std::unordered_map and Boost 1.74's unordered_map (benchmarks.md).
// Iteration order is never used for a decision.
// A byte per slot holds seven bits of the key's hash (0: empty), so that a
// probe compares keys only on a match: at a load of 3/4 a search for an absent
// key passes about eight slots, and each key compared was a cache miss.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FLAT_HASH_MAP_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FLAT_HASH_MAP_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The finalizer of splitmix64: every input bit reaches every output bit.
inline std::uint64_t mix_bits(std::uint64_t x)
{
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

template <class Key, class Value, class Hash>
class Flat_hash_map
{
public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  void clear()
  {
    if(size_ == 0) return;
    std::fill(tags_.begin(), tags_.end(), std::uint8_t(0));
    size_ = 0;
  }

  Value* find(const Key& key)
  {
    if(size_ == 0) return nullptr;
    const std::uint64_t h = hash_of(key);
    const std::uint8_t tag = tag_of(h);
    for(std::size_t s = std::size_t(h) & mask_;; s = (s + 1) & mask_)
    {
      if(tags_[s] == 0) return nullptr;
      if(tags_[s] == tag && slots_[s].first == key) return &slots_[s].second;
    }
  }
  const Value* find(const Key& key) const { return const_cast<Flat_hash_map*>(this)->find(key); }
  bool contains(const Key& key) const { return find(key) != nullptr; }

  /// Inserts `(key, value)` if `key` is absent; returns the stored value and whether it was inserted.
  std::pair<Value*, bool> emplace(const Key& key, const Value& value)
  {
    if(4 * (size_ + 1) > 3 * slots_.size()) grow(); // load at most 3/4
    const std::uint64_t h = hash_of(key);
    const std::uint8_t tag = tag_of(h);
    std::size_t s = std::size_t(h) & mask_;
    for(; tags_[s] != 0; s = (s + 1) & mask_)
      if(tags_[s] == tag && slots_[s].first == key) return {&slots_[s].second, false};
    tags_[s] = tag;
    slots_[s] = {key, value};
    ++size_;
    return {&slots_[s].second, true};
  }

  Value& operator[](const Key& key) { return *emplace(key, Value()).first; }

  bool erase(const Key& key)
  {
    if(size_ == 0) return false;
    const std::uint64_t h = hash_of(key);
    const std::uint8_t tag = tag_of(h);
    std::size_t s = std::size_t(h) & mask_;
    for(; tags_[s] != 0; s = (s + 1) & mask_)
      if(tags_[s] == tag && slots_[s].first == key) break;
    if(tags_[s] == 0) return false;
    // Backward shift: move later entries of the run into the hole when their home allows.
    for(std::size_t next = (s + 1) & mask_; tags_[next] != 0; next = (next + 1) & mask_)
    {
      const std::size_t home = std::size_t(hash_of(slots_[next].first)) & mask_;
      if(((next - home) & mask_) >= ((next - s) & mask_))
      {
        slots_[s] = std::move(slots_[next]);
        tags_[s] = tags_[next];
        s = next;
      }
    }
    tags_[s] = 0;
    --size_;
    return true;
  }

  template <class F>
  void for_each(F f) const
  {
    for(std::size_t s = 0; s < slots_.size(); ++s)
      if(tags_[s] != 0) f(slots_[s].first, slots_[s].second);
  }

private:
  static std::uint64_t hash_of(const Key& key) { return mix_bits(Hash()(key)); }
  /// Seven high bits of the hash, never 0: the slot comes from the low bits.
  static std::uint8_t tag_of(std::uint64_t h) { return std::uint8_t(0x80 | (h >> 57)); }

  void grow()
  {
    std::vector<std::pair<Key, Value>> old_slots;
    std::vector<std::uint8_t> old_tags;
    old_slots.swap(slots_);
    old_tags.swap(tags_);
    const std::size_t capacity = old_slots.empty() ? 64 : 2 * old_slots.size();
    slots_.resize(capacity);
    tags_.assign(capacity, 0);
    mask_ = capacity - 1;
    size_ = 0;
    for(std::size_t s = 0; s < old_slots.size(); ++s)
      if(old_tags[s] != 0) emplace(old_slots[s].first, old_slots[s].second);
  }

  std::vector<std::pair<Key, Value>> slots_;
  std::vector<std::uint8_t> tags_; ///< 0: empty; else 0x80 and seven bits of the hash
  std::size_t mask_ = 0, size_ = 0;
};

/// A set: a map to nothing.
struct Nothing {};

template <class Key, class Hash>
class Flat_hash_set
{
public:
  bool empty() const { return map_.empty(); }
  std::size_t size() const { return map_.size(); }
  void clear() { map_.clear(); }
  bool insert(const Key& key) { return map_.emplace(key, Nothing()).second; }
  bool erase(const Key& key) { return map_.erase(key); }
  bool contains(const Key& key) const { return map_.contains(key); }
  template <class F>
  void for_each(F f) const { map_.for_each([&](const Key& k, const Nothing&) { f(k); }); }

private:
  Flat_hash_map<Key, Nothing, Hash> map_;
};

/// A set that may contain keys never inserted, never misses one that was: one
/// bit per key (a Bloom filter with one hash), to spare lookups in a large map
/// that most keys are not in. `clear(n)` sizes it for about `n` keys.
template <class Key, class Hash>
class Bit_filter
{
public:
  void clear(std::size_t expected_keys)
  {
    std::size_t words = 64;
    while(64 * words < 8 * expected_keys) words *= 2; // about one bit in eight set
    words_.assign(words, 0);
    set_bits_ = 0;
  }
  void insert(const Key& key)
  {
    if(words_.empty()) clear(1 << 13);
    const std::size_t b = bit_of(key);
    std::uint64_t& word = words_[b / 64];
    const std::uint64_t bit = std::uint64_t(1) << (b % 64);
    if(!(word & bit)) ++set_bits_;
    word |= bit;
  }
  bool is_empty() const { return words_.empty(); }
  /// Whether a sixteenth of the bits are set (as many absent keys pass).
  bool is_crowded() const { return 16 * set_bits_ > 64 * words_.size(); }
  bool contains(const Key& key) const
  {
    if(words_.empty()) return false;
    const std::size_t b = bit_of(key);
    return (words_[b / 64] >> (b % 64)) & 1;
  }

private:
  std::size_t bit_of(const Key& key) const { return std::size_t(mix_bits(Hash()(key))) & (64 * words_.size() - 1); }
  std::vector<std::uint64_t> words_;
  std::size_t set_bits_ = 0;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FLAT_HASH_MAP_H
