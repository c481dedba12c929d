// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap shrink: removes points from a saved case while it still fails;
// edge_swap replay: runs a saved case again.

#ifndef EDGE_SWAP_SHRINK_COMMAND_H
#define EDGE_SWAP_SHRINK_COMMAND_H

#include "experiment_case.h"
#include "output_files.h"
#include <cstdio>
#include <fstream>
#include <iostream>

namespace edge_swap {

/// Runs a saved case again and prints its outcome (JSON).
inline int run_replay(const std::string& path, std::size_t max_cycles)
{
  if(max_cycles > 1000000000) throw Usage_error("--max-cycles is at most 1000000000");
  Experiment_case c = read_case_file(path);
  if(max_cycles) c.max_cycles = max_cycles;
  const Experiment_outcome o = run_case(c);
  // Cells that do not form a triangulation are bad input, not an outcome.
  if(o.ending.rfind("bad start: ", 0) == 0) throw Usage_error(path + ": bad case file: " + o.ending.substr(11));
  std::cout << outcome_json(o).dump() << '\n';
  return 0;
}

struct Shrink_options
{
  std::string input, output, expect;
};

/// Removes points from a saved case, in halves, quarters, ... down to single
/// points, as long as the case still fails as `expect` says ("failure": not
/// CGAL's Delaunay triangulation at the end; "stuck": plain swapping stuck).
inline int run_shrink(const Shrink_options& opt)
{
  check_output_paths({opt.output});
  Experiment_case c = read_case_file(opt.input);
  if(c.start == "cells") throw Usage_error("a case with an explicit start triangulation cannot be shrunk");
  const std::string expect = !opt.expect.empty() ? opt.expect : (c.strategy == "plain" ? "stuck" : "failure");
  if(expect != "stuck" && expect != "failure") throw Usage_error("--expect is stuck or failure");
  auto fails = [&](const Experiment_case& k) {
    if(!ES::point_set_problem(k.points).empty()) return false;
    const auto o = run_case(k);
    return expect == "stuck" ? o.ending == "stuck" : !o.equal_to_cgal;
  };
  if(!fails(c)) throw Usage_error("the case does not fail as '" + expect + "' to begin with");
  for(std::size_t chunk = c.points.size() / 2; chunk >= 1;)
  {
    bool removed = false;
    for(std::size_t from = 0; from < c.points.size() && c.points.size() > 4;)
    {
      Experiment_case smaller = c;
      const std::size_t to = std::min(from + chunk, smaller.points.size());
      smaller.points.erase(smaller.points.begin() + from, smaller.points.begin() + to);
      if(smaller.points.size() >= 4 && fails(smaller))
      {
        c = smaller;
        removed = true;
        std::cerr << "shrink: " << c.points.size() << " points\n";
      }
      else
        from = to;
    }
    if(!removed) chunk /= 2;
  }
  nlohmann::json out = case_json(c);
  out["outcome"] = outcome_json(run_case(c));
  out["expect"] = expect;
  if(expect == "stuck")
  {
    Experiment_case helper = c;
    helper.strategy = "helper";
    out["helper_from_the_same_start"] = outcome_json(run_case(helper));
  }
  Output_files files;
  files.add(opt.output, [&out](std::ostream& os) { os << out.dump(1) << '\n'; });
  files.commit();
  std::cout << "shrink: " << c.points.size() << " points still " << expect << " (" << opt.output << ")\n";
  return 0;
}

} // namespace edge_swap

#endif
