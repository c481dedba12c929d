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
  return std::stoul(start.substr(start.find(':') + 1));
}

namespace internal_experiment {

inline ES::Swap_options swap_options(const Experiment_case& c)
{
  ES::Swap_options options;
  options.face_order = (c.order == "storage") ? ES::STORAGE_ORDER : ES::RANDOM_ORDER;
  options.random_seed = c.seed;
  options.max_cycles = c.max_cycles;
  return options;
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
  const auto seq = ES::internal::basis_first(c.points, tr.geom_traits(),
                                             ES::internal::insertion_sequence<K>(c.points, ES::INPUT_ORDER));
  const auto options = swap_options(c);
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

/// Runs the case exactly and compares the end with CGAL's Delaunay triangulation.
inline Experiment_outcome run_case(const Experiment_case& c)
{
  Experiment_outcome o;
  CGAL::Real_timer timer;
  timer.start();
  Plain_triangulation tr;
  if(c.strategy == "insertion")
    internal_experiment::run_insertion(tr, c, o);
  else
  {
    if(c.start == "placing")
      ES::insert_by_placing(tr, c.points, ES::INPUT_ORDER);
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
    const auto options = internal_experiment::swap_options(c);
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

inline Experiment_case case_from_json(const nlohmann::json& j)
{
  Experiment_case c;
  try
  {
    for(const auto& p : j.at("points"))
    {
      if(!p.is_array() || p.size() != 3) throw Usage_error("a point is not three numbers");
      c.points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    }
    c.start = j.at("start").get<std::string>();
    c.strategy = j.at("strategy").get<std::string>();
    c.order = j.at("order").get<std::string>();
    c.seed = j.at("seed").get<unsigned>();
    c.max_cycles = j.value("max_cycles", std::size_t(1000));
    if(c.start == "cells") c.cells = j.at("cells").get<std::vector<std::array<std::size_t, 4>>>();
  }
  catch(const nlohmann::json::exception& e)
  {
    throw Usage_error(std::string("bad case file: ") + e.what());
  }
  for(const Point& p : c.points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Usage_error("bad case file: a coordinate is not finite");
  if(c.strategy != "plain" && c.strategy != "helper" && c.strategy != "insertion")
    throw Usage_error("bad case file: unknown strategy '" + c.strategy + "'");
  if(c.order != "storage" && c.order != "random") throw Usage_error("bad case file: unknown order '" + c.order + "'");
  const std::string problem = ES::point_set_problem(c.points, K());
  if(!problem.empty()) throw Usage_error("bad case file: " + problem);
  return c;
}

} // namespace edge_swap

#endif
