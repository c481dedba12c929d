// SPDX-License-Identifier: GPL-3.0-or-later
// A facet named by its three vertices, so that it can be found again after
// flips have reused the cells that held it. The vertices are kept in address
// order: addresses serve hashing and equality only, never a decision.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_KEY_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_KEY_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Handle>
std::uintptr_t address_of(Handle h)
{
  return reinterpret_cast<std::uintptr_t>(&*h);
}

inline std::uint64_t rotate_left(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }

/// Hash of a handle by its address (for driver storage indexed by cell or
/// vertex); the tables mix the bits.
struct Handle_hash
{
  template <class Handle>
  std::size_t operator()(Handle h) const { return std::size_t(address_of(h)); }
};

template <class Tr>
struct Facet_key
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  Vertex_handle u, v, w; ///< address order

  friend bool operator==(const Facet_key& a, const Facet_key& b) { return a.u == b.u && a.v == b.v && a.w == b.w; }
};

template <class Tr>
Facet_key<Tr> facet_key(typename Tr::Cell_handle c, int i)
{
  std::array<typename Tr::Vertex_handle, 3> t = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                                                 c->vertex((i + 3) & 3)};
  auto less = [](typename Tr::Vertex_handle a, typename Tr::Vertex_handle b) { return address_of(a) < address_of(b); };
  std::sort(t.begin(), t.end(), less);
  return {t[0], t[1], t[2]};
}

struct Facet_key_hash
{
  template <class Key>
  std::size_t operator()(const Key& k) const
  {
    return std::size_t(address_of(k.u) ^ rotate_left(address_of(k.v), 21) ^ rotate_left(address_of(k.w), 42));
  }
};

/// An edge named by its two vertices in address order.
template <class Tr>
struct Edge_key
{
  typename Tr::Vertex_handle a, b;
  friend bool operator==(const Edge_key& x, const Edge_key& y) { return x.a == y.a && x.b == y.b; }
};

template <class Tr>
Edge_key<Tr> edge_key(typename Tr::Vertex_handle a, typename Tr::Vertex_handle b)
{
  if(address_of(b) < address_of(a)) std::swap(a, b);
  return {a, b};
}

struct Edge_key_hash
{
  template <class Key>
  std::size_t operator()(const Key& k) const
  {
    return std::size_t(address_of(k.a) ^ rotate_left(address_of(k.b), 32));
  }
};

/// Finds facet `key` in the triangulation, exactly: first in the `hint` cell
/// (one that held it once) and its neighbours (the usual case, O(1)), else
/// among the cells around its first vertex. False exactly when no cell of
/// `tr` has the three vertices.
template <class Tr>
bool find_facet(const Tr& tr, const Facet_key<Tr>& key, typename Tr::Cell_handle hint,
                typename Tr::Cell_handle& c, int& i)
{
  auto holds = [&](typename Tr::Cell_handle d) {
    int a, b, e;
    if(!d->has_vertex(key.u, a) || !d->has_vertex(key.v, b) || !d->has_vertex(key.w, e)) return false;
    c = d;
    i = 6 - a - b - e;
    return true;
  };
  const auto& cells = tr.tds().cells();
  if(hint != typename Tr::Cell_handle() && cells.is_used(hint))
  {
    if(holds(hint)) return true;
    for(int k = 0; k < 4; ++k)
      if(holds(hint->neighbor(k))) return true;
  }
  int a, b, e;
  if(!tr.tds().is_facet(key.u, key.v, key.w, c, a, b, e)) return false;
  i = 6 - a - b - e;
  return true;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_KEY_H
