// SPDX-License-Identifier: GPL-3.0-or-later
// The cells whose quality operations a change may have changed: what the
// quality driver queues again after an operation.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_CHANGE_NEIGHBOURHOOD_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_CHANGE_NEIGHBOURHOOD_H

#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Removes the repeated items of `items`, keeping each first occurrence in
/// place: the order stays the order met, which no address decides.
template <class Handle>
void keep_first_occurrences(std::vector<Handle>& items)
{
  std::vector<std::pair<Handle, std::size_t>> sorted;
  sorted.reserve(items.size());
  for(std::size_t k = 0; k < items.size(); ++k) sorted.emplace_back(items[k], k);
  std::sort(sorted.begin(), sorted.end());
  std::vector<bool> keep(items.size(), false);
  for(std::size_t k = 0; k < sorted.size(); ++k)
    if(k == 0 || !(sorted[k].first == sorted[k - 1].first)) keep[sorted[k].second] = true;
  std::size_t n = 0;
  for(std::size_t k = 0; k < items.size(); ++k)
    if(keep[k]) items[n++] = items[k];
  items.resize(n);
}

/// The cells around new cells whose operations may have changed (the new
/// cells themselves are not listed; a cell may be listed more than once).
/// With edge removal alone: those sharing an edge with a new cell (the ring
/// of that edge changed). With multi-face removal: a sandwich at a facet of
/// a cell reads cells around the two vertices off that facet, no more than
/// the ring limit + 1 steps away through facets around that vertex, from
/// the cell or from its neighbour across the facet. So for each vertex v of
/// a new cell, the cells around v within the ring limit + 2 such steps of a
/// new cell, and their neighbours (a walk, not the whole star: a vertex of a
/// placing triangulation has thousands of cells). The scratch storage is
/// kept between calls.
template <class Tr>
class Change_neighbourhood
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;

  explicit Change_neighbourhood(const Tr& tr) : tr_(tr) {}

  const std::vector<Cell_handle>& operator()(const std::vector<Cell_handle>& created, bool multi_face_removal,
                                             int maximum_ring)
  {
    around_.clear();
    if(multi_face_removal) walk_around_corners(created, maximum_ring);
    else
      for(Cell_handle c : created)
      {
        if(tr_.is_infinite(c)) continue;
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j)
          {
            auto circ = tr_.incident_cells(c, i, j), done = circ;
            do around_.push_back(circ);
            while(++circ != done);
          }
      }
    return around_;
  }

private:
  void walk_around_corners(const std::vector<Cell_handle>& created, int maximum_ring)
  {
    corners_.clear();
    for(Cell_handle c : created)
      for(int i = 0; i < 4; ++i)
        if(!tr_.is_infinite(c->vertex(i))) corners_.push_back(c->vertex(i));
    keep_first_occurrences(corners_);
    for(Vertex_handle v : corners_)
    {
      // Breadth first from the new cells around v, through facets around v.
      walk_.clear();
      seen_.clear();
      for(Cell_handle c : created)
        if(c->has_vertex(v) && seen_.insert(c)) walk_.emplace_back(c, 0);
      for(std::size_t k = 0; k < walk_.size(); ++k)
      {
        const auto [c, depth] = walk_[k];
        around_.push_back(c);
        for(int i = 0; i < 4; ++i)
        {
          // A neighbour through v is walked, and so listed, unless the
          // walk ends here or has been there.
          const Cell_handle n = c->neighbor(i);
          if(c->vertex(i) == v || depth == maximum_ring + 2) around_.push_back(n);
          else if(seen_.insert(n)) walk_.emplace_back(n, depth + 1);
        }
      }
    }
  }

  const Tr& tr_;
  std::vector<Cell_handle> around_;
  std::vector<Vertex_handle> corners_;
  std::vector<std::pair<Cell_handle, int>> walk_;
  Flat_hash_set<Cell_handle, Handle_hash> seen_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_OPTIMIZER_CHANGE_NEIGHBOURHOOD_H
