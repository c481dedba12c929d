// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap shrink: removes points from a saved case while it still fails;
// edge_swap replay: runs a saved case again.

#ifndef EDGE_SWAP_SHRINK_COMMAND_H
#define EDGE_SWAP_SHRINK_COMMAND_H

#include "output_files.h"
#include "types.h"
#include <CGAL/Edge_swapping_3/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/shrink_conjecture_case.h>
#include <iostream>

namespace edge_swap {

/// Runs a saved case again and prints its outcome (JSON); with a trace path,
/// writes the run's trace there (ES::trace_conjecture_case) as well.
inline int run_replay(const std::string& path, std::size_t max_cycles, const std::string& trace_path)
{
  if(max_cycles > 1000000000) throw Usage_error("--max-cycles is at most 1000000000");
  if(!trace_path.empty()) check_output_paths({trace_path});
  ES::Conjecture_case<Point> c = IO::read_conjecture_case_file<Point>(path);
  if(max_cycles) c.max_cycles = max_cycles;
  if(!trace_path.empty() && c.strategy == ES::INSERTION_WITH_PLAIN_SWAPS)
    throw Usage_error("--trace: traces are written for the plain and helper strategies, not for insertion");
  ES::Conjecture_outcome o;
  if(trace_path.empty())
    o = ES::run_conjecture_case(c);
  else
  {
    // The trace goes straight to its file, written all or nothing like every output.
    Output_files files;
    files.add(trace_path, [&](std::ostream& out) {
      o = ES::trace_conjecture_case(c, out);
      if(o.bad_start) throw std::invalid_argument("bad case file: " + o.start_problem);
    });
    try
    {
      files.commit();
    }
    catch(const Usage_error&)
    {
      if(o.bad_start) throw Usage_error(path + ": bad case file: " + o.start_problem);
      throw;
    }
  }
  // Cells that do not form a triangulation are bad input, not an outcome.
  if(o.bad_start) throw Usage_error(path + ": bad case file: " + o.start_problem);
  nlohmann::json j = IO::conjecture_outcome_json(o);
  // The helper in the fixed order: the driver found a state that came back, so the run loops
  // (a trace runs every cycle and does not look).
  if(o.loop_period > 0) j["loop"] = {{"round", o.loop_round}, {"period", o.loop_period}};
  std::cout << j.dump() << '\n';
  return 0;
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

} // namespace edge_swap

#endif
