// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap experiment --stream: TOPCOM's triangulations as they are
// enumerated, never all held. They are run in batches of a fixed size; each
// batch appends the lines of its instances that did not end on CGAL's
// Delaunay triangulation (stuck, at the cycle limit, failed, invalid) and
// one tally line with the counts of all of them. A stopped run resumes after
// the last tally (what a batch wrote before its tally is removed); `--shard
// I/N` keeps the batches whose number is I modulo N.
//
// The file: a first line {"stream": OPTIONS}, then instance lines (as
// without --stream) and lines {"tally": {...}} (doc/Edge_swapping_3/conjectures.md).

#ifndef EDGE_SWAP_EXPERIMENT_STREAM_H
#define EDGE_SWAP_EXPERIMENT_STREAM_H

#include "experiment_options.h"
#include <CGAL/Edge_swapping_3/IO/topcom_runner.h>
#include <CGAL/Real_timer.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace edge_swap {
namespace internal_experiment {

/// The counts of one row (strategy, order, reading) of a tally.
struct Stream_row
{
  std::size_t instances = 0, converged = 0, stuck = 0, limit = 0, equal = 0, failures = 0, invalid = 0, bad_start = 0;
  double cycles = 0, swaps = 0, seconds = 0;
  std::size_t max_cycles = 0;

  void add(const ES::Conjecture_case<Point>& c, const ES::Conjecture_outcome& o)
  {
    ++instances;
    converged += o.ending == ES::CONVERGED;
    stuck += o.ending == ES::STUCK;
    limit += o.ending == ES::CYCLE_LIMIT_REACHED;
    equal += o.equal_to_cgal;
    failures += ES::is_counterexample(c, o);
    invalid += !o.valid;
    bad_start += o.bad_start;
    cycles += double(o.cycles);
    for(std::size_t s : o.swaps) swaps += double(s);
    seconds += o.seconds;
    max_cycles = (std::max)(max_cycles, o.cycles);
  }
  void add(const Stream_row& r)
  {
    instances += r.instances, converged += r.converged, stuck += r.stuck, limit += r.limit, equal += r.equal;
    failures += r.failures, invalid += r.invalid, bad_start += r.bad_start;
    cycles += r.cycles, swaps += r.swaps, seconds += r.seconds;
    max_cycles = (std::max)(max_cycles, r.max_cycles);
  }
  nlohmann::json json() const
  {
    return {{"instances", instances}, {"converged", converged}, {"stuck", stuck}, {"limit", limit},
            {"equal", equal},         {"failures", failures},   {"invalid", invalid}, {"bad_start", bad_start},
            {"cycles", cycles},       {"swaps", swaps},         {"seconds", seconds}, {"max_cycles", max_cycles}};
  }
  static Stream_row from_json(const nlohmann::json& j)
  {
    Stream_row r;
    r.instances = j.at("instances"), r.converged = j.at("converged"), r.stuck = j.at("stuck"), r.limit = j.at("limit");
    r.equal = j.at("equal"), r.failures = j.at("failures"), r.invalid = j.at("invalid"), r.bad_start = j.at("bad_start");
    r.cycles = j.at("cycles"), r.swaps = j.at("swaps"), r.seconds = j.at("seconds"), r.max_cycles = j.at("max_cycles");
    return r;
  }
};

/// A row's name: strategy, order, and the reading when it is not the package's.
inline std::array<std::string, 3> stream_row_key(const ES::Conjecture_instance& in)
{
  return {ES::conjecture_strategy_name(in.strategy), ES::face_order_name(in.order),
          in.reading.is_default() ? std::string() : ES::helper_reading_name(in.reading)};
}

/// One tally: the counts of the triangulations [first, first + count) of a point set.
struct Stream_tally
{
  std::string set;
  std::size_t points = 0, first = 0, count = 0;
  std::size_t plain_stuck_from = 0, helper_failed_from = 0; ///< triangulations
  bool complete = false;    ///< TOPCOM's enumeration of the set ended with this batch
  bool truncated = false;   ///< ... because --topcom-limit was reached
  std::size_t enumerated = 0; ///< the set's triangulations (complete tallies only)
  std::map<std::array<std::string, 3>, Stream_row> rows;

  nlohmann::json json() const
  {
    nlohmann::json r = nlohmann::json::array();
    for(const auto& [k, row] : rows)
    {
      auto j = row.json();
      j["strategy"] = k[0], j["order"] = k[1];
      if(!k[2].empty()) j["reading"] = k[2];
      r.push_back(j);
    }
    nlohmann::json t = {{"set", set},   {"points", points}, {"first", first}, {"count", count},
                        {"plain_stuck_from", plain_stuck_from}, {"helper_failed_from", helper_failed_from},
                        {"complete", complete}, {"rows", r}};
    if(complete) t["triangulations"] = enumerated, t["truncated"] = truncated;
    return {{"tally", t}};
  }
  static Stream_tally from_json(const nlohmann::json& line)
  {
    const auto& t = line.at("tally");
    Stream_tally s;
    s.set = t.at("set"), s.points = t.at("points"), s.first = t.at("first"), s.count = t.at("count");
    s.plain_stuck_from = t.at("plain_stuck_from"), s.helper_failed_from = t.at("helper_failed_from");
    s.complete = t.at("complete");
    if(s.complete) s.enumerated = t.at("triangulations"), s.truncated = t.at("truncated");
    for(const auto& r : t.at("rows"))
      s.rows[{r.at("strategy").get<std::string>(), r.at("order").get<std::string>(),
              r.contains("reading") ? r.at("reading").get<std::string>() : std::string()}] = Stream_row::from_json(r);
    return s;
  }
};

/// Reads a streamed results file line by line: calls `tally(t)` for each
/// tally and checks every other line. Returns the length of the part to
/// keep (up to the end of the last tally, or of the first line). Throws
/// `Input_error` naming the file and line, or `Usage_error` when the
/// file's options are not `options`.
template <class Tally>
std::size_t read_stream_file(const std::string& path, const nlohmann::json& options, Tally tally)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Usage_error("cannot read '" + path + "'");
  std::string line;
  std::size_t number = 0, offset = 0, keep = 0;
  while(std::getline(in, line))
  {
    if(in.eof()) break; // a last line without its newline: a stop while writing it
    ++number;
    offset += line.size() + 1;
    const auto j = nlohmann::json::parse(line, nullptr, false);
    auto fail = [&](const std::string& what) {
      throw IO::Input_error(path + ":" + std::to_string(number) + ": " + what);
    };
    if(j.is_discarded()) fail("not a JSON line");
    if(number == 1)
    {
      if(!j.is_object() || !j.contains("stream")) fail("not a file of experiment --stream (no {\"stream\": ...} line)");
      if(j["stream"] != options)
        throw Usage_error(path + " was written with other options: " + j["stream"].dump() + "; these are " +
                          options.dump());
      keep = offset;
    }
    else if(j.is_object() && j.contains("tally"))
    {
      try
      {
        tally(Stream_tally::from_json(j));
      }
      catch(const nlohmann::json::exception& e)
      {
        fail(std::string("a bad tally: ") + e.what());
      }
      keep = offset;
    }
    else
    {
      const std::string problem = IO::results_line_problem(j);
      if(!problem.empty()) fail("not a results line: " + problem);
    }
  }
  return keep;
}

/// The options that a streamed file records in its first line: a resume must use the same.
inline nlohmann::json stream_options(const ES::Conjecture_experiment<Point>& experiment, const std::string& shard,
                                     std::size_t batch, std::size_t limit)
{
  nlohmann::json strategies = nlohmann::json::array(), orders = nlohmann::json::array(),
                 readings = nlohmann::json::array();
  for(auto s : experiment.strategies) strategies.push_back(ES::conjecture_strategy_name(s));
  for(auto o : experiment.orders) orders.push_back(ES::face_order_name(o));
  for(const auto& r : experiment.readings) readings.push_back(ES::helper_reading_name(r));
  return {{"strategies", strategies}, {"orders", orders},   {"readings", readings},
          {"max_cycles", experiment.max_cycles}, {"batch", batch}, {"shard", shard},
          {"topcom_limit", limit}};
}

/// Prints the summary of the tallies of a streamed file.
inline void print_stream_summary(const std::string& path, const std::vector<Stream_tally>& tallies, std::ostream& os)
{
  std::map<std::array<std::string, 5>, Stream_row> rows; // family, points, strategy, order, reading
  struct Set_row
  {
    std::size_t triangulations = 0, plain_stuck_from = 0, helper_failed_from = 0, enumerated = 0;
    bool complete = false, truncated = false;
  };
  std::map<std::string, Set_row> sets;
  for(const auto& t : tallies)
  {
    Set_row& s = sets[t.set];
    s.triangulations += t.count, s.plain_stuck_from += t.plain_stuck_from, s.helper_failed_from += t.helper_failed_from;
    if(t.complete) s.complete = true, s.truncated = t.truncated, s.enumerated = t.enumerated;
    for(const auto& [k, r] : t.rows) rows[{t.set.substr(0, t.set.find('|')), std::to_string(t.points), k[0], k[1], k[2]}].add(r);
  }
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%-18s %6s %-8s %-8s %11s %11s %9s %9s %11s %8s %7s %8s %10s  %s\n", "family",
                "points", "strategy", "order", "instances", "converged", "stuck", "limit", "equal", "failures",
                "invalid", "mean cyc", "max cycles", "reading");
  os << buffer;
  std::size_t total = 0;
  for(const auto& [k, r] : rows)
  {
    total += r.instances;
    std::snprintf(buffer, sizeof buffer, "%-18s %6s %-8s %-8s %11zu %11zu %9zu %9zu %11zu %8zu %7zu %8.2f %10zu  %s\n",
                  k[0].c_str(), k[1].c_str(), k[2].c_str(), k[3].c_str(), r.instances, r.converged, r.stuck, r.limit,
                  r.equal, r.failures, r.invalid, r.instances ? r.cycles / double(r.instances) : 0.0, r.max_cycles,
                  k[4].empty() ? "(package's)" : k[4].c_str());
    os << buffer;
  }
  os << total << " instances in " << path
     << " (failures: the helper strategy not ending on CGAL's Delaunay triangulation)\n\nTOPCOM starts, streamed:\n";
  for(const auto& [name, s] : sets)
  {
    os << "  " << name << ": " << s.triangulations << " triangulations run";
    if(s.complete)
      os << " of " << s.enumerated << (s.truncated ? " (--topcom-limit reached)" : " (all)");
    else
      os << " (enumeration not finished)";
    os << "; plain stuck from " << s.plain_stuck_from << ", helper failed from " << s.helper_failed_from << "\n";
  }
}

} // namespace internal_experiment

/// edge_swap experiment --stream (the options are checked by run_experiment()).
inline int run_streamed_experiment(const Experiment_options& opt, const ES::Conjecture_experiment<Point>& experiment,
                                   std::size_t shard, std::size_t shards)
{
  using namespace internal_experiment;
  if(opt.starts != std::vector<std::string>{"topcom"}) throw Usage_error("--stream needs --starts topcom (and no other start)");
  if(std::find(experiment.strategies.begin(), experiment.strategies.end(), ES::INSERTION_WITH_PLAIN_SWAPS) !=
     experiment.strategies.end())
    throw Usage_error("--stream runs TOPCOM starts: the insertion strategy has none");
  const std::size_t limit = opt.topcom_limit_given ? opt.topcom_limit : std::numeric_limits<std::size_t>::max();
  const std::size_t batch_size = opt.stream_batch;
  if(batch_size == 0 || batch_size > 10000000) throw Usage_error("--stream-batch is from 1 to 10000000");
  const nlohmann::json options =
      stream_options(experiment, opt.shard, batch_size, opt.topcom_limit_given ? opt.topcom_limit : 0);

  // Points TOPCOM cannot read exactly are refused before the file is touched
  // (each family at each size with the first seed; every set is written again).
  for(const auto& family : experiment.families)
    for(std::size_t size : family.rfind("file:", 0) == 0 ? std::vector<std::size_t>{0} : experiment.sizes)
    {
      std::ostringstream sink;
      try
      {
        IO::write_topcom_points(sink, ES::conjecture_family_points(experiment, family, size, experiment.first_seed));
      }
      catch(const std::invalid_argument& e)
      {
        throw Usage_error(family + (size ? " with " + std::to_string(size) + " points" : std::string()) + ": " + e.what());
      }
    }
  // Where each point set stands: the next triangulation, and whether it is done.
  std::map<std::string, std::size_t> next;
  std::set<std::string> complete;
  const bool existed = std::filesystem::exists(opt.output) && std::filesystem::file_size(opt.output) > 0;
  if(existed)
  {
    const std::size_t keep = read_stream_file(opt.output, options, [&](const Stream_tally& t) {
      next[t.set] = (std::max)(next[t.set], t.first + t.count);
      if(t.complete) complete.insert(t.set);
    });
    std::filesystem::resize_file(opt.output, keep);
  }
  std::ofstream out(opt.output, std::ios::app | std::ios::binary);
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  auto write = [&](const std::string& text) {
    errno = 0;
    out << text << std::flush;
    if(!out) throw Usage_error("cannot write '" + opt.output + "'" + (errno ? std::string(": ") + std::strerror(errno) : ""));
  };
  if(!existed) write(nlohmann::json{{"stream", options}}.dump() + "\n");
  if(!opt.cases_dir.empty()) std::filesystem::create_directories(opt.cases_dir);

  CGAL::Real_timer timer;
  timer.start();
  double next_report = 5;
  std::size_t instances_run = 0, failures = 0;
  unsigned threads = 0;
  // A file made by this run and given nothing yet is not left behind by an error.
  bool wrote_tally = false;
  try
  {
    for(const auto& family : experiment.families)
      for(std::size_t size : family.rfind("file:", 0) == 0 ? std::vector<std::size_t>{0} : experiment.sizes)
        for(unsigned seed = experiment.first_seed;; ++seed)
        {
          const std::string set = family + "|" + std::to_string(size) + "|" + std::to_string(seed);
          if(!complete.count(set))
          {
            const std::vector<Point> points = ES::conjecture_family_points(experiment, family, size, seed);
            ES::Conjecture_instances batch;
            auto& held = batch.topcom_cells[set];
            std::size_t first = 0;
            // Runs the held triangulations and writes their lines and tally.
            auto run_batch = [&](bool last, std::size_t enumerated) {
              Stream_tally tally;
              tally.set = set, tally.points = points.size(), tally.first = first, tally.count = held.size();
              tally.complete = last, tally.enumerated = enumerated, tally.truncated = last && enumerated >= limit;
              std::vector<ES::Conjecture_instance> list;
              for(std::size_t t = 0; t < held.size(); ++t)
                ES::append_start_instances(experiment, family, size, seed, "topcom:" + std::to_string(first + t), list);
              for(const auto& in : list) tally.rows[stream_row_key(in)]; // every row, even when empty
              std::vector<const ES::Conjecture_instance*> todo;
              for(const auto& in : list) todo.push_back(&in);
              batch.topcom_first[set] = first;
              std::set<std::string> stuck_from, failed_from;
              std::string lines;
              auto record = [&](const ES::Conjecture_instance& in, const ES::Conjecture_case<Point>& c,
                                const ES::Conjecture_outcome& o) {
                tally.rows[stream_row_key(in)].add(c, o);
                const bool failure = ES::is_counterexample(c, o);
                if(in.strategy == ES::PLAIN_SWAPS && o.ending == ES::STUCK) stuck_from.insert(in.start);
                if(in.strategy == ES::HELPER_STRATEGY && failure) failed_from.insert(in.start);
                if(failure || o.bad_start || !o.valid || !o.equal_to_cgal || o.ending != ES::CONVERGED)
                  lines += instance_line(in, c, o).dump() + "\n";
                save_case_if_wanted(opt, in, c, o);
                failures += failure;
              };
              try
              {
                threads = ES::run_conjecture_experiment(todo, experiment, batch,
                                                        ES::parameters::number_of_threads(opt.threads, CGAL::parameters::visitor(record)));
              }
              catch(const std::bad_alloc&)
              {
                throw Usage_error("out of memory");
              }
              tally.plain_stuck_from = stuck_from.size(), tally.helper_failed_from = failed_from.size();
              write(lines + tally.json().dump() + "\n");
              wrote_tally = true;
              instances_run += list.size();
              held.clear();
              if(timer.time() >= next_report)
              {
                next_report = timer.time() + 5;
                std::cerr << "experiment: " << set << ": triangulation " << first + tally.count << ", " << instances_run
                          << " instances (" << int(double(instances_run) / timer.time()) << " a second), failures "
                          << failures << "\n";
              }
            };
            const std::size_t resume = next.count(set) ? next[set] : 0;
            std::size_t enumerated = 0;
            try
            {
              enumerated = IO::for_each_topcom_triangulation(points, limit, [&](std::size_t t, const auto& cells) {
                if(t < resume || (t / batch_size) % shards != shard) return true;
                if(held.empty()) first = t;
                held.push_back(cells);
                if((t + 1) % batch_size == 0) run_batch(false, 0);
                return true;
              });
            }
            catch(const std::invalid_argument& e)
            {
              throw Usage_error(e.what());
            }
            std::cerr << "experiment: TOPCOM: " << enumerated << (enumerated >= limit ? "+ (limit)" : "")
                      << " fine triangulations of " << set << "\n";
            if(held.empty()) first = enumerated;
            run_batch(true, enumerated); // the rest, and the mark that the set is done
          }
          if(seed == experiment.last_seed) break;
        }
  }
  catch(...)
  {
    if(!existed && !wrote_tally)
    {
      out.close();
      std::remove(opt.output.c_str());
    }
    throw;
  }
  out.close();
  if(!out) throw Usage_error("cannot write '" + opt.output + "'");
  std::cerr << "experiment: " << instances_run << " instances in " << timer.time() << " s"
            << (threads ? " on " + std::to_string(threads) + " threads" : std::string()) << "\n";
  std::vector<Stream_tally> tallies;
  read_stream_file(opt.output, options, [&](const Stream_tally& t) { tallies.push_back(t); });
  print_stream_summary(opt.output, tallies, std::cout);
  return 0;
}

} // namespace edge_swap

#endif
