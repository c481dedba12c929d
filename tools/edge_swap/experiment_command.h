// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap experiment: the conjecture laboratory. Enumerates instances
// (point family, size, seed, start, strategy, face order), runs them on all
// cores, appends one JSON line per instance to the output (so a stopped run
// resumes where it was: finished instances are skipped), and prints a summary
// of the whole file. `--shard I/N` keeps the instances whose number is I
// modulo N, so that N jobs of a scheduler split one experiment.

#ifndef EDGE_SWAP_EXPERIMENT_COMMAND_H
#define EDGE_SWAP_EXPERIMENT_COMMAND_H

#include "experiment_case.h"
#include "experiment_summary.h"
#include "topcom_runner.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include "output_files.h"
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <system_error>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <memory>
#include <new>
#include <thread>

namespace edge_swap {

struct Experiment_options
{
  std::vector<std::string> families{"random-cube"};
  std::vector<std::size_t> sizes{100};
  std::string seeds = "1-10";
  std::vector<std::string> starts{"placing"};
  std::vector<std::string> strategies{"plain", "helper"};
  std::vector<std::string> orders{"random"};
  std::vector<std::string> point_files;
  std::string output;
  std::string shard = "0/1";
  unsigned threads = 0;
  std::size_t max_cycles = 1000;
  std::string cases_dir;
  std::size_t stuck_case_max_points = 50;
  std::size_t topcom_limit = 100000;
};

struct Experiment_instance
{
  std::string family;
  std::size_t size = 0;
  unsigned seed = 1;
  std::string start;     ///< placing | scramble:K | topcom:I | - (insertion)
  std::string strategy;
  std::string order;

  std::string key() const
  {
    return family + "|" + std::to_string(size) + "|" + std::to_string(seed) + "|" + start + "|" + strategy + "|" + order;
  }
};

namespace internal_experiment {

inline std::pair<unsigned, unsigned> parse_range(const std::string& s, const std::string& what)
{
  const auto dash = s.find('-');
  const unsigned long long a = whole_number(s.substr(0, dash), what, 4000000000ULL);
  const unsigned long long b = dash == std::string::npos ? a : whole_number(s.substr(dash + 1), what, 4000000000ULL);
  if(b < a) throw Usage_error(what + " '" + s + "' is not N or A-B with A <= B");
  return {unsigned(a), unsigned(b)};
}

inline std::pair<std::size_t, std::size_t> parse_shard(const std::string& s)
{
  const auto slash = s.find('/');
  if(slash == std::string::npos) throw Usage_error("--shard '" + s + "' is not I/N with 0 <= I < N");
  const std::size_t i = whole_number(s.substr(0, slash), "--shard I/N"), n = whole_number(s.substr(slash + 1), "--shard I/N");
  if(n == 0 || i >= n) throw Usage_error("--shard '" + s + "' is not I/N with 0 <= I < N");
  return {i, n};
}

// The points of a user file (family "file:PATH"), read once for all instances.
typedef std::map<std::string, std::vector<Point>> Point_files;

inline std::vector<Point> read_point_file(const std::string& path)
{
  std::vector<Point> points;
  for(const auto& p : CGAL::Edge_swapping_3::IO::read_node_file(path).points) points.emplace_back(p[0], p[1], p[2]);
  const std::string problem = ES::point_set_problem(points);
  if(!problem.empty()) throw Usage_error(path + ": " + problem);
  return points;
}

// The points of a family, in the family's own order.
inline std::vector<Point> family_points(const std::string& family, std::size_t size, unsigned seed,
                                        const Point_files& files)
{
  if(family.rfind("file:", 0) == 0) return files.at(family);
  try
  {
    return ES::make_point_family<Point>(family, size, seed);
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(e.what());
  }
}

// The same points in an order drawn from `seed` (placing and insertion orders).
inline std::vector<Point> shuffled(std::vector<Point> points, unsigned seed)
{
  CGAL::Random r(seed);
  for(std::size_t k = 0; k + 1 < points.size(); ++k)
    std::swap(points[k], points[k + std::size_t(r.get_int(0, int(points.size() - k)))]);
  return points;
}

inline std::string file_safe(std::string s)
{
  for(char& ch : s)
    if(!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.') ch = '_';
  return s;
}

} // namespace internal_experiment

inline int run_experiment(const Experiment_options& opt)
{
  using namespace internal_experiment;
  if(opt.output.empty()) throw Usage_error("-o OUT.jsonl is required");
  const auto [first_seed, last_seed] = parse_range(opt.seeds, "--seeds");
  const auto [shard, shards] = parse_shard(opt.shard);
  for(const auto& s : opt.strategies)
    if(s != "plain" && s != "helper" && s != "insertion") throw Usage_error("unknown strategy '" + s + "'");
  for(const auto& o : opt.orders)
    if(o != "storage" && o != "random") throw Usage_error("unknown face order '" + o + "'");
  for(const auto& s : opt.starts)
    if(s != "placing" && s != "topcom" && s.rfind("scramble:", 0) != 0) throw Usage_error("unknown start '" + s + "'");
  std::vector<std::string> families; // --families "" leaves only the point files
  for(const auto& f : opt.families)
    if(!f.empty()) families.push_back(f);
  for(const auto& f : opt.point_files) families.push_back("file:" + f);
  if(families.empty()) throw Usage_error("no point family and no --points-file");
  if(opt.threads > 256) throw Usage_error("--threads is at most 256");
  if(opt.max_cycles > 1000000000) throw Usage_error("--max-cycles is at most 1000000000");
  for(std::size_t size : opt.sizes)
    if(size < 4 || size > 100000000)
      throw Usage_error("--sizes: " + std::to_string(size) + " points; a size is from 4 to 100000000");
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
  Point_files files;
  for(const auto& f : families)
  {
    if(f.rfind("file:", 0) == 0)
    {
      files[f] = read_point_file(f.substr(5));
      if(topcom && files[f].size() > topcom_max_points)
        throw Usage_error("--starts topcom takes at most 20 points; '" + f.substr(5) + "' has " +
                          std::to_string(files[f].size()));
    }
    else
      for(std::size_t size : opt.sizes)
      {
        const auto points = family_points(f, size, first_seed, files);
        if(topcom && points.size() > topcom_max_points)
          throw Usage_error("--starts topcom takes at most 20 points; family " + f + " has " + std::to_string(points.size()));
        const std::string problem = ES::point_set_problem(points);
        if(!problem.empty())
          throw Usage_error("family " + f + " with " + std::to_string(size) + " points (seed " + std::to_string(first_seed) +
                            "): " + problem);
      }
  }
  // The results already there are checked before anything is appended; a
  // line cut short by a stop is removed, so that appending starts on a new line.
  const bool existed = std::filesystem::exists(opt.output);
  std::set<std::string> done;
  for(const auto& j : read_results_file(opt.output, true)) done.insert(j["key"].get<std::string>());

  // Enumerate: the same list, in the same order, for every shard and every resume.
  std::vector<Experiment_instance> instances;
  std::map<std::string, std::vector<std::vector<std::array<std::size_t, 4>>>> topcom_cells; // by point set
  for(const auto& family : families)
    for(std::size_t size : family.rfind("file:", 0) == 0 ? std::vector<std::size_t>{0} : opt.sizes)
      for(unsigned seed = first_seed; seed <= last_seed; ++seed)
      {
        const std::string set = family + "|" + std::to_string(size) + "|" + std::to_string(seed);
        for(const auto& start : opt.starts)
        {
          std::size_t count = 1;
          if(start == "topcom")
          {
            bool truncated = false;
            auto& cells = topcom_cells[set] = topcom_triangulations(family_points(family, size, seed, files), opt.topcom_limit,
                                                                     truncated);
            count = cells.size();
            std::cerr << "experiment: TOPCOM: " << count << (truncated ? "+ (limit)" : "")
                      << " fine triangulations of " << set << "\n";
          }
          for(std::size_t t = 0; t < count; ++t)
            for(const auto& strategy : opt.strategies)
              if(strategy != "insertion")
                for(const auto& order : opt.orders)
                  instances.push_back({family, size, seed, start == "topcom" ? "topcom:" + std::to_string(t) : start,
                                       strategy, order});
        }
        for(const auto& order : opt.orders)
          if(std::find(opt.strategies.begin(), opt.strategies.end(), "insertion") != opt.strategies.end())
            instances.push_back({family, size, seed, "-", "insertion", order});
      }

  std::vector<const Experiment_instance*> todo;
  std::size_t in_shard = 0;
  for(std::size_t k = 0; k < instances.size(); ++k)
    if(k % shards == shard)
    {
      ++in_shard;
      if(!done.count(instances[k].key())) todo.push_back(&instances[k]);
    }
  std::cerr << "experiment: " << instances.size() << " instances, " << in_shard << " in shard " << shard << "/" << shards
            << ", " << (in_shard - todo.size()) << " already in " << opt.output << ", " << todo.size() << " to run\n";
  if(!opt.cases_dir.empty()) std::filesystem::create_directories(opt.cases_dir);

  std::ofstream out(opt.output, std::ios::app | std::ios::binary);
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  std::string write_error;
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0, failures = 0;
  CGAL::Real_timer timer;
  timer.start();
  double next_report = 2;
  std::string error;

  auto work_on_instances = [&]() {
    for(std::size_t k; (k = next++) < todo.size();)
    {
      const Experiment_instance& in = *todo[k];
      Experiment_case c;
      try
      {
        c.points = family_points(in.family, in.size, in.seed, files);
        c.strategy = in.strategy;
        c.order = in.order;
        c.seed = in.seed;
        c.max_cycles = opt.max_cycles;
        if(in.start.rfind("topcom:", 0) == 0)
        {
          c.start = "cells";
          c.cells = oriented_cells(c.points, topcom_cells.at(in.family + "|" + std::to_string(in.size) + "|" +
                                                            std::to_string(in.seed))[std::stoul(in.start.substr(7))]);
        }
        else
        {
          c.start = (in.start == "-") ? "-" : in.start;
          if(in.start == "placing" || in.start == "-") c.points = shuffled(c.points, in.seed);
        }
        const Experiment_outcome o = run_case(c);
        nlohmann::json j = {{"key", in.key()},         {"family", in.family},     {"size", in.size},
                            {"points", c.points.size()}, {"seed", in.seed},        {"start", in.start},
                            {"strategy", in.strategy},  {"order", in.order},       {"failure", is_failure(c, o)}};
        j.update(outcome_json(o));
        std::string saved;
        if(!opt.cases_dir.empty() &&
           (is_failure(c, o) || (o.ending == "stuck" && c.points.size() <= opt.stuck_case_max_points)))
        {
          saved = opt.cases_dir + "/" + (is_failure(c, o) ? "failure-" : "stuck-") + file_safe(in.key()) + ".json";
          nlohmann::json file = case_json(c);
          file["outcome"] = outcome_json(o);
          file["instance"] = in.key();
          std::ofstream case_file(saved);
          case_file << file.dump(1) << '\n';
          case_file.close();
          if(!case_file) throw Usage_error("cannot write '" + saved + "'");
        }
        std::lock_guard<std::mutex> lock(mutex);
        errno = 0;
        out << j.dump() << '\n' << std::flush;
        if(!out)
        {
          if(write_error.empty())
            write_error = "cannot write '" + opt.output + "'" + (errno ? std::string(": ") + std::strerror(errno) : "");
          next = todo.size();
          return;
        }
        ++finished;
        failures += is_failure(c, o);
        if(timer.time() >= next_report)
        {
          next_report = timer.time() + 2;
          std::cerr << "experiment: " << finished << "/" << todo.size() << " (" << int(finished / timer.time())
                    << " a second), failures " << failures << "\n";
        }
      }
      catch(const std::exception& e)
      {
        std::lock_guard<std::mutex> lock(mutex);
        if(error.empty()) error = in.key() + ": " + e.what();
        next = todo.size();
      }
    }
  };
  // A thread never lets an exception out (that would abort the program): one
  // thrown while an error is being recorded (memory exhausted) stops the run.
  auto work = [&]() noexcept {
    try
    {
      work_on_instances();
    }
    catch(...)
    {
      std::lock_guard<std::mutex> lock(mutex);
      if(error.empty()) error = "out of memory"; // short: no allocation
      next = todo.size();
    }
  };
  // As many threads as can start (at least this one): a thread that cannot
  // start is reported, not fatal. Thread stacks take address space until none
  // is left, so 32 MB of it is held back while they start, for the work.
  const unsigned wanted = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  std::unique_ptr<char[]> held_back(new(std::nothrow) char[std::size_t(32) << 20]);
  std::vector<std::thread> pool;
  pool.reserve(wanted);
  for(unsigned t = 1; t < wanted; ++t)
  {
    try
    {
      pool.emplace_back(work);
    }
    catch(const std::system_error& e)
    {
      std::cerr << "experiment: warning: only " << t << " of " << wanted << " threads could start (" << e.what() << ")\n";
      break;
    }
  }
  held_back.reset();
  const unsigned threads = unsigned(pool.size()) + 1;
  work();
  for(auto& t : pool) t.join();
  out.close();
  if(!out && write_error.empty()) write_error = "cannot write '" + opt.output + "'";
  if(!write_error.empty())
  {
    if(!existed && finished == 0) std::remove(opt.output.c_str());
    throw Usage_error(write_error);
  }
  if(!error.empty()) throw Usage_error(error);
  std::cerr << "experiment: " << finished << " instances in " << timer.time() << " s on " << threads << " threads\n";
  print_summary(opt.output, read_results_file(opt.output, false), std::cout);
  return 0;
}

} // namespace edge_swap

#endif
