// SPDX-License-Identifier: GPL-3.0-or-later
// The conjecture laboratory's files, in JSON (nlohmann-json): a case file
// holds everything needed to run a case again; a results file holds one
// line per instance; and the summary of a results file per family, start,
// strategy and order, and per point set of TOPCOM starts. Every field read
// is checked: a bad file gets an error that names the problem (the case and
// results readers are fuzzed: test/Edge_swapping_3/fuzz).

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_IO_CONJECTURE_JSON_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_IO_CONJECTURE_JSON_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <nlohmann/json.hpp>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3Laboratory
/// The outcome `o` as the fields of a results line or a case file.
inline nlohmann::json conjecture_outcome_json(const Conjecture_outcome& o)
{
  return {{"ending", conjecture_ending_name(o)},
          {"cycles", o.cycles},
          {"swaps", {{"2-3", o.swaps[0]}, {"3-2", o.swaps[1]}, {"2-2", o.swaps[2]}, {"4-4", o.swaps[3]}}},
          {"equal_to_cgal", o.equal_to_cgal},
          {"valid", o.valid},
          {"non_delaunay_facets", o.non_delaunay_facets},
          {"insertions_not_converged", o.insertions_not_converged},
          {"seconds", o.seconds}};
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// A case file: everything needed to run the case `c` again.
template <class Point>
nlohmann::json conjecture_case_json(const Conjecture_case<Point>& c)
{
  nlohmann::json points = nlohmann::json::array();
  for(const Point& p : c.points)
    points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  nlohmann::json j = {{"points", points},
                      {"start", conjecture_start_name(c)},
                      {"strategy", conjecture_strategy_name(c.strategy)},
                      {"order", face_order_name(c.order)},
                      {"seed", c.seed},
                      {"max_cycles", c.max_cycles}};
  if(c.start == GIVEN_CELLS_START) j["cells"] = c.cells;
  if(!c.reading.is_default()) j["reading"] = helper_reading_name(c.reading);
  if(c.schedule == WORK_QUEUE) j["schedule"] = "queue";
  return j;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The case in `j`, read from the file `name`; an `Input_error` that names
/// the file and the field for anything missing, of the wrong type or out of
/// range, and for points that cannot be triangulated.
template <class Point>
Conjecture_case<Point> conjecture_case_from_json(const nlohmann::json& j, const std::string& name)
{
  auto fail = [&](const std::string& what) { throw Input_error(name + ": bad case file: " + what); };
  if(!j.is_object()) fail("not a JSON object");
  auto text = [&](const char* key) {
    if(!j.contains(key) || !j[key].is_string()) fail(std::string("\"") + key + "\" is missing or not a string");
    return j[key].get<std::string>();
  };
  auto whole = [&](const nlohmann::json& v, const std::string& what, unsigned long long largest) {
    if(!v.is_number_unsigned() || v.get<unsigned long long>() > largest)
      fail(what + " is missing or not a whole number from 0 to " + std::to_string(largest));
    return v.get<unsigned long long>();
  };
  Conjecture_case<Point> c;
  if(!j.contains("points") || !j["points"].is_array()) fail("\"points\" is missing or not a list");
  for(const auto& p : j["points"])
  {
    if(!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
      fail("point " + std::to_string(c.points.size()) + " is not three numbers");
    c.points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  const std::string start = text("start"), strategy = text("strategy"), order = text("order");
  if(!j.contains("seed")) fail("\"seed\" is missing or not a whole number from 0 to 4294967295");
  c.seed = unsigned(whole(j["seed"], "\"seed\"", 4294967295ULL));
  c.max_cycles = j.contains("max_cycles") ? std::size_t(whole(j["max_cycles"], "\"max_cycles\"", 1000000000ULL))
                                          : std::size_t(1000);
  if(!conjecture_strategy_from_name(strategy, c.strategy))
    fail("unknown strategy '" + strategy + "' (plain, helper, insertion)");
  if(!face_order_from_name(order, c.order)) fail("unknown order '" + order + "' (storage, random, priority)");
  if(j.contains("reading") && !helper_reading_from_name(text("reading"), c.reading))
    fail("unknown reading '" + text("reading") + "' (laboratory/doc/traces.md)");
  if(j.contains("schedule"))
  {
    const std::string schedule = text("schedule");
    if(schedule != "cycles" && schedule != "queue") fail("unknown schedule '" + schedule + "' (cycles, queue)");
    c.schedule = schedule == "queue" ? WORK_QUEUE : PAPER_CYCLES;
  }
  const std::string problem = point_set_problem(c.points);
  if(!problem.empty()) fail(problem);
  if(start.rfind("scramble:", 0) == 0)
  {
    c.start = SCRAMBLED_DELAUNAY_START;
    unsigned long long flips = 0;
    const std::string k = start.substr(9);
    const auto status = k.empty() || k[0] == '+' ? internal::Number_status::not_a_number : internal::parse_number(k, flips);
    if(status == internal::Number_status::not_a_number) fail("start scramble:K needs a whole number, not " + quote_token(k));
    if(status == internal::Number_status::out_of_range || flips > 1000000000ULL)
    {
      const std::string quoted = quote_token(k);
      fail("start scramble:K is " + quoted.substr(1, quoted.size() - 2) + ", more than 1000000000");
    }
    c.scramble_flips = std::size_t(flips);
  }
  else if(start == "cells")
  {
    c.start = GIVEN_CELLS_START;
    if(!j.contains("cells") || !j["cells"].is_array()) fail("start \"cells\" without a list \"cells\"");
    for(const auto& t : j["cells"])
    {
      std::array<std::size_t, 4> cell;
      if(!t.is_array() || t.size() != 4) fail("cell " + std::to_string(c.cells.size()) + " is not four point indices");
      for(int i = 0; i < 4; ++i)
      {
        if(!t[i].is_number_unsigned() || t[i].get<unsigned long long>() >= c.points.size())
          fail("cell " + std::to_string(c.cells.size()) + " names a point that does not exist");
        cell[i] = t[i].get<std::size_t>();
      }
      c.cells.push_back(cell);
    }
  }
  else if(start == "placing")
    c.start = PLACING_START;
  else if(start == "-")
    c.start = NO_START;
  else
    fail("unknown start '" + start + "' (placing, scramble:K, cells)");
  if((c.start == NO_START) != (c.strategy == INSERTION_WITH_PLAIN_SWAPS))
    fail("start '-' goes with the strategy insertion, and only with it");
  if(c.schedule == WORK_QUEUE && (c.strategy == INSERTION_WITH_PLAIN_SWAPS || !c.reading.is_default()))
    fail("the schedule 'queue' runs plain swapping and the helper's default reading only");
  return c;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The case in the file at `path` (see `conjecture_case_from_json()`).
template <class Point>
Conjecture_case<Point> read_conjecture_case_file(const std::string& path)
{
  const std::string text = read_text_file(path);
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if(j.is_discarded()) throw Input_error(path + ": not JSON");
  return conjecture_case_from_json<Point>(j, path);
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// An empty string if `j` is a results line as `edge_swap_lab experiment` writes
/// it (every field the summary and resuming read, of the right type);
/// otherwise the first problem.
inline std::string results_line_problem(const nlohmann::json& j)
{
  if(!j.is_object()) return "not a JSON object";
  for(const char* key : {"key", "family", "start", "strategy", "order", "ending"})
    if(!j.contains(key) || !j[key].is_string()) return std::string("\"") + key + "\" is missing or not a string";
  for(const char* key : {"size", "points", "seed"})
    if(!j.contains(key) || !j[key].is_number_unsigned()) return std::string("\"") + key + "\" is missing or not a whole number";
  if(j["seed"].get<unsigned long long>() > 4294967295ULL) return "\"seed\" is too large";
  if(j.contains("order_seed") &&
     (!j["order_seed"].is_number_unsigned() || j["order_seed"].get<unsigned long long>() > 4294967295ULL))
    return "\"order_seed\" is not a whole number below 2^32";
  for(const char* key : {"cycles", "seconds"})
    if(!j.contains(key) || !j[key].is_number()) return std::string("\"") + key + "\" is missing or not a number";
  for(const char* key : {"failure", "equal_to_cgal", "valid"})
    if(!j.contains(key) || !j[key].is_boolean()) return std::string("\"") + key + "\" is missing or not true or false";
  return std::string();
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The lines of `text`, the content of the results file `path`, each checked
/// (an `Input_error` names the file, the line and the problem). A last line
/// without its newline (a run stopped while writing it) is left out.
inline std::vector<nlohmann::json> read_results_text(const std::string& path, const std::string& text)
{
  std::vector<nlohmann::json> lines;
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  std::size_t number = 0;
  for(std::size_t begin = 0; begin < complete;)
  {
    const std::size_t end = text.find('\n', begin);
    ++number;
    const auto j =
        nlohmann::json::parse(text.begin() + std::ptrdiff_t(begin), text.begin() + std::ptrdiff_t(end), nullptr, false);
    begin = end + 1;
    if(j.is_discarded()) throw Input_error(path + ":" + std::to_string(number) + ": not a JSON line");
    const std::string problem = results_line_problem(j);
    if(!problem.empty()) throw Input_error(path + ":" + std::to_string(number) + ": not a results line: " + problem);
    lines.push_back(j);
  }
  return lines;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The lines of the results file at `path` (see `read_results_text()`);
/// with `drop_cut_line`, a last line without its newline is also removed
/// from the file, so that appending starts on a new line. A missing file
/// has no lines.
inline std::vector<nlohmann::json> read_results_file(const std::string& path, bool drop_cut_line)
{
  std::error_code ec;
  if(!std::filesystem::exists(path, ec)) return {};
  const std::string text = read_text_file(path);
  auto lines = read_results_text(path, text);
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  if(drop_cut_line && complete != text.size()) std::filesystem::resize_file(path, complete);
  return lines;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Prints the summary of the results `lines` (checked by `read_results_text()`)
/// of the file `path`: per family, start, strategy and order, the instances,
/// how they ended, the counterexamples; and per point set of TOPCOM starts,
/// from how many triangulations plain swapping was stuck and the helper failed.
inline void print_results_summary(const std::string& path, const std::vector<nlohmann::json>& lines, std::ostream& os)
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
    std::string strategy = j["strategy"];
    if(j.contains("reading")) strategy += " " + j["reading"].get<std::string>();
    Row& r = rows[{j["family"], start, strategy, j["order"]}];
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

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_IO_CONJECTURE_JSON_H
