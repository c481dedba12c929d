// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap_lab: the conjecture laboratory's program. Experiments over many
// instances, saved cases replayed and shrunk, traces for the independent
// checker. Exit 2 for bad options or input, with nothing written.

#include "case_commands.h"
#include "experiment_command.h"
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace edge_swap_lab;
  CLI::App app{"edge_swap_lab: the conjecture laboratory of Edge_swapping_3 (laboratory/doc/conjectures.md)"};
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();
  app.fallthrough();
  app.add_flag("-q,--quiet", quiet, "no progress lines on standard error");

  Experiment_options exp;
  auto* experiment = app.add_subcommand("experiment", "many instances, one JSON line each, a summary");
  experiment->add_option("-o,--output", exp.output, "JSON lines, appended to: a stopped run resumes")->required();
  experiment->add_option("--families", exp.families, "point families, comma separated: random-cube, random-ball, sphere, "
                         "grid, cospherical, planes, clusters, jittered-grid, nearly-flat, random-integer, cube-corners, "
                         "cube-centre, octahedron, octahedron-centre, cube-face-centres, grid-2x2x3, grid-3x3x2, "
                         "two-spheres")->delimiter(',');
  experiment->add_option("--points-file", exp.point_files, "TetGen .node point sets of your own (more families)")->delimiter(',');
  experiment->add_option("--sizes", exp.sizes, "numbers of points, comma separated")->delimiter(',');
  experiment->add_option("--seeds", exp.seeds, "seeds: N or A-B (each one a point set and a face-order stream)");
  experiment->add_option("--starts", exp.starts, "placing (random order), scramble:K (Delaunay and K random flips), topcom (every fine triangulation)")->delimiter(',');
  experiment->add_option("--strategies", exp.strategies, "plain, helper, insertion")->delimiter(',');
  experiment->add_option("--orders", exp.orders, "face orders: storage, random, priority")->delimiter(',');
  experiment->add_option("--readings", exp.readings, "the helper's readings of Algorithm 4, separated by ';' "
                         "(laboratory/doc/traces.md), or all (36)");
  experiment->add_option("--max-cycles", exp.max_cycles, "cycle limit of each run")->check(CLI::PositiveNumber);
  experiment->add_option("--threads", exp.threads, "threads (default: all cores)");
  experiment->add_option("--shard", exp.shard, "I/N: run only the instances numbered I modulo N");
  experiment->add_option("--cases", exp.cases_dir, "folder for the failing cases and the small stuck ones (to shrink)");
  experiment->add_option("--stuck-case-max-points", exp.stuck_case_max_points, "save stuck plain runs up to this size");
  auto* topcom_limit = experiment->add_option("--topcom-limit", exp.topcom_limit,
                                              "at most this many TOPCOM triangulations per point set (default 100000; "
                                              "none with --stream)")->check(CLI::PositiveNumber);
  experiment->add_flag("--stream", exp.stream, "stream TOPCOM's triangulations in batches: one tally line per batch, "
                                               "a line only for runs not ending on CGAL's triangulation");
  experiment->add_option("--order-seeds", exp.order_seeds, "per-set (default: every TOPCOM start of a point set runs its "
                         "seed's face orders) or per-start (each start its own seed: independent samples)");
  experiment->add_option("--stream-batch", exp.stream_batch, "with --stream: triangulations per batch (default 4096)");

  std::string replay_path, replay_trace;
  std::size_t replay_cycles = 0;
  auto* replay = app.add_subcommand("replay", "run a saved case again and print its outcome");
  replay->add_option("CASE", replay_path, "a case file written by experiment --cases or shrink")->required();
  replay->add_option("--max-cycles", replay_cycles, "another cycle limit");
  replay->add_option("--trace", replay_trace,
                     "write every visit and the state after every cycle here (JSON lines; laboratory/doc/traces.md)");

  Trace_options tr;
  auto* trace = app.add_subcommand("trace", "run plain swapping or the helper from a TetGen file and write its trace");
  trace->add_option("INPUT", tr.input, "points (.node, placed in file order) or a start triangulation (.ele, its "
                    ".node beside it)")->required();
  trace->add_option("-o,--output", tr.output, "the trace (JSON lines; laboratory/doc/traces.md)")->required();
  trace->add_option("--strategy", tr.strategy, "helper or plain (Algorithm 3 alone)");
  trace->add_option("--start", tr.start, "of a .node: placing or scramble:K (Delaunay and K random flips)");
  trace->add_option("--order", tr.order, "face order: storage, random or priority");
  trace->add_option("--reading", tr.reading, "the helper's reading of Algorithm 4 (default: the package's)");
  trace->add_option("--schedule", tr.schedule, "cycles (the paper's) or queue (the package's work queue)");
  trace->add_option("--seed", tr.seed, "seed of the face order and the scrambling flips");
  trace->add_option("--max-cycles", tr.max_cycles, "cycle limit");

  Shrink_options shr;
  auto* shrink = app.add_subcommand("shrink", "remove points from a saved case while it still fails");
  shrink->add_option("CASE", shr.input, "a case file written by experiment --cases")->required();
  shrink->add_option("-o,--output", shr.output, "the smaller case (JSON)")->required();
  shrink->add_option("--expect", shr.expect, "stuck (plain) or failure (not CGAL's Delaunay triangulation)");

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::Success& e) // --help
  {
    return app.exit(e);
  }
  catch(const CLI::ParseError& e)
  {
    app.exit(e);
    return 2;
  }

  try
  {
    if(*experiment)
    {
      exp.topcom_limit_given = topcom_limit->count() > 0;
      return run_experiment(exp);
    }
    if(*replay) return run_replay(replay_path, replay_cycles, replay_trace);
    if(*trace) return run_trace(tr);
    return run_shrink(shr);
  }
  catch(const std::exception& e)
  {
    std::cerr << "edge_swap_lab: error: " << e.what() << '\n';
    return 2;
  }
}
