// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment (not a test): the adversarial order class. From every fine
// triangulation (TOPCOM) of a small point set, an adversary chooses, in every
// cycle, the order in which the facets listed at the cycle's start are visited
// (a listed facet that does not exist at its turn is passed; with same-cycle
// readings, the order of the cycle's sweep through all vertex triples). Is
// there a choice of orders under which the helper strategy never ends?
//
//   experiment_adversarial_orders [--reduce | --effective | --tag-bounds] SOURCE READING MAX_STATES [TRACE]
//   experiment_adversarial_orders --traps SOURCE READING MAX_STATES [TRACE] [--shard I/N]
//   experiment_adversarial_orders --delaunay-first SOURCE READING [TRACE]
//
// SOURCE is random-integer:N:SET or family:NAME:N:SEED (as for
// experiment_priority_loops), whose every TOPCOM triangulation is a start, a
// case file (.json, start "cells"), whose cells are the one start, or
// topcom:CASE.json, every TOPCOM triangulation of a case file's points
// (integer coordinates); READING
// a reading of Algorithm 4, or "next-cycle" or "same-cycle" for the 18
// readings with that visit of made facets, or "all" for the 36.
//
// The search is laboratory/search/adversarial_search.h. A start is
// "settled" when its whole graph was searched within MAX_STATES states: then
// the answer (a loop exists or not) is exact. Every loop found is confirmed
// by the independent checker, which certifies it by the state that comes
// back; with TRACE the trace of the loop with the fewest swaps over all
// starts is saved there. With --reduce the search skips orders that differ
// from one it makes only by neighbouring visits that commute (a partial-order
// reduction, described in adversarial_search.h: the answers are the same,
// the orders kept may differ; at 7 points it is slower than the full search).
// With --effective the search is laboratory/search/effective_visit_search.h,
// which branches only on the visits that change the state (with the
// reduction): the same answers, under every reading, on starts of more than
// 9 points. The starts of a set share its graph of states (each state's
// cycle is searched once), so "nodes" counts only those searched anew for a
// start. It prints the states from which an end can be reached, and
// one line of progress to standard error for each of the first 10 states,
// then every 100.
// With --tag-bounds no order is searched: laboratory/search/tag_bound_closure.h
// finds the least set of triangulations, each with a bound on its tags, that
// holds the start and is closed under every visit (MAX_STATES: at most that
// many triangulations). When CGAL's triangulation is not in it, no order at
// all reaches CGAL's triangulation from that start; TRACE then receives the
// certificate of the first such start (of the first reading that has one),
// which check_tag_bounds.py checks.
// With --traps the starts are streamed from TOPCOM (never all held) and each
// start's tag-bound set is searched only until CGAL's triangulation joins it
// (tag_bound_closure::search's stop_at_delaunay): a scan for traps, starts
// from which no order at all reaches CGAL's triangulation. It prints each
// trap found and, per reading, the starts whose set holds CGAL's
// triangulation, the traps, and the starts undecided within MAX_STATES
// triangulations; TRACE receives the certificate of the trap with the
// fewest triangulations (the first of them). Progress goes to standard error
// every 10,000 starts. With --shard I/N only the starts numbered I modulo N
// (in TOPCOM's order) are scanned: N shards, on any machines, scan each start
// once, and their counts add up.
// With --delaunay-first nothing is searched: each start's first cycle visits
// its locally Delaunay facets first, then the others
// (adversarial_search::delaunay_facets_first). Where plain swapping is stuck
// that cycle swaps nothing, so under the no-swap readings the run ends there,
// stuck: an order that ends it exists, and a uniformly random order of the
// cycle is that one with positive probability. It prints, per reading, the
// starts, those at which plain swapping is stuck, and the runs the cycle ends
// (each trace confirmed by the checker); TRACE receives the first such trace.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/Helper_reading.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include "adversarial_search.h"
#include "laboratory_arguments.h"
#include "effective_visit_search.h"
#include "tag_bound_closure.h"
#include <algorithm>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;
using adversarial_search::Loop_found;

namespace {

typedef std::vector<std::array<std::size_t, 4>> Cell_list; // a triangulation, as TOPCOM gives it

// The trace header of a start under a reading, for the searches.
nlohmann::json start_header(const std::vector<K::Point_3>& points, const Cell_list& cells,
                            const ES::Helper_reading& reading)
{
  nlohmann::json h{{"format", "Edge_swapping_3 visit trace"}, {"version", 1}, {"strategy", "helper"},
                   {"schedule", "cycles"}, {"order", "adversarial"}, {"seed", 0}, {"max_rounds", 1000000}};
  nlohmann::json point_list = nlohmann::json::array(), cell_list = nlohmann::json::array();
  for(const auto& p : points) point_list.push_back({p.x(), p.y(), p.z()});
  for(const auto& c : cells) cell_list.push_back({c[0], c[1], c[2], c[3]});
  h["points"] = point_list;
  h["cells"] = cell_list;
  h["reading"] = ES::helper_reading_name(reading);
  return h;
}

// --delaunay-first: one cycle from every start under every reading.
int delaunay_first(const std::vector<K::Point_3>& points, const std::vector<Cell_list>& starts,
                   const std::vector<ES::Helper_reading>& readings, const char* trace_file)
{
  std::string first_trace;
  std::cout << points.size() << " points, " << starts.size() << (starts.size() == 1 ? " start\n" : " starts\n");
  for(const ES::Helper_reading& reading : readings)
  {
    std::size_t plain_stuck = 0, stuck = 0, converged = 0;
    for(const Cell_list& cells : starts)
    {
      const nlohmann::json header = start_header(points, cells, reading);
      const trace_checker::Checker model(header);
      std::size_t flips = 0;
      for(const auto& f : model.interior_facets())
      {
        const auto [d, e] = model.apexes(f);
        const trace_checker::Checker::Decision r = model.decide(f, d, e);
        flips += !r.delaunay && r.swap;
      }
      plain_stuck += flips == 0 && !model.is_delaunay();
      const std::string trace = adversarial_search::write_trace(header, {adversarial_search::delaunay_facets_first(model)});
      std::istringstream in(trace);
      const trace_checker::Result check = trace_checker::check_trace(in);
      if(!check.ok)
      {
        std::cerr << "experiment_adversarial_orders: the checker refuses a first cycle's trace: " << check.error << '\n';
        return 1;
      }
      converged += check.end == "converged";
      if(check.end != "stuck") continue;
      ++stuck;
      if(first_trace.empty()) first_trace = trace;
    }
    std::cout << "reading " << ES::helper_reading_name(reading) << ": " << starts.size() << " starts, " << plain_stuck
              << " where plain swapping is stuck; the first cycle, locally Delaunay facets first, ends " << stuck
              << " runs stuck and " << converged << " on CGAL's triangulation\n";
  }
  if(trace_file && !first_trace.empty())
  {
    std::ofstream out(trace_file);
    out << first_trace;
    if(!out)
    {
      std::cerr << "experiment_adversarial_orders: " << trace_file << ": cannot write the trace\n";
      return 2;
    }
  }
  return 0;
}

// --traps: every start (the given one, or TOPCOM's streamed) under every reading.
int scan_for_traps(const std::vector<K::Point_3>& points, const std::vector<Cell_list>& given,
                   const std::vector<ES::Helper_reading>& readings, std::size_t max_triangulations,
                   const char* certificate_file, std::size_t shard, std::size_t shards)
{
  std::vector<std::size_t> holds_delaunay(readings.size()), trapped(readings.size()), undecided(readings.size());
  std::size_t starts = 0, fewest = std::numeric_limits<std::size_t>::max();
  nlohmann::json best;
  // One model per reading, made (and its points checked) at the first start;
  // TOPCOM's starts are triangulations of the points, a case file's is checked in main.
  std::vector<trace_checker::Checker> models;
  auto visit = [&](std::size_t index, const Cell_list& cells) {
    if(index % shards != shard) return true;
    if(models.empty())
      for(const auto& reading : readings) models.emplace_back(start_header(points, cells, reading));
    tag_bound_closure::Cells start;
    for(auto t : cells)
    {
      std::sort(t.begin(), t.end());
      start.insert(t);
    }
    for(std::size_t r = 0; r < readings.size(); ++r)
    {
      const tag_bound_closure::Closure c = tag_bound_closure::search(models[r], start, max_triangulations, true);
      if(c.delaunay > 0)
      {
        ++holds_delaunay[r];
        continue;
      }
      if(!c.closed)
      {
        ++undecided[r];
        continue;
      }
      ++trapped[r];
      std::cout << "start " << index << ": a trap under " << ES::helper_reading_name(readings[r]) << ", "
                << c.bounds.size() << " triangulations, " << c.can_end
                << " with a state that ends the run under no-swap-no-tag" << std::endl;
      if(c.bounds.size() < fewest)
      {
        fewest = c.bounds.size();
        best = tag_bound_closure::certificate(start_header(points, cells, readings[r]), c);
      }
    }
    if(++starts % 10000 == 0) std::cerr << starts << " starts scanned\n";
    return true;
  };
  try
  {
    if(!given.empty())
      for(std::size_t t = 0; t < given.size(); ++t) visit(t, given[t]);
    else
      ES::IO::for_each_topcom_triangulation(points, std::numeric_limits<std::size_t>::max(), visit);
  }
  catch(const std::exception& e) // TOPCOM missing or failing, points TOPCOM cannot read
  {
    std::cerr << "experiment_adversarial_orders: " << e.what() << '\n';
    return 2;
  }
  std::cout << points.size() << " points, " << starts << " starts";
  if(shards > 1) std::cout << ", shard " << shard << '/' << shards << " (the starts numbered " << shard << " modulo " << shards << ')';
  std::cout << '\n';
  for(std::size_t r = 0; r < readings.size(); ++r)
    std::cout << "reading " << ES::helper_reading_name(readings[r]) << ": " << starts << " starts, " << holds_delaunay[r]
              << " with CGAL's triangulation in their set, " << undecided[r] << " undecided, traps " << trapped[r] << "\n";
  if(certificate_file && !best.is_null())
  {
    std::ofstream out(certificate_file);
    out << best.dump() << '\n';
    if(!out)
    {
      std::cerr << "experiment_adversarial_orders: " << certificate_file << ": cannot write the certificate\n";
      return 2;
    }
  }
  return 0;
}

int run(int argc, char** argv)
{
  const std::string flag = argc > 1 ? argv[1] : "";
  const bool reduce = flag == "--reduce", effective = flag == "--effective", tag_bounds = flag == "--tag-bounds",
             traps = flag == "--traps", first_cycle = flag == "--delaunay-first";
  if(reduce || effective || tag_bounds || traps || first_cycle)
  {
    --argc;
    ++argv;
  }
  std::size_t shard = 0, shards = 1;
  if(traps && argc > 2 && std::string(argv[argc - 2]) == "--shard")
  {
    // I/N: whole numbers, I < N.
    const std::string value = argv[argc - 1];
    const std::size_t slash = value.find('/');
    const bool digits = slash != std::string::npos && slash > 0 && slash + 1 < value.size() &&
                        value.find_first_not_of("0123456789/") == std::string::npos &&
                        value.find('/', slash + 1) == std::string::npos && value.size() < 16;
    if(digits) shard = std::stoul(value.substr(0, slash)), shards = std::stoul(value.substr(slash + 1));
    if(!digits || shards == 0 || shard >= shards)
    {
      std::cerr << "experiment_adversarial_orders: --shard takes I/N, with whole numbers I < N, not '" << value << "'\n";
      return 2;
    }
    argc -= 2;
  }
  bool stray_option = false; // e.g. --shard without its value, or where it does not belong
  for(int i = 1; i < argc; ++i) stray_option = stray_option || std::string(argv[i]).rfind("--", 0) == 0;
  if(stray_option || (first_cycle ? argc != 3 && argc != 4 : argc != 4 && argc != 5))
  {
    std::cerr << "usage: experiment_adversarial_orders [--reduce | --effective | --tag-bounds] SOURCE READING "
                 "MAX_STATES [TRACE]\n"
                 "       experiment_adversarial_orders --traps SOURCE READING MAX_STATES [TRACE] [--shard I/N]\n"
                 "       experiment_adversarial_orders --delaunay-first SOURCE READING [TRACE]\n";
    return 2;
  }
  using laboratory_arguments::whole_number;
  const std::string source = argv[1];
  std::vector<K::Point_3> points;
  std::vector<Cell_list> starts;
  try
  {
    if(!laboratory_arguments::named_point_set(source, points))
    {
      if(source.size() <= 5 || source.compare(source.size() - 5, 5, ".json") != 0)
      {
        std::cerr << "experiment_adversarial_orders: SOURCE is random-integer:N:SET, family:NAME:N:SEED, a case file "
                     "(.json) or topcom:CASE.json\n";
        return 2;
      }
      // topcom:CASE.json takes the points only; CASE.json its start as well.
      const bool all_triangulations = source.rfind("topcom:", 0) == 0;
      const std::string file = all_triangulations ? source.substr(7) : source;
      const ES::Conjecture_case<K::Point_3> c = ES::IO::read_conjecture_case_file<K::Point_3>(file);
      points = c.points;
      if(!all_triangulations)
      {
        if(c.start != ES::GIVEN_CELLS_START) throw std::runtime_error(file + ": its start is not \"cells\"");
        starts.push_back(c.cells);
      }
    }
  }
  catch(const std::exception& e) // a malformed name, an unknown family, points that cannot be triangulated; the
                                 // reader's messages name the file
  {
    std::cerr << "experiment_adversarial_orders: " << e.what() << '\n';
    return 2;
  }
  std::vector<ES::Helper_reading> readings;
  const std::string which = argv[2];
  if(which == "all" || which == "next-cycle" || which == "same-cycle")
  {
    for(const auto& r : ES::all_helper_readings())
      if(which == "all" || (r.made_facets == ES::MADE_FACETS_NEXT_CYCLE) == (which == "next-cycle"))
        readings.push_back(r);
  }
  else
  {
    readings.emplace_back();
    if(!ES::helper_reading_from_name(which, readings.back()))
    {
      std::cerr << "experiment_adversarial_orders: unknown reading '" << which << "'\n";
      return 2;
    }
  }
  std::size_t max_states = 0;
  if(!first_cycle && (!whole_number(argv[3], max_states) || max_states == 0))
  {
    std::cerr << "experiment_adversarial_orders: MAX_STATES is a whole number above 0, not '" << argv[3] << "'\n";
    return 2;
  }
  if(!starts.empty()) // a case file's start: a triangulation of its points, or an error naming the file
  {
    try
    {
      trace_checker::Checker check(start_header(points, starts.front(), readings.front()));
    }
    catch(const std::exception& e)
    {
      std::cerr << "experiment_adversarial_orders: " << source << ": its cells are not a triangulation of its points: "
                << e.what() << '\n';
      return 2;
    }
  }
  if(traps) return scan_for_traps(points, starts, readings, max_states, argc == 5 ? argv[4] : nullptr, shard, shards);
  if(starts.empty())
  {
    try
    {
      starts = ES::IO::topcom_triangulations(points, 1000000).triangulations;
    }
    catch(const std::exception& e) // TOPCOM missing or failing, points TOPCOM cannot read
    {
      std::cerr << "experiment_adversarial_orders: " << e.what() << '\n';
      return 2;
    }
  }
  if(first_cycle) return delaunay_first(points, starts, readings, argc == 4 ? argv[3] : nullptr);
  std::cout << points.size() << " points, " << starts.size() << (starts.size() == 1 ? " start\n" : " triangulations\n");
  std::size_t best_swaps = std::numeric_limits<std::size_t>::max();
  std::string best_trace;
  bool certificate_written = false; // --tag-bounds: once, for the first start found
  for(const ES::Helper_reading& reading : readings)
  {
    std::size_t settled = 0, loops = 0, states = 0, fewest = std::numeric_limits<std::size_t>::max(), fewest_cycles = 0;
    std::size_t surely = 0, off_delaunay = 0;
    std::vector<nlohmann::json> headers;
    for(const auto& start : starts) headers.push_back(start_header(points, start, reading));
    if(tag_bounds)
    {
      std::size_t closed = 0, unreached = 0;
      for(std::size_t t = 0; t < starts.size(); ++t)
      {
        const tag_bound_closure::Closure c = tag_bound_closure::search(headers[t], max_states);
        std::cout << "start " << t << ": " << c.bounds.size() << " triangulations" << (c.closed ? "" : " (not closed)")
                  << ", " << c.delaunay << " of them CGAL's";
        if(c.closed) std::cout << "; " << c.can_end << " with a state that ends the run under no-swap-no-tag";
        std::cout << std::endl;
        closed += c.closed;
        if(!c.closed || c.delaunay > 0) continue;
        if(argc == 5 && !certificate_written)
        {
          std::ofstream out(argv[4]);
          out << tag_bound_closure::certificate(headers[t], c).dump() << '\n';
          if(!out)
          {
            std::cerr << "experiment_adversarial_orders: " << argv[4] << ": cannot write the certificate\n";
            return 2;
          }
          certificate_written = true;
        }
        ++unreached;
      }
      std::cout << "reading " << ES::helper_reading_name(reading) << ": " << starts.size() << " starts, " << closed
                << " closed, no order reaches CGAL's triangulation from " << unreached << "\n";
      continue;
    }
    // The changing-visit search shares one graph of states among the starts.
    std::vector<effective_visit_search::Closure> closures;
    if(effective)
    {
      try
      {
        closures = effective_visit_search::search_all(
            headers, max_states, true, 0, [&](std::size_t t, std::size_t done, std::size_t found, std::size_t nodes) {
              if(done <= 10 || done % 100 == 0)
                std::cerr << "start " << t << ": " << done << " of " << found << " states searched, " << nodes
                          << " nodes\n";
            });
      }
      catch(const effective_visit_search::Too_many_numbers&)
      {
        std::cerr << "experiment_adversarial_orders: more than 4,096 cells or vertex triples met: too large to search\n";
        return 2;
      }
    }
    for(std::size_t t = 0; t < starts.size(); ++t)
    {
      const nlohmann::json& h = headers[t];
      Loop_found r;
      if(effective)
      {
        const effective_visit_search::Closure& c = closures[t];
        r = c;
        std::cout << "start " << t << ": " << c.states << " states" << (c.settled ? "" : " (not settled)") << ", "
                  << c.transitions << " cycles between them, " << c.nodes << " nodes; " << c.states_that_can_end
                  << " can end the run in one cycle";
        if(c.settled) std::cout << ", " << c.states_reaching_end << " can reach an end";
        if(c.loop) std::cout << "; a loop of " << c.loop_swaps << " swaps in " << c.loop_cycles << " cycles"
                             << (c.fewest_swaps_searched ? " (the fewest)" : "");
        std::cout << std::endl;
      }
      else
        r = adversarial_search::search(h, max_states, reduce);
      settled += r.settled;
      states += r.states;
      surely += r.ends_with_probability_one;
      off_delaunay += r.can_end_off_delaunay;
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
    std::cout << "reading " << ES::helper_reading_name(reading) << ": " << starts.size() << " starts, "
              << settled << " settled, " << loops << " with a certified loop";
    if(loops > 0) std::cout << " (fewest swaps " << fewest << ", in " << fewest_cycles << " cycles)";
    std::cout << ", " << states << " states; random orders end with probability one from " << surely
              << "; an end not Delaunay is reachable from " << off_delaunay << "\n";
  }
  if(argc == 5 && !best_trace.empty()) std::ofstream(argv[4]) << best_trace;
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(argc, argv);
  }
  catch(const std::exception& e) // TOPCOM failing, or a file that cannot be written
  {
    std::cerr << "experiment_adversarial_orders: " << e.what() << '\n';
    return 2;
  }
}
