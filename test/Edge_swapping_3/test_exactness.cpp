// SPDX-License-Identifier: GPL-3.0-or-later
// Exactness against CGAL's Delaunay_triangulation_3, cell for cell: the helper
// strategy from placing and scrambled starts, and plain Algorithm 3, on random
// and degenerate families. Every random input prints its seed.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>

using namespace test;

namespace {

auto random_order(unsigned seed, ES::Schedule schedule = ES::WORK_QUEUE)
{
  return ES::parameters::schedule(schedule,
                                  ES::parameters::face_order(ES::RANDOM_ORDER, CGAL::parameters::random_seed(seed)));
}

const char* schedule_name(ES::Schedule s) { return s == ES::WORK_QUEUE ? "work queue" : "paper cycles"; }

void require_equal_to_cgal(const Tr& tr, const ES::Swap_report& report)
{
  REQUIRE(tr.is_valid(true));
  REQUIRE(report.ending == ES::CONVERGED);
  REQUIRE(report.non_delaunay_facets == 0);
  const auto cmp = ES::compare_with_delaunay(tr);
  REQUIRE(cmp.non_delaunay_facets == 0);
  REQUIRE(cmp.identical);
}

} // namespace

TEST_CASE("Helper strategy from placing starts equals CGAL's Delaunay triangulation", "[exactness][helper]")
{
  for(unsigned seed = 1; seed <= 10; ++seed)
    for(const auto& family : families(seed))
      for(auto order : {ES::SPATIAL_ORDER, ES::INPUT_ORDER})
      {
        // Both schedules, one placing order each.
        const auto schedule = order == ES::SPATIAL_ORDER ? ES::WORK_QUEUE : ES::PAPER_CYCLES;
        INFO("family " << family.name << ", seed " << seed << ", placing in "
                       << (order == ES::SPATIAL_ORDER ? "spatial" : "input") << " order, " << schedule_name(schedule));
        Tr tr;
        ES::insert_by_placing(tr, family.points, ES::parameters::insertion_order(order));
        const auto report = CGAL::swap_edges_with_helper(tr, random_order(seed, schedule));
        require_equal_to_cgal(tr, report);
      }
}

TEST_CASE("Helper strategy from scrambled Delaunay starts equals CGAL's", "[exactness][helper]")
{
  for(unsigned seed = 1; seed <= 10; ++seed)
    for(const auto& family : families(seed))
      for(auto schedule : {ES::WORK_QUEUE, ES::PAPER_CYCLES})
      {
        INFO("family " << family.name << ", seed " << seed << ", " << schedule_name(schedule));
        Tr tr;
        ES::insert_delaunay(tr, family.points);
        ES::scramble(tr, 5 * family.points.size(), seed);
        const auto report = CGAL::swap_edges_with_helper(tr, random_order(seed, schedule));
        require_equal_to_cgal(tr, report);
      }
}

TEST_CASE("Helper strategy on regular grids from 2x2x2 to 10x10x10", "[exactness][helper]")
{
  for(int n = 2; n <= 10; ++n)
  {
    INFO("grid " << n << "x" << n << "x" << n);
    Tr tr;
    ES::insert_by_placing(tr, grid(n, n, n));
    const auto report = CGAL::swap_edges_with_helper(tr, random_order(unsigned(n)));
    require_equal_to_cgal(tr, report);
  }
}

namespace {

std::vector<Point> fixture_points(const std::string& name)
{
  const auto node = CGAL::Edge_swapping_3::IO::read_node_file(std::string(EDGE_SWAPPING_3_FIXTURES) + "/" + name);
  std::vector<Point> points;
  for(const auto& p : node.points) points.emplace_back(p[0], p[1], p[2]);
  return points;
}

// Runs the helper strategy in the paper's exact cycles, storage order, and
// checks every cycle's triangulation. Returns the report.
ES::Swap_report helper_in_storage_order(Tr& tr, std::size_t max_cycles)
{
  auto after_cycle = [&](const ES::Cycle_record&) { REQUIRE(tr.is_valid(true)); };
  namespace np = ES::parameters;
  return CGAL::swap_edges_with_helper(
    tr, np::schedule(ES::PAPER_CYCLES, np::face_order(ES::STORAGE_ORDER, np::cycle_visitor(after_cycle,
                       CGAL::parameters::number_of_iterations(max_cycles)))));
}

} // namespace

TEST_CASE("Fixed: the storage-order 'cycles' of the 300-point fixture and the 11x11x11 grid came from skipped facets", "[exactness][helper][finding]")
{
  // With an early driver, the helper in storage order had not
  // ended by cycle 300 on both (a 2-cycle on the fixture): facets that still
  // existed were not found again and skipped, tags were lost to CGAL's
  // traversals, and a cycle that only set tags ended the run. With the exact
  // cycles both converge to CGAL's triangulation.
  for(const auto& input : {std::make_pair(std::string("300-point fixture"), fixture_points("helper_storage_order_cycle_300.node")),
                           std::make_pair(std::string("grid 11x11x11"), grid(11, 11, 11))})
  {
    INFO(input.first);
    Tr tr;
    ES::insert_by_placing(tr, input.second);
    require_equal_to_cgal(tr, helper_in_storage_order(tr, 300));
  }
}

TEST_CASE("Helper strategy at 1 000 to 20 000 random points", "[exactness][helper][large]")
{
  for(std::size_t n : {1000, 5000, 20000})
  {
    const unsigned seed = unsigned(n) + 7;
    INFO(n << " points in a cube, seed " << seed);
    Tr tr;
    ES::insert_by_placing(tr, random_in_cube(n, seed));
    require_equal_to_cgal(tr, CGAL::swap_edges_with_helper(tr, random_order(seed)));
  }
}

TEST_CASE("Plain Algorithm 3: valid - and equal to CGAL whenever it converges", "[exactness][plain]")
{
  std::size_t converged = 0, stuck = 0;
  for(unsigned seed = 1; seed <= 5; ++seed)
    for(const auto& family : families(seed))
      for(auto order : {ES::STORAGE_ORDER, ES::RANDOM_ORDER})
      {
        const auto schedule = order == ES::STORAGE_ORDER ? ES::PAPER_CYCLES : ES::WORK_QUEUE;
        INFO("family " << family.name << ", seed " << seed << ", " << schedule_name(schedule));
        Tr tr;
        ES::insert_by_placing(tr, family.points);
        namespace np = ES::parameters;
        const auto report = CGAL::swap_edges(
          tr, ES::Delaunay_criterion(),
          np::delaunay_repair(false, np::schedule(schedule, np::face_order(order, CGAL::parameters::random_seed(seed)))));
        REQUIRE(tr.is_valid(true));
        REQUIRE(report.ending != ES::CYCLE_LIMIT_REACHED);
        if(report.ending == ES::CONVERGED)
        {
          ++converged;
          REQUIRE(ES::compare_with_delaunay(tr).identical);
        }
        else
        {
          ++stuck;
          REQUIRE(report.non_delaunay_facets > 0);
          REQUIRE_FALSE(ES::compare_with_delaunay(tr).identical);
        }
      }
  WARN("plain Algorithm 3: " << converged << " converged, " << stuck << " stuck");
  REQUIRE(converged > 0);
}

TEST_CASE("Without perturbation - a cospherical set ends locally Delaunay but may differ from CGAL", "[exactness]")
{
  // The cube corners: all eight cospherical. Any triangulation is Delaunay
  // without the perturbation, so no swap is made.
  Tr tr;
  ES::insert_by_placing(tr, grid(2, 2, 2), ES::parameters::insertion_order(ES::INPUT_ORDER));
  const auto report = CGAL::swap_edges(tr, ES::Delaunay_criterion(), ES::parameters::perturbation(ES::NO_PERTURBATION));
  REQUIRE(report.ending == ES::CONVERGED);
  REQUIRE(report.total_swaps()[0] + report.total_swaps()[1] + report.total_swaps()[2] + report.total_swaps()[3] == 0);
  REQUIRE(ES::number_of_non_delaunay_facets(tr, ES::parameters::perturbation(ES::NO_PERTURBATION)) == 0);
  // With CGAL's perturbation the same start is swapped to CGAL's triangulation.
  const auto perturbed = CGAL::swap_edges(tr, ES::Delaunay_criterion());
  REQUIRE(perturbed.ending == ES::CONVERGED);
  REQUIRE(ES::compare_with_delaunay(tr).identical);
}
