// SPDX-License-Identifier: GPL-3.0-or-later
// The adversarial order class, searched exactly on small point sets: an
// adversary chooses, in every cycle, the order in which the facets listed at
// the cycle's start are visited (a listed facet that does not exist at its
// turn is passed). With same-cycle readings the adversary chooses the sweep:
// an order of all vertex triples, each visited at its turn if it is an
// interior facet then, so facets made in the cycle can be visited in it.
// From a start triangulation, the search enumerates every
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

#ifndef EDGE_SWAPPING_3_LABORATORY_ADVERSARIAL_SEARCH_H
#define EDGE_SWAPPING_3_LABORATORY_ADVERSARIAL_SEARCH_H

#include "trace_checker.h"
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
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

/// A set of the cells (4-subsets) or facets (3-subsets) of at most 9 points, by number.
struct Mask
{
  std::uint64_t w[2] = {0, 0};

  void set(int k) { w[k >> 6] |= std::uint64_t(1) << (k & 63); }
  void reset(int k) { w[k >> 6] &= ~(std::uint64_t(1) << (k & 63)); }
  bool test(int k) const { return (w[k >> 6] >> (k & 63)) & 1; }
  bool empty() const { return w[0] == 0 && w[1] == 0; }
  Mask minus(const Mask& o) const { return Mask{{w[0] & ~o.w[0], w[1] & ~o.w[1]}}; }
  Mask intersection(const Mask& o) const { return Mask{{w[0] & o.w[0], w[1] & o.w[1]}}; }
  bool operator==(const Mask& o) const { return w[0] == o.w[0] && w[1] == o.w[1]; }
  bool operator<(const Mask& o) const { return w[1] != o.w[1] ? w[1] < o.w[1] : w[0] < o.w[0]; }
  std::uint64_t hash() const { return w[0] * 0x9E3779B97F4A7C15ull ^ (w[1] + 0x632BE59BD9B4E019ull) * 0xBF58476D1CE4E5B9ull; }

  /// Calls `f(k)` for each member, in increasing order.
  template <class F>
  void for_each(F f) const
  {
    for(int i = 0; i < 2; ++i)
      for(std::uint64_t b = w[i]; b != 0; b &= b - 1) f(64 * i + __builtin_ctzll(b));
  }
};

/// The interior facets of a set of cells (those in two of them), as a set of
/// facet numbers, given the numbers of each cell's four facets.
template <class Set>
Set interior_facets(const Set& cells, const std::vector<std::array<int, 4>>& cell_facets)
{
  Set once, twice;
  cells.for_each([&](int k) {
    for(int f : cell_facets[std::size_t(k)])
    {
      if(once.test(f)) twice.set(f);
      once.set(f);
    }
  });
  return twice;
}

/// The cells and facets of the points, numbered in lexicographic order (so a
/// facet's number orders facets as the listing does), and the visits met so
/// far: each is computed once on the checker's model, then read from here.
class Space
{
public:
  explicit Space(const Checker& start) : model_(start)
  {
    const std::size_t n = start.points().size();
    if(n > 9) throw std::invalid_argument("adversarial search: at most 9 points (cells numbered in 128 bits)");
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        for(std::size_t c = b + 1; c < n; ++c)
        {
          facet_number_[Facet{a, b, c}] = int(facets_.size());
          facets_.push_back(Facet{a, b, c});
          for(std::size_t d = c + 1; d < n; ++d)
          {
            cell_number_[Cell{a, b, c, d}] = int(cells_.size());
            cells_.push_back(Cell{a, b, c, d});
          }
        }
    for(const Cell& t : cells_)
      cell_facets_.push_back({facet_number_.at(Facet{t[1], t[2], t[3]}), facet_number_.at(Facet{t[0], t[2], t[3]}),
                              facet_number_.at(Facet{t[0], t[1], t[3]}), facet_number_.at(Facet{t[0], t[1], t[2]})});
  }

  /// The interior facets of the cells: those in two of them.
  Mask interior(const Mask& cells) const { return interior_facets(cells, cell_facets_); }

  Mask cell_mask(const std::set<Cell>& cells) const
  {
    Mask m;
    for(const Cell& t : cells) m.set(cell_number_.at(t));
    return m;
  }
  std::set<Cell> cell_set(const Mask& m) const
  {
    std::set<Cell> out;
    m.for_each([&](int k) { out.insert(cells_[std::size_t(k)]); });
    return out;
  }
  const Facet& facet(int k) const { return facets_[std::size_t(k)]; }

  /// The model at a state of cells and tags.
  const Checker& model(const Mask& cells, const Mask& tags)
  {
    model_.set_state(cell_set(cells), cell_set(tags));
    return model_;
  }

  /// The state after `start_round()` (tags cleared or not), and the facets
  /// the round may visit: those there at its start (next-cycle), or every
  /// vertex triple (same-cycle: a sweep gives each triple a place).
  std::pair<Mask, Mask> round_start(const Mask& cells, const Mask& tags, Mask& listed)
  {
    model(cells, tags);
    model_.start_round();
    listed = Mask();
    if(model_.visits_made_facets())
      for(int f = 0; f < int(facets_.size()); ++f) listed.set(f);
    else
      listed = interior(cells);
    return {cells, cell_mask(model_.tags())};
  }

  bool is_delaunay(const Mask& cells)
  {
    model(cells, Mask());
    return model_.is_delaunay();
  }

  struct Visit
  {
    Mask cells, tags;
    bool swap = false, changed = false;
  };

  /// One visit of facet number `f` at a state: passed if the facet is not there.
  Visit visit(const Mask& cells, const Mask& tags, int f)
  {
    const Key key{cells, tags, f};
    const auto it = visits_.find(key);
    if(it != visits_.end()) return it->second;
    Visit v{cells, tags};
    model(cells, tags);
    if(model_.has_interior_facet(facets_[std::size_t(f)]))
    {
      const auto [d, e] = model_.apexes(facets_[std::size_t(f)]);
      const Checker::Decision r = model_.decide(facets_[std::size_t(f)], d, e);
      model_.apply(r);
      v.cells = cell_mask(model_.cells());
      v.tags = cell_mask(model_.tags());
      v.swap = r.swap;
      // A cycle that only tags ends the run when the reading ends on a cycle without swaps.
      v.changed = r.swap || (!r.new_tags.empty() && !model_.ends_without_swap());
    }
    visits_.emplace(key, v);
    return v;
  }

  /// Whether visiting f and g from a state, in either order, ends the same.
  bool commute(const Mask& cells, const Mask& tags, int f, int g)
  {
    const Visit a1 = visit(cells, tags, f), a2 = visit(a1.cells, a1.tags, g);
    const Visit b1 = visit(cells, tags, g), b2 = visit(b1.cells, b1.tags, f);
    return int(a1.swap) + int(a2.swap) == int(b1.swap) + int(b2.swap) &&
           (a1.changed || a2.changed) == (b1.changed || b2.changed) && a2.cells == b2.cells && a2.tags == b2.tags;
  }

private:
  struct Key
  {
    Mask cells, tags;
    int facet;
    bool operator==(const Key& o) const { return cells == o.cells && tags == o.tags && facet == o.facet; }
  };
  struct Key_hash
  {
    std::size_t operator()(const Key& k) const
    {
      return std::size_t(k.cells.hash() ^ (k.tags.hash() * 31) ^ (std::uint64_t(k.facet) * 0x94D049BB133111EBull));
    }
  };

  Checker model_;
  std::vector<Cell> cells_;
  std::vector<Facet> facets_;
  std::vector<std::array<int, 4>> cell_facets_; // by cell number
  std::map<Cell, int> cell_number_;
  std::map<Facet, int> facet_number_;
  std::unordered_map<Key, Visit, Key_hash> visits_;
};

// Records that a cycle search reached the end (cells, tags, busy) of its cycle
// with `swaps` swaps by `order`: an idle end can end the run; each end keeps
// its fewest swaps and the first order met with them.
template <class Search, class Set>
void record_end(Search& search, const Set& cells, const Set& tags, bool busy, std::size_t swaps,
                const std::vector<int>& order)
{
  if(!busy)
  {
    search.can_end = true;
    search.can_end_off_delaunay = search.can_end_off_delaunay || !search.space.is_delaunay(cells);
  }
  const auto key = std::make_tuple(cells, tags, busy);
  auto end = search.ends.find(key);
  if(end == search.ends.end() || end->second.first > swaps) search.ends[key] = {swaps, order};
}

// Every end of one cycle from a state at a cycle's start: the state, whether
// the cycle was busy, its fewest swaps and one order that reaches it with
// them (the first met with them, depth first in the listed order). A node
// (state, triples allowed, busy) met again is searched again only for what is
// new: with fewer swaps than before (all of it), or with facets allowed next
// that the reduction kept back before (those).
//
// Only facets that are there are visited. A listed triple that is not there
// at its turn is passed; passing it at one moment it is not there or another
// ends the same, so the search passes a triple only just before a flip makes
// it again (or, with same-cycle, makes it new), by trying the flip's
// children with and without each triple it makes that is still allowed, and
// the triples still allowed and not there at the cycle's end are passed then.
struct Cycle_search
{
  Space& space;
  std::size_t max_nodes;
  bool reduce = false;
  std::size_t nodes = 0;
  struct Node
  {
    Mask cells, tags, allowed;
    bool busy;
    bool operator==(const Node& o) const
    {
      return cells == o.cells && tags == o.tags && allowed == o.allowed && busy == o.busy;
    }
  };
  struct Node_hash
  {
    std::size_t operator()(const Node& n) const
    {
      return std::size_t(n.cells.hash() ^ (n.tags.hash() * 31) ^ (n.allowed.hash() * 961) ^ std::uint64_t(n.busy));
    }
  };
  struct Searched
  {
    std::size_t swaps;  // the fewest swaps it was met with
    Mask not_searched;  // the facets left not searched next from it
  };
  std::unordered_map<Node, Searched, Node_hash> seen;
  std::map<std::tuple<Mask, Mask, bool>, std::pair<std::size_t, std::vector<int>>> ends; // -> swaps, order
  bool can_end = false;               // some order makes this cycle end the run
  bool can_end_off_delaunay = false;  // ... on a triangulation that is not Delaunay

  // `allowed`: the triples not visited or passed yet; `not_next`: the facets
  // the reduction keeps from being visited next.
  void run(const Mask& cells, const Mask& tags, const Mask& allowed, bool busy, std::size_t swaps,
           std::vector<int>& order, const Mask& not_next)
  {
    const Mask present = space.interior(cells);
    const Mask left = allowed.intersection(present); // the facets still to visit
    Mask next = left.minus(not_next);
    const auto [it, added] = seen.try_emplace(Node{cells, tags, allowed, busy}, Searched{swaps, not_next});
    if(!added)
    {
      Searched& before = it->second;
      if(swaps < before.swaps) before.swaps = swaps;
      else
      {
        next = before.not_searched.minus(not_next).intersection(left);
        if(next.empty()) return;
      }
      before.not_searched = before.not_searched.intersection(not_next);
    }
    if(++nodes > max_nodes) throw Search_limit_reached();
    if(left.empty())
    {
      record_end(*this, cells, tags, busy, swaps, order);
      return;
    }
    next.for_each([&](int f) {
      Mask rest = allowed;
      rest.reset(f);
      // The facets to visit listed before f that commute with it here.
      Mask after_f;
      if(reduce)
        left.for_each([&](int g) {
          if(g < f && space.commute(cells, tags, g, f)) after_f.set(g);
        });
      const Space::Visit v = space.visit(cells, tags, f);
      // The triples the visit makes that are still allowed: each may have been passed just before.
      std::vector<int> made;
      space.interior(v.cells).minus(present).intersection(rest).for_each([&](int g) { made.push_back(g); });
      order.push_back(f);
      for(std::size_t passed = 0; passed < (std::size_t(1) << made.size()); ++passed)
      {
        Mask r = rest;
        for(std::size_t k = 0; k < made.size(); ++k)
          if((passed >> k) & 1) r.reset(made[k]);
        run(v.cells, v.tags, r, busy || v.changed, swaps + v.swap, order, after_f);
      }
      order.pop_back();
    });
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
  // A last cycle that changed nothing ends the run (none before it can: the path goes on).
  const std::string end = !m.round_is_idle() ? "cycle limit reached" : m.is_delaunay() ? "converged" : "stuck";
  out << nlohmann::json{{"end", end}, {"rounds", path.size()}}.dump() << '\n';
  return out.str();
}

/// The order of a first cycle that visits the locally Delaunay facets of the
/// model's state first, then the others (each part in the facets' order).
/// With no tag set yet no help swap can be made before the others' turns, so
/// where no facet that is not locally Delaunay has a flip (plain swapping is
/// stuck), this cycle swaps nothing, and under a no-swap reading it ends the
/// run, stuck. Any lifetime of tags, trigger or visit of made facets.
inline std::vector<Facet> delaunay_facets_first(const Checker& model)
{
  std::vector<Facet> first, then;
  for(const Facet& f : model.interior_facets())
  {
    const auto [d, e] = model.apexes(f);
    (model.decide(f, d, e).delaunay ? first : then).push_back(f);
  }
  first.insert(first.end(), then.begin(), then.end());
  return first;
}

struct Loop_found
{
  bool settled = false, loop = false;
  /// Settled searches: whether every state reached can still end the run (so
  /// uniformly random orders, which give every order a positive chance each
  /// cycle, end it with probability one), and whether some end is not Delaunay.
  bool ends_with_probability_one = false, can_end_off_delaunay = false;
  std::size_t states = 0;
  std::size_t nodes = 0; // the nodes (state, facets left) the cycles' searches visited
  std::size_t loop_swaps = 0, loop_cycles = 0;
  std::string trace;
};

/// The search from the start of `header` (a trace header with its cells),
/// within `max_states` states at cycles' ends.
inline Loop_found search(const nlohmann::json& header, std::size_t max_states, bool reduce = false)
{
  Loop_found result;
  Space space{Checker(header)};
  std::vector<std::pair<Mask, Mask>> models; // the states at cycles' ends, by number
  std::map<State, std::size_t> index;
  std::vector<std::vector<Transition>> out;
  std::vector<std::size_t> parent;
  std::vector<std::vector<Facet>> parent_order;
  std::vector<char> can_end;
  {
    const Checker start(header);
    models.emplace_back(space.cell_mask(start.cells()), space.cell_mask(start.tags()));
    index[{start.cells(), start.tags()}] = 0;
  }
  out.emplace_back();
  parent.push_back(0);
  parent_order.emplace_back();
  try
  {
    for(std::size_t s = 0; s < models.size(); ++s)
    {
      Mask listed;
      const auto [cells, tags] = space.round_start(models[s].first, models[s].second, listed);
      Cycle_search cycle{space, max_states * 64, reduce};
      std::vector<int> order;
      cycle.run(cells, tags, listed, false, 0, order, Mask());
      result.nodes += cycle.nodes;
      can_end.resize(models.size());
      can_end[s] = cycle.can_end;
      result.can_end_off_delaunay = result.can_end_off_delaunay || cycle.can_end_off_delaunay;
      // The ends in the order of their cells and tags as sets, as the states are numbered.
      std::map<std::pair<State, bool>, std::pair<std::size_t, std::vector<Facet>>> ends;
      for(const auto& [key, found] : cycle.ends)
      {
        std::vector<Facet> facets;
        for(int f : found.second) facets.push_back(space.facet(f));
        ends[{State(space.cell_set(std::get<0>(key)), space.cell_set(std::get<1>(key))), std::get<2>(key)}] = {
            found.first, facets};
      }
      for(const auto& [key, found] : ends)
      {
        if(!key.second) continue; // an idle cycle: the run ends
        auto [it, added] = index.emplace(key.first, models.size());
        if(added)
        {
          models.emplace_back(space.cell_mask(key.first.first), space.cell_mask(key.first.second));
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

#endif // EDGE_SWAPPING_3_LABORATORY_ADVERSARIAL_SEARCH_H
