// SPDX-License-Identifier: GPL-3.0-or-later
// The Delaunay repair: from where plain flips (Algorithm 3 with the
// Delaunay criterion) are stuck, the helper strategy (Algorithm 4) in runs
// that alternate with plain flips, then, if that has not converged, the
// cells rebuilt by flip insertion of the vertices (the paper's, which ends
// on Delaunay by Joe's 1991 theorem; with CGAL's perturbation it gives
// CGAL's cells, as the tests check). It sits above the drivers and flip
// insertion, and `swap_edges` calls it for a Delaunay criterion.
//
// The rebuild inserts into a second triangulation, whose cells are then
// moved into `tr` onto its own vertices: only the old vertices, the new
// triangulation and arrays of a few words per vertex are held at once.

#ifndef CGAL_EDGE_SWAPPING_3_DELAUNAY_REPAIR_H
#define CGAL_EDGE_SWAPPING_3_DELAUNAY_REPAIR_H

#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/swap_rules.h>
#include <algorithm>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Returns the number of finite cells made. `tr` must be of dimension 3 and
/// its points distinct (a valid triangulation), so no vertex is lost. If an
/// exception is thrown, `tr` is left without cells. Should flip insertion
/// leave a facet stuck, its triangulation (valid, not Delaunay) is kept all
/// the same: the caller counts what is not Delaunay and says so.
template <class Tr>
std::size_t rebuild_as_delaunay(Tr& tr)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  std::vector<Vertex_handle> vertices;
  vertices.reserve(tr.number_of_vertices());
  for(Vertex_handle v : tr.finite_vertex_handles()) vertices.push_back(v);
  tr.tds().cells().clear();
  {
    Tr built(tr.geom_traits());
    std::vector<Vertex_handle> made; // made[k] in `built` is vertices[k]
    {
      std::vector<typename Tr::Point> points;
      points.reserve(vertices.size());
      for(Vertex_handle v : vertices) points.push_back(v->point());
      made = delaunay_by_insertion(built, points).vertices;
    }
    CGAL_assertion(built.dimension() == 3 && made.size() == vertices.size());
    {
      // Each vertex of `built` by its slot number, replaced by ours.
      Compact_container_index<typename Tr::Triangulation_data_structure::Vertex_range> index(built.tds().vertices());
      std::vector<Vertex_handle> ours(index.number_of_slots());
      for(std::size_t k = 0; k < made.size(); ++k) ours[index(made[k])] = vertices[k];
      ours[index(built.infinite_vertex())] = tr.infinite_vertex();
      made = {};
      for(auto c : built.tds().cell_handles())
        for(int i = 0; i < 4; ++i)
        {
          const Vertex_handle v = ours[index(c->vertex(i))];
          c->set_vertex(i, v);
          v->set_cell(c);
        }
      tr.tds().cells().swap(built.tds().cells()); // `built` goes with its vertices alone
    }
  }
  return tr.number_of_finite_cells();
}

/// The Delaunay repair from a run of plain flips that did not converge
/// (`report`, with the facets left not locally Delaunay in `stuck`):
/// `plain_flips(seeds, scanned, stuck)` runs plain flips again, as
/// `swap_edges` does; `lawson` says whether it makes the common flips itself
/// (then the helper runs in bursts between them). `report` is completed:
/// the path, the helper's rounds, the rounds appended, the ending.
template <class Tr, class Constraints, class NamedParameters, class PlainFlips>
void repair_to_delaunay(Tr& tr, Swap_report& report, std::vector<Facet_key<Tr>>& stuck, PlainFlips plain_flips,
                        bool lawson, const Driver_settings& s, const Constraints& constraints,
                        const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::vector<std::pair<typename Tr::Cell_handle, int>> Facets;
  // Stuck (or out of rounds): the helper, then the rebuild.
  report.stuck_after_plain_flips = report.non_delaunay_facets;
  report.first_helper_round = report.cycles.size() + 1;
  Driver_settings hs = driver_settings(np, RANDOM_ORDER);
  const std::size_t helper_rounds =
      choose_parameter(get_parameter(np, internal_np::helper_rounds_before_rebuild), std::size_t(100));
  auto append = [&](const Swap_report& part) {
    for(Cycle_record r : part.cycles)
    {
      r.cycle += report.cycles.size();
      report.cycles.push_back(r);
    }
    report.ending = part.ending;
    report.non_delaunay_facets = part.non_delaunay_facets;
  };
  // Without tags the helper does nothing on a Delaunay facet: its first
  // round needs only the facets plain flips left. With the common flips,
  // the helper runs two rounds (one tags, one swaps), then plain flips
  // until they are stuck again (the helper's own plain swaps cost several
  // times more), then the helper for twice as many rounds, and so on:
  // plain flips can undo what a short helper run did (its tags are lost).
  for(std::size_t burst = 2; report.helper_rounds < helper_rounds; burst *= 2)
  {
    hs.max_rounds = helper_rounds - report.helper_rounds;
    if(lawson) hs.max_rounds = (std::min)(hs.max_rounds, burst);
    std::vector<Facet_key<Tr>> left;
    const Swap_report helper = run_helper(tr, hs, constraints, np, stuck, &left);
    report.helper_rounds += helper.number_of_cycles();
    report.repair_path = HELPER_FLIPS;
    append(helper);
    if(report.ending == CONVERGED || !lawson || helper.number_of_cycles() == 0) break;
    Facets seeds;
    for(const auto& key : left)
    {
      typename Tr::Cell_handle c;
      int i;
      if(find_facet(tr, key, typename Tr::Cell_handle(), c, i)) seeds.emplace_back(c, i);
    }
    stuck.clear();
    const std::size_t n_seeds = seeds.size();
    report.repair_path = PLAIN_FLIPS_AFTER_HELPER;
    append(plain_flips(&seeds, n_seeds, stuck));
    if(report.ending == CONVERGED) break;
    ++hs.random_seed; // another order next time
  }
  // A domain mesh is never rebuilt: the rebuild knows no constraint.
  if(report.ending != CONVERGED && std::is_same<Constraints, No_constraints>::value)
  {
    report.repair_path = REBUILT;
    report.rebuilt_cells = rebuild_as_delaunay(tr);
    // Flip insertion ends on Delaunay (Joe 1991); counted, not assumed.
    report.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr, s.perturbation);
    report.ending = report.non_delaunay_facets == 0 ? CONVERGED : STUCK;
  }
}

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_DELAUNAY_REPAIR_H
