// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap_lab experiment: the conjecture laboratory. Enumerates instances
// (point family, size, seed, start, strategy, face order), runs them on all
// cores, appends one JSON line per instance to the output (so a stopped run
// resumes where it was: finished instances are skipped), and prints a summary
// of the whole file. `--shard I/N` keeps the instances whose number is I
// modulo N, so that N jobs of a scheduler split one experiment. With
// --stream, TOPCOM starts are streamed instead (experiment_stream.h).

#ifndef EDGE_SWAP_LAB_EXPERIMENT_COMMAND_H
#define EDGE_SWAP_LAB_EXPERIMENT_COMMAND_H

#include "experiment_options.h"
#include "experiment_stream.h"
#include "types.h"
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_experiment.h>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace edge_swap_lab {


inline int run_experiment(const Experiment_options& opt)
{
  using namespace internal_experiment;
  if(opt.output.empty()) throw Usage_error("-o OUT.jsonl is required");
  ES::Conjecture_experiment<Point> experiment;
  std::tie(experiment.first_seed, experiment.last_seed) = parse_range(opt.seeds, "--seeds");
  const auto [shard, shards] = parse_shard(opt.shard);
  experiment.strategies.clear();
  for(const auto& s : opt.strategies)
  {
    experiment.strategies.emplace_back();
    if(!ES::conjecture_strategy_from_name(s, experiment.strategies.back())) throw Usage_error("unknown strategy '" + s + "'");
  }
  experiment.orders.clear();
  for(const auto& o : opt.orders)
  {
    experiment.orders.emplace_back();
    if(!ES::face_order_from_name(o, experiment.orders.back())) throw Usage_error("unknown face order '" + o + "'");
  }
  if(opt.readings == "all")
    experiment.readings = ES::all_helper_readings();
  else if(!opt.readings.empty())
  {
    experiment.readings.clear();
    std::string name;
    std::istringstream list(opt.readings);
    while(std::getline(list, name, ';'))
    {
      experiment.readings.emplace_back();
      if(!ES::helper_reading_from_name(name, experiment.readings.back()))
        throw Usage_error("--readings: unknown reading '" + name + "' (laboratory/doc/traces.md)");
    }
    if(experiment.readings.empty()) throw Usage_error("--readings: no reading");
  }
  for(const auto& s : opt.starts)
    if(s != "placing" && s != "topcom" && s.rfind("scramble:", 0) != 0) throw Usage_error("unknown start '" + s + "'");
  experiment.starts = opt.starts;
  experiment.families.clear(); // --families "" leaves only the point files
  for(const auto& f : opt.families)
    if(!f.empty()) experiment.families.push_back(f);
  for(const auto& f : opt.point_files) experiment.families.push_back("file:" + f);
  if(experiment.families.empty()) throw Usage_error("no point family and no --points-file");
  if(opt.threads > 256) throw Usage_error("--threads is at most 256");
  if(opt.max_cycles > 1000000000) throw Usage_error("--max-cycles is at most 1000000000");
  experiment.max_cycles = opt.max_cycles;
  if(!ES::order_seeds_from_name(opt.order_seeds, experiment.order_seeds))
    throw Usage_error("--order-seeds '" + opt.order_seeds + "' is not per-set or per-start");
  for(std::size_t size : opt.sizes)
    if(size < 4 || size > 100000000)
      throw Usage_error("--sizes: " + std::to_string(size) + " points; a size is from 4 to 100000000");
  experiment.sizes = opt.sizes;
  for(const auto& s : opt.starts)
    if(s.rfind("scramble:", 0) == 0) whole_number(s.substr(9), "--starts scramble:K");
  check_output_paths({opt.output});
  if(!opt.cases_dir.empty() && std::filesystem::exists(opt.cases_dir) && !std::filesystem::is_directory(opt.cases_dir))
    throw Usage_error("--cases '" + opt.cases_dir + "' is not a folder");
  // TOPCOM enumerates every triangulation: beyond a few dozen points it would
  // not end, so a typo is not allowed to start it.
  constexpr std::size_t topcom_max_points = 20;
  const bool topcom = std::find(opt.starts.begin(), opt.starts.end(), "topcom") != opt.starts.end();
  // Read, and an unknown family name or a point set that cannot be
  // triangulated rejected, before anything runs. A family is checked at each
  // size with the first seed; every instance checks its own points again.
  for(const auto& f : experiment.families)
  {
    if(f.rfind("file:", 0) == 0)
    {
      const auto& points = experiment.point_files[f] = read_point_file(f.substr(5));
      if(topcom && points.size() > topcom_max_points)
        throw Usage_error("--starts topcom takes at most 20 points; '" + f.substr(5) + "' has " +
                          std::to_string(points.size()));
    }
    else
      for(std::size_t size : opt.sizes)
      {
        std::vector<Point> points;
        try
        {
          points = ES::conjecture_family_points(experiment, f, size, experiment.first_seed);
        }
        catch(const std::invalid_argument& e)
        {
          throw Usage_error(e.what());
        }
        if(topcom && points.size() > topcom_max_points)
          throw Usage_error("--starts topcom takes at most 20 points; family " + f + " has " + std::to_string(points.size()));
        const std::string problem = ES::point_set_problem(points);
        if(!problem.empty())
          throw Usage_error("family " + f + " with " + std::to_string(size) + " points (seed " +
                            std::to_string(experiment.first_seed) + "): " + problem);
      }
  }
  if(opt.stream) return run_streamed_experiment(opt, experiment, shard, shards);
  // The results already there are checked before anything is appended; a
  // line cut short by a stop is removed, so that appending starts on a new line.
  const bool existed = std::filesystem::exists(opt.output);
  std::set<std::string> done;
  for(const auto& j : IO::read_results_file(opt.output, true))
  {
    // A line of a TOPCOM start has an "order_seed" exactly when it ran with a seed per start.
    if(j["start"].get<std::string>().rfind("topcom:", 0) == 0 &&
       j.contains("order_seed") != (experiment.order_seeds == ES::ORDER_SEED_PER_START))
      throw Usage_error(opt.output + " was written with --order-seeds " +
                        (j.contains("order_seed") ? "per-start" : "per-set") + "; this run has " + opt.order_seeds);
    done.insert(j["key"].get<std::string>());
  }

  // Enumerate: the same list, in the same order, for every shard and every resume.
  const ES::Conjecture_instances instances = ES::conjecture_instances(experiment, [&](const std::vector<Point>& points, const std::string& set) {
    IO::Topcom_triangulations t;
    try
    {
      t = IO::topcom_triangulations(points, opt.topcom_limit);
    }
    catch(const std::invalid_argument& e)
    {
      throw Usage_error(e.what());
    }
    std::cerr << "experiment: TOPCOM: " << t.triangulations.size() << (t.truncated ? "+ (limit)" : "")
              << " fine triangulations of " << set << "\n";
    return t.triangulations;
  });
  std::vector<const ES::Conjecture_instance*> todo;
  std::size_t in_shard = 0;
  for(std::size_t k = 0; k < instances.instances.size(); ++k)
    if(k % shards == shard)
    {
      ++in_shard;
      if(!done.count(instances.instances[k].key())) todo.push_back(&instances.instances[k]);
    }
  std::cerr << "experiment: " << instances.instances.size() << " instances, " << in_shard << " in shard " << shard << "/"
            << shards << ", " << (in_shard - todo.size()) << " already in " << opt.output << ", " << todo.size()
            << " to run\n";
  if(!opt.cases_dir.empty()) std::filesystem::create_directories(opt.cases_dir);

  std::ofstream out(opt.output, std::ios::app | std::ios::binary);
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  std::size_t finished = 0, failures = 0;
  CGAL::Real_timer timer;
  timer.start();
  double next_report = 2;
  // One instance at a time: its results line, and its case file when it failed or is a small stuck one.
  auto record = [&](const ES::Conjecture_instance& in, const ES::Conjecture_case<Point>& c, const ES::Conjecture_outcome& o) {
    const bool failure = ES::is_counterexample(c, o);
    const nlohmann::json j = instance_line(in, c, o, experiment.order_seeds);
    save_case_if_wanted(opt, in, c, o);
    errno = 0;
    out << j.dump() << '\n' << std::flush;
    if(!out)
    {
      if(!existed && finished == 0) std::remove(opt.output.c_str());
      throw Usage_error("cannot write '" + opt.output + "'" + (errno ? std::string(": ") + std::strerror(errno) : ""));
    }
    ++finished;
    failures += failure;
    if(!quiet && timer.time() >= next_report)
    {
      next_report = timer.time() + 2;
      std::cerr << "experiment: " << finished << "/" << todo.size() << " (" << int(finished / timer.time())
                << " a second), failures " << failures << "\n";
    }
  };
  unsigned threads = 0;
  try
  {
    threads = ES::run_conjecture_experiment(todo, experiment, instances,
                                            ES::parameters::number_of_threads(opt.threads, CGAL::parameters::visitor(record)));
  }
  catch(const std::bad_alloc&)
  {
    throw Usage_error("out of memory");
  }
  out.close();
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  if(opt.threads > threads)
    std::cerr << "experiment: warning: built without TBB, so " << threads << " thread ran of " << opt.threads
              << " asked\n";
  std::cerr << "experiment: " << finished << " instances in " << timer.time() << " s on " << threads << " threads\n";
  IO::print_results_summary(opt.output, IO::read_results_file(opt.output, false), std::cout);
  return 0;
}

} // namespace edge_swap_lab

#endif
