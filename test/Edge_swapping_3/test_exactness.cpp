// Exactness against CGAL's Delaunay_triangulation_3, cell for cell: the helper
// strategy from placing and scrambled starts, and plain Algorithm 3, on random
// and degenerate families. Every random input prints its seed.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/IO/tetgen.h>

using namespace test;

namespace {

ES::Swap_options random_order(unsigned seed)
{
  ES::Swap_options o;
  o.face_order = ES::RANDOM_ORDER;
  o.random_seed = seed;
  return o;
}

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
        INFO("family " << family.name << ", seed " << seed << ", placing in "
                       << (order == ES::SPATIAL_ORDER ? "spatial" : "input") << " order");
        Tr tr;
        ES::insert_by_placing(tr, family.points, order);
        const auto report = CGAL::swap_edges_with_helper(tr, random_order(seed));
        require_equal_to_cgal(tr, report);
      }
}

TEST_CASE("Helper strategy from scrambled Delaunay starts equals CGAL's", "[exactness][helper]")
{
  for(unsigned seed = 1; seed <= 10; ++seed)
    for(const auto& family : families(seed))
    {
      INFO("family " << family.name << ", seed " << seed);
      Tr tr;
      ES::insert_delaunay(tr, family.points);
      ES::scramble(tr, 5 * family.points.size(), seed);
      const auto report = CGAL::swap_edges_with_helper(tr, random_order(seed));
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

// Runs the helper strategy in storage order and checks that it does not end:
// every cycle's triangulation is valid, the cycle limit is reached with
// non-Delaunay facets left. Returns the period (up to 50) with which the cell
// sets of the last 100 cycles repeat, or 0 if they do not.
std::size_t require_periodic_cycle(const std::vector<Point>& points)
{
  Tr tr;
  ES::insert_by_placing(tr, points);
  ES::Swap_options options;
  options.face_order = ES::STORAGE_ORDER;
  options.max_cycles = 300;
  std::vector<std::vector<Cell_points>> last;
  options.cycle_visitor = [&](const ES::Cycle_record& r) {
    REQUIRE(tr.is_valid(true)); // every flip valid, exactly
    if(r.cycle > options.max_cycles - 100) last.push_back(cell_set(tr));
  };
  const auto report = CGAL::swap_edges_with_helper(tr, options);
  REQUIRE(report.ending == ES::CYCLE_LIMIT_REACHED);
  REQUIRE(report.non_delaunay_facets > 0);
  REQUIRE(last.size() == 100);
  std::size_t period = 0;
  for(std::size_t p = 1; p <= 50 && period == 0; ++p)
  {
    bool repeats = true;
    for(std::size_t k = 0; k + p < last.size(); ++k) repeats = repeats && last[k] == last[k + p];
    if(repeats) period = p;
  }

  // The same start in random face order reaches CGAL's triangulation.
  Tr again;
  ES::insert_by_placing(again, points);
  require_equal_to_cgal(again, CGAL::swap_edges_with_helper(again, random_order(1)));
  return period;
}

} // namespace

TEST_CASE("Finding: in storage face order the helper strategy can cycle (fixture)", "[exactness][helper][finding]")
{
  SECTION("300 random points")
  {
    REQUIRE(require_periodic_cycle(fixture_points("helper_storage_order_cycle_300.node")) == 2);
  }
  SECTION("grid 11x11x11")
  {
    // No short period here: storage order also depends on where flips put cells.
    require_periodic_cycle(grid(11, 11, 11));
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
        INFO("family " << family.name << ", seed " << seed);
        Tr tr;
        ES::insert_by_placing(tr, family.points);
        ES::Swap_options options;
        options.face_order = order;
        options.random_seed = seed;
        const auto report = CGAL::swap_edges(tr, ES::Delaunay_criterion(), options);
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
  ES::insert_by_placing(tr, grid(2, 2, 2), ES::INPUT_ORDER);
  ES::Swap_options options;
  options.perturbation = ES::NO_PERTURBATION;
  const auto report = CGAL::swap_edges(tr, ES::Delaunay_criterion(ES::NO_PERTURBATION), options);
  REQUIRE(report.ending == ES::CONVERGED);
  REQUIRE(report.total_swaps()[0] + report.total_swaps()[1] + report.total_swaps()[2] + report.total_swaps()[3] == 0);
  REQUIRE(ES::number_of_non_delaunay_facets(tr, ES::NO_PERTURBATION) == 0);
  // With CGAL's perturbation the same start is swapped to CGAL's triangulation.
  const auto perturbed = CGAL::swap_edges(tr, ES::Delaunay_criterion());
  REQUIRE(perturbed.ending == ES::CONVERGED);
  REQUIRE(ES::compare_with_delaunay(tr).identical);
}
