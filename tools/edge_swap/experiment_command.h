// edge_swap experiment: the conjecture laboratory. Enumerates instances
// (point family, size, seed, start, strategy, face order), runs them on all
// cores, appends one JSON line per instance to the output (so a stopped run
// resumes where it was: finished instances are skipped), and prints a summary
// of the whole file. `--shard I/N` keeps the instances whose number is I
// modulo N, so that N jobs of a scheduler split one experiment.
//
// edge_swap shrink: removes points from a saved case while it still fails.

#ifndef EDGE_SWAP_EXPERIMENT_COMMAND_H
#define EDGE_SWAP_EXPERIMENT_COMMAND_H

#include "experiment_case.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/IO/topcom.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

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
  try
  {
    const auto dash = s.find('-');
    std::size_t used = 0;
    const unsigned long a = std::stoul(s.substr(0, dash), &used);
    if(used != (dash == std::string::npos ? s.size() : dash)) throw std::invalid_argument(s);
    unsigned long b = a;
    if(dash != std::string::npos)
    {
      b = std::stoul(s.substr(dash + 1), &used);
      if(used != s.size() - dash - 1) throw std::invalid_argument(s);
    }
    if(b < a || b > 4000000000UL) throw std::invalid_argument(s);
    return {unsigned(a), unsigned(b)};
  }
  catch(const std::exception&)
  {
    throw Usage_error(what + " '" + s + "' is not N or A-B");
  }
}

inline std::pair<std::size_t, std::size_t> parse_shard(const std::string& s)
{
  const auto slash = s.find('/');
  try
  {
    if(slash == std::string::npos) throw std::invalid_argument(s);
    const std::size_t i = std::stoul(s.substr(0, slash)), n = std::stoul(s.substr(slash + 1));
    if(n == 0 || i >= n) throw std::invalid_argument(s);
    return {i, n};
  }
  catch(const std::exception&)
  {
    throw Usage_error("--shard '" + s + "' is not I/N with 0 <= I < N");
  }
}

// The points of a family (or of a user file, family "file:PATH"), in the
// family's own order.
inline std::vector<Point> family_points(const std::string& family, std::size_t size, unsigned seed)
{
  if(family.rfind("file:", 0) == 0)
  {
    std::vector<Point> points;
    for(const auto& p : CGAL::Edge_swapping_3::IO::read_node_file(family.substr(5)).points)
      points.emplace_back(p[0], p[1], p[2]);
    return points;
  }
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

inline std::string topcom_program()
{
  for(const char* name : {"topcom-points2allfinetriangs", "points2allfinetriangs"})
    if(std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0) return name;
  throw Usage_error("TOPCOM is not installed (Debian: apt-get install topcom)");
}

// Every fine triangulation of `points` (at most `limit`), from TOPCOM.
inline std::vector<std::vector<std::array<std::size_t, 4>>> topcom_triangulations(const std::vector<Point>& points,
                                                                                  std::size_t limit, bool& truncated)
{
  const std::string program = topcom_program();
  const auto dir = std::filesystem::temp_directory_path();
  const std::string stem = (dir / ("edge_swap_topcom_" + std::to_string(::getpid()) + "_" +
                                   std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()))))
                               .string();
  {
    std::ofstream in(stem + ".in");
    try
    {
      CGAL::Edge_swapping_3::IO::write_topcom_points(in, points);
    }
    catch(const std::invalid_argument& e)
    {
      throw Usage_error(e.what());
    }
  }
  const std::string command = program + " < '" + stem + ".in' 2> /dev/null | head -n " + std::to_string(limit) +
                              " > '" + stem + ".out'";
  const int status = std::system(command.c_str());
  std::ifstream out(stem + ".out");
  auto triangulations = CGAL::Edge_swapping_3::IO::read_topcom_triangulations(out);
  std::remove((stem + ".in").c_str());
  std::remove((stem + ".out").c_str());
  if(status != 0 && triangulations.empty()) throw std::runtime_error("TOPCOM failed: " + command);
  truncated = triangulations.size() >= limit;
  return triangulations;
}

// The instance file lines already there, by key; a last line cut short by a
// stop is removed so that appending starts on a new line.
inline std::set<std::string> finished_keys(const std::string& path)
{
  std::set<std::string> keys;
  std::ifstream in(path, std::ios::binary);
  if(!in) return keys;
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto last_newline = all.rfind('\n');
  const std::size_t complete = (last_newline == std::string::npos) ? 0 : last_newline + 1;
  if(complete != all.size()) std::filesystem::resize_file(path, complete);
  std::istringstream lines(all.substr(0, complete));
  std::string line;
  while(std::getline(lines, line))
  {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if(!j.is_discarded() && j.contains("key")) keys.insert(j["key"].get<std::string>());
  }
  return keys;
}

inline std::string file_safe(std::string s)
{
  for(char& ch : s)
    if(!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.') ch = '_';
  return s;
}

// The summary of every instance in the file: per family, start, strategy and
// order; and per TOPCOM point set.
inline void print_summary(const std::string& path, std::ostream& os)
{
  struct Row
  {
    std::size_t instances = 0, converged = 0, stuck = 0, limit = 0, equal = 0, failures = 0, invalid = 0;
    double cycles = 0, seconds = 0;
  };
  std::map<std::array<std::string, 4>, Row> rows;
  struct Topcom_row
  {
    std::set<std::string> triangulations, stuck_from, failed_from;
    std::size_t plain = 0, plain_stuck = 0, helper = 0, helper_failed = 0;
  };
  std::map<std::string, Topcom_row> topcom;
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if(j.is_discarded() || !j.contains("key")) continue;
    std::string start = j["start"];
    const bool is_topcom = start.rfind("topcom:", 0) == 0;
    if(is_topcom) start = "topcom";
    Row& r = rows[{j["family"], start, j["strategy"], j["order"]}];
    ++r.instances;
    const std::string ending = j["ending"];
    r.converged += ending == "converged";
    r.stuck += ending == "stuck";
    r.limit += ending == "cycle limit reached";
    r.equal += j["equal_to_cgal"].get<bool>();
    r.failures += j["failure"].get<bool>();
    r.invalid += !j["valid"].get<bool>();
    r.cycles += j["cycles"].get<double>();
    r.seconds += j["seconds"].get<double>();
    if(is_topcom)
    {
      Topcom_row& t = topcom[j["family"].get<std::string>() + " n=" + std::to_string(j["points"].get<std::size_t>()) +
                             " seed " + std::to_string(j["seed"].get<unsigned>())];
      t.triangulations.insert(j["start"].get<std::string>());
      const bool stuck = j["strategy"] == "plain" && ending == "stuck";
      const bool failed = j["strategy"] == "helper" && j["failure"].get<bool>();
      t.plain += j["strategy"] == "plain";
      t.helper += j["strategy"] == "helper";
      t.plain_stuck += stuck;
      t.helper_failed += failed;
      if(stuck) t.stuck_from.insert(j["start"].get<std::string>());
      if(failed) t.failed_from.insert(j["start"].get<std::string>());
    }
  }
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%-18s %-12s %-9s %-7s %9s %9s %7s %7s %9s %8s %7s %11s\n", "family", "start",
                "strategy", "order", "instances", "converged", "stuck", "limit", "equal", "failures", "invalid",
                "mean cycles");
  os << buffer;
  std::size_t total = 0;
  for(const auto& [k, r] : rows)
  {
    total += r.instances;
    std::snprintf(buffer, sizeof buffer, "%-18s %-12s %-9s %-7s %9zu %9zu %7zu %7zu %9zu %8zu %7zu %11.1f\n",
                  k[0].c_str(), k[1].c_str(), k[2].c_str(), k[3].c_str(), r.instances, r.converged, r.stuck, r.limit,
                  r.equal, r.failures, r.invalid, r.cycles / double(r.instances));
    os << buffer;
  }
  os << total << " instances in " << path << " (failures: the helper strategy or insertion not ending on CGAL's "
     << "Delaunay triangulation)\n";
  if(!topcom.empty())
  {
    os << "\nTOPCOM starts (every fine triangulation):\n";
    for(const auto& [name, t] : topcom)
      os << "  " << name << ": " << t.triangulations.size() << " triangulations; plain stuck from "
         << t.stuck_from.size() << " (" << t.plain_stuck << " of " << t.plain << " runs); helper failed from "
         << t.failed_from.size() << " (" << t.helper_failed << " of " << t.helper << " runs)\n";
  }
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
  for(const auto& f : families)
    if(f.rfind("file:", 0) != 0) family_points(f, 4, 1); // an unknown name fails here, before anything runs

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
            auto& cells = topcom_cells[set] = topcom_triangulations(family_points(family, size, seed), opt.topcom_limit,
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

  const std::set<std::string> done = finished_keys(opt.output);
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

  std::ofstream out(opt.output, std::ios::app);
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0, failures = 0;
  CGAL::Real_timer timer;
  timer.start();
  double next_report = 2;
  std::string error;

  auto work = [&]() {
    for(std::size_t k; (k = next++) < todo.size();)
    {
      const Experiment_instance& in = *todo[k];
      Experiment_case c;
      try
      {
        c.points = family_points(in.family, in.size, in.seed);
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
          if(!(std::ofstream(saved) << file.dump(1) << '\n')) throw Usage_error("cannot write '" + saved + "'");
        }
        std::lock_guard<std::mutex> lock(mutex);
        out << j.dump() << '\n' << std::flush;
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
  const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for(unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
  for(auto& t : pool) t.join();
  out.close();
  if(!error.empty()) throw Usage_error(error);
  std::cerr << "experiment: " << finished << " instances in " << timer.time() << " s on " << threads << " threads\n";
  print_summary(opt.output, std::cout);
  return 0;
}

/// Runs a saved case again and prints its outcome (JSON).
inline int run_replay(const std::string& path, std::size_t max_cycles)
{
  std::ifstream in(path);
  if(!in) throw Usage_error("cannot read '" + path + "'");
  const auto j = nlohmann::json::parse(in, nullptr, false);
  if(j.is_discarded()) throw Usage_error("'" + path + "' is not JSON");
  Experiment_case c = case_from_json(j);
  if(max_cycles) c.max_cycles = max_cycles;
  std::cout << outcome_json(run_case(c)).dump() << '\n';
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
  std::ifstream in(opt.input);
  if(!in) throw Usage_error("cannot read '" + opt.input + "'");
  const auto j = nlohmann::json::parse(in, nullptr, false);
  if(j.is_discarded()) throw Usage_error("'" + opt.input + "' is not JSON");
  Experiment_case c = case_from_json(j);
  if(c.start == "cells") throw Usage_error("a case with an explicit start triangulation cannot be shrunk");
  const std::string expect = !opt.expect.empty() ? opt.expect : (c.strategy == "plain" ? "stuck" : "failure");
  if(expect != "stuck" && expect != "failure") throw Usage_error("--expect is stuck or failure");
  auto fails = [&](const Experiment_case& k) {
    if(!ES::point_set_problem(k.points, K()).empty()) return false;
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
  std::ofstream file(opt.output);
  if(!(file << out.dump(1) << '\n'))
  {
    file.close();
    std::remove(opt.output.c_str());
    throw Usage_error("cannot write '" + opt.output + "'");
  }
  std::cout << "shrink: " << c.points.size() << " points still " << expect << " (" << opt.output << ")\n";
  return 0;
}

} // namespace edge_swap

#endif
