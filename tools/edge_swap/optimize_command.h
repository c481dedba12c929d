// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap optimize: build or read a triangulation, run a driver, write the result.

#ifndef EDGE_SWAP_OPTIMIZE_COMMAND_H
#define EDGE_SWAP_OPTIMIZE_COMMAND_H

#include "interruption.h"
#include "mesh_files.h"
#include "progress.h"
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/mesh_statistics.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <type_traits>

namespace edge_swap {

struct Optimize_options
{
  std::string input, output, start = "placing", order;
  std::string criterion; ///< empty: `default_criterion()`
  std::string perturb = "cgal", history, stats, schedule = "queue";
  std::string reading; ///< the helper's reading of Algorithm 4 (empty: the package's)
  std::string operations; ///< the worst-first driver's operations, or paper-flips (empty: the default)
  std::string angle_range = "keep"; ///< the worst-first driver's dihedral angles: keep or free
  bool helper = false, start_given = false, paper = false, angle_range_given = false;
  bool flip_driver_options_given = false; ///< `--perturb` or `--max-cycles`, which only the flip driver reads
  double quality_target = 0;          ///< `--quality-target`, when `quality_target_given`
  bool quality_target_given = false;
  double time_limit = 0;              ///< `--time-limit`, seconds, when `time_limit_given`
  bool time_limit_given = false;
  unsigned threads = 0;               ///< `--threads`: 0 for every core
  bool threads_given = false;
  int moves_per_vertex = ES::internal::default_maximum_moves; ///< `--moves-per-vertex`
  bool moves_per_vertex_given = false;
  unsigned int seed = 0;
  std::size_t max_cycles = 1000;
};


/// Builds the start triangulation of a point set as `--start` says.
inline void build_start(Triangulation& tr, const Input& in, const std::string& start, unsigned int seed)
{
  std::vector<Triangulation::Vertex_handle> vertices;
  if(start == "placing" || start == "placing:input")
    vertices = ES::insert_by_placing(tr, in.points, ES::parameters::insertion_order(start == "placing" ? ES::SPATIAL_ORDER : ES::INPUT_ORDER));
  else if(start == "delaunay" || start.rfind("scramble:", 0) == 0)
    vertices = ES::insert_delaunay(tr, in.points);
  else
    throw Usage_error("unknown --start '" + start + "' (placing, placing:input, delaunay or scramble:K)");
  for(std::size_t k = 0; k < vertices.size(); ++k) vertices[k]->info() = k;
  if(start.rfind("scramble:", 0) == 0)
  {
    ES::scramble(tr, whole_number(start.substr(9), "--start scramble:K"), seed);
  }
}

inline nlohmann::json statistics_json(const ES::Mesh_statistics& s)
{
  return {{"vertices", s.vertices}, {"edges", s.edges}, {"faces", s.faces}, {"cells", s.cells},
          {"min_dihedral_angle", s.min_dihedral_angle}, {"max_dihedral_angle", s.max_dihedral_angle}};
}

/// Calls `run(criterion)` with the criterion named `name`.
template <class Run>
auto with_criterion(const std::string& name, Run run)
{
  if(name == "delaunay") return run(ES::Delaunay_criterion());
  if(name == "minmax-dihedral") return run(ES::Min_max_dihedral_angle_criterion());
  if(name == "maxmin-dihedral") return run(ES::Max_min_dihedral_angle_criterion());
  if(name == "min-edges") return run(ES::Min_edges_criterion());
  if(name == "aspect-ratio") return run(ES::Aspect_ratio_criterion(ES::CIRCUMRADIUS_OVER_INRADIUS));
  if(name == "edge-ratio") return run(ES::Aspect_ratio_criterion(ES::EDGE_LENGTH_RATIO));
  if(name == "radius-ratio") return run(ES::Max_min_radius_ratio_criterion());
  if(name == "dihedral-sine") return run(ES::Max_min_dihedral_sine_criterion());
  if(name == "volume-length") return run(ES::Max_min_volume_length_criterion());
  throw Usage_error("unknown --criterion '" + name + "'");
}

/// `--operations paper-flips`: the flip driver of `swap_edges` (rounds over every facet).
constexpr unsigned paper_flips = 1u << 30;

/// The bits of `--operations` (a comma-separated list).
inline unsigned quality_operations(const std::string& list)
{
  unsigned bits = 0;
  std::size_t begin = 0;
  while(begin <= list.size())
  {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string name = list.substr(begin, end - begin);
    if(name == "flips") bits |= ES::FLIPS;
    else if(name == "edge-removal") bits |= ES::EDGE_REMOVAL;
    else if(name == "multi-face-removal") bits |= ES::MULTI_FACE_REMOVAL;
    else if(name == "two-step-edge-removal") bits |= ES::TWO_STEP_EDGE_REMOVAL;
    else if(name == "smoothing") bits |= ES::SMOOTHING;
    else if(name == "boundary-smoothing") bits |= ES::SMOOTHING | ES::BOUNDARY_SMOOTHING;
    else if(name == "vertex-removal") bits |= ES::VERTEX_REMOVAL;
    else if(name == "vertex-insertion") bits |= ES::VERTEX_INSERTION;
    else if(name == "topological") bits |= ES::TOPOLOGICAL_OPERATIONS;
    else if(name == "all") bits |= ES::ALL_OPERATIONS;
    else if(name == "paper-flips") bits |= paper_flips;
    else
      throw Usage_error("--operations: unknown operation '" + name +
                        "' (flips, edge-removal, multi-face-removal, two-step-edge-removal, smoothing, "
                        "boundary-smoothing, vertex-removal, vertex-insertion, topological, all, paper-flips)");
    begin = end + 1;
  }
  if((bits & paper_flips) && bits != paper_flips)
    throw Usage_error("--operations paper-flips is the paper's driver alone; it cannot go with other operations");
  return bits;
}

/// The operations of `optimize` with a quality criterion when `--operations`
/// is not given: the best combination measured (doc/Edge_swapping_3/benchmarks.md).
constexpr const char* default_quality_operations = "all";

/// The counts and extreme qualities of the mesh's domain.
inline ES::Mesh_statistics domain_statistics(const Triangulation& tr, const Input& in)
{
  return ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
    return ES::mesh_statistics(tr, ES::parameters::mesh_constraints(constraints));
  });
}

/// The worst-first driver's visitor: its progress, and the numbers and
/// field values of the vertices that vertex insertion makes and removal takes.
template <class Criterion>
class Worst_first_visitor : public Worst_first_progress<Criterion>
{
public:
  Worst_first_visitor(const Criterion& criterion, Input& mesh)
      : Worst_first_progress<Criterion>(criterion), numbers_(mesh, &ES::two_spheres_flow_field<Point>) {}

  void after_insertion(const Triangulation& tr, Triangulation::Vertex_handle v,
                       const std::array<Triangulation::Vertex_handle, 4>& corners, const std::array<double, 4>& weights) const
  {
    numbers_.after_insertion(tr, v, corners, weights);
  }
  void before_removal(const Triangulation& tr, Triangulation::Vertex_handle v, Triangulation::Vertex_handle onto) const
  {
    numbers_.before_removal(tr, v, onto);
  }

private:
  ES::Numbered_vertex_visitor<Point> numbers_;
};

/// The worst-first driver (`--operations`) on `tr`: runs, writes, reports.
inline int run_worst_first(const Optimize_options& o, const Input& given, Triangulation& tr, unsigned operations)
{
  Input in = given; // vertex insertion appends points
  const std::size_t points_before = in.points.size();
  bool in_parts = false;
  const std::size_t vertices_before = ES::number_of_mesh_vertices(tr);
  const std::size_t cells_before = ES::number_of_mesh_cells(tr);
  namespace np = ES::parameters;
  std::optional<Interruption_scope> interruption(std::in_place);
  const double time_limit = o.time_limit_given ? o.time_limit : HUGE_VAL;
  const ES::Quality_report report = ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
    return with_criterion(o.criterion, [&](const auto& criterion) {
      if constexpr(!ES::Is_worst_tetrahedron_criterion<std::decay_t<decltype(criterion)>>::value)
        return ES::Quality_report(); // refused before any work
      else
      {
        typedef std::decay_t<decltype(criterion)> Criterion;
        in_parts = ES::internal::number_of_parts<std::decay_t<decltype(constraints)>>(
                       tr, ES::internal::threads_asked(o.threads)) > 1;
        const auto settings = np::keep_dihedral_angle_range(o.angle_range == "keep",
            np::operations(operations, np::number_of_threads(o.threads, np::maximum_moves_per_vertex(o.moves_per_vertex,
                np::stop_flag(interruption->flag(), np::mesh_constraints(constraints,
                CGAL::parameters::visitor(Worst_first_visitor<Criterion>(criterion, in))
                    .maximum_running_time(time_limit)))))));
        return o.quality_target_given
                   ? ES::improve_worst_tetrahedra(tr, criterion, np::quality_target(o.quality_target, settings))
                   : ES::improve_worst_tetrahedra(tr, criterion, settings);
      }
    });
  });
  // Parts tell of the vertices they make in an order the threads' timing decides.
  if(in_parts) ES::renumber_added_points(tr, in, points_before);
  // Ctrl-C while the files are written ends the program (no file is left half written).
  interruption.reset();
  Output_files files;
  add_mesh_files(files, o.output, tr, in);
  if(!o.stats.empty())
    files.add(o.stats, [&](std::ostream& out) {
      nlohmann::json j = {{"strategy", o.criterion},
                          {"driver", "worst first"},
                          {"operations", o.operations},
                          {"angle_range", o.angle_range},
                          {"ending", ES::swap_ending_name(report.ending)},
                          {"edge_removals", report.edge_removals},
                          {"two_step_edge_removals", report.two_step_removals},
                          {"multi_face_removals", report.face_removals},
                          {"faces_removed", report.faces_removed},
                          {"smoothing_moves", report.smoothing_moves},
                          {"vertex_removals", report.vertex_removals},
                          {"vertex_insertions", report.vertex_insertions},
                          {"flips", {{"2-3", report.flips[0]}, {"3-2", report.flips[1]}, {"2-2", report.flips[2]},
                                     {"4-4", report.flips[3]}}},
                          {"visits", report.visits},
                          {"stuck", report.stuck},
                          {"worst_before", report.worst_before},
                          {"worst_after", report.worst_after},
                          {"seconds", report.seconds}};
      if(o.quality_target_given) j["quality_target"] = o.quality_target;
      if(o.time_limit_given) j["time_limit"] = o.time_limit;
      j["threads"] = ES::internal::threads_asked(o.threads);
      j["moves_per_vertex"] = o.moves_per_vertex;
      out << j.dump(2) << '\n';
    });
  files.commit();
  const auto& f = report.flips;
  std::cout << o.criterion << ", worst first (" << o.operations << "): " << ES::swap_ending_name(report.ending)
            << "; edge removals " << report.edge_removals << " (" << report.two_step_removals
            << " more in two steps), multi-face removals " << report.face_removals
            << " (" << report.faces_removed << " faces), flips 2-3 " << f[0] << ", 3-2 " << f[1] << ", 2-2 "
            << f[2] << ", 4-4 " << f[3] << ", smoothing moves " << report.smoothing_moves;
  if(operations & (ES::VERTEX_REMOVAL | ES::VERTEX_INSERTION))
    std::cout << ", vertices removed " << report.vertex_removals << ", inserted " << report.vertex_insertions << " ("
              << vertices_before << " -> " << ES::number_of_mesh_vertices(tr) << ")";
  std::cout << "; worst "
            << report.worst_before << " -> " << report.worst_after << "; cells " << cells_before << " -> " << ES::number_of_mesh_cells(tr) << "; " << report.seconds << " s\n";
  // Interrupted: the mesh so far is written, and the status says it was cut short (128 + SIGINT, as a shell says).
  return report.ending == ES::INTERRUPTED ? 130 : 0;
}

/// The criterion of `optimize` when `--criterion` is not given: the
/// Delaunay criterion for a point set (the paper's construction) and for
/// --helper and --paper, which are its; for a mesh, the dihedral sine with
/// every operation, the best two-sided result of the quality benchmark
/// (doc/Edge_swapping_3/benchmarks.md, "Quality operations").
inline std::string default_criterion(const Optimize_options& o)
{
  return (IO::has_extension(o.input, ".node") || o.helper || o.paper) ? "delaunay" : "dihedral-sine";
}

inline int run_optimize(const Optimize_options& given)
{
  Optimize_options o = given;
  const bool criterion_given = !o.criterion.empty();
  if(!criterion_given) o.criterion = default_criterion(o);
  // Said when an option of the flip driver meets a mesh's default criterion.
  const std::string defaulted =
      criterion_given ? "" : " (a mesh's default criterion is dihedral-sine: add --criterion delaunay for the flip driver)";
  // Every option is checked before any work, and nothing is written before the end.
  std::vector<std::string> outputs = mesh_output_paths(o.output);
  outputs.push_back(o.history);
  outputs.push_back(o.stats);
  check_output_paths(outputs);
  if(o.helper && o.criterion != "delaunay")
    throw Usage_error("--helper is the helper strategy of the Delaunay criterion; it cannot go with --criterion " + o.criterion);
  if(o.perturb != "cgal" && o.perturb != "none") throw Usage_error("--perturb is cgal or none");
  ES::Face_order face_order = ES::STORAGE_ORDER;
  if(!o.order.empty() && !ES::face_order_from_name(o.order, face_order))
    throw Usage_error("--order is storage, random or priority");
  // The library's defaults: storage order, but random for the helper (which can loop in storage order).
  if(o.order.empty() && o.helper) face_order = ES::RANDOM_ORDER;
  if(o.schedule != "queue" && o.schedule != "cycles") throw Usage_error("--schedule is queue or cycles");
  ES::Helper_reading reading;
  if(!o.reading.empty())
  {
    if(!o.helper) throw Usage_error("--reading sets the helper strategy's reading of Algorithm 4: add --helper");
    if(!ES::helper_reading_from_name(o.reading, reading))
      throw Usage_error("--reading '" + o.reading + "' is not a reading: LIFETIME,CONDITION,ENDING[,same-cycle] with "
                        "LIFETIME until-destroyed, cleared-each-cycle or never-cleared, CONDITION pass-over, "
                        "any-tetrahedron or facet-cells, ENDING no-swap-no-tag or no-swap (laboratory/doc/traces.md)");
    if(!reading.is_default() && o.schedule != "cycles")
      throw Usage_error("--reading " + o.reading + " runs on the paper's cycles: add --schedule cycles (the work "
                        "queue runs the package's reading, until-destroyed,pass-over,no-swap-no-tag)");
    if(reading.made_facets == ES::MADE_FACETS_SAME_CYCLE && face_order == ES::STORAGE_ORDER)
      throw Usage_error("--reading " + o.reading + " visits the facets made in a cycle in that cycle, which needs "
                        "--order priority or random");
  }
  if(o.paper && o.criterion != "delaunay")
    throw Usage_error("--paper turns off the Delaunay repair; it cannot go with --criterion " + o.criterion);
  if(o.start.rfind("scramble:", 0) == 0) whole_number(o.start.substr(9), "--start scramble:K");
  // Delaunay and min-edges run the flip driver; a quality criterion runs the
  // worst-first driver with the default operations unless told otherwise.
  const bool quality_criterion = o.criterion != "delaunay" && o.criterion != "min-edges";
  if(!o.operations.empty() && !quality_criterion)
    throw Usage_error("--operations drives a quality criterion (minmax-dihedral, maxmin-dihedral, aspect-ratio, "
                      "edge-ratio, radius-ratio, dihedral-sine, volume-length), not --criterion " + o.criterion);
  with_criterion(o.criterion, [](const auto&) { return 0; }); // an unknown name fails here
  Optimize_options options = o;
  if(quality_criterion && options.operations.empty()) options.operations = default_quality_operations;
  unsigned operations = quality_criterion ? quality_operations(options.operations) : 0u;
  if(operations == paper_flips) operations = 0;
  if(operations != 0 && !o.history.empty())
    throw Usage_error("--history records rounds, which the worst-first driver (--operations " + options.operations +
                      ") has not; --operations paper-flips has them" + defaulted);
  if(o.quality_target_given && operations == 0)
    throw Usage_error("--quality-target sets the worst-first driver (a quality --criterion, --operations other than "
                      "paper-flips)");
  if(o.angle_range_given && operations == 0)
    throw Usage_error("--angle-range sets the worst-first driver (a quality --criterion, --operations other than "
                      "paper-flips)");
  if(o.quality_target_given && !std::isfinite(o.quality_target))
    throw Usage_error("--quality-target must be a finite number");
  if(o.time_limit_given && operations == 0)
    throw Usage_error("--time-limit sets the worst-first driver (a quality --criterion, --operations other than "
                      "paper-flips)");
  if(o.time_limit_given && !(std::isfinite(o.time_limit) && o.time_limit > 0))
    throw Usage_error("--time-limit must be a positive number of seconds");
  if(o.threads_given && operations == 0)
    throw Usage_error("--threads sets the worst-first driver (a quality --criterion, --operations other than "
                      "paper-flips)");
  if(o.moves_per_vertex_given && !(operations & ES::SMOOTHING))
    throw Usage_error(operations == 0 ? std::string("--moves-per-vertex bounds the worst-first driver's smoothing (a "
                                                    "quality --criterion, --operations other than paper-flips)")
                                      : "--moves-per-vertex bounds smoothing, which --operations " + options.operations +
                                            " leaves out: add smoothing");
  if(operations != 0 && (!o.order.empty() || o.schedule != "queue"))
    throw Usage_error("--order and --schedule set the paper's flip driver (--operations paper-flips), not the "
                      "worst-first driver (--operations " + options.operations + ")" + defaulted);
  if(operations != 0 && o.flip_driver_options_given)
    throw Usage_error("--perturb and --max-cycles set the flip driver (the Delaunay and min-edges criteria, or "
                      "--operations paper-flips), not the worst-first driver (--operations " + options.operations +
                      ")" + defaulted);

  Input in = read_input(o.input);
  Triangulation tr;
  if(in.is_mesh)
  {
    if(o.start_given) throw Usage_error("--start applies to a .node input; a mesh input is its own start");
    const std::string problem = ES::build_numbered_mesh(tr, in);
    if(!problem.empty()) throw IO::Input_error(o.input + ": " + problem);
  }
  else
  {
    require_valid_point_set(in, o.input);
    // A quality criterion starts from the Delaunay triangulation; the
    // Delaunay criterion and the helper from the paper's placing start.
    const bool delaunay_start = !o.start_given && !o.helper && o.criterion != "delaunay";
    build_start(tr, in, delaunay_start ? "delaunay" : o.start, o.seed);
    ES::mark_point_set_domain(tr);
  }

  if(operations != 0) return run_worst_first(options, in, tr, operations);

  // The full statistics (every dihedral angle) only when --stats asks for them.
  const bool with_statistics = !o.stats.empty();
  const std::size_t cells_before = ES::number_of_mesh_cells(tr);
  const ES::Mesh_statistics before = with_statistics ? domain_statistics(tr, in) : ES::Mesh_statistics();
  namespace np = ES::parameters;
  const auto perturbation = (o.perturb == "cgal") ? ES::CGAL_PERTURBATION : ES::NO_PERTURBATION;
  const auto parameters = np::schedule(
    o.schedule == "queue" ? ES::WORK_QUEUE : ES::PAPER_CYCLES,
    np::face_order(face_order, np::helper_reading(reading,
                   np::perturbation(perturbation,
                                    np::record_non_delaunay_facets(!o.history.empty(),
                                    np::cycle_visitor(cycle_progress(o.helper ? "helper" : o.criterion),
                                    np::delaunay_repair(!o.paper, CGAL::parameters::random_seed(o.seed)
                                                                    .number_of_iterations(o.max_cycles))))))));

  // A Medit mesh keeps its boundaries and subdomains; a point set or a
  // TetGen mesh is a triangulation of its convex hull, hull faces included.
  auto run = [&](const auto& parameters) {
    return ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
      if(o.helper) return CGAL::swap_edges_with_helper(tr, np::mesh_constraints(constraints, parameters));
      return with_criterion(o.criterion, [&](const auto& criterion) {
        return CGAL::swap_edges(tr, criterion, np::mesh_constraints(constraints, parameters));
      });
    });
  };
  const ES::Swap_report report = run(parameters);
  const ES::Mesh_statistics after = with_statistics ? domain_statistics(tr, in) : ES::Mesh_statistics();
  const bool repairs = !o.helper && !o.paper && o.criterion == "delaunay";

  Output_files files;
  add_mesh_files(files, o.output, tr, in);
  if(!o.history.empty())
    files.add(o.history, [&report](std::ostream& out) {
      out << "cycle,swaps_2_3,swaps_3_2,swaps_2_2,swaps_4_4,cells,non_delaunay_faces,visits,new_tags,rule\n";
      for(const auto& r : report.cycles)
        out << r.cycle << ',' << r.swaps[0] << ',' << r.swaps[1] << ',' << r.swaps[2] << ',' << r.swaps[3]
            << ',' << r.cells << ',' << r.non_delaunay_facets << ',' << r.visits << ',' << r.new_tags << ','
            << ES::round_rule_name(r.rule) << '\n';
    });
  if(!o.stats.empty())
    files.add(o.stats, [&](std::ostream& out) {
      const auto t = report.total_swaps();
      nlohmann::json j = {{"before", statistics_json(before)},
                          {"after", statistics_json(after)},
                          {"strategy", o.helper ? "helper" : o.criterion},
                          {"ending", ES::swap_ending_name(report.ending)},
                          {"cycles", report.number_of_cycles()},
                          {"swaps", {{"2-3", t[0]}, {"3-2", t[1]}, {"2-2", t[2]}, {"4-4", t[3]}}},
                          {"non_delaunay_faces", report.non_delaunay_facets},
                          {"schedule", o.schedule},
                          {"visits", report.number_of_visits()},
                          {"seconds", report.seconds}};
      if(report.loop_period > 0) j["loop"] = {{"round", report.loop_round}, {"period", report.loop_period}};
      if(repairs)
        j["delaunay_repair"] = {{"path", ES::delaunay_repair_path_name(report.repair_path)},
                                {"stuck_after_plain_flips", report.stuck_after_plain_flips},
                                {"helper_rounds", report.helper_rounds},
                                {"first_helper_round", report.first_helper_round},
                                {"rebuilt_cells", report.rebuilt_cells}};
      out << j.dump(2) << '\n';
    });
  files.commit();

  const auto t = report.total_swaps();
  std::cout << (o.helper ? "helper" : o.criterion) << ": " << ES::swap_ending_name(report.ending) << " after "
            << report.number_of_cycles() << " rounds; swaps 2-3 " << t[0] << ", 3-2 " << t[1] << ", 2-2 "
            << t[2] << ", 4-4 " << t[3] << "; cells " << cells_before << " -> " << ES::number_of_mesh_cells(tr) << "; "
            << report.seconds << " s\n";
  if(report.loop_period > 0)
    std::cout << "loop: the state after round " << report.loop_round << " is that after round "
              << report.loop_round - report.loop_period << " (period " << report.loop_period
              << "); rounds to the limit added up\n";
  if(repairs && report.repair_path != ES::PLAIN_FLIPS)
  {
    std::cout << "delaunay repair: plain flips left " << report.stuck_after_plain_flips
              << " faces not locally Delaunay; helper " << report.helper_rounds << " rounds; ";
    if(report.ending != ES::CONVERGED)
      std::cout << "not converged: " << report.non_delaunay_facets << " faces left not locally Delaunay"
                << (report.repair_path == ES::REBUILT ? "" : " (a domain mesh is never rebuilt)");
    else switch(report.repair_path)
    {
    case ES::HELPER_FLIPS: std::cout << "a helper round finished the work"; break;
    case ES::PLAIN_FLIPS_AFTER_HELPER: std::cout << "plain flips finished the work after the helper's rounds"; break;
    default:
      std::cout << "the helper had not converged, so the cells were rebuilt by flip insertion ("
                << report.rebuilt_cells << " cells)";
    }
    std::cout << "\n";
  }
  // Flip insertion ends on Delaunay (Joe 1991): a rebuild that does not is a
  // defect of the package, never hidden. The run is deterministic, so its
  // input and options are the case that replays it.
  if(repairs && report.repair_path == ES::REBUILT && report.ending != ES::CONVERGED)
  {
    std::cerr << "edge_swap: defect: the rebuild by flip insertion left " << report.non_delaunay_facets
              << " faces not locally Delaunay. The same input and options replay it; please report them.\n";
    return 1;
  }
  return 0;
}

} // namespace edge_swap

#endif
