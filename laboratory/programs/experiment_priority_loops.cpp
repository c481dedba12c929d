// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment (not a test): from every fine triangulation of a case's points
// (TOPCOM), the helper strategy in the fixed face order (PRIORITY_ORDER) for
// each seed; how many starts are still swapping at the cycle limit, and how
// many end stuck (possible in the readings that end on a cycle without swaps).
//
//   experiment_priority_loops CASE SEEDS MAX_CYCLES [READING [SAVE_DIR]] [--shard I/N] [--stream-batch B] [--hold N]
//                             [--trace-limit N] [--order-seeds per-set|per-start]
//   experiment_priority_loops --list-readings     (the 36 readings' names, one a line)
//
// SEEDS is LAST (seeds 1 to LAST) or FIRST-LAST; the laboratory's streams
// order the faces of point set SET by seed SET. With --shard I/N, only the
// triangulations numbered I modulo N (in TOPCOM's order) are starts: N shards
// together are the whole run, and their counts add up. With --stream-batch B,
// the shards take blocks of B triangulations instead: the block numbered K
// (triangulations K B to K B + B - 1) is in shard K modulo N, as in `edge_swap
// experiment --stream --stream-batch B --shard I/N` (B is 4096 there by
// default), so a shard of a stream can be certified on its own and its counts
// compared with the stream's. With --order-seeds
// per-start, the triangulation numbered I runs the priority of the seed
// order_seed_of_start(SEED, I), as `edge_swap_lab experiment --order-seeds
// per-start` does: each start its own fixed order (the default, per-set,
// gives every start SEED's).
//
// The starts (the shard's, with --shard) are enumerated by TOPCOM once and
// held in memory when there are at most 10^6 of them (--hold N: N), so that
// every reading and seed runs on the one enumeration; with more they are
// streamed from TOPCOM again for each reading and seed, never held. Finding
// that out costs one enumeration more (about 30 s and 1 GB for 12 points):
// --hold 0 streams from the start. A shard of 1/64 of the 12 random points
// (32,768 starts) is held in about 40 MB.
//
// CASE is a case file (its points are used), random-integer:N:SET for the
// laboratory's N random integer points of set SET, or family:NAME:N:SEED for
// any family of point_families.h (the degenerate sets among them); N is from
// 4 to 10^8 (laboratory_arguments.h).
//
// READING names a reading of Algorithm 4 (Helper_reading.h), for example
// "cleared-each-cycle,any-tetrahedron,no-swap", or several separated by
// spaces (run in that order), or is "all" for the 36; the default is the
// package's. With SAVE_DIR, the first certified loop of each
// reading is saved there as a case file with its trace, unless one of the
// same size and reading is there already.
//
// Per reading it prints the certified loop with the fewest swaps in one turn
// (its seed and triangulation; the first of them).
//
// Every run that does not end on CGAL's Delaunay triangulation is traced and
// replayed by the independent checker (laboratory/checker/trace_checker.h),
// which confirms each decision and certifies the loops: laboratory/doc/traces.md.
// Each start runs untraced to MAX_CYCLES, and one still going there with no
// loop found on to the trace limit (--trace-limit N; 8 MAX_CYCLES when N is 0
// or not given). In the fixed order the helper's driver finds a state that
// comes back, adds its period up instead of running it, and says where the
// state first came back (Swap_report::loop_round). A loop found so is traced
// to that cycle, and the checker certifies it from the trace alone; any other
// run not on CGAL's triangulation at MAX_CYCLES is traced whole, to the trace
// limit. The order is fixed, so a loop certified early is the run's loop at
// any limit. A run still going at MAX_CYCLES is counted there; one that ends
// after MAX_CYCLES, or is still going at the trace limit with no state
// repeated, is counted apart ("at the limit, not certified"). "loops certified
// by cycles traced" counts the loops by the length of the trace that certified
// them, in bins (at most 4, 16, 32, ...).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_experiment.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include "laboratory_arguments.h"
#include "trace_checker.h"
#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;

namespace {

const char* const usage =
  "usage: experiment_priority_loops CASE SEEDS MAX_CYCLES [READING [SAVE_DIR]] [--shard I/N] [--stream-batch B] "
  "[--hold N] [--trace-limit N] [--order-seeds per-set|per-start]\n";

/// The checker refused a trace: the run stops.
struct Refused
{
};

int run(int argc, char** argv)
{
  if(argc == 2 && std::string(argv[1]) == "--list-readings")
  {
    for(const ES::Helper_reading& reading : ES::all_helper_readings()) std::cout << ES::helper_reading_name(reading) << '\n';
    return 0;
  }
  std::size_t shard = 0, shards = 1, batch = 1, hold_limit = 1000000, trace_limit = 0;
  ES::Order_seeds order_seeds = ES::ORDER_SEED_PER_SET;
  for(int k = 1; k < argc;)
  {
    const std::string option = argv[k];
    if(option != "--shard" && option != "--stream-batch" && option != "--hold" && option != "--trace-limit" &&
       option != "--order-seeds")
    {
      ++k;
      continue;
    }
    const std::string value = k + 1 < argc ? argv[k + 1] : "";
    if(option == "--order-seeds")
    {
      if(!ES::order_seeds_from_name(value, order_seeds))
      {
        std::cerr << "experiment_priority_loops: --order-seeds per-set or per-start, not '" << value << "'\n";
        return 2;
      }
      std::copy(argv + k + 2, argv + argc, argv + k);
      argc -= 2;
      continue;
    }
    bool ok = !value.empty() && value.find_first_not_of(option == "--shard" ? "0123456789/" : "0123456789") == std::string::npos;
    try
    {
      if(ok && option == "--hold")
        hold_limit = std::stoul(value);
      else if(ok && option == "--trace-limit")
        trace_limit = std::stoul(value);
      else if(ok && option == "--stream-batch")
        ok = (batch = std::stoul(value)) > 0;
      else if(ok)
      {
        const auto slash = value.find('/');
        ok = slash != std::string::npos;
        if(ok) shard = std::stoul(value.substr(0, slash)), shards = std::stoul(value.substr(slash + 1));
        ok = ok && shards > 0 && shard < shards;
      }
    }
    catch(const std::exception&) // empty or too large
    {
      ok = false;
    }
    if(!ok)
    {
      std::cerr << "experiment_priority_loops: " << option
                << (option == "--shard"          ? " I/N, with whole numbers I < N"
                    : option == "--stream-batch" ? " B, a whole number at least 1"
                                                 : " N, a whole number")
                << ", not '" << value
                << "'\n";
      return 2;
    }
    std::copy(argv + k + 2, argv + argc, argv + k); // the positional arguments, in order
    argc -= 2;
  }
  if(argc < 4 || argc > 6)
  {
    std::cerr << usage;
    return 2;
  }
  // SEEDS is LAST or FIRST-LAST, each at most 2^32 - 1.
  using laboratory_arguments::whole_number;
  const std::string seeds = argv[2];
  const auto dash = seeds.find('-');
  std::size_t first_seed = 1, last_seed = 0, max_cycles = 0;
  const std::size_t most_seed = std::numeric_limits<unsigned>::max();
  const bool seeds_ok = (dash == std::string::npos || whole_number(seeds.substr(0, dash), first_seed, most_seed)) &&
                        whole_number(seeds.substr(dash == std::string::npos ? 0 : dash + 1), last_seed, most_seed) &&
                        first_seed <= last_seed;
  if(!seeds_ok || !whole_number(argv[3], max_cycles) || max_cycles == 0)
  {
    std::cerr << "experiment_priority_loops: SEEDS is LAST or FIRST-LAST (FIRST <= LAST <= 4294967295) and "
                 "MAX_CYCLES a whole number above 0, not '"
              << seeds << "' and '" << argv[3] << "'\n";
    return 2;
  }
  if(trace_limit == 0) trace_limit = max_cycles > std::size_t(-1) / 8 ? max_cycles : 8 * max_cycles;
  if(trace_limit < max_cycles)
  {
    std::cerr << "experiment_priority_loops: --trace-limit N, with N at least MAX_CYCLES (" << max_cycles << ")\n";
    return 2;
  }
  std::vector<ES::Helper_reading> readings(1);
  if(argc >= 5 && std::string(argv[4]) == "all")
    readings = ES::all_helper_readings();
  else if(argc >= 5)
  {
    readings.clear();
    std::istringstream names(argv[4]);
    for(std::string name; names >> name;)
    {
      readings.emplace_back();
      if(!ES::helper_reading_from_name(name, readings.back()))
      {
        std::cerr << "experiment_priority_loops: unknown reading '" << name << "'\n";
        return 2;
      }
    }
    if(readings.empty())
    {
      std::cerr << "experiment_priority_loops: READING is empty\n";
      return 2;
    }
  }
  ES::Conjecture_case<K::Point_3> c;
  const std::string source = argv[1];
  if(!laboratory_arguments::named_point_set(source, c.points))
    c = ES::IO::read_conjecture_case_file<K::Point_3>(source);
  const auto in_shard = [&](std::size_t t) { return (t / batch) % shards == shard; };
  // The shard's starts, held when there are at most hold_limit (one TOPCOM enumeration for every
  // reading and seed); else streamed from TOPCOM again for each reading and seed.
  std::vector<std::pair<std::size_t, std::vector<std::array<std::size_t, 4>>>> held; // (number, cells), in TOPCOM's order
  std::size_t enumerated = 0; // TOPCOM's triangulations, when the starts are held
  bool streamed = hold_limit == 0; // --hold 0: without enumerating first
  if(!streamed)
  {
    enumerated = ES::IO::for_each_topcom_triangulation(
      c.points, std::size_t(-1), [&](std::size_t t, const std::vector<std::array<std::size_t, 4>>& cells) {
        if(!in_shard(t)) return true;
        if(held.size() == hold_limit)
        {
          streamed = true; // too many to hold
          return false;
        }
        held.emplace_back(t, cells);
        return true;
      });
    if(streamed) held = decltype(held)(); // memory back
  }
  const auto for_each_start = [&](auto visit) {
    if(!streamed)
    {
      for(const auto& [t, cells] : held) visit(t, cells);
      return;
    }
    ES::IO::for_each_topcom_triangulation(c.points, std::size_t(-1),
                                          [&](std::size_t t, const std::vector<std::array<std::size_t, 4>>& cells) {
                                            if(in_shard(t)) visit(t, cells);
                                            return true;
                                          });
  };
  std::cout << c.points.size() << " points, ";
  if(streamed && hold_limit == 0)
    std::cout << "triangulations streamed";
  else if(streamed)
    std::cout << "more than " << hold_limit << (shards > 1 ? " starts in the shard" : " triangulations") << ", streamed";
  else
    std::cout << enumerated << " triangulations";
  if(shards > 1 && batch == 1)
    std::cout << ", shard " << shard << '/' << shards << " (the triangulations numbered " << shard << " modulo " << shards << ')';
  else if(shards > 1)
    std::cout << ", shard " << shard << '/' << shards << " in blocks of " << batch << " (the blocks numbered " << shard
              << " modulo " << shards << ')';
  if(order_seeds == ES::ORDER_SEED_PER_START) std::cout << ", a priority per start (--order-seeds per-start)";
  std::cout << '\n';
  c.strategy = ES::HELPER_STRATEGY;
  c.order = ES::PRIORITY_ORDER;
  c.start = ES::GIVEN_CELLS_START;
  const std::string save_dir = argc == 6 ? argv[5] : "";
  // The lengths of the traces that certified loops are counted in these bins (printed as
  // "loops certified by cycles traced"): at most 4, 16, 32, 64, ..., the trace limit.
  std::vector<std::size_t> rungs;
  for(std::size_t cycles = 4; cycles < trace_limit; cycles = cycles == 4 ? 16 : 2 * cycles)
    rungs.push_back(cycles);
  rungs.push_back(trace_limit);
  for(const ES::Helper_reading& reading : readings)
  {
    c.reading = reading;
    std::cout << "reading " << ES::helper_reading_name(c.reading) << '\n';
    std::size_t all_limit = 0, all_stuck = 0, all_certified = 0, runs = 0;
    std::size_t ended_later = 0, stuck_later = 0, unsettled = 0; // of the runs at the limit
    bool saved = false;
    std::vector<std::size_t> certified_on(rungs.size()); // loops certified by a trace of each bin
    // Of the runs at the trace limit: loops the driver found, those certified by the trace to
    // where the driver said the state first came back; the runs traced to the trace limit (no
    // loop found, or that trace certified none).
    std::size_t driver_loops = 0, first_trace = 0, whole_traces = 0;
    std::size_t fewest_swaps = 0, fewest_seed = 0, fewest_start = 0, loops_seen = 0; // the loop with the fewest swaps
    for(std::size_t seed_number = first_seed; seed_number <= last_seed; ++seed_number)
    {
      const unsigned seed = unsigned(seed_number);
      std::size_t limit = 0, stuck = 0, certified = 0;
      long long first = -1;
      for_each_start([&](std::size_t t, const std::vector<std::array<std::size_t, 4>>& cells) {
        c.cells = ES::oriented_cells(c.points, cells);
        c.seed = order_seeds == ES::ORDER_SEED_PER_START ? ES::order_seed_of_start(seed, t) : seed;
        if(++runs % 100000 == 0) // progress of a long run, on stderr
          std::cerr << "reading " << ES::helper_reading_name(c.reading) << ": " << runs << " runs; seed " << seed
                    << ": " << limit << " at the limit so far\n";
        // Untraced first: under the fixed order the driver finds a state that comes back and adds
        // its period up to the limit, so a loop costs a few of its periods here; it says where
        // the state first came back (Swap_report::loop_round), and the trace below stops there.
        // A run on CGAL's triangulation at MAX_CYCLES is not counted, ended or not (as in
        // edge_swap_lab experiment).
        c.max_cycles = max_cycles;
        ES::Conjecture_outcome o = ES::run_conjecture_case(c);
        if(o.equal_to_cgal) return;
        if(o.ending == ES::CYCLE_LIMIT_REACHED && o.loop_period == 0 && trace_limit > max_cycles)
        {
          c.max_cycles = trace_limit; // a loop that closes later, or a run that ends later
          o = ES::run_conjecture_case(c);
        }
        // Every run that did not end on CGAL's triangulation, traced and replayed by the independent checker.
        std::stringstream trace;
        trace_checker::Result r;
        std::size_t traced_cycles = 0;
        auto trace_to = [&](std::size_t cycles) {
          c.max_cycles = traced_cycles = cycles;
          trace.str("");
          trace.clear(); // a check read it to its end
          o = ES::trace_conjecture_case(c, trace);
          r = trace_checker::check_trace(trace);
        };
        bool checked = false;
        if(o.ending == ES::CYCLE_LIMIT_REACHED && o.loop_period > 0)
        {
          // The driver's loop: traced to the cycle where its state first came back, where the
          // checker finds the state repeated, unless the driver placed it by hashes equal by chance.
          ++driver_loops;
          trace_to(o.loop_round);
          checked = !r.ok || r.loop_certified;
          first_trace += r.ok && r.loop_certified;
        }
        if(!checked) // the whole run: it ends, or no state came back by then
        {
          trace_to(trace_limit);
          whole_traces += o.ending == ES::CYCLE_LIMIT_REACHED;
        }
        if(r.ok && r.loop_certified)
          ++certified_on[std::lower_bound(rungs.begin(), rungs.end(), traced_cycles) - rungs.begin()];
        if(!r.ok)
        {
          std::cerr << "seed " << seed << ", triangulation " << t << ": the checker refuses the trace: " << r.error << '\n';
          throw Refused();
        }
        if(first < 0) first = (long long)t;
        if(o.ending != ES::CYCLE_LIMIT_REACHED && o.cycles <= max_cycles)
        {
          ++stuck;
          return;
        }
        ++limit;
        if(o.ending != ES::CYCLE_LIMIT_REACHED) // ended after MAX_CYCLES
          ++(o.equal_to_cgal ? ended_later : stuck_later);
        else if(!r.loop_certified)
          ++unsettled;
        certified += r.loop_certified;
        if(r.loop_certified && (loops_seen++ == 0 || r.loop_swaps < fewest_swaps))
        {
          fewest_swaps = r.loop_swaps;
          fewest_seed = seed;
          fewest_start = t;
        }
        if(r.loop_certified && !saved && !save_dir.empty())
        {
          // The first certified loop of this reading, as a case file and its trace.
          std::string reading_name = ES::helper_reading_name(c.reading);
          std::replace(reading_name.begin(), reading_name.end(), ',', '_');
          const std::string name =
            save_dir + "/loop_" + std::to_string(c.points.size()) + "_points_" + reading_name + ".json";
          if(!std::ifstream(name)) // an earlier run's is kept
          {
            std::ofstream(name) << ES::IO::conjecture_case_json(c).dump(1) << '\n'; // with the limit traced
            std::ofstream(name.substr(0, name.size() - 5) + ".trace.jsonl") << trace.str();
          }
          saved = true;
        }
      });
      all_limit += limit;
      all_stuck += stuck;
      all_certified += certified;
      std::cout << "seed " << seed << ": " << limit << " starts still swapping at cycle " << max_cycles << " ("
                << certified << " loops certified), " << stuck << " stuck (first: triangulation " << first << ")\n";
    }
    std::cout << "loops certified by cycles traced:";
    for(std::size_t k = 0; k < rungs.size(); ++k)
      std::cout << ' ' << rungs[k] << ": " << certified_on[k] << (k + 1 < rungs.size() ? "," : "\n");
    std::cout << "loops the driver found: " << driver_loops
              << ", certified traced to where it said the state came back: " << first_trace
              << "; runs at the trace limit traced whole: " << whole_traces << '\n';
    std::cout << "fewest swaps in a certified loop: ";
    if(loops_seen == 0) std::cout << "- (no loop)\n";
    else
    {
      std::string priority; // the start's own seed, which its case file holds
      if(order_seeds == ES::ORDER_SEED_PER_START)
        priority = ", its priority seed " + std::to_string(ES::order_seed_of_start(unsigned(fewest_seed), fewest_start));
      std::cout << fewest_swaps << " (seed " << fewest_seed << ", triangulation " << fewest_start << priority << ")\n";
    }
    // The runs at the limit that are not certified loops: what became of them by the trace limit.
    std::cout << "at the limit, not certified: " << ended_later << " ended after cycle " << max_cycles
              << " on CGAL's triangulation, " << stuck_later << " ended stuck after it, " << unsettled
              << " still swapping at cycle " << trace_limit << " with no state repeated\n";
    std::cout << "all seeds: " << runs << " runs, " << all_limit << " still swapping (" << all_certified
              << " loops certified by the checker), " << all_stuck << " stuck" << std::endl; // the reading is done
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(argc, argv);
  }
  catch(const Refused&)
  {
    return 1;
  }
  catch(const std::exception& e) // a file, point family or number that cannot be read
  {
    std::cerr << "experiment_priority_loops: " << e.what() << '\n';
    return 2;
  }
}
