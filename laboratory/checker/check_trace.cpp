// SPDX-License-Identifier: GPL-3.0-or-later
// check_trace TRACE: replays a trace of the laboratory with the independent
// checker (trace_checker.h) and prints what it confirmed, as JSON. Exit 0: every
// line confirmed; 1: a line failed (the message names it); 2: no such file.

#include "trace_checker.h"
#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: check_trace TRACE\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if(!in)
  {
    std::cerr << "check_trace: cannot read '" << argv[1] << "'\n";
    return 2;
  }
  const trace_checker::Result r = trace_checker::check_trace(in);
  nlohmann::json out{{"confirmed", r.ok},        {"visits", r.visits}, {"rounds", r.rounds},
                     {"swaps", r.swaps},         {"end", r.end},       {"ends_on_delaunay", r.ends_on_delaunay},
                     {"loop_certified", r.loop_certified}};
  if(r.loop_certified) out["loop"] = {{"state_after_round", r.loop_from}, {"again_after_round", r.loop_to}};
  if(!r.ok) out["error"] = std::string(argv[1]) + ": " + r.error;
  std::cout << out.dump() << '\n';
  return r.ok ? 0 : 1;
}
