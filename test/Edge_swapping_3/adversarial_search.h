// SPDX-License-Identifier: GPL-3.0-or-later
// The adversarial order class, searched exactly on small point sets: an
// adversary chooses, in every cycle, the order in which the facets listed at
// the cycle's start are visited (a listed facet that does not exist at its
// turn is passed). From a start triangulation, the search enumerates every
// state (cells and tags) at a cycle's end that some sequence of orders
// reaches, and for each every state the next cycle can end in (depth first
// over the facets not yet visited, states already seen cut off). A cycle with
// no swap (and, with the ending no-swap-no-tag, no new tag) ends the run. A
// loop is a cycle of transitions with a swap on it; the one with the fewest
// swaps is written as a trace (order "adversarial"), which the checker
// certifies by the state that comes back. The rule is the checker's model
// (`Checker::decide` and `apply`), not the drivers'.
//
// With `reduce`, orders that differ only by two neighbouring visits that
// commute are searched once (a partial-order reduction): after visiting h
// from state s, a facet f listed before h is not visited next if h then f and
// f then h, from s, end in the same cells and tags with the same swaps and
// the same new tags. Any order can be rewritten into one the reduced search
// makes, by exchanging such pairs (each exchange puts an earlier-listed facet
// first, so the rewriting ends), with the same end, swaps and activity: the
// ends of a cycle and their fewest swaps are the same, only the order kept
// for each end may differ.

#ifndef EDGE_SWAPPING_3_TEST_ADVERSARIAL_SEARCH_H
#define EDGE_SWAPPING_3_TEST_ADVERSARIAL_SEARCH_H

#include "trace_checker.h"
#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace adversarial_search {

using trace_checker::Cell;
using trace_checker::Checker;
using trace_checker::Facet;

typedef std::pair<std::set<Cell>, std::set<Cell>> State; // cells, tags

struct Transition
{
  std::size_t to;
  std::size_t swaps;
  std::vector<Facet> order; // the visits, in the order the adversary chose
};

struct Search_limit_reached
{
};

// Every end of one cycle from `start` (a model at a cycle's end): the state,
// whether the cycle was idle, its swaps and one order that reaches it.
struct Cycle_search
{
  std::size_t max_nodes;
  bool reduce = false;
  std::size_t nodes = 0;
  std::set<std::tuple<std::set<Cell>, std::set<Cell>, std::vector<Facet>, bool, std::vector<Facet>>> seen;
  std::map<std::pair<State, bool>, std::pair<std::size_t, std::vector<Facet>>> ends; // -> swaps, order
  bool can_end = false;               // some order makes this cycle end the run
  bool can_end_off_delaunay = false;  // ... on a triangulation that is not Delaunay

  struct Step
  {
    bool swap = false, changed = false;
  };

  // One visit of `f` on `m`: passed if `f` is not there.
  static Step visit(Checker& m, const Facet& f)
  {
    if(!m.has_interior_facet(f)) return {};
    const auto [d, e] = m.apexes(f);
    const Checker::Decision r = m.decide(f, d, e);
    m.apply(r);
    // A cycle that only tags ends the run when the reading ends on a cycle without swaps.
    return {r.swap, r.swap || (!r.new_tags.empty() && !m.ends_without_swap())};
  }

  // Whether visiting f and g from `m`, in either order, ends the same.
  static bool commute(const Checker& m, const Facet& f, const Facet& g)
  {
    Checker a = m, b = m;
    const Step a1 = visit(a, f), a2 = visit(a, g);
    const Step b1 = visit(b, g), b2 = visit(b, f);
    return int(a1.swap) + int(a2.swap) == int(b1.swap) + int(b2.swap) &&
           (a1.changed || a2.changed) == (b1.changed || b2.changed) && a.cells() == b.cells() && a.tags() == b.tags();
  }

  // `not_next`: the facets the reduction keeps from being visited next.
  void run(const Checker& m, std::vector<Facet> left, bool busy, std::size_t swaps, std::vector<Facet>& order,
           const std::vector<Facet>& not_next = {})
  {
    if(!seen.insert({m.cells(), m.tags(), left, busy, not_next}).second) return;
    if(++nodes > max_nodes) throw Search_limit_reached();
    if(left.empty())
    {
      if(!busy)
      {
        can_end = true;
        can_end_off_delaunay = can_end_off_delaunay || !m.is_delaunay();
      }
      const auto key = std::make_pair(State(m.cells(), m.tags()), busy);
      auto it = ends.find(key);
      if(it == ends.end() || it->second.first > swaps) ends[key] = {swaps, order};
      return;
    }
    for(std::size_t k = 0; k < left.size(); ++k)
    {
      const Facet f = left[k];
      if(std::find(not_next.begin(), not_next.end(), f) != not_next.end()) continue;
      std::vector<Facet> rest = left;
      rest.erase(rest.begin() + std::ptrdiff_t(k));
      // The facets listed before f (in `left`, the listed order) that commute with it here.
      std::vector<Facet> after_f;
      if(reduce)
        for(std::size_t j = 0; j < k; ++j)
          if(commute(m, left[j], f)) after_f.push_back(left[j]);
      order.push_back(f);
      Checker next = m;
      const Step step = visit(next, f); // passed if f is not there at its turn
      run(next, rest, busy || step.changed, swaps + step.swap, order, after_f);
      order.pop_back();
    }
  }
};

inline nlohmann::json cells_json(const std::set<Cell>& cells)
{
  nlohmann::json list = nlohmann::json::array();
  for(const Cell& t : cells) list.push_back({t[0], t[1], t[2], t[3]});
  return list;
}

// The trace of the cycles `path` (the orders) from the start, in the format of traces.md.
inline std::string write_trace(const nlohmann::json& header, const std::vector<std::vector<Facet>>& path)
{
  nlohmann::json h = header;
  h["max_rounds"] = path.size();
  std::ostringstream out;
  out << h.dump() << '\n';
  Checker m(h);
  for(std::size_t round = 1; round <= path.size(); ++round)
  {
    if(round > 1) m.start_round();
    for(const Facet& f : path[round - 1])
    {
      if(!m.has_interior_facet(f)) continue;
      const auto [d, e] = m.apexes(f);
      const Checker::Decision r = m.decide(f, d, e);
      nlohmann::json line;
      line["facet"] = {f[0], f[1], f[2]};
      line["apexes"] = {d, e};
      line["delaunay"] = r.delaunay;
      line["kind"] = r.kind;
      line["cells"] = cells_json(r.five_cells);
      std::vector<int> tagged;
      for(const Cell& t : r.five_cells) tagged.push_back(int(m.tags().count(t)));
      line["tagged"] = tagged;
      line["new_tags"] = cells_json(r.new_tags);
      line["flip"] = r.swap ? nlohmann::json(r.flip_name) : nlohmann::json(nullptr);
      line["created"] = r.swap ? cells_json(std::set<Cell>(r.new_cells.begin(), r.new_cells.end())) : nlohmann::json::array();
      out << line.dump() << '\n';
      m.apply(r);
    }
    std::set<Cell> tagged;
    for(const Cell& t : m.tags())
      if(m.cells().count(t)) tagged.insert(t);
    out << nlohmann::json{{"round", round}, {"swaps", m.round_swaps()}, {"new_tags", m.round_new_tags()},
                          {"cells", cells_json(m.cells())}, {"tagged", cells_json(tagged)}}.dump()
        << '\n';
  }
  out << nlohmann::json{{"end", "cycle limit reached"}, {"rounds", path.size()}}.dump() << '\n';
  return out.str();
}

struct Loop_found
{
  bool settled = false, loop = false;
  /// Settled searches: whether every state reached can still end the run (so
  /// uniformly random orders, which give every order a positive chance each
  /// cycle, end it with probability one), and whether some end is not Delaunay.
  bool ends_with_probability_one = false, can_end_off_delaunay = false;
  std::size_t states = 0;
  std::size_t loop_swaps = 0, loop_cycles = 0;
  std::string trace;
};

/// The search from the start of `header` (a trace header with its cells),
/// within `max_states` states at cycles' ends.
inline Loop_found search(const nlohmann::json& header, std::size_t max_states, bool reduce = false)
{
  Loop_found result;
  std::vector<Checker> models;
  std::map<State, std::size_t> index;
  std::vector<std::vector<Transition>> out;
  std::vector<std::size_t> parent;
  std::vector<std::vector<Facet>> parent_order;
  std::vector<char> can_end;
  models.emplace_back(header);
  index[{models[0].cells(), models[0].tags()}] = 0;
  out.emplace_back();
  parent.push_back(0);
  parent_order.emplace_back();
  try
  {
    for(std::size_t s = 0; s < models.size(); ++s)
    {
      Checker m = models[s];
      m.start_round();
      Cycle_search cycle{max_states * 64, reduce};
      std::vector<Facet> order;
      cycle.run(m, m.interior_facets(), false, 0, order);
      can_end.resize(models.size());
      can_end[s] = cycle.can_end;
      result.can_end_off_delaunay = result.can_end_off_delaunay || cycle.can_end_off_delaunay;
      for(const auto& [key, found] : cycle.ends)
      {
        if(!key.second) continue; // an idle cycle: the run ends
        auto [it, added] = index.emplace(key.first, models.size());
        if(added)
        {
          // The model at that state: the start's replayed along the orders.
          Checker n = models[s];
          n.start_round();
          for(const Facet& f : found.second)
            if(n.has_interior_facet(f))
            {
              const auto [d, e] = n.apexes(f);
              n.apply(n.decide(f, d, e));
            }
          models.push_back(n);
          out.emplace_back();
          parent.push_back(s);
          parent_order.push_back(found.second);
          if(models.size() > max_states) throw Search_limit_reached();
        }
        out[s].push_back({it->second, found.first, found.second});
      }
    }
    result.settled = true;
    // Every state from which an end is reachable: backwards from the states that can end.
    std::vector<std::vector<std::size_t>> into(models.size());
    for(std::size_t u = 0; u < out.size(); ++u)
      for(const Transition& t : out[u]) into[t.to].push_back(u);
    std::vector<char> reaches_end(models.size(), 0);
    std::vector<std::size_t> stack;
    for(std::size_t u = 0; u < models.size(); ++u)
      if(can_end[u]) reaches_end[u] = 1, stack.push_back(u);
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      stack.pop_back();
      for(std::size_t u : into[v])
        if(!reaches_end[u]) reaches_end[u] = 1, stack.push_back(u);
    }
    result.ends_with_probability_one = std::find(reaches_end.begin(), reaches_end.end(), 0) == reaches_end.end();
  }
  catch(const Search_limit_reached&)
  {
  }
  result.states = models.size();
  // A loop: a transition u -> v with a swap, and a way back from v to u. The
  // fewest swaps in all: breadth-first from v counting cycles, then swaps.
  std::size_t best = std::numeric_limits<std::size_t>::max();
  std::vector<std::vector<Facet>> best_path;
  for(std::size_t u = 0; u < out.size(); ++u)
    for(const Transition& t : out[u])
    {
      if(t.swaps == 0) continue;
      std::vector<long> back(models.size(), -1);
      std::vector<std::size_t> via(models.size());
      std::queue<std::size_t> q;
      back[t.to] = long(t.to);
      q.push(t.to);
      while(!q.empty() && back[u] < 0)
      {
        const std::size_t x = q.front();
        q.pop();
        for(std::size_t k = 0; k < out[x].size(); ++k)
          if(back[out[x][k].to] < 0)
          {
            back[out[x][k].to] = long(x);
            via[out[x][k].to] = k;
            q.push(out[x][k].to);
          }
      }
      if(back[u] < 0) continue;
      std::vector<std::vector<Facet>> loop; // u -> t.to -> ... -> u
      std::size_t swaps = t.swaps;
      for(std::size_t x = u; x != t.to; x = std::size_t(back[x]))
      {
        const Transition& step = out[std::size_t(back[x])][via[x]];
        loop.insert(loop.begin(), step.order);
        swaps += step.swaps;
      }
      loop.insert(loop.begin(), t.order);
      if(swaps >= best) continue;
      best = swaps;
      std::vector<std::vector<Facet>> lead; // the start -> u
      for(std::size_t x = u; x != 0; x = parent[x]) lead.insert(lead.begin(), parent_order[x]);
      best_path = lead;
      // The loop twice: its first pass ends on the state the second comes back to.
      for(int pass = 0; pass < 2; ++pass) best_path.insert(best_path.end(), loop.begin(), loop.end());
      result.loop_cycles = loop.size();
    }
  if(!best_path.empty())
  {
    result.loop = true;
    result.loop_swaps = best;
    result.trace = write_trace(header, best_path);
  }
  return result;
}

} // namespace adversarial_search

#endif // EDGE_SWAPPING_3_TEST_ADVERSARIAL_SEARCH_H
