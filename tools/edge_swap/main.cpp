// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap: the command-line program of Edge_swapping_3. Parses options,
// reads, calls the library, writes. Exit 2 for bad options or input. It first
// starts itself again with glibc's huge pages (huge_pages.h).

#include "check_command.h"
#include "demo_command.h"
#include "huge_pages.h"
#include "mesh_domain_command.h"
#include "optimize_command.h"
#include "refine_commands.h"
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace edge_swap;
  restart_with_huge_pages(argv);
  CLI::App app{"edge_swap: 3-D edge swapping (Gandhi & Barth 1993) on CGAL triangulations"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "edge_swap " EDGE_SWAP_VERSION);
  // Every option's help shows its default; options of the program as a whole may also follow the command.
  app.option_defaults()->always_capture_default();
  app.fallthrough();
  app.add_flag("-q,--quiet", quiet, "no progress lines on standard error");
  std::string msh_format = "4.1";
  app.add_option("--msh-format", msh_format, "how .msh outputs are written: 4.1, 4.1-binary, 2.2 or 2.2-binary")
      ->check(CLI::IsMember({"4.1", "4.1-binary", "2.2", "2.2-binary"}))
      ->capture_default_str();
  std::string vtu_format = "ascii";
  app.add_option("--vtu-format", vtu_format, "how .vtu outputs are written: ascii, or binary (zlib, as ParaView writes)")
      ->check(CLI::IsMember({"ascii", "binary"}))
      ->capture_default_str();

  Optimize_options opt;
  auto* optimize = app.add_subcommand("optimize", "swap edges of a point set's start triangulation or of a mesh");
  optimize->add_option("INPUT", opt.input, "points (TetGen .node) or a mesh: TetGen .ele (its .node beside it), "
                       "Medit .mesh, Gmsh .msh (4.1 or 2.2, ASCII or binary) or VTK .vtu")->required();
  optimize->add_option("-o,--output", opt.output, "output mesh: Y.ele (Y.node is written beside it), Y.mesh, Y.msh "
                       "or Y.vtu")->required();
  optimize->add_option("--criterion", opt.criterion,
                       "delaunay|minmax-dihedral|maxmin-dihedral|min-edges|aspect-ratio (circumradius/inradius)|"
                       "edge-ratio (longest/shortest edge)|radius-ratio (3r/R)|dihedral-sine|volume-length "
                       "(default: dihedral-sine for a mesh; delaunay for a .node point set, and with --helper or --paper)")
      ->check(CLI::IsMember({"delaunay", "minmax-dihedral", "maxmin-dihedral", "min-edges", "aspect-ratio", "edge-ratio",
                             "radius-ratio", "dihedral-sine", "volume-length"}));
  optimize->add_option("--operations", opt.operations,
                       "quality criteria: the worst-first driver's operations, comma-separated: flips, edge-removal, "
                       "multi-face-removal, two-step-edge-removal, smoothing (moves interior points), boundary-smoothing "
                       "(smoothing that also moves points within flat boundary faces and along straight boundary "
                       "edges), vertex-removal and vertex-insertion (interior vertices taken away and added where "
                       "a cell has an angle below 30 or above 140 degrees), topological (all but smoothing), all (all "
                       "but boundary-smoothing and the vertex changes) (default); or paper-flips: the paper's driver "
                       "(rounds over every facet)");
  optimize->add_flag("--helper", opt.helper, "the helper strategy (Algorithm 4, Delaunay)");
  auto* start = optimize->add_option("--start", opt.start, "start of a point set: placing|placing:input|delaunay|scramble:K (default: delaunay with a quality "
                                     "criterion, placing with the Delaunay criterion or --helper)");
  optimize->add_option("--order", opt.order, "face order: storage, random (drawn anew each cycle) or priority (a "
                       "fixed order of vertex triples drawn from --seed); default storage, random with --helper");
  optimize->add_option("--reading", opt.reading, "with --helper: its reading of Algorithm 4, e.g. "
                       "never-cleared,facet-cells,no-swap (laboratory/doc/traces.md); other than the default "
                       "with --schedule cycles");
  optimize->add_option("--seed", opt.seed, "seed of every random choice");
  auto* perturb = optimize->add_option("--perturb", opt.perturb, "Delaunay tie-breaking: cgal|none")
                      ->check(CLI::IsMember({"cgal", "none"}));
  auto* max_cycles = optimize->add_option("--max-cycles", opt.max_cycles, "round (cycle) limit")->check(CLI::PositiveNumber);
  optimize->add_option("--schedule", opt.schedule, "queue (only what changed) or cycles (the paper's)");
  optimize->add_flag("--paper", opt.paper, "Delaunay: the paper's Algorithm 3 alone, no repair of a stuck state");
  auto* target = optimize->add_option("--quality-target", opt.quality_target,
                                      "worst-first driver: work only on the cells worse than this value of the "
                                      "criterion's measure (degrees for the dihedral angles)");
  auto* angle_range = optimize->add_option("--angle-range", opt.angle_range,
                       "worst-first driver: keep (no operation makes a dihedral angle smaller than the input's "
                       "smallest or larger than its largest) or free (the criterion alone decides)")
      ->check(CLI::IsMember({"keep", "free"}));
  auto* time_limit = optimize->add_option("--time-limit", opt.time_limit,
                                          "worst-first driver: end after this many seconds with the mesh so far "
                                          "(valid, and written; the report says \"time limit reached\"); Ctrl-C "
                                          "does the same at any time (exit status 130)");
  auto* threads = optimize->add_option("--threads", opt.threads,
                                       "worst-first driver: threads (default 0: every core); a mesh of at least "
                                       "5,000 cells a thread is cut into as many parts; the same number gives the "
                                       "same mesh")
                      ->check(CLI::Range(0u, 4096u));
  auto* moves_per_vertex = optimize->add_option("--moves-per-vertex", opt.moves_per_vertex,
                                                "worst-first driver with smoothing: the most moves of one vertex "
                                                "(default 200; fewer end sooner, with worse cells left)")
                               ->check(CLI::Range(1, 1000000000));
  optimize->add_option("--history", opt.history, "CSV: one row per cycle");
  optimize->add_option("--stats", opt.stats, "JSON: counts, angles, ending, time");

  std::string check_path;
  auto* check = app.add_subcommand("check", "validity and Delaunay checks of a mesh");
  check->add_option("MESH", check_path, "mesh: TetGen .ele, Medit .mesh, Gmsh .msh or VTK .vtu")->required();

  Insert_options ins;
  auto* insert = app.add_subcommand("insert", "insert points into a mesh by splitting and swapping outward");
  insert->add_option("MESH", ins.mesh, "mesh: .ele, .mesh, .msh or .vtu")->required();
  insert->add_option("--points", ins.points, "TetGen .node file of the points, inserted in file order")->required();
  insert->add_option("-o,--output", ins.output, "output .ele, .mesh, .msh or .vtu")->required();
  insert->add_option("--criterion", ins.criterion, "swap criterion (default delaunay)");

  Refine_options ref;
  auto* refine = app.add_subcommand("refine", "insert sites at circumcenters: by aspect ratio or by a field's gradient");
  refine->add_option("MESH", ref.mesh, "mesh: .ele, .mesh, .msh or .vtu")->required();
  refine->add_option("-o,--output", ref.output, "output .ele, .mesh, .msh or .vtu")->required();
  refine->add_option("--by", ref.by, "aspect-ratio or gradient")->required();
  refine->add_option("--target", ref.target, "aspect-ratio: the largest aspect ratio wanted");
  refine->add_option("--ratio", ref.ratio, "aspect-ratio: edge (longest/shortest edge, default) or circumradius-inradius (R/r)");
  refine->add_option("--max-sites", ref.max_sites, "aspect-ratio: site budget");
  refine->add_option("--field", ref.field, "gradient: a vertex field of the input, or flow-density / flow-speed");
  refine->add_option("--sites", ref.sites, "gradient: sites per round, e.g. 2000,2000");
  refine->add_option("--criterion", ref.criterion, "swap criterion (default delaunay)");
  refine->add_option("--history", ref.history, "CSV: one row per round");

  std::string stats_path, stats_json;
  auto* stats = app.add_subcommand("stats", "counts, dihedral-angle and aspect-ratio extremes and histograms");
  stats->add_option("MESH", stats_path, "mesh: .ele, .mesh, .msh or .vtu")->required();
  stats->add_option("--json", stats_json, "also write the figures as JSON");

  std::string domain_name, domain_output;
  double domain_size = 0.35;
  auto* mesh_domain = app.add_subcommand("mesh-domain", "mesh a domain with CGAL Mesh_3 (two-spheres)");
  mesh_domain->add_option("DOMAIN", domain_name, "two-spheres")->required();
  mesh_domain->add_option("-o,--output", domain_output, "output .mesh, .msh, .vtu or .ele")->required();
  mesh_domain->add_option("--size", domain_size, "target edge and cell size (default 0.35: about 5,000 vertices)");


  std::size_t demo_points = 8000;
  unsigned int demo_seed = 1;
  auto* demo = app.add_subcommand("demo", "helper strategy to CGAL's Delaunay, then the paper's minimum-edge table");
  demo->add_option("--points", demo_points, "number of random points")->check(CLI::Range(4, 100000000));
  demo->add_option("--seed", demo_seed, "random seed");

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::Success& e) // --help, --version
  {
    return app.exit(e);
  }
  catch(const CLI::ParseError& e)
  {
    // A misspelled command: name it and the commands there are.
    if(argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty())
    {
      std::string names;
      for(const auto* command : app.get_subcommands([](const CLI::App*) { return true; }))
        names += (names.empty() ? "" : ", ") + command->get_name();
      std::cerr << "edge_swap: error: unknown command '" << argv[1] << "'; the commands are " << names
                << " (edge_swap --help)\n";
      return 2;
    }
    app.exit(e);
    return 2;
  }

  mesh_file_options.msh = msh_format == "4.1"          ? IO::MSH_4_1_ASCII
                          : msh_format == "4.1-binary" ? IO::MSH_4_1_BINARY
                          : msh_format == "2.2"        ? IO::MSH_2_2_ASCII
                                                       : IO::MSH_2_2_BINARY;
  mesh_file_options.vtu = vtu_format == "binary" ? IO::VTU_BINARY_ZLIB : IO::VTU_ASCII;
  try
  {
    if(*optimize)
    {
      opt.start_given = start->count() > 0;
      opt.quality_target_given = target->count() > 0;
      opt.time_limit_given = time_limit->count() > 0;
      opt.threads_given = threads->count() > 0;
      opt.moves_per_vertex_given = moves_per_vertex->count() > 0;
      opt.angle_range_given = angle_range->count() > 0;
      opt.flip_driver_options_given = perturb->count() > 0 || max_cycles->count() > 0;
      return run_optimize(opt);
    }
    if(*check) return run_check(check_path);
    if(*insert) return run_insert(ins);
    if(*refine) return run_refine(ref);
    if(*stats) return run_stats(stats_path, stats_json);
    if(*mesh_domain) return run_mesh_domain(domain_name, domain_output, domain_size);
    return run_demo(demo_points, demo_seed);
  }
  catch(const std::exception& e)
  {
    std::cerr << "edge_swap: error: " << e.what() << '\n';
    return 2;
  }
}
