// SPDX-License-Identifier: GPL-3.0-or-later
// The options of edge_swap_lab experiment, and what its two ways of running
// (instance lists, and streamed TOPCOM triangulations) share: parsing
// ranges, the results line of an instance and its case file.

#ifndef EDGE_SWAP_LAB_EXPERIMENT_OPTIONS_H
#define EDGE_SWAP_LAB_EXPERIMENT_OPTIONS_H

#include "types.h"
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/IO/tetgen.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_experiment.h>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace edge_swap_lab {

struct Experiment_options
{
  std::vector<std::string> families{"random-cube"};
  std::vector<std::size_t> sizes{100};
  std::string seeds = "1-10";
  std::vector<std::string> starts{"placing"};
  std::vector<std::string> strategies{"plain", "helper"};
  std::vector<std::string> orders{"random"};
  std::string readings; // the helper's, separated by ';', or "all"
  std::vector<std::string> point_files;
  std::string output;
  std::string shard = "0/1";
  unsigned threads = 0;
  std::size_t max_cycles = 1000;
  std::string cases_dir;
  std::size_t stuck_case_max_points = 50;
  std::size_t topcom_limit = 100000; // per point set; none by default with --stream
  bool topcom_limit_given = false;
  bool stream = false; // stream TOPCOM's triangulations, with tallies (experiment_stream.h)
  std::size_t stream_batch = 4096; // triangulations per tally (and per shard unit)
  std::string order_seeds = "per-set"; // or per-start: the face-order seed of TOPCOM starts
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

inline std::vector<Point> read_point_file(const std::string& path)
{
  std::vector<Point> points;
  for(const auto& p : IO::read_node_file(path).points) points.emplace_back(p[0], p[1], p[2]);
  const std::string problem = ES::point_set_problem(points);
  if(!problem.empty()) throw Usage_error(path + ": " + problem);
  return points;
}

inline std::string file_safe(std::string s)
{
  for(char& ch : s)
    if(!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.') ch = '_';
  return s;
}

/// The results line of one instance of an experiment with `order_seeds`.
inline nlohmann::json instance_line(const ES::Conjecture_instance& in, const ES::Conjecture_case<Point>& c,
                                    const ES::Conjecture_outcome& o, ES::Order_seeds order_seeds)
{
  nlohmann::json j = {{"key", in.key()},
                      {"family", in.family},
                      {"size", in.size},
                      {"points", c.points.size()},
                      {"seed", in.seed},
                      {"start", in.start},
                      {"strategy", ES::conjecture_strategy_name(in.strategy)},
                      {"order", ES::face_order_name(in.order)},
                      {"failure", ES::is_counterexample(c, o)}};
  if(!in.reading.is_default()) j["reading"] = ES::helper_reading_name(in.reading);
  if(order_seeds == ES::ORDER_SEED_PER_START && in.start.rfind("topcom:", 0) == 0) j["order_seed"] = c.seed;
  j.update(IO::conjecture_outcome_json(o));
  return j;
}

/// Saves the case of an instance in `--cases` when it failed, or when it is a
/// small stuck one (to shrink).
inline void save_case_if_wanted(const Experiment_options& opt, const ES::Conjecture_instance& in,
                                const ES::Conjecture_case<Point>& c, const ES::Conjecture_outcome& o)
{
  const bool failure = ES::is_counterexample(c, o);
  if(opt.cases_dir.empty() ||
     !(failure || (!o.bad_start && o.ending == ES::STUCK && c.points.size() <= opt.stuck_case_max_points)))
    return;
  const std::string saved = opt.cases_dir + "/" + (failure ? "failure-" : "stuck-") + file_safe(in.key()) + ".json";
  nlohmann::json file = IO::conjecture_case_json(c);
  file["outcome"] = IO::conjecture_outcome_json(o);
  file["instance"] = in.key();
  std::ofstream case_file(saved);
  case_file << file.dump(1) << '\n';
  case_file.close();
  if(!case_file) throw Usage_error("cannot write '" + saved + "'");
}

} // namespace internal_experiment

} // namespace edge_swap_lab

#endif
