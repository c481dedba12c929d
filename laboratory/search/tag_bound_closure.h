// SPDX-License-Identifier: GPL-3.0-or-later
// Whether any order at all can bring the helper strategy from a start to
// CGAL's triangulation, decided without searching orders: a set of
// triangulations, each with a bound on its tags, that holds the start and is
// closed under every visit.
//
// The set I = {(T, B) : T in the closure, B within the bound M(T)} of states
// (cells and tags) is closed when every visit of every interior facet from
// every state of I leads to a state of I. The rule is monotone in the tags,
// so that is checked on (T, M(T)) alone, facet by facet:
//   - not locally Delaunay, no flip: its five points' cells join M(T);
//   - not locally Delaunay, a flip: the flipped T' is in the closure and
//     (M(T) + the five points' cells - the flip's old cells) is within M(T');
//   - locally Delaunay, a flip, and a cell M(T) holds would let it swap (a
//     help swap: the condition of the reading): T' is in the closure and
//     M(T) - the old cells is within M(T').
// A state of I with fewer tags swaps at most where (T, M(T)) does, and sets
// at most the tags it sets. Every run, in any order (fixed, random, chosen by
// an adversary, same-cycle or next-cycle, any ending), visits only facets of
// the state it is in, so it stays in I. If no T of I is CGAL's triangulation,
// no order reaches it from the start. Tags cleared at each cycle are fewer
// tags, so until-destroyed's closure holds cleared-each-cycle's runs too.
//
// Ends under no-swap-no-tag: a cycle that changes nothing starts in a state at
// which every visit is inert. Within I, T has such a state exactly when it has
// no flip of a facet that is not locally Delaunay, the cells of the five
// points of its facets that are not locally Delaunay (the fewest tags such a
// state holds) are within M(T), and with just those tags no help swap is
// allowed (cleared-each-cycle: with no tags, at a cycle's start).
//
// The closure is the least one, found by a worklist from (start, no tags);
// the model is the independent checker's rule (trace_checker.h). Its
// certificate, a JSON file, is checked apart by check_tag_bounds.py.

#ifndef EDGE_SWAPPING_3_LABORATORY_TAG_BOUND_CLOSURE_H
#define EDGE_SWAPPING_3_LABORATORY_TAG_BOUND_CLOSURE_H

#include "trace_checker.h"
#include <map>
#include <queue>
#include <set>
#include <tuple>

namespace tag_bound_closure {

using trace_checker::Cell;
using trace_checker::Checker;

typedef std::set<Cell> Cells;

struct Closure
{
  std::map<Cells, Cells> bounds; ///< each triangulation reached, and the bound on its tags
  bool closed = false;           ///< the worklist emptied within the limit: the set is closed
  std::size_t delaunay = 0;      ///< triangulations of the set that are CGAL's
  std::size_t can_end = 0;       ///< triangulations with a state at which no visit changes anything
  std::size_t passes = 0;        ///< triangulations taken from the worklist
};

namespace internal {

// Whether T has a state within `bound` at which every visit is inert.
inline bool has_inert_state(Checker& model, const Cells& cells, const Cells& bound, bool cleared_each_cycle)
{
  Cells fewest; // the tags every inert state holds
  if(!cleared_each_cycle)
  {
    model.set_state(cells, {});
    for(const auto& f : model.interior_facets())
    {
      const auto [d, e] = model.apexes(f);
      const Checker::Decision r = model.decide(f, d, e);
      if(!r.delaunay) fewest.insert(r.five_cells.begin(), r.five_cells.end());
    }
    for(const Cell& t : fewest)
      if(!bound.count(t)) return false;
  }
  model.set_state(cells, fewest);
  for(const auto& f : model.interior_facets())
  {
    const auto [d, e] = model.apexes(f);
    const Checker::Decision r = model.decide(f, d, e);
    if(r.swap || !r.new_tags.empty()) return false;
  }
  return true;
}

} // namespace internal

/// The least closed set from `start_cells`, under the reading of `model` (a
/// checker of the points, in any state), within `max_triangulations`. With
/// `stop_at_delaunay` the search stops as soon as CGAL's triangulation joins
/// the set (then `delaunay` is 1 and `closed` false): enough to tell that the
/// start is no trap, and the cheap answer for the many starts that are not.
/// It then takes the triangulations with the fewest facets that are not
/// locally Delaunay first; the least set is the same in any order, only the
/// way there differs.
inline Closure search(Checker model, const Cells& start_cells, std::size_t max_triangulations,
                      bool stop_at_delaunay = false)
{
  model.set_state(start_cells, {});
  Checker probe = model; // counts a new triangulation's facets that are not locally Delaunay
  const bool tags_outlive_cells = model.tags_outlive_cells();
  const bool cleared_each_cycle = model.clears_tags_each_cycle();
  Closure result;
  // The worklist: (priority, arrival, triangulation); map keys do not move.
  typedef std::tuple<std::size_t, std::size_t, const Cells*> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> work;
  std::set<const Cells*> waiting;
  std::size_t arrivals = 0;
  auto priority = [&](const Cells& cells) -> std::size_t {
    if(!stop_at_delaunay) return 0; // first in, first out
    probe.set_state(cells, {});
    return probe.facets_not_delaunay();
  };
  if(stop_at_delaunay)
  {
    // Plain swapping first: a facet that is not locally Delaunay swaps
    // wherever it has a flip, under every reading and with any tags, so its
    // runs stay in the set; and they end, since each flip lowers the lifted
    // triangulation. Most starts are seen to be no traps this way.
    for(bool flipped = true; flipped;)
    {
      flipped = false;
      for(const auto& f : probe.interior_facets())
      {
        const auto [d, e] = probe.apexes(f);
        const Checker::Decision r = probe.decide(f, d, e);
        if(r.delaunay || !r.swap) continue;
        probe.flip(r);
        flipped = true;
        break;
      }
    }
    if(probe.is_delaunay())
    {
      result.delaunay = 1;
      return result;
    }
  }
  std::map<const Cells*, std::size_t> rank; // each triangulation's priority
  const Cells* start = &result.bounds.try_emplace(model.cells(), model.tags()).first->first;
  rank[start] = priority(*start);
  work.emplace(rank[start], arrivals++, start);
  waiting.insert(start);
  while(!work.empty())
  {
    const Cells& cells = *std::get<2>(work.top());
    work.pop();
    waiting.erase(&cells);
    ++result.passes;
    // Until the bound of T stops growing: each visit from (T, M(T)).
    for(bool grew = true; grew;)
    {
      grew = false;
      const Cells bound = result.bounds.at(cells);
      model.set_state(cells, bound);
      std::vector<std::pair<Cells, Cells>> flipped;
      for(const auto& f : model.interior_facets())
      {
        const auto [d, e] = model.apexes(f);
        const Checker::Decision r = model.decide(f, d, e);
        if(!r.swap)
        {
          if(!r.new_tags.empty())
          {
            result.bounds[cells].insert(r.new_tags.begin(), r.new_tags.end());
            grew = true;
          }
          continue;
        }
        Cells tags = bound, after = cells;
        tags.insert(r.new_tags.begin(), r.new_tags.end());
        for(const Cell& t : r.old_cells)
        {
          after.erase(t);
          if(!tags_outlive_cells) tags.erase(t);
        }
        after.insert(r.new_cells.begin(), r.new_cells.end());
        flipped.emplace_back(std::move(after), std::move(tags));
      }
      for(const auto& [after, tags] : flipped)
      {
        auto [it, added] = result.bounds.try_emplace(after);
        const std::size_t before = it->second.size();
        it->second.insert(tags.begin(), tags.end());
        if(!added && it->second.size() == before) continue; // nothing new
        if(added) rank[&it->first] = priority(it->first);
        if(stop_at_delaunay && rank[&it->first] == 0)
        {
          result.delaunay = 1;
          return result;
        }
        if(waiting.insert(&it->first).second) work.emplace(rank[&it->first], arrivals++, &it->first);
      }
    }
    if(result.bounds.size() > max_triangulations) break;
  }
  result.closed = work.empty();
  for(const auto& [cells, bound] : result.bounds)
  {
    model.set_state(cells, {});
    result.delaunay += model.is_delaunay();
    if(result.closed) result.can_end += internal::has_inert_state(model, cells, bound, cleared_each_cycle);
  }
  return result;
}

/// The same from the start of `header` (a trace header: points, cells, reading).
inline Closure search(const nlohmann::json& header, std::size_t max_triangulations, bool stop_at_delaunay = false)
{
  Checker model(header); // checks the points and the start
  const Cells start = model.cells();
  return search(std::move(model), start, max_triangulations, stop_at_delaunay);
}

/// The certificate of a closed set, for check_tag_bounds.py: the points, the
/// start, and each triangulation with its tag bound (cells as sorted point numbers).
inline nlohmann::json certificate(const nlohmann::json& header, const Closure& closure)
{
  auto cell_list = [](const Cells& cells) {
    nlohmann::json out = nlohmann::json::array();
    for(const Cell& t : cells) out.push_back({t[0], t[1], t[2], t[3]});
    return out;
  };
  nlohmann::json triangulations = nlohmann::json::array();
  for(const auto& [cells, bound] : closure.bounds)
    triangulations.push_back({{"cells", cell_list(cells)}, {"tag_bound", cell_list(bound)}});
  const Checker model(header);
  return {{"format", "Edge_swapping_3 tag-bound certificate"},
          {"version", 1},
          {"reading", header.at("reading")},
          {"points", header.at("points")},
          {"start", cell_list(model.cells())},
          {"triangulations", triangulations}};
}

} // namespace tag_bound_closure

#endif // EDGE_SWAPPING_3_LABORATORY_TAG_BOUND_CLOSURE_H
