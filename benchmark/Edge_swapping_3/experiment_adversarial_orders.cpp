// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment (not a test): the adversarial order class. From every fine
// triangulation (TOPCOM) of a small point set, an adversary chooses, in every
// cycle, the order in which the facets listed at the cycle's start are visited
// (a listed facet that does not exist at its turn is passed). Is there a
// choice of orders under which the helper strategy never ends?
//
//   experiment_adversarial_orders SOURCE READING MAX_STATES [TRACE]
//
// SOURCE is random-integer:N:SET or family:NAME:N:SEED (as for
// experiment_priority_loops); READING a reading of Algorithm 4 whose made
// facets wait for the next cycle, or "all" for the 18 such readings.
//
// For each start, the search enumerates every state (cells and tags) at a
// cycle's end that some sequence of orders reaches, and for each state every
// state the next cycle can end in under some order (a depth-first search over
// the facets not yet visited, with the states already seen cut off). The run
// ends after a cycle with no swap (and, with the ending no-swap-no-tag, no new
// tag); every other transition continues. A loop is a cycle of transitions
// with a swap on it. A start is "settled" when its whole graph was searched
// within MAX_STATES states: then the answer (a loop exists or not) is exact.
//
// The model of the rule is the independent checker's (trace_checker.h,
// `decide` and `apply`), not the drivers'. Each loop found with the fewest
// swaps is written as a trace (order "adversarial": the start, the cycles
// that lead to the loop, and the loop twice) and confirmed by the checker,
// which certifies it by the state that comes back; with TRACE the trace of
// the shortest loop over all starts is saved there.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/Helper_reading.h>
#include <CGAL/Edge_swapping_3/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include "trace_checker.h"
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;
using trace_checker::Cell;
using trace_checker::Checker;
using trace_checker::Facet;

namespace {

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
  std::size_t nodes = 0;
  std::set<std::tuple<std::set<Cell>, std::set<Cell>, std::vector<Facet>, bool>> seen;
  std::map<std::pair<State, bool>, std::pair<std::size_t, std::vector<Facet>>> ends; // -> swaps, order

  void run(const Checker& m, std::vector<Facet> left, bool busy, std::size_t swaps, std::vector<Facet>& order)
  {
    if(!seen.insert({m.cells(), m.tags(), left, busy}).second) return;
    if(++nodes > max_nodes) throw Search_limit_reached();
    if(left.empty())
    {
      const auto key = std::make_pair(State(m.cells(), m.tags()), busy);
      auto it = ends.find(key);
      if(it == ends.end() || it->second.first > swaps) ends[key] = {swaps, order};
      return;
    }
    for(std::size_t k = 0; k < left.size(); ++k)
    {
      std::vector<Facet> rest = left;
      rest.erase(rest.begin() + std::ptrdiff_t(k));
      const Facet f = left[k];
      order.push_back(f);
      if(!m.has_interior_facet(f))
        run(m, rest, busy, swaps, order); // passed: it is not there at its turn
      else
      {
        Checker next = m;
        const auto [d, e] = next.apexes(f);
        const Checker::Decision r = next.decide(f, d, e);
        next.apply(r);
        run(next, rest, busy || r.swap || !r.new_tags.empty(), swaps + r.swap, order);
      }
      order.pop_back();
    }
  }
};

nlohmann::json cells_json(const std::set<Cell>& cells)
{
  nlohmann::json list = nlohmann::json::array();
  for(const Cell& t : cells) list.push_back({t[0], t[1], t[2], t[3]});
  return list;
}

// The trace of the cycles `path` (the orders) from the start, in the format of traces.md.
std::string write_trace(const nlohmann::json& header, const std::vector<std::vector<Facet>>& path)
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
  std::size_t states = 0;
  std::size_t loop_swaps = 0, loop_cycles = 0;
  std::string trace;
};

// The search from one start.
Loop_found search(const nlohmann::json& header, std::size_t max_states)
{
  Loop_found result;
  std::vector<Checker> models;
  std::map<State, std::size_t> index;
  std::vector<std::vector<Transition>> out;
  std::vector<std::size_t> parent;
  std::vector<std::vector<Facet>> parent_order;
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
      Cycle_search cycle{max_states * 64};
      std::vector<Facet> order;
      cycle.run(m, m.interior_facets(), false, 0, order);
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

} // namespace

int main(int argc, char** argv)
{
  if(argc != 4 && argc != 5)
  {
    std::cerr << "usage: experiment_adversarial_orders SOURCE READING MAX_STATES [TRACE]\n";
    return 2;
  }
  const std::string source = argv[1];
  std::vector<K::Point_3> points;
  std::vector<std::string> part(1);
  for(char ch : source)
    if(ch == ':') part.emplace_back();
    else part.back() += ch;
  if(part[0] == "random-integer" && part.size() == 3)
    points = ES::point_families::random_integer<K::Point_3>(std::stoul(part[1]), unsigned(std::stoul(part[2])));
  else if(part[0] == "family" && part.size() == 4)
    points = ES::make_point_family<K::Point_3>(part[1], std::stoul(part[2]), unsigned(std::stoul(part[3])));
  else
  {
    std::cerr << "experiment_adversarial_orders: SOURCE is random-integer:N:SET or family:NAME:N:SEED\n";
    return 2;
  }
  std::vector<ES::Helper_reading> readings;
  if(std::string(argv[2]) == "all")
  {
    for(const auto& r : ES::all_helper_readings())
      if(r.made_facets == ES::MADE_FACETS_NEXT_CYCLE) readings.push_back(r);
  }
  else
  {
    readings.emplace_back();
    if(!ES::helper_reading_from_name(argv[2], readings.back()) ||
       readings.back().made_facets != ES::MADE_FACETS_NEXT_CYCLE)
    {
      std::cerr << "experiment_adversarial_orders: unknown reading, or one with same-cycle: '" << argv[2] << "'\n";
      return 2;
    }
  }
  const std::size_t max_states = std::stoul(argv[3]);
  const auto all = ES::IO::topcom_triangulations(points, 1000000);
  std::cout << points.size() << " points, " << all.triangulations.size() << " triangulations\n";
  nlohmann::json header{{"format", "Edge_swapping_3 visit trace"}, {"version", 1}, {"strategy", "helper"},
                        {"schedule", "cycles"}, {"order", "adversarial"}, {"seed", 0},
                        {"max_rounds", 1000000}};
  nlohmann::json point_list = nlohmann::json::array();
  for(const auto& p : points) point_list.push_back({p.x(), p.y(), p.z()});
  header["points"] = point_list;
  std::size_t best_swaps = std::numeric_limits<std::size_t>::max();
  std::string best_trace;
  for(const ES::Helper_reading& reading : readings)
  {
    header["reading"] = ES::helper_reading_name(reading);
    std::size_t settled = 0, loops = 0, states = 0, fewest = std::numeric_limits<std::size_t>::max(), fewest_cycles = 0;
    for(std::size_t t = 0; t < all.triangulations.size(); ++t)
    {
      nlohmann::json h = header;
      nlohmann::json cells = nlohmann::json::array();
      for(const auto& c : all.triangulations[t]) cells.push_back({c[0], c[1], c[2], c[3]});
      h["cells"] = cells;
      const Loop_found r = search(h, max_states);
      settled += r.settled;
      states += r.states;
      if(!r.loop) continue;
      ++loops;
      // The certificate, confirmed by the checker as any trace is.
      std::istringstream in(r.trace);
      const trace_checker::Result check = trace_checker::check_trace(in);
      if(!check.ok || !check.loop_certified)
      {
        std::cerr << "triangulation " << t << ": the checker does not certify the loop: " << check.error << '\n';
        return 1;
      }
      if(r.loop_swaps < fewest)
      {
        fewest = r.loop_swaps;
        fewest_cycles = r.loop_cycles;
      }
      if(r.loop_swaps < best_swaps)
      {
        best_swaps = r.loop_swaps;
        best_trace = r.trace;
      }
    }
    std::cout << "reading " << ES::helper_reading_name(reading) << ": " << all.triangulations.size() << " starts, "
              << settled << " settled, " << loops << " with a certified loop";
    if(loops > 0) std::cout << " (fewest swaps " << fewest << ", in " << fewest_cycles << " cycles)";
    std::cout << ", " << states << " states\n";
  }
  if(argc == 5 && !best_trace.empty()) std::ofstream(argv[4]) << best_trace;
  return 0;
}
