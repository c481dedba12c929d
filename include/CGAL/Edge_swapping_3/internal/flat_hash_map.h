// A hash map with open addressing (linear probing, deletion by backward
// shift) for the drivers' per-cell and per-facet state. Node-based maps
// allocate on every insertion; a driver inserts and erases a few dozen keys
// per flip, so their allocations dominated its time. Debian 12's Boost (1.74)
// has no flat map, hence this one. Iteration order is never used for a decision.

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
    std::fill(used_.begin(), used_.end(), std::uint8_t(0));
    size_ = 0;
  }

  Value* find(const Key& key)
  {
    if(size_ == 0) return nullptr;
    for(std::size_t s = slot_of(key);; s = (s + 1) & mask_)
    {
      if(!used_[s]) return nullptr;
      if(slots_[s].first == key) return &slots_[s].second;
    }
  }
  const Value* find(const Key& key) const { return const_cast<Flat_hash_map*>(this)->find(key); }
  bool contains(const Key& key) const { return find(key) != nullptr; }

  /// Inserts `(key, value)` if `key` is absent; returns the stored value and whether it was inserted.
  std::pair<Value*, bool> emplace(const Key& key, const Value& value)
  {
    if(4 * (size_ + 1) > 3 * slots_.size()) grow(); // load at most 3/4
    std::size_t s = slot_of(key);
    for(; used_[s]; s = (s + 1) & mask_)
      if(slots_[s].first == key) return {&slots_[s].second, false};
    used_[s] = 1;
    slots_[s] = {key, value};
    ++size_;
    return {&slots_[s].second, true};
  }

  Value& operator[](const Key& key) { return *emplace(key, Value()).first; }

  bool erase(const Key& key)
  {
    if(size_ == 0) return false;
    std::size_t s = slot_of(key);
    for(; used_[s]; s = (s + 1) & mask_)
      if(slots_[s].first == key) break;
    if(!used_[s]) return false;
    // Backward shift: move later entries of the run into the hole when their home allows.
    for(std::size_t next = (s + 1) & mask_; used_[next]; next = (next + 1) & mask_)
    {
      const std::size_t home = slot_of(slots_[next].first);
      if(((next - home) & mask_) >= ((next - s) & mask_))
      {
        slots_[s] = std::move(slots_[next]);
        s = next;
      }
    }
    used_[s] = 0;
    --size_;
    return true;
  }

  template <class F>
  void for_each(F f) const
  {
    for(std::size_t s = 0; s < slots_.size(); ++s)
      if(used_[s]) f(slots_[s].first, slots_[s].second);
  }

private:
  std::size_t slot_of(const Key& key) const { return std::size_t(mix_bits(Hash()(key))) & mask_; }

  void grow()
  {
    std::vector<std::pair<Key, Value>> old_slots;
    std::vector<std::uint8_t> old_used;
    old_slots.swap(slots_);
    old_used.swap(used_);
    const std::size_t capacity = old_slots.empty() ? 64 : 2 * old_slots.size();
    slots_.resize(capacity);
    used_.assign(capacity, 0);
    mask_ = capacity - 1;
    size_ = 0;
    for(std::size_t s = 0; s < old_slots.size(); ++s)
      if(old_used[s]) emplace(old_slots[s].first, old_slots[s].second);
  }

  std::vector<std::pair<Key, Value>> slots_;
  std::vector<std::uint8_t> used_;
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

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FLAT_HASH_MAP_H
