// edge_swap: the command-line program of Edge_swapping_3. Parses options,
// reads, calls the library, writes. Exit 2 for bad options or input.

#include "check_command.h"
#include "demo_command.h"
#include "optimize_command.h"
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace edge_swap;
  CLI::App app{"edge_swap: 3-D edge swapping (Gandhi & Barth 1993) on CGAL triangulations"};
  app.require_subcommand(1);

  Optimize_options opt;
  auto* optimize = app.add_subcommand("optimize", "swap edges of a point set's start triangulation or of a mesh");
  optimize->add_option("INPUT", opt.input, "TetGen .node (points) or .ele (mesh, .node beside it)")->required();
  optimize->add_option("-o,--output", opt.output, "output Y.ele (Y.node is written beside it)")->required();
  optimize->add_option("--criterion", opt.criterion, "delaunay|minmax-dihedral|maxmin-dihedral|min-edges|aspect-ratio");
  optimize->add_flag("--helper", opt.helper, "the helper strategy (Algorithm 4, Delaunay)");
  auto* start = optimize->add_option("--start", opt.start, "placing|placing:input|delaunay|scramble:K (point sets)");
  optimize->add_option("--order", opt.order, "face order: random (default) or storage");
  optimize->add_option("--seed", opt.seed, "seed of every random choice");
  optimize->add_option("--perturb", opt.perturb, "Delaunay tie-breaking: cgal|none");
  optimize->add_option("--max-cycles", opt.max_cycles, "cycle limit")->check(CLI::PositiveNumber);
  optimize->add_option("--history", opt.history, "CSV: one row per cycle");
  optimize->add_option("--stats", opt.stats, "JSON: counts, angles, ending, time");

  std::string check_path;
  auto* check = app.add_subcommand("check", "validity and Delaunay checks of a mesh");
  check->add_option("MESH", check_path, "TetGen .ele mesh")->required();

  std::size_t demo_points = 8000;
  unsigned int demo_seed = 1;
  auto* demo = app.add_subcommand("demo", "helper strategy to CGAL's Delaunay, then the paper's minimum-edge table");
  demo->add_option("--points", demo_points, "number of random points")->check(CLI::Range(4, 100000000));
  demo->add_option("--seed", demo_seed, "random seed");

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::CallForHelp& e)
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
    if(*optimize)
    {
      opt.start_given = start->count() > 0;
      return run_optimize(opt);
    }
    if(*check) return run_check(check_path);
    return run_demo(demo_points, demo_seed);
  }
  catch(const std::exception& e)
  {
    std::cerr << "edge_swap: error: " << e.what() << '\n';
    return 2;
  }
}
