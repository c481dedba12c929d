// SPDX-License-Identifier: GPL-3.0-or-later
// Flip insertion of weighted points (regular_by_insertion) against CGAL's
// Regular_triangulation_3 on the same points: vertices (with weights) and
// cells, hidden and removed points, and the facets left non-regular.
// Usage: experiment_regular_insertion [N] (default 2000 random points).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/edge_swapping_3.h>
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Regular_triangulation_3<K> Rt;
typedef K::Weighted_point_3 Weighted_point;
typedef K::Point_3 Point;
namespace ES = CGAL::Edge_swapping_3;

std::set<std::array<Point, 4>> cells(const Rt& t)
{
  std::set<std::array<Point, 4>> s;
  for(auto c : t.finite_cell_handles())
  {
    std::array<Point, 4> q;
    for(int k = 0; k < 4; ++k) q[k] = c->vertex(k)->point().point();
    std::sort(q.begin(), q.end());
    s.insert(q);
  }
  return s;
}

std::set<std::pair<Point, double>> vertices(const Rt& t)
{
  std::set<std::pair<Point, double>> s;
  for(auto v : t.finite_vertex_handles()) s.insert({v->point().point(), v->point().weight()});
  return s;
}

std::size_t non_regular_facets(const Rt& t)
{
  std::size_t n = 0;
  for(auto c : t.all_cell_handles())
    for(int i = 0; i < 4; ++i) n += !ES::is_locally_regular(t, c, i);
  return n;
}

bool run(const std::string& name, const std::vector<Weighted_point>& points)
{
  CGAL::Real_timer ours_time, cgal_time;
  Rt tr;
  ours_time.start();
  const auto report = ES::regular_by_insertion(tr, points);
  ours_time.stop();
  cgal_time.start();
  const Rt cgal(points.begin(), points.end());
  cgal_time.stop();
  const auto swaps = report.swaps;
  const bool same = vertices(tr) == vertices(cgal) && cells(tr) == cells(cgal);
  std::cout << name << ": " << points.size() << " points; ours " << tr.number_of_vertices() << " vertices, "
            << swaps[0] + swaps[1] + swaps[2] + swaps[3] << " flips, " << report.stuck_facets << " stuck facets, "
            << non_regular_facets(tr) << " non-regular facets, " << ours_time.time() << " s; CGAL "
            << cgal.number_of_vertices() << " vertices, " << cgal_time.time() << " s; "
            << (same ? "equal cell for cell" : "DIFFERENT") << "\n";
  return same;
}

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 2000;
  if(n < 4 || n > 10000000)
  {
    std::cerr << "experiment_regular_insertion: N is from 4 to 10^7\n";
    return 2;
  }
  bool all = true;
  for(double largest : {0.0, 0.001, 0.01, 0.05})
  {
    CGAL::Random rng(7);
    std::vector<Weighted_point> points;
    for(int i = 0; i < n; ++i)
      points.emplace_back(Point(rng.get_double(), rng.get_double(), rng.get_double()),
                          largest > 0 ? rng.get_double(0, largest) : 0.0);
    all = run("random, weights below " + std::to_string(largest), points) && all;
  }
  std::vector<Weighted_point> equal, alternating, integer;
  for(int x = 0; x < 6; ++x)
    for(int y = 0; y < 6; ++y)
      for(int z = 0; z < 6; ++z)
      {
        equal.emplace_back(Point(x, y, z), 0.25);
        alternating.emplace_back(Point(x, y, z), (x + y + z) % 2 ? 0.0 : 0.6);
        integer.emplace_back(Point(x, y, z), double((7 * x + 3 * y + z) % 4));
      }
  all = run("6x6x6 grid, equal weights", equal) && all;
  all = run("6x6x6 grid, weights 0 and 0.6 alternating", alternating) && all;
  all = run("6x6x6 grid, integer weights 0 to 3", integer) && all;
  // Random integer weights on grids: power ties, redundant vertices on the
  // facets and edges of the cells that replace them.
  int equal_runs = 0;
  const int seeds = 50;
  for(int seed = 1; seed <= seeds; ++seed)
  {
    std::mt19937 rng(seed);
    std::vector<Weighted_point> points;
    for(int x = 0; x < 5; ++x)
      for(int y = 0; y < 5; ++y)
        for(int z = 0; z < 5; ++z) points.emplace_back(Point(x, y, z), double(rng() % 4));
    std::shuffle(points.begin(), points.end(), rng);
    Rt tr;
    ES::regular_by_insertion(tr, points, ES::parameters::insertion_order(seed % 2 ? ES::INPUT_ORDER : ES::SPATIAL_ORDER));
    const Rt cgal(points.begin(), points.end());
    const bool same = vertices(tr) == vertices(cgal) && cells(tr) == cells(cgal);
    if(!same) std::cout << "5x5x5 grid, random integer weights 0 to 3, seed " << seed << ": DIFFERENT\n";
    equal_runs += same;
  }
  std::cout << "5x5x5 grids, random integer weights 0 to 3, seeds 1 to " << seeds << ", input and spatial order: "
            << equal_runs << " of " << seeds << " equal cell for cell\n";
  all = all && equal_runs == seeds;
  return all ? 0 : 1;
}
