// The summary of an experiment's JSON lines: per family, start, strategy and
// order, and per point set of TOPCOM starts.

#ifndef EDGE_SWAP_EXPERIMENT_SUMMARY_H
#define EDGE_SWAP_EXPERIMENT_SUMMARY_H

#include <nlohmann/json.hpp>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <string>

namespace edge_swap {

/// Prints the summary of every instance in the file at `path`.
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

} // namespace edge_swap

#endif
