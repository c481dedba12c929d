// SPDX-License-Identifier: GPL-3.0-or-later
// An experiment's results file (JSON lines, one per instance): reading it
// with every line checked, and its summary per family, start, strategy and
// order, and per point set of TOPCOM starts.

#ifndef EDGE_SWAP_EXPERIMENT_SUMMARY_H
#define EDGE_SWAP_EXPERIMENT_SUMMARY_H

#include "types.h"
#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <vector>
#include <array>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>

namespace edge_swap {

/// An empty string if `j` is a results line as `experiment` writes it
/// (every field the summary and resuming read, of the right type); otherwise
/// the first problem.
inline std::string results_line_problem(const nlohmann::json& j)
{
  if(!j.is_object()) return "not a JSON object";
  for(const char* key : {"key", "family", "start", "strategy", "order", "ending"})
    if(!j.contains(key) || !j[key].is_string()) return std::string("\"") + key + "\" is missing or not a string";
  for(const char* key : {"size", "points", "seed"})
    if(!j.contains(key) || !j[key].is_number_unsigned()) return std::string("\"") + key + "\" is missing or not a whole number";
  if(j["seed"].get<unsigned long long>() > 4294967295ULL) return "\"seed\" is too large";
  for(const char* key : {"cycles", "seconds"})
    if(!j.contains(key) || !j[key].is_number()) return std::string("\"") + key + "\" is missing or not a number";
  for(const char* key : {"failure", "equal_to_cgal", "valid"})
    if(!j.contains(key) || !j[key].is_boolean()) return std::string("\"") + key + "\" is missing or not true or false";
  return std::string();
}

/// The lines of `text`, the content of the results file `path` (see `read_results_file`).
inline std::vector<nlohmann::json> read_results_text(const std::string& path, const std::string& text)
{
  std::vector<nlohmann::json> lines;
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  std::size_t number = 0;
  for(std::size_t begin = 0; begin < complete;)
  {
    const std::size_t end = text.find('\n', begin);
    ++number;
    const auto j = nlohmann::json::parse(text.begin() + std::ptrdiff_t(begin), text.begin() + std::ptrdiff_t(end), nullptr, false);
    begin = end + 1;
    if(j.is_discarded()) throw Usage_error(path + ":" + std::to_string(number) + ": not a JSON line");
    const std::string problem = results_line_problem(j);
    if(!problem.empty()) throw Usage_error(path + ":" + std::to_string(number) + ": not a results line: " + problem);
    lines.push_back(j);
  }
  return lines;
}

/// The lines of the results file at `path`, each checked; a Usage_error names
/// the file, the line and the problem. A last line without its newline (a run
/// stopped while writing it) is left out, and with `drop_cut_line` removed
/// from the file, so that appending starts on a new line. A missing file has
/// no lines.
inline std::vector<nlohmann::json> read_results_file(const std::string& path, bool drop_cut_line)
{
  std::error_code ec;
  if(!std::filesystem::exists(path, ec)) return {};
  const std::string text = CGAL::Edge_swapping_3::IO::read_text_file(path);
  auto lines = read_results_text(path, text);
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  if(drop_cut_line && complete != text.size()) std::filesystem::resize_file(path, complete);
  return lines;
}

/// Prints the summary of the results `lines` (checked by `read_results_file`) of the file `path`.
inline void print_summary(const std::string& path, const std::vector<nlohmann::json>& lines, std::ostream& os)
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
  for(const auto& j : lines)
  {
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

} // namespace edge_swap

#endif
