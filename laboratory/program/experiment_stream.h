// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap_lab experiment --stream: TOPCOM's triangulations as they are
// enumerated, never all held. They are run in batches of a fixed size; each
// batch appends the lines of its instances that did not end on CGAL's
// Delaunay triangulation (stuck, at the cycle limit, failed, invalid) and
// one tally line with the counts of all of them. A stopped run resumes after
// the last tally (what a batch wrote before its tally is removed); `--shard
// I/N` keeps the batches whose number is I modulo N.
//
// The file's format: Laboratory/IO/streamed_results.h.

#ifndef EDGE_SWAP_LAB_EXPERIMENT_STREAM_H
#define EDGE_SWAP_LAB_EXPERIMENT_STREAM_H

#include "experiment_options.h"
#include <CGAL/Edge_swapping_3/Laboratory/IO/streamed_results.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Real_timer.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace edge_swap_lab {
namespace internal_experiment {

/// A row's name: strategy, order, and the reading when it is not the package's.
inline std::array<std::string, 3> stream_row_key(const ES::Conjecture_instance& in)
{
  return {ES::conjecture_strategy_name(in.strategy), ES::face_order_name(in.order),
          in.reading.is_default() ? std::string() : ES::helper_reading_name(in.reading)};
}

/// Reads the streamed results file `path` (IO::read_streamed_results()),
/// requiring the options `options`; returns the length a resume keeps.
template <class Tally>
std::size_t read_stream_file(const std::string& path, const nlohmann::json& options, Tally tally)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Usage_error("cannot read '" + path + "'");
  std::size_t keep = 0;
  const nlohmann::json written = IO::read_streamed_results(path, in, tally, keep);
  if(written != options)
    throw Usage_error(path + " was written with other options: " + written.dump() + "; these are " + options.dump());
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
  nlohmann::json options = {{"strategies", strategies}, {"orders", orders},   {"readings", readings},
                             {"max_cycles", experiment.max_cycles}, {"batch", batch}, {"shard", shard},
                             {"topcom_limit", limit}};
  // Recorded only when not the default, so that older files still resume.
  if(experiment.order_seeds != ES::ORDER_SEED_PER_SET) options["order_seeds"] = ES::order_seeds_name(experiment.order_seeds);
  return options;
}

} // namespace internal_experiment

/// edge_swap_lab experiment --stream (the options are checked by run_experiment()).
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
    const std::size_t keep = read_stream_file(opt.output, options, [&](const IO::Streamed_tally& t) {
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
              IO::Streamed_tally tally;
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
                  lines += instance_line(in, c, o, experiment.order_seeds).dump() + "\n";
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
              write(lines + IO::streamed_tally_json(tally).dump() + "\n");
              wrote_tally = true;
              instances_run += list.size();
              held.clear();
              if(!quiet && timer.time() >= next_report)
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
  std::vector<IO::Streamed_tally> tallies;
  read_stream_file(opt.output, options, [&](const IO::Streamed_tally& t) { tallies.push_back(t); });
  IO::print_streamed_summary(opt.output, tallies, std::cout);
  return 0;
}

} // namespace edge_swap_lab

#endif
