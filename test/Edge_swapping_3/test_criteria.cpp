// SPDX-License-Identifier: GPL-3.0-or-later
// The quality criteria: the quantity each optimizes never gets worse, cycle
// after cycle, and the result stays a valid triangulation. Minimum edges
// reproduces the paper's reduction.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/mesh_statistics.h>

using namespace test;

namespace {

// Runs `criterion` from a placing start and checks after every cycle that
// `global` (the worst value over the mesh) never got worse.
template <class Criterion, class Global>
void check_monotone(const Criterion& criterion, Global global, bool larger_is_worse, unsigned seed)
{
  INFO("seed " << seed);
  Tr tr;
  ES::insert_by_placing(tr, random_in_cube(500, seed));
  double previous = global(tr);
  const double start = previous;
  auto after_round = [&](const ES::Cycle_record&) {
    const double now = global(tr);
    if(larger_is_worse) REQUIRE(now <= previous);
    else REQUIRE(now >= previous);
    previous = now;
  };
  const auto report = CGAL::swap_edges(tr, criterion, ES::parameters::cycle_visitor(after_round));
  REQUIRE(tr.is_valid(true));
  REQUIRE(report.ending == ES::CONVERGED);
  // A placing start is poor: the run must change it, and never for the worse.
  const auto t = report.total_swaps();
  REQUIRE(t[0] + t[1] + t[2] + t[3] > 0);
  if(larger_is_worse) REQUIRE(previous <= start);
  else REQUIRE(previous >= start);
}

} // namespace

TEST_CASE("MinMax dihedral angle: the largest angle never grows", "[criteria]")
{
  for(unsigned seed : {1u, 2u, 3u})
    check_monotone(ES::Min_max_dihedral_angle_criterion(),
                   [](const Tr& tr) { return ES::mesh_statistics(tr).max_dihedral_angle; }, true, seed);
}

TEST_CASE("MaxMin dihedral angle: the smallest angle never shrinks", "[criteria]")
{
  for(unsigned seed : {1u, 2u, 3u})
    check_monotone(ES::Max_min_dihedral_angle_criterion(),
                   [](const Tr& tr) { return ES::mesh_statistics(tr).min_dihedral_angle; }, false, seed);
}

TEST_CASE("Aspect ratio - both definitions: the largest ratio never grows", "[criteria]")
{
  for(unsigned seed : {1u, 2u})
  {
    check_monotone(ES::Aspect_ratio_criterion(ES::EDGE_LENGTH_RATIO),
                   [](const Tr& tr) { return ES::mesh_statistics(tr).max_edge_length_ratio; }, true, seed);
    check_monotone(ES::Aspect_ratio_criterion(ES::CIRCUMRADIUS_OVER_INRADIUS),
                   [](const Tr& tr) { return ES::mesh_statistics(tr).max_circumradius_over_inradius; }, true, seed);
  }
}

TEST_CASE("Minimum edges: the counts never grow, and 8 000 points lose at least 10% of their cells", "[criteria]")
{
  const unsigned seed = 1;
  INFO("8000 points in a cube, seed " << seed);
  Tr tr;
  ES::insert_delaunay(tr, random_in_cube(8000, seed));
  const auto before = ES::mesh_statistics(tr);
  std::size_t previous = before.cells;
  auto after_round = [&](const ES::Cycle_record& r) {
    REQUIRE(r.cells <= previous);
    previous = r.cells;
  };
  const auto report = CGAL::swap_edges(tr, ES::Min_edges_criterion(), ES::parameters::cycle_visitor(after_round));
  const auto after = ES::mesh_statistics(tr);
  REQUIRE(tr.is_valid(true));
  REQUIRE(report.ending == ES::CONVERGED);
  REQUIRE(report.total_swaps()[0] == 0); // only 3-2 flips
  const std::size_t removed = report.total_swaps()[1];
  // Each 3-2 flip removes one edge, one face and one cell (paper section 4).
  REQUIRE(before.cells - after.cells == removed);
  REQUIRE(before.edges - after.edges == removed);
  REQUIRE(before.faces - after.faces == 2 * removed);
  REQUIRE(double(before.cells - after.cells) >= 0.10 * double(before.cells));
}

// A criterion of one's own, as in the example: prefer the shorter longest edge.
struct Shorter_longest_edge
{
  template <class T>
  bool operator()(const T& tr, const ES::Five_point_configuration<T>& conf) const
  {
    auto longest = [](const auto& a, const auto& b, const auto& c, const auto& d) {
      const std::array<K::Point_3, 4> p = {a, b, c, d};
      double m = 0;
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) m = (std::max)(m, CGAL::squared_distance(p[i], p[j]));
      return m;
    };
    const auto w = ES::worst_current_and_alternative(tr, conf, longest, true);
    return w.second < w.first * (1 - 1e-12);
  }
};

TEST_CASE("A user-written criterion works with the same driver", "[criteria]")
{
  check_monotone(Shorter_longest_edge(),
                 [](const Tr& tr) {
                   double m = 0;
                   for(auto e : tr.finite_edges())
                     m = (std::max)(m, CGAL::squared_distance(e.first->vertex(e.second)->point(),
                                                              e.first->vertex(e.third)->point()));
                   return m;
                 },
                 true, 4);
}
