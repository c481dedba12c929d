// SPDX-License-Identifier: GPL-3.0-or-later
// The results file of `edge_swap_lab experiment --stream`: a first line
// {"stream": OPTIONS}, then, per batch of TOPCOM triangulations of a point
// set, the results lines (conjecture_json.h) of its runs that did not end
// on CGAL's Delaunay triangulation and one line {"tally": {...}} with the
// counts of all its runs (laboratory/doc/conjectures.md). Every field
// read is checked; the reader is fuzzed (test/Edge_swapping_3/fuzz).

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_IO_STREAMED_RESULTS_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_IO_STREAMED_RESULTS_H

#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

namespace internal {

// The largest count a tally may hold: exact in a double, far from wrapping.
constexpr std::size_t largest_tally_count = std::size_t(1) << 50;

inline std::size_t tally_count(const nlohmann::json& j, const char* key)
{
  if(!j.is_object() || !j.contains(key) || !j[key].is_number_unsigned() ||
     j[key].get<std::uint64_t>() > largest_tally_count)
    throw Input_error(std::string("\"") + key + "\" is missing or not a whole number up to 2^50");
  return std::size_t(j[key].get<std::uint64_t>());
}

inline double tally_sum(const nlohmann::json& j, const char* key)
{
  if(!j.contains(key) || !j[key].is_number() || !(j[key].get<double>() >= 0) || !std::isfinite(j[key].get<double>()))
    throw Input_error(std::string("\"") + key + "\" is missing or not a finite number >= 0");
  return j[key].get<double>();
}

inline std::string tally_text(const nlohmann::json& j, const char* key)
{
  if(!j.is_object() || !j.contains(key) || !j[key].is_string())
    throw Input_error(std::string("\"") + key + "\" is missing or not a string");
  return j[key].get<std::string>();
}

inline bool tally_flag(const nlohmann::json& j, const char* key)
{
  if(!j.contains(key) || !j[key].is_boolean()) throw Input_error(std::string("\"") + key + "\" is missing or not true or false");
  return j[key].get<bool>();
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Laboratory
/// The counts of one row (strategy, order, reading) of a tally.
struct Streamed_row
{
  std::size_t instances = 0;  ///< runs
  std::size_t converged = 0;  ///< runs that ended with nothing left to do
  std::size_t stuck = 0;      ///< runs that ended stuck
  std::size_t limit = 0;      ///< runs still going at the cycle limit
  std::size_t equal = 0;      ///< runs that ended on CGAL's Delaunay triangulation, cell for cell
  std::size_t failures = 0;   ///< counterexamples (`is_counterexample()`)
  std::size_t invalid = 0;    ///< runs that ended on a triangulation `is_valid()` refuses
  std::size_t bad_start = 0;  ///< runs whose start was not a triangulation
  double cycles = 0;          ///< the cycles of all the runs
  double swaps = 0;           ///< the swaps of all the runs
  double seconds = 0;         ///< the time of all the runs
  std::size_t max_cycles = 0; ///< the most cycles of a run

  /// Counts one run.
  template <class Point>
  void add(const Conjecture_case<Point>& c, const Conjecture_outcome& o)
  {
    ++instances;
    converged += o.ending == CONVERGED;
    stuck += o.ending == STUCK;
    limit += o.ending == CYCLE_LIMIT_REACHED;
    equal += o.equal_to_cgal;
    failures += is_counterexample(c, o);
    invalid += !o.valid;
    bad_start += o.bad_start;
    cycles += double(o.cycles);
    for(std::size_t s : o.swaps) swaps += double(s);
    seconds += o.seconds;
    max_cycles = (std::max)(max_cycles, o.cycles);
  }
  /// Adds the counts of `r`.
  void add(const Streamed_row& r)
  {
    instances += r.instances, converged += r.converged, stuck += r.stuck, limit += r.limit, equal += r.equal;
    failures += r.failures, invalid += r.invalid, bad_start += r.bad_start;
    cycles += r.cycles, swaps += r.swaps, seconds += r.seconds;
    max_cycles = (std::max)(max_cycles, r.max_cycles);
  }
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// One tally: the runs from the triangulations [first, first + count) of a point set.
struct Streamed_tally
{
  std::string set;            ///< family|size|seed
  std::size_t points = 0;             ///< the set's points
  std::size_t first = 0;              ///< the number of the first triangulation (TOPCOM's order, from 0)
  std::size_t count = 0;              ///< the triangulations
  std::size_t plain_stuck_from = 0;   ///< triangulations from which plain swapping was stuck in some order
  std::size_t helper_failed_from = 0; ///< triangulations from which the helper failed under some order or reading
  bool complete = false;      ///< TOPCOM's enumeration of the set ended with this batch
  bool truncated = false;     ///< ... because the triangulation limit was reached
  std::size_t enumerated = 0; ///< the set's triangulations (complete tallies only)
  /// By strategy, order and reading (empty: the package's).
  std::map<std::array<std::string, 3>, Streamed_row> rows;
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// The line of `t`.
inline nlohmann::json streamed_tally_json(const Streamed_tally& t)
{
  nlohmann::json rows = nlohmann::json::array();
  for(const auto& [k, r] : t.rows)
  {
    nlohmann::json j = {{"strategy", k[0]},    {"order", k[1]},         {"instances", r.instances},
                        {"converged", r.converged}, {"stuck", r.stuck}, {"limit", r.limit},
                        {"equal", r.equal},    {"failures", r.failures}, {"invalid", r.invalid},
                        {"bad_start", r.bad_start}, {"cycles", r.cycles}, {"swaps", r.swaps},
                        {"seconds", r.seconds}, {"max_cycles", r.max_cycles}};
    if(!k[2].empty()) j["reading"] = k[2];
    rows.push_back(j);
  }
  nlohmann::json j = {{"set", t.set},
                      {"points", t.points},
                      {"first", t.first},
                      {"count", t.count},
                      {"plain_stuck_from", t.plain_stuck_from},
                      {"helper_failed_from", t.helper_failed_from},
                      {"complete", t.complete},
                      {"rows", rows}};
  if(t.complete) j["triangulations"] = t.enumerated, j["truncated"] = t.truncated;
  return {{"tally", j}};
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The tally of the line `line` (an object with the key "tally"); an
/// `Input_error` names the first field that is missing, of the wrong type
/// or inconsistent.
inline Streamed_tally streamed_tally_from_json(const nlohmann::json& line)
{
  using namespace internal;
  const nlohmann::json& t = line.at("tally");
  Streamed_tally s;
  s.set = tally_text(t, "set");
  s.points = tally_count(t, "points"), s.first = tally_count(t, "first"), s.count = tally_count(t, "count");
  s.plain_stuck_from = tally_count(t, "plain_stuck_from"), s.helper_failed_from = tally_count(t, "helper_failed_from");
  if(s.plain_stuck_from > s.count || s.helper_failed_from > s.count)
    throw Input_error("more triangulations stuck or failed than the tally has");
  s.complete = tally_flag(t, "complete");
  if(s.complete)
  {
    s.enumerated = tally_count(t, "triangulations"), s.truncated = tally_flag(t, "truncated");
    if(s.first + s.count > s.enumerated) throw Input_error("a tally beyond the set's triangulations");
  }
  if(!t.contains("rows") || !t["rows"].is_array()) throw Input_error("\"rows\" is missing or not a list");
  for(const auto& r : t["rows"])
  {
    Streamed_row row;
    row.instances = tally_count(r, "instances");
    std::size_t* counts[] = {&row.converged, &row.stuck, &row.limit, &row.equal, &row.failures, &row.invalid, &row.bad_start};
    const char* names[] = {"converged", "stuck", "limit", "equal", "failures", "invalid", "bad_start"};
    for(int k = 0; k < 7; ++k)
      if((*counts[k] = tally_count(r, names[k])) > row.instances)
        throw Input_error(std::string("\"") + names[k] + "\" is more than \"instances\"");
    if(row.converged + row.stuck + row.limit > row.instances) throw Input_error("more endings than instances");
    row.cycles = tally_sum(r, "cycles"), row.swaps = tally_sum(r, "swaps"), row.seconds = tally_sum(r, "seconds");
    row.max_cycles = tally_count(r, "max_cycles");
    const std::array<std::string, 3> key = {tally_text(r, "strategy"), tally_text(r, "order"),
                                            r.contains("reading") ? tally_text(r, "reading") : std::string()};
    if(!s.rows.emplace(key, row).second) throw Input_error("a row named twice");
  }
  return s;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Reads the streamed results `in` of the file `path` line by line: returns
/// the options of its first line, calls `tally(t)` for each tally and
/// checks every other line as a results line. `keep` is set to the length
/// of the part a resume keeps (up to the end of the last tally, or of the
/// first line); a last line without its newline (a stop while writing it)
/// is left out. An `Input_error` names the file, the line and the problem.
template <class Tally>
nlohmann::json read_streamed_results(const std::string& path, std::istream& in, Tally tally, std::size_t& keep)
{
  nlohmann::json options;
  std::string line;
  std::size_t number = 0, offset = 0;
  keep = 0;
  while(std::getline(in, line))
  {
    if(in.eof()) break; // no newline: cut short
    ++number;
    offset += line.size() + 1;
    auto fail = [&](const std::string& what) {
      throw Input_error(path + ":" + std::to_string(number) + ": " + what);
    };
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if(j.is_discarded()) fail("not a JSON line");
    if(number == 1)
    {
      if(!j.is_object() || !j.contains("stream") || !j["stream"].is_object())
        fail("not a file of experiment --stream (no {\"stream\": ...} line)");
      options = j["stream"];
      keep = offset;
    }
    else if(j.is_object() && j.contains("tally"))
    {
      try
      {
        tally(streamed_tally_from_json(j));
      }
      catch(const std::exception& e) // Input_error, and a JSON value not of the type read
      {
        fail(std::string("a bad tally: ") + e.what());
      }
      keep = offset;
    }
    else
    {
      const std::string problem = results_line_problem(j);
      if(!problem.empty()) fail("not a results line: " + problem);
    }
  }
  if(number == 0) throw Input_error(path + ": empty, not a file of experiment --stream");
  return options;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Prints the summary of `tallies` (of the file `path`): per family, size,
/// strategy, order and reading the runs and how they ended; per point set
/// the triangulations run, and from how many plain swapping was stuck and
/// the helper failed.
inline void print_streamed_summary(const std::string& path, const std::vector<Streamed_tally>& tallies, std::ostream& os)
{
  std::map<std::array<std::string, 5>, Streamed_row> rows; // family, points, strategy, order, reading
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
    for(const auto& [k, r] : t.rows)
      rows[{t.set.substr(0, t.set.find('|')), std::to_string(t.points), k[0], k[1], k[2]}].add(r);
  }
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%-18s %6s %-8s %-8s %11s %11s %9s %9s %11s %8s %7s %8s %10s  %s\n", "family",
                "points", "strategy", "order", "instances", "converged", "stuck", "limit", "equal", "failures",
                "invalid", "mean cyc", "max cycles", "reading");
  os << buffer;
  std::size_t total = 0;
  for(const auto& [k, r] : rows)
  {
    total += r.instances;
    std::snprintf(buffer, sizeof buffer, "%-18.60s %6s %-8.20s %-8.20s %11zu %11zu %9zu %9zu %11zu %8zu %7zu %8.2f %10zu  %.200s\n",
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
      os << " of " << s.enumerated << (s.truncated ? " (the triangulation limit reached)" : " (all)");
    else
      os << " (enumeration not finished)";
    os << "; plain stuck from " << s.plain_stuck_from << ", helper failed from " << s.helper_failed_from << "\n";
  }
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_IO_STREAMED_RESULTS_H
