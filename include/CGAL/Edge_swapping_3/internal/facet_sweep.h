// One cycle's list of interior facets. A flip reuses or frees cells, so a facet
// is kept as its two cells and its three vertices and found again when its
// turn comes, in those cells or their neighbours (O(1) checks). A facet that
// is not there was destroyed by a flip (or destroyed and made again): like
// every facet a flip creates, it waits for the next cycle. A cycle that makes
// no swap therefore still visits every facet, so the endings are exact.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SWEEP_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SWEEP_H

#include <CGAL/Random.h>
#include <CGAL/Edge_swapping_3/Swap_options.h>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

template <class Tr>
struct Facet_key
{
  typename Tr::Cell_handle cell, other;
  typename Tr::Vertex_handle u, v, w;
};

/// A random permutation that keeps memory locality: the list is cut into
/// blocks of neighbouring facets, the blocks are shuffled, and so is each block.
template <class T>
void shuffle_in_blocks(std::vector<T>& v, CGAL::Random& rng, std::size_t block = 512)
{
  auto shuffle = [&rng](auto first, std::size_t n) {
    for(std::size_t k = n; k > 1; --k) std::swap(first[k - 1], first[std::size_t(rng.get_int(0, int(k)))]);
  };
  const std::size_t blocks = (v.size() + block - 1) / block;
  std::vector<std::size_t> order(blocks);
  for(std::size_t b = 0; b < blocks; ++b) order[b] = b;
  shuffle(order.begin(), blocks);
  std::vector<T> shuffled;
  shuffled.reserve(v.size());
  for(std::size_t b : order)
  {
    const std::size_t first = b * block, n = (std::min)(block, v.size() - first);
    const std::size_t start = shuffled.size();
    shuffled.insert(shuffled.end(), v.begin() + std::ptrdiff_t(first), v.begin() + std::ptrdiff_t(first + n));
    shuffle(shuffled.begin() + std::ptrdiff_t(start), n);
  }
  v.swap(shuffled);
}

/// The interior facets of `tr`, each once, in storage order or shuffled.
/// Of the two cells of a facet, the one whose opposite vertex is
/// lexicographically smaller holds it: the choice never depends on addresses.
template <class Tr>
void collect_interior_facets(const Tr& tr, Face_order order, CGAL::Random& rng,
                             std::vector<Facet_key<Tr>>& out)
{
  out.clear();
  out.reserve(2 * tr.number_of_cells());
  auto compare_xyz = tr.geom_traits().compare_xyz_3_object();
  for(auto c : tr.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      const auto n = c->neighbor(i);
      if(tr.is_infinite(n)) continue;
      const auto m = n->vertex(n->index(c));
      if(compare_xyz(c->vertex(i)->point(), m->point()) != SMALLER) continue;
      out.push_back({c, n, c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)});
    }
  if(order == RANDOM_ORDER)
    shuffle_in_blocks(out, rng);
}

/// Finds the facet again in the cells it was between or their neighbours;
/// false if it is not there (see above).
template <class Tr>
bool find_facet(const Tr& tr, const Facet_key<Tr>& key, typename Tr::Cell_handle& c, int& i)
{
  auto holds = [&](typename Tr::Cell_handle d) {
    int a, b, e;
    if(!d->has_vertex(key.u, a) || !d->has_vertex(key.v, b) || !d->has_vertex(key.w, e)) return false;
    c = d;
    i = 6 - a - b - e;
    return true;
  };
  const auto& cells = tr.tds().cells();
  for(auto d : {key.cell, key.other})
    if(cells.is_used(d) && holds(d)) return true;
  for(auto d : {key.cell, key.other})
    if(cells.is_used(d))
      for(int k = 0; k < 4; ++k)
        if(holds(d->neighbor(k))) return true;
  return false;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SWEEP_H
