// SPDX-License-Identifier: GPL-3.0-or-later
// Experiment (not a test): escape times of the helper strategy in random
// order. One point set and one start, the face order drawn anew each cycle
// from seeds FIRST to LAST; one JSON line per seed with the cycle at which the
// run ended (or the limit), its ending, and whether it is CGAL's triangulation.
//
//   experiment_escape_times SOURCE FIRST LAST MAX_CYCLES [THREADS [SAVE_DIR]]
//
// SOURCE is a case file (its points and start are used), a TetGen .node file
// (its points, in the file's order, with a placing start), or FAMILY:N:SET for
// the laboratory's point family FAMILY with N points drawn from SET and a
// placing start. Runs are spread over THREADS of TBB's threads (default 2);
// the lines come in seed order. laboratory/doc/conjectures.md plots them
// (plot_escape_times.py). With SAVE_DIR, each run not ended by MAX_CYCLES is
// run again and its last triangulation saved there as a case file
// (unended_seed_S.json, start "cells"): a trapped state others can start from.
// Its tags are not in it (a case has none), nor the state of the random order.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <atomic>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;

namespace {

// Runs `c` as run_conjecture_case does and saves its last triangulation as a case.
void save_last_state(const ES::Conjecture_case<K::Point_3>& c, const std::string& path)
{
  CGAL::Triangulation_3<K> tr;
  if(c.start == ES::PLACING_START)
    ES::insert_by_placing(tr, c.points, ES::parameters::insertion_order(ES::INPUT_ORDER));
  else
  {
    std::vector<CGAL::Triangulation_3<K>::Vertex_handle> vertices;
    ES::build_triangulation_from_cells(tr, c.points, c.cells, vertices);
  }
  CGAL::swap_edges_with_helper(tr, ES::internal::laboratory_swap_parameters(c));
  std::map<K::Point_3, std::size_t> number;
  for(std::size_t k = 0; k < c.points.size(); ++k) number.emplace(c.points[k], k);
  ES::Conjecture_case<K::Point_3> last = c;
  last.start = ES::GIVEN_CELLS_START;
  last.cells.clear();
  for(auto cell : tr.finite_cell_handles())
    last.cells.push_back({number.at(cell->vertex(0)->point()), number.at(cell->vertex(1)->point()),
                          number.at(cell->vertex(2)->point()), number.at(cell->vertex(3)->point())});
  nlohmann::json j = ES::IO::conjecture_case_json(last);
  j["state_after_cycles"] = c.max_cycles;
  std::ofstream(path) << j.dump() << '\n';
}

// The points and start of SOURCE (see the top of this file).
ES::Conjecture_case<K::Point_3> read_source(const std::string& source)
{
  ES::Conjecture_case<K::Point_3> c;
  const auto ends_with = [&](const std::string& suffix) {
    return source.size() >= suffix.size() && source.compare(source.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  const auto colon = source.find(':');
  if(ends_with(".node"))
  {
    for(const auto& p : ES::IO::read_node_file(source).points) c.points.emplace_back(p[0], p[1], p[2]);
    c.start = ES::PLACING_START;
  }
  else if(colon != std::string::npos && !ends_with(".json"))
  {
    const auto second = source.find(':', colon + 1);
    c.points = ES::make_point_family<K::Point_3>(source.substr(0, colon), std::stoul(source.substr(colon + 1, second - colon - 1)),
                                                 unsigned(std::stoul(source.substr(second + 1))));
    c.start = ES::PLACING_START;
  }
  else
    c = ES::IO::read_conjecture_case_file<K::Point_3>(source);
  return c;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 5 || argc > 7)
  {
    std::cerr << "usage: experiment_escape_times SOURCE FIRST LAST MAX_CYCLES [THREADS [SAVE_DIR]]\n";
    return 2;
  }
  const std::string source = argv[1];
  ES::Conjecture_case<K::Point_3> c;
  unsigned first = 0, last = 0, threads = 2;
  try
  {
    c = read_source(source);
    c.max_cycles = std::stoul(argv[4]);
    first = unsigned(std::stoul(argv[2]));
    last = unsigned(std::stoul(argv[3]));
    if(argc >= 6) threads = unsigned(std::stoul(argv[5]));
  }
  catch(const std::exception& e) // a file or a number that cannot be read
  {
    std::cerr << "experiment_escape_times: " << e.what() << '\n';
    return 2;
  }
  if(last < first || threads == 0)
  {
    std::cerr << "experiment_escape_times: FIRST must not exceed LAST, and THREADS must be at least 1\n";
    return 2;
  }
  c.strategy = ES::HELPER_STRATEGY;
  c.order = ES::RANDOM_ORDER;
  const std::string save_dir = argc == 7 ? argv[6] : "";
  std::vector<std::string> lines(last - first + 1);
  std::atomic<unsigned> next{first};
  std::mutex out;
  unsigned printed = first;
  auto work = [&] {
    for(unsigned seed; (seed = next++) <= last;)
    {
      ES::Conjecture_case<K::Point_3> run = c;
      run.seed = seed;
      const ES::Conjecture_outcome o = ES::run_conjecture_case(run);
      if(!save_dir.empty() && o.ending == ES::CYCLE_LIMIT_REACHED)
        save_last_state(run, save_dir + "/unended_seed_" + std::to_string(seed) + ".json");
      nlohmann::json j{{"source", source}, {"points", c.points.size()}, {"seed", seed}, {"cycles", o.cycles},
                       {"ending", ES::conjecture_ending_name(o)}, {"equal_to_cgal", o.equal_to_cgal},
                       {"seconds", o.seconds}};
      std::lock_guard<std::mutex> lock(out);
      lines[seed - first] = j.dump();
      for(; printed <= last && !lines[printed - first].empty(); ++printed) std::cout << lines[printed - first] << std::endl;
    }
  };
  // TBB's threads, as the package's runner uses (CGAL_LINKED_WITH_TBB); without TBB, this one.
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena arena{int(threads)};
  arena.execute([&]() { tbb::parallel_for(0u, threads, [&](unsigned) { work(); }); });
#else
  work();
#endif
  return 0;
}
