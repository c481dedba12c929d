// SPDX-License-Identifier: GPL-3.0-or-later
// Counts the bytes a benchmark holds through operator new, and their peak, so
// that a driver's own memory can be told from the triangulation's. Include in
// one translation unit only: it replaces the global operator new and delete.

#ifndef EDGE_SWAPPING_3_ALLOCATION_COUNTER_H
#define EDGE_SWAPPING_3_ALLOCATION_COUNTER_H

#include <cstddef>
#include <cstdlib>
#include <malloc.h>
#include <new>

namespace allocation_counter {
inline std::size_t current = 0, peak = 0;
inline void reset_peak() { peak = current; }
} // namespace allocation_counter

void* operator new(std::size_t n)
{
  void* p = std::malloc(n);
  if(p == nullptr) throw std::bad_alloc();
  allocation_counter::current += malloc_usable_size(p);
  if(allocation_counter::current > allocation_counter::peak) allocation_counter::peak = allocation_counter::current;
  return p;
}
void operator delete(void* p) noexcept
{
  if(p == nullptr) return;
  allocation_counter::current -= malloc_usable_size(p);
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

#endif
