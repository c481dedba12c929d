// SPDX-License-Identifier: GPL-3.0-or-later
// One case of the conjecture laboratory: points, a start triangulation, a
// strategy (plain Algorithm 3, the helper strategy, or insertion one point at
// a time with plain swaps after each) and a face order; running it exactly,
// and the JSON that records it or saves it to be reproduced and shrunk.

#ifndef EDGE_SWAP_EXPERIMENT_CASE_H
#define EDGE_SWAP_EXPERIMENT_CASE_H

#include "types.h"
#include <CGAL/Real_timer.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <nlohmann/json.hpp>
#include <array>
#include <string>
#include <vector>

namespace edge_swap {

namespace ES = CGAL::Edge_swapping_3;
typedef CGAL::Triangulation_3<K> Plain_triangulation;

struct Experiment_case
{
  std::vector<Point> points;                      ///< placing and insertion: in insertion order
  std::string start = "placing";                  ///< placing | scramble:K | cells | - (insertion)
  std::vector<std::array<std::size_t, 4>> cells;  ///< start "cells" (a TOPCOM triangulation)
  std::string strategy = "helper";                ///< plain | helper | insertion
  std::string order = "random";                   ///< storage | random
  unsigned seed = 1;
  std::size_t max_cycles = 1000;
};

struct Experiment_outcome
{
  std::string ending;               ///< converged | stuck | cycle limit reached | bad start: ...
  std::size_t cycles = 0;
  std::array<std::size_t, ES::number_of_flip_kinds> swaps{};
  bool equal_to_cgal = false;
  bool valid = false;               ///< the final triangulation passes is_valid
  long long non_delaunay_facets = -1;
  std::size_t insertions_not_converged = 0; ///< insertion: swaps after an insertion that did not converge
  double seconds = 0;
};

/// A failure of a conjecture: the helper strategy, or insertion with plain
/// swaps, did not end on CGAL's Delaunay triangulation.
inline bool is_failure(const Experiment_case& c, const Experiment_outcome& o)
{
  return c.strategy != "plain" && o.ending.rfind("bad start", 0) != 0 && !o.equal_to_cgal;
}

/// The cells with their vertices ordered so that each is positively oriented
/// (TOPCOM gives unordered sets); a flat one is left as it is.
inline std::vector<std::array<std::size_t, 4>> oriented_cells(const std::vector<Point>& points,
                                                              std::vector<std::array<std::size_t, 4>> cells)
{
  for(auto& t : cells)
    if(t[0] < points.size() && t[1] < points.size() && t[2] < points.size() && t[3] < points.size() &&
       CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[0], t[1]);
  return cells;
}

inline std::size_t scramble_flips(const std::string& start)
{
  return whole_number(start.substr(start.find(':') + 1), "start scramble:K");
}

namespace internal_experiment {

// The laboratory runs the paper's method as the paper states it: its cycles
// over all facets, and no repair after a stuck state.
inline auto swap_parameters(const Experiment_case& c)
{
  namespace np = ES::parameters;
  return np::schedule(ES::PAPER_CYCLES,
                      np::face_order((c.order == "storage") ? ES::STORAGE_ORDER : ES::RANDOM_ORDER,
                                     np::delaunay_repair(false, CGAL::parameters::random_seed(c.seed)
                                                                  .number_of_iterations(c.max_cycles))));
}

inline void add_report(Experiment_outcome& o, const ES::Swap_report& r)
{
  o.cycles += r.number_of_cycles();
  const auto t = r.total_swaps();
  for(int k = 0; k < ES::number_of_flip_kinds; ++k) o.swaps[k] += t[k];
}

// Conjecture 2: each point is split in (or joined to the hull) and plain
// swaps over all facets, in the case's face order, follow. The first four
// affinely independent points start (one tetrahedron is Delaunay).
inline void run_insertion(Plain_triangulation& tr, const Experiment_case& c, Experiment_outcome& o)
{
  const auto seq = ES::insertion_sequence(c.points, ES::parameters::insertion_order(ES::INPUT_ORDER));
  const auto options = swap_parameters(c);
  Plain_triangulation::Vertex_handle hint;
  for(std::size_t k : seq)
  {
    const auto cell = hint == Plain_triangulation::Vertex_handle() ? Plain_triangulation::Cell_handle() : hint->cell();
    hint = tr.insert(c.points[k], cell);
    if(tr.dimension() < 3 || tr.number_of_vertices() < 5) continue;
    const auto r = CGAL::swap_edges(tr, ES::Delaunay_criterion(), options);
    add_report(o, r);
    if(r.ending != ES::CONVERGED) ++o.insertions_not_converged;
  }
  o.ending = o.insertions_not_converged == 0 ? "converged" : "stuck";
}

} // namespace internal_experiment

/// Runs the case exactly and compares the end with CGAL's Delaunay
/// triangulation. Throws Usage_error for points that cannot be triangulated.
inline Experiment_outcome run_case(const Experiment_case& c)
{
  const std::string problem = ES::point_set_problem(c.points);
  if(!problem.empty()) throw Usage_error(problem);
  Experiment_outcome o;
  CGAL::Real_timer timer;
  timer.start();
  Plain_triangulation tr;
  if(c.strategy == "insertion")
    internal_experiment::run_insertion(tr, c, o);
  else
  {
    if(c.start == "placing")
      ES::insert_by_placing(tr, c.points, ES::parameters::insertion_order(ES::INPUT_ORDER));
    else if(c.start.rfind("scramble:", 0) == 0)
    {
      ES::insert_delaunay(tr, c.points);
      ES::scramble(tr, scramble_flips(c.start), c.seed);
    }
    else if(c.start == "cells")
    {
      std::vector<Plain_triangulation::Vertex_handle> vertices;
      const std::string problem = ES::build_triangulation_from_cells(tr, c.points, c.cells, vertices);
      if(!problem.empty())
      {
        o.ending = "bad start: " + problem;
        return o;
      }
    }
    else
      throw Usage_error("unknown start '" + c.start + "' (placing, scramble:K, cells)");
    const auto options = internal_experiment::swap_parameters(c);
    ES::Swap_report r;
    if(c.strategy == "plain")
      r = CGAL::swap_edges(tr, ES::Delaunay_criterion(), options);
    else if(c.strategy == "helper")
      r = CGAL::swap_edges_with_helper(tr, options);
    else
      throw Usage_error("unknown strategy '" + c.strategy + "' (plain, helper, insertion)");
    internal_experiment::add_report(o, r);
    o.ending = ES::swap_ending_name(r.ending);
    o.non_delaunay_facets = r.non_delaunay_facets;
  }
  o.valid = tr.is_valid();
  o.equal_to_cgal = o.valid && ES::compare_with_delaunay(tr).identical;
  o.seconds = timer.time();
  return o;
}

inline nlohmann::json outcome_json(const Experiment_outcome& o)
{
  return {{"ending", o.ending},
          {"cycles", o.cycles},
          {"swaps", {{"2-3", o.swaps[0]}, {"3-2", o.swaps[1]}, {"2-2", o.swaps[2]}, {"4-4", o.swaps[3]}}},
          {"equal_to_cgal", o.equal_to_cgal},
          {"valid", o.valid},
          {"non_delaunay_facets", o.non_delaunay_facets},
          {"insertions_not_converged", o.insertions_not_converged},
          {"seconds", o.seconds}};
}

/// A case file: everything needed to run the case again.
inline nlohmann::json case_json(const Experiment_case& c)
{
  nlohmann::json points = nlohmann::json::array();
  for(const Point& p : c.points) points.push_back({p.x(), p.y(), p.z()});
  nlohmann::json j = {{"points", points}, {"start", c.start},       {"strategy", c.strategy},
                      {"order", c.order},   {"seed", c.seed},         {"max_cycles", c.max_cycles}};
  if(c.start == "cells") j["cells"] = c.cells;
  return j;
}

/// The case in `j`, read from the file `name`; a Usage_error that names the
/// file and the field for anything missing, of the wrong type or out of range.
inline Experiment_case case_from_json(const nlohmann::json& j, const std::string& name)
{
  auto fail = [&](const std::string& what) { throw Usage_error(name + ": bad case file: " + what); };
  if(!j.is_object()) fail("not a JSON object");
  auto text = [&](const char* key) {
    if(!j.contains(key) || !j[key].is_string()) fail(std::string("\"") + key + "\" is missing or not a string");
    return j[key].get<std::string>();
  };
  auto whole = [&](const char* key, unsigned long long largest) {
    if(!j.contains(key) || !j[key].is_number_unsigned() || j[key].get<unsigned long long>() > largest)
      fail(std::string("\"") + key + "\" is missing or not a whole number from 0 to " + std::to_string(largest));
    return j[key].get<unsigned long long>();
  };
  Experiment_case c;
  if(!j.contains("points") || !j["points"].is_array()) fail("\"points\" is missing or not a list");
  for(const auto& p : j["points"])
  {
    if(!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
      fail("point " + std::to_string(c.points.size()) + " is not three numbers");
    c.points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  c.start = text("start");
  c.strategy = text("strategy");
  c.order = text("order");
  c.seed = unsigned(whole("seed", 4294967295ULL));
  c.max_cycles = j.contains("max_cycles") ? std::size_t(whole("max_cycles", 1000000000ULL)) : std::size_t(1000);
  if(c.strategy != "plain" && c.strategy != "helper" && c.strategy != "insertion")
    fail("unknown strategy '" + c.strategy + "' (plain, helper, insertion)");
  if(c.order != "storage" && c.order != "random") fail("unknown order '" + c.order + "' (storage, random)");
  const std::string problem = ES::point_set_problem(c.points);
  if(!problem.empty()) fail(problem);
  if(c.start.rfind("scramble:", 0) == 0)
    whole_number(c.start.substr(9), name + ": bad case file: start scramble:K");
  else if(c.start == "cells")
  {
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
  else if(c.start != "placing" && c.start != "-")
    fail("unknown start '" + c.start + "' (placing, scramble:K, cells)");
  return c;
}

/// The case in the file at `path` (see `case_from_json`).
inline Experiment_case read_case_file(const std::string& path)
{
  const std::string text = ES::IO::read_text_file(path);
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if(j.is_discarded()) throw Usage_error(path + ": not JSON");
  return case_from_json(j, path);
}

} // namespace edge_swap

#endif
