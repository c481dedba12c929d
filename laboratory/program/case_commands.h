// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap_lab replay: runs a saved case again, its trace written if asked;
// edge_swap_lab trace: runs a case made from a TetGen file and writes its trace;
// edge_swap_lab shrink: removes points from a saved case while it still fails.

#ifndef EDGE_SWAP_LAB_CASE_COMMANDS_H
#define EDGE_SWAP_LAB_CASE_COMMANDS_H

#include "types.h"
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/shrink_conjecture_case.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <filesystem>
#include <iostream>

namespace edge_swap_lab {

/// Runs the case `c` (read from `source`) and prints its outcome (JSON); with
/// a trace path, writes the run's trace there (ES::trace_conjecture_case) as
/// well. Start cells that are no triangulation are refused after `bad_start`.
inline int run_case(const ES::Conjecture_case<Point>& c, const std::string& source, const std::string& bad_start,
                    const std::string& trace_path)
{
  if(!trace_path.empty() && c.strategy == ES::INSERTION_WITH_PLAIN_SWAPS)
    throw Usage_error("--trace: traces are written for the plain and helper strategies, not for insertion");
  const std::string problem = ES::point_set_problem(c.points);
  if(!problem.empty()) throw Usage_error(source + ": " + problem);
  ES::Conjecture_outcome o;
  try
  {
    if(trace_path.empty())
      o = ES::run_conjecture_case(c);
    else
    {
      // The trace goes straight to its file, written all or nothing like every output.
      Output_files files;
      files.add(trace_path, [&](std::ostream& out) {
        o = ES::trace_conjecture_case(c, out);
        if(o.bad_start) throw std::invalid_argument(o.start_problem);
      });
      files.commit();
    }
  }
  catch(const std::exception& e)
  {
    if(o.bad_start) throw Usage_error(source + ": " + bad_start + o.start_problem);
    throw Usage_error(source + ": " + e.what());
  }
  // Cells that do not form a triangulation are bad input, not an outcome.
  if(o.bad_start) throw Usage_error(source + ": " + bad_start + o.start_problem);
  nlohmann::json j = IO::conjecture_outcome_json(o);
  // The helper in the fixed order: the driver found a state that came back, so the run loops
  // (a trace runs every cycle and does not look).
  if(o.loop_period > 0) j["loop"] = {{"round", o.loop_round}, {"period", o.loop_period}};
  std::cout << j.dump() << '\n';
  return 0;
}

/// Runs a saved case again (another cycle limit if `max_cycles` is not 0).
inline int run_replay(const std::string& path, std::size_t max_cycles, const std::string& trace_path)
{
  if(max_cycles > 1000000000) throw Usage_error("--max-cycles is at most 1000000000");
  if(!trace_path.empty()) check_output_paths({trace_path});
  ES::Conjecture_case<Point> c = IO::read_conjecture_case_file<Point>(path);
  if(max_cycles) c.max_cycles = max_cycles;
  return run_case(c, path, "bad case file: ", trace_path);
}

struct Trace_options
{
  std::string input, output, strategy = "helper", start = "placing", order = "random", reading, schedule = "cycles";
  unsigned seed = 1;
  std::size_t max_cycles = 1000;
};

/// The case that `edge_swap_lab trace` runs: the points of a .node file
/// placed in file order (or Delaunay scrambled by K flips), or the cells of an
/// .ele file (its .node beside it), under the options' strategy and rule.
inline ES::Conjecture_case<Point> case_of_tetgen_file(const Trace_options& o)
{
  ES::Conjecture_case<Point> c;
  if(!ES::conjecture_strategy_from_name(o.strategy, c.strategy) || c.strategy == ES::INSERTION_WITH_PLAIN_SWAPS)
    throw Usage_error("--strategy is plain or helper, not '" + o.strategy + "'");
  if(!ES::face_order_from_name(o.order, c.order)) throw Usage_error("--order is storage, random or priority");
  if(o.schedule != "queue" && o.schedule != "cycles") throw Usage_error("--schedule is queue or cycles");
  c.schedule = o.schedule == "queue" ? ES::WORK_QUEUE : ES::PAPER_CYCLES;
  if(!o.reading.empty())
  {
    if(c.strategy != ES::HELPER_STRATEGY) throw Usage_error("--reading is the helper's: add --strategy helper");
    if(!ES::helper_reading_from_name(o.reading, c.reading))
      throw Usage_error("--reading '" + o.reading + "' is not a reading (laboratory/doc/traces.md)");
  }
  if(c.schedule == ES::WORK_QUEUE && !c.reading.is_default())
    throw Usage_error("--reading " + o.reading + ": the work queue runs plain swapping and the helper's default reading "
                      "only; add --schedule cycles");
  if(o.max_cycles == 0 || o.max_cycles > 1000000000) throw Usage_error("--max-cycles is from 1 to 1000000000");
  c.seed = o.seed;
  c.max_cycles = o.max_cycles;
  const std::string ext = std::filesystem::path(o.input).extension().string();
  if(ext != ".node" && ext != ".ele") throw Usage_error(o.input + ": a trace starts from a .node or an .ele file");
  const std::string node_path = ext == ".node" ? o.input : o.input.substr(0, o.input.size() - 4) + ".node";
  const IO::Node_file node = IO::read_node_file(node_path);
  for(const auto& p : node.points) c.points.emplace_back(p[0], p[1], p[2]);
  if(ext == ".ele")
  {
    if(o.start != "placing") throw Usage_error("--start applies to a .node input; an .ele input is its own start");
    c.start = ES::GIVEN_CELLS_START;
    c.cells = IO::read_ele_file(o.input, c.points.size(), node.first_index);
  }
  else if(o.start.rfind("scramble:", 0) == 0)
  {
    c.start = ES::SCRAMBLED_DELAUNAY_START;
    c.scramble_flips = whole_number(o.start.substr(9), "--start scramble:K");
  }
  else if(o.start != "placing")
    throw Usage_error("--start is placing or scramble:K, not '" + o.start + "'");
  return c;
}

/// Runs the case made from a TetGen file and writes its trace.
inline int run_trace(const Trace_options& o)
{
  check_output_paths({o.output});
  return run_case(case_of_tetgen_file(o), o.input, "the cells are not a triangulation: ", o.output);
}

struct Shrink_options
{
  std::string input, output, expect;
};

/// Removes points from a saved case as long as it still fails as `expect`
/// says ("failure": not CGAL's Delaunay triangulation at the end; "stuck":
/// plain swapping stuck), and writes the smaller case with its outcome.
inline int run_shrink(const Shrink_options& opt)
{
  check_output_paths({opt.output});
  ES::Conjecture_case<Point> c = IO::read_conjecture_case_file<Point>(opt.input);
  if(c.start == ES::GIVEN_CELLS_START) throw Usage_error("a case with an explicit start triangulation cannot be shrunk");
  const std::string expect = !opt.expect.empty() ? opt.expect : (c.strategy == ES::PLAIN_SWAPS ? "stuck" : "failure");
  if(expect != "stuck" && expect != "failure") throw Usage_error("--expect is stuck or failure");
  try
  {
    c = ES::shrink_conjecture_case(c, expect == "stuck" ? ES::KEEP_STUCK : ES::KEEP_COUNTEREXAMPLE,
                                   CGAL::parameters::visitor([](std::size_t n) { std::cerr << "shrink: " << n << " points\n"; }));
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(e.what());
  }
  nlohmann::json out = IO::conjecture_case_json(c);
  out["outcome"] = IO::conjecture_outcome_json(ES::run_conjecture_case(c));
  out["expect"] = expect;
  if(expect == "stuck")
  {
    ES::Conjecture_case<Point> helper = c;
    helper.strategy = ES::HELPER_STRATEGY;
    out["helper_from_the_same_start"] = IO::conjecture_outcome_json(ES::run_conjecture_case(helper));
  }
  Output_files files;
  files.add(opt.output, [&out](std::ostream& os) { os << out.dump(1) << '\n'; });
  files.commit();
  std::cout << "shrink: " << c.points.size() << " points still " << expect << " (" << opt.output << ")\n";
  return 0;
}

} // namespace edge_swap_lab

#endif
