// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's cycles, the facets made during a cycle visited in it.
//
// A cycle is a sweep through a total order of vertex triples: the fixed
// order (priority), or one drawn for the cycle (random: the priority of a
// seed made from the run's seed and the cycle's number). A facet is visited
// when the sweep reaches its place if it exists then, whether it was there
// when the cycle began or a flip made it since; one whose place the sweep
// has passed waits for the next cycle. A triple has one place, so a cycle
// visits it at most once and ends.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_SAME_CYCLE_SWEEPS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_SAME_CYCLE_SWEEPS_H

#include <CGAL/Edge_swapping_3/internal/paper_cycles.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The paper's cycles in which the facets a flip makes are visited in the
/// same cycle (the reading MADE_FACETS_SAME_CYCLE).
template <class Derived, class Base>
class Same_cycle_sweeps : public Base
{
protected:
  CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES
  CGAL_EDGE_SWAPPING_3_DRIVER_VISITS_NAMES
  CGAL_EDGE_SWAPPING_3_LOOP_DETECTION_NAMES

  Same_cycle_sweeps(Tr& tr, const Driver_settings& settings) : Base(tr, settings) {}

  /// After a flip: the cells it made, for the sweep to place their facets.
  void sweeps_after_flip(const std::array<Cell_handle, 4>& created, int n)
  {
    if(sweeping_) made_.assign(created.begin(), created.begin() + n);
  }

  struct Sweep_place
  {
    std::uint64_t priority;
    std::array<Vertex_handle, 3> v; // by their points, lexicographically
  };

  Sweep_place sweep_place(std::uint64_t seed, Cell_handle c, int i) const
  {
    Sweep_place p;
    for(int k = 0; k < 3; ++k) p.v[k] = c->vertex((i + 1 + k) & 3);
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    std::sort(p.v.begin(), p.v.end(), [&](Vertex_handle a, Vertex_handle b) {
      return compare(bare_point(a->point()), bare_point(b->point())) == SMALLER;
    });
    p.priority = facet_priority(seed, bare_point(p.v[0]->point()), bare_point(p.v[1]->point()),
                                bare_point(p.v[2]->point()));
    return p;
  }

  bool comes_before(const Sweep_place& a, const Sweep_place& b) const
  {
    if(a.priority != b.priority) return a.priority < b.priority;
    const auto compare = tr_.geom_traits().compare_xyz_3_object();
    for(int k = 0; k < 3; ++k)
      if(a.v[k] != b.v[k]) return compare(bare_point(a.v[k]->point()), bare_point(b.v[k]->point())) == SMALLER;
    return false;
  }

  template <class Rule>
  Swap_report run_sweeps(Rule& visit)
  {
    if(settings_.face_order == STORAGE_ORDER)
      throw std::invalid_argument("Edge_swapping_3: visiting the facets made during a cycle in it needs the "
                                  "priority or the random face order");
    queueing_ = false;
    sweeping_ = true;
    Swap_report report;
    report.ending = CYCLE_LIMIT_REACHED;
    auto before = [this](const Sweep_place& a, const Sweep_place& b) { return comes_before(a, b); };
    for(std::size_t round = 1; round <= settings_.max_rounds; ++round)
    {
      record_ = Cycle_record();
      record_.cycle = round;
      begin_cycle_tags();
      const std::uint64_t seed = settings_.face_order == RANDOM_ORDER
                                   ? random_sweep_seed(settings_.random_seed, round)
                                   : std::uint64_t(settings_.random_seed);
      std::set<Sweep_place, decltype(before)> ahead(before);
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(holds_facet(tr_, c, i)) ahead.insert(sweep_place(seed, c, i));
      while(!ahead.empty())
      {
        const Sweep_place place = *ahead.begin();
        ahead.erase(ahead.begin());
        Cell_handle c;
        int i;
        std::array<Vertex_handle, 3> v = place.v;
        std::sort(v.begin(), v.end(), [](Vertex_handle a, Vertex_handle b) { return address_of(a) < address_of(b); });
        if(!find_facet(tr_, Key{v[0], v[1], v[2]}, Cell_handle(), c, i)) continue; // destroyed
        if(tr_.is_infinite(c) || tr_.is_infinite(c->neighbor(i))) continue;
        if(!holds_facet(tr_, c, i))
        {
          const Cell_handle n = c->neighbor(i);
          i = n->index(c);
          c = n;
        }
        made_.clear();
        visit_facet(visit, c, i);
        for(Cell_handle m : made_)
          for(int j = 0; j < 4; ++j)
            if(holds_facet(tr_, m, j))
            {
              const Sweep_place p = sweep_place(seed, m, j);
              if(comes_before(place, p)) ahead.insert(p);
            }
      }
      end_round(report);
      if(cycle_ends_run())
      {
        report.ending = CONVERGED;
        break;
      }
      if(skip_repeats_) round = skip_repeated_cycles(report, round);
    }
    sweeping_ = false;
    return report;
  }

  bool sweeping_ = false;          // run_sweeps: a flip lists the cells it made in made_
  std::vector<Cell_handle> made_;
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_SAME_CYCLE_SWEEPS_H
