// One cycle's list of interior facets. A flip reuses or frees cells, so a facet
// is kept as its cell and its three vertices and found again when its turn
// comes: the cell is checked in O(1) (still in use, still holding the three
// vertices), else the facet is looked up around its first vertex.

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
  typename Tr::Cell_handle cell;
  typename Tr::Vertex_handle u, v, w;
};

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
      out.push_back({c, c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)});
    }
  if(order == RANDOM_ORDER)
    for(std::size_t k = out.size(); k > 1; --k)
      std::swap(out[k - 1], out[std::size_t(rng.get_int(0, int(k)))]);
}

/// Finds the facet again; false if it no longer exists.
template <class Tr>
bool find_facet(const Tr& tr, const Facet_key<Tr>& key, typename Tr::Cell_handle& c, int& i)
{
  c = key.cell;
  int a, b, d;
  if(tr.tds().cells().is_used(c) && c->has_vertex(key.u, a) && c->has_vertex(key.v, b) &&
     c->has_vertex(key.w, d))
  {
    i = 6 - a - b - d;
    return true;
  }
  if(!tr.is_facet(key.u, key.v, key.w, c, a, b, d)) return false;
  i = 6 - a - b - d;
  return true;
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_FACET_SWEEP_H
