// SPDX-License-Identifier: GPL-3.0-or-later
// Flip-based insertion (paper section 5): one point at a time with plain
// flips ends on CGAL's Delaunay_triangulation_3, cell for cell (the paper's
// second conjecture, Joe's theorem), wherever the point falls.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <cmath>

using namespace test;

namespace {

void require_cgal_delaunay(const Tr& tr, const ES::Insertion_report<Tr>& totals)
{
  REQUIRE(tr.is_valid(true));
  REQUIRE(totals.stuck_facets == 0);
  const auto cmp = ES::compare_with_delaunay(tr);
  REQUIRE(cmp.non_delaunay_facets == 0);
  REQUIRE(cmp.identical);
}

} // namespace

TEST_CASE("Insertion with plain flips equals CGAL's Delaunay triangulation on every family", "[insertion][exactness]")
{
  for(unsigned seed = 1; seed <= 5; ++seed)
    for(const auto& family : families(seed))
      for(auto order : {ES::SPATIAL_ORDER, ES::INPUT_ORDER})
      {
        INFO("family " << family.name << ", seed " << seed << ", "
                       << (order == ES::SPATIAL_ORDER ? "spatial" : "input") << " order");
        Tr tr;
        const auto totals = ES::delaunay_by_insertion(tr, family.points, ES::parameters::insertion_order(order));
        const auto& vertices = totals.vertices;
        for(std::size_t k = 0; k < vertices.size(); ++k) REQUIRE(vertices[k]->point() == family.points[k]);
        require_cgal_delaunay(tr, totals);
      }
}

TEST_CASE("Insertion in a random order of a grid equals CGAL's", "[insertion][exactness]")
{
  for(unsigned seed = 1; seed <= 5; ++seed)
  {
    INFO("seed " << seed);
    auto points = grid(5, 5, 5);
    CGAL::Random rng(seed);
    std::shuffle(points.begin(), points.end(), std::mt19937(seed));
    Tr tr;
    const auto totals = ES::delaunay_by_insertion(tr, points, ES::parameters::insertion_order(ES::INPUT_ORDER));
    require_cgal_delaunay(tr, totals);
  }
}

TEST_CASE("A point inside a cell on a facet on an edge on a vertex or outside the hull", "[insertion]")
{
  // The Delaunay triangulation of a 3x3x3 grid, then points at each kind of
  // location; after each insertion the result must be CGAL's.
  const std::vector<Point> base = grid(3, 3, 3);
  struct Case { const char* where; Point p; Tr::Locate_type expected; };
  const std::vector<Case> cases = {
      {"inside a cell", Point(0.3, 0.2, 0.1), Tr::CELL},
      {"on a grid edge", Point(0.5, 0, 0), Tr::EDGE},
      {"on a vertex", Point(2, 0, 2), Tr::VERTEX},
      {"outside the hull", Point(3, 1.2, 0.7), Tr::OUTSIDE_CONVEX_HULL},
      {"on a hull edge", Point(1.5, 1.5, 2), Tr::EDGE},
      {"on a hull facet", Point(0.2, 0.1, 0), Tr::FACET},
      {"on an interior facet", Point(1, 0.2, 0.1), Tr::FACET},
      {"on an interior grid vertex", Point(1, 1, 1), Tr::VERTEX},
      {"far outside, coplanar with a hull face", Point(7, -3, 0), Tr::OUTSIDE_CONVEX_HULL}};
  for(const auto& c : cases)
  {
    INFO(c.where);
    Tr tr;
    ES::delaunay_by_insertion(tr, base);
    std::vector<Point> all = base;
    const auto r = ES::insert_by_swapping(tr, c.p, ES::Delaunay_criterion());
    REQUIRE(r.location == c.expected);
    REQUIRE(r.vertex != Tr::Vertex_handle());
    REQUIRE(r.vertex->point() == c.p);
    REQUIRE(r.is_new == (c.expected != Tr::VERTEX));
    REQUIRE(r.stuck_facets == 0);
    REQUIRE(tr.is_valid(true));
    REQUIRE(ES::compare_with_delaunay(tr).identical);
  }

  // The midpoint of a random edge is exactly on it (coordinates are halved).
  Tr tr;
  std::vector<Point> dyadic; // multiples of 2^-10: midpoints are exact
  for(const Point& q : random_in_cube(50, 7))
    dyadic.emplace_back(std::round(q.x() * 1024) / 1024, std::round(q.y() * 1024) / 1024, std::round(q.z() * 1024) / 1024);
  ES::delaunay_by_insertion(tr, dyadic);
  const auto c = *tr.finite_cell_handles().begin();
  const Point p = CGAL::midpoint(c->vertex(0)->point(), c->vertex(1)->point());
  const auto r = ES::insert_by_swapping(tr, p, ES::Delaunay_criterion());
  REQUIRE(r.location == Tr::EDGE);
  REQUIRE(ES::compare_with_delaunay(tr).identical);
}

TEST_CASE("Insertion under the MinMax criterion keeps a valid triangulation and back-propagates", "[insertion]")
{
  const unsigned seed = 3;
  INFO("seed " << seed);
  Tr tr;
  ES::insert_delaunay(tr, random_in_cube(200, seed));
  const CGAL::Exact_rational volume = exact_volume(tr);
  CGAL::Random rng(seed);
  std::size_t swaps = 0;
  for(int k = 0; k < 50; ++k)
  {
    const Point p(rng.get_double(0.1, 0.9), rng.get_double(0.1, 0.9), rng.get_double(0.1, 0.9));
    const auto r = ES::insert_by_swapping(tr, p, ES::Min_max_dihedral_angle_criterion());
    REQUIRE(r.is_new);
    REQUIRE_FALSE(r.swap_limit_reached);
    swaps += r.total_swaps();
  }
  REQUIRE(tr.number_of_vertices() == 250);
  REQUIRE(tr.is_valid(true));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(swaps > 0);
}

TEST_CASE("The three orientations of a link flip agree with the kernel's Orientation_3", "[insertion][exactness]")
{
  // The batched semi-static filter must give the kernel's exact sign on every
  // input: random, nearly coplanar (one ulp off the plane), exactly coplanar,
  // and coordinates near the underflow and overflow guards.
  const auto orientation = K().orientation_3_object();
  std::size_t zeros = 0;
  for(unsigned seed = 1; seed <= 5; ++seed)
  {
    INFO("seed " << seed);
    CGAL::Random r(seed);
    for(double scale : {1.0, 1e-100, 1e-300, 1e100, 1e150})
      for(int trial = 0; trial < 400; ++trial)
      {
        std::array<Point, 4> cell;
        for(auto& q : cell) q = Point(r.get_double(-1, 1) * scale, r.get_double(-1, 1) * scale, r.get_double(-1, 1) * scale);
        if(orientation(cell[0], cell[1], cell[2], cell[3]) == CGAL::NEGATIVE) std::swap(cell[0], cell[1]);
        if(orientation(cell[0], cell[1], cell[2], cell[3]) != CGAL::POSITIVE) continue;
        Point e;
        switch(trial % 4)
        {
        case 0: // anywhere
          e = Point(r.get_double(-1, 1) * scale, r.get_double(-1, 1) * scale, r.get_double(-1, 1) * scale);
          break;
        case 1: // on a vertex: every determinant with two equal rows is exactly zero
          e = cell[trial % 4];
          break;
        case 2: // on an integer grid with the vertices: exactly coplanar quadruples
          for(auto& q : cell) q = Point(r.get_int(0, 3), r.get_int(0, 3), r.get_int(0, 3));
          if(orientation(cell[0], cell[1], cell[2], cell[3]) == CGAL::NEGATIVE) std::swap(cell[0], cell[1]);
          e = Point(r.get_int(0, 3), r.get_int(0, 3), r.get_int(0, 3));
          break;
        default: // one ulp off a vertex: nearly every determinant is tiny
        {
          const Point& q = cell[trial % 4];
          e = Point(std::nextafter(q.x(), 2 * scale), q.y(), q.z());
        }
        }
        if(orientation(cell[0], cell[1], cell[2], cell[3]) != CGAL::POSITIVE) continue;
        const std::array<const Point*, 4> p = {&cell[0], &cell[1], &cell[2], &cell[3]};
        for(int i = 0; i < 4; ++i)
        {
          const auto o = ES::internal::orientations_with_apex(K(), p, i, e);
          for(int k = 0; k < 4; ++k)
          {
            if(k == i) continue;
            auto q = cell;
            q[k] = e;
            const auto exact = orientation(q[0], q[1], q[2], q[3]);
            REQUIRE(o[k] == exact);
            if(exact == CGAL::ZERO) ++zeros;
          }
        }
      }
  }
  REQUIRE(zeros > 100); // the degenerate cases were met
}
