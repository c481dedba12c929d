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

/// The order of a cycle's visit, as blocks of `block` neighbouring facets:
/// in storage order, the blocks in order; in random order (a permutation that
/// keeps memory locality), the blocks shuffled and each block shuffled in place.
template <class T>
std::vector<std::size_t> visiting_blocks(std::vector<T>& facets, Face_order order, CGAL::Random& rng,
                                         std::size_t block)
{
  auto shuffle = [&rng](auto first, std::size_t n) {
    for(std::size_t k = n; k > 1; --k) std::swap(first[k - 1], first[std::size_t(rng.get_int(0, int(k)))]);
  };
  std::vector<std::size_t> blocks((facets.size() + block - 1) / block);
  for(std::size_t b = 0; b < blocks.size(); ++b) blocks[b] = b;
  if(order == RANDOM_ORDER)
  {
    shuffle(blocks.begin(), blocks.size());
    for(std::size_t b : blocks)
      shuffle(facets.begin() + std::ptrdiff_t(b * block), (std::min)(block, facets.size() - b * block));
  }
  return blocks;
}

/// The interior facets of `tr`, each once, in storage order.
/// Of the two cells of a facet, the one whose opposite vertex is
/// lexicographically smaller holds it: the choice never depends on addresses.
template <class Tr>
void collect_interior_facets(const Tr& tr, std::vector<Facet_key<Tr>>& out)
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
