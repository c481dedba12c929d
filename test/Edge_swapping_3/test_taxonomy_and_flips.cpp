// SPDX-License-Identifier: GPL-3.0-or-later
// The five-point taxonomy (paper Figs. 6 and 7) on exact integer
// configurations, the flips between the two triangulations, and random flip
// sequences that must keep the triangulation valid and its volume exact.

#include "test_common.h"
#include <CGAL/Random.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <map>

using namespace test;

namespace {

// Triangulation_3's own insertion in the given order: no flip.
Tr place(const std::vector<Point>& points)
{
  Tr tr;
  ES::insert_by_placing(tr, points, ES::parameters::insertion_order(ES::INPUT_ORDER));
  REQUIRE(tr.dimension() == 3);
  return tr;
}

Tr::Vertex_handle vertex_at(const Tr& tr, const Point& p)
{
  for(auto v : tr.finite_vertex_handles())
    if(v->point() == p) return v;
  FAIL("no vertex at the point");
  return Tr::Vertex_handle();
}

// The facet with these three corners.
std::pair<Tr::Cell_handle, int> facet(const Tr& tr, const Point& a, const Point& b, const Point& c)
{
  Tr::Cell_handle cell;
  int i, j, k;
  REQUIRE(tr.is_facet(vertex_at(tr, a), vertex_at(tr, b), vertex_at(tr, c), cell, i, j, k));
  return {cell, 6 - i - j - k};
}

ES::Configuration_kind kind_of(const Tr& tr, const Point& a, const Point& b, const Point& c)
{
  const auto f = facet(tr, a, b, c);
  return ES::classify_facet(tr, f.first, f.second).kind();
}

// Swaps the facet, checks the new cells, swaps back through `back` and
// checks that the original cell set returns exactly.
void check_round_trip(Tr& tr, const std::array<Point, 3>& there, ES::Configuration_kind expected_there,
                      const std::array<Point, 3>& back, ES::Configuration_kind expected_back)
{
  const auto original = cell_set(tr);
  REQUIRE(kind_of(tr, there[0], there[1], there[2]) == expected_there);
  auto f = facet(tr, there[0], there[1], there[2]);
  REQUIRE(ES::flip_facet(tr, f.first, f.second));
  REQUIRE(tr.is_valid(true));
  REQUIRE(cell_set(tr) != original);
  REQUIRE(kind_of(tr, back[0], back[1], back[2]) == expected_back);
  f = facet(tr, back[0], back[1], back[2]);
  REQUIRE(ES::flip_facet(tr, f.first, f.second));
  REQUIRE(tr.is_valid(true));
  REQUIRE(cell_set(tr) == original);
}

// An unswappable facet is refused and nothing changes.
void check_refused(Tr& tr, const std::array<Point, 3>& f3, ES::Configuration_kind expected)
{
  const auto original = cell_set(tr);
  REQUIRE(kind_of(tr, f3[0], f3[1], f3[2]) == expected);
  const auto f = facet(tr, f3[0], f3[1], f3[2]);
  REQUIRE_FALSE(ES::flip_facet(tr, f.first, f.second));
  REQUIRE(tr.is_valid(true));
  REQUIRE(cell_set(tr) == original);
}

} // namespace

TEST_CASE("Fig. 6(a) and 6(b): two convex tetrahedra flip 2-3 and back 3-2", "[taxonomy][flips]")
{
  const Point a(0, 0, 0), b(4, 0, 0), c(0, 4, 0), d(1, 1, 3), e(1, 1, -3);
  Tr tr = place({a, b, c, d, e});
  REQUIRE(tr.number_of_finite_cells() == 2);
  check_round_trip(tr, {a, b, c}, ES::TWO_TETRAHEDRA_CONVEX, {d, e, a}, ES::THREE_TETRAHEDRA_CONVEX);
  // The three-tetrahedra state has all three facets around the new edge swappable.
  auto f = facet(tr, a, b, c);
  REQUIRE(ES::flip_facet(tr, f.first, f.second));
  REQUIRE(tr.number_of_finite_cells() == 3);
  for(const Point& x : {a, b, c})
    REQUIRE(kind_of(tr, d, e, x) == ES::THREE_TETRAHEDRA_CONVEX);
}

TEST_CASE("Fig. 6(c): a planar hull face flips 2-2 and back", "[taxonomy][flips]")
{
  // The square z = 0 is a hull face; the apex is off-centre.
  const Point p0(0, 0, 0), p1(2, 0, 0), p2(2, 2, 0), p3(0, 2, 0), apex(1, 0, 3);
  Tr tr = place({p0, p1, p2, p3, apex});
  REQUIRE(tr.number_of_finite_cells() == 2);
  // Whichever diagonal placing chose, flip to the other and back.
  Tr::Cell_handle c;
  int i, j;
  const bool diagonal_02 = tr.is_edge(vertex_at(tr, p0), vertex_at(tr, p2), c, i, j);
  if(diagonal_02)
    check_round_trip(tr, {apex, p0, p2}, ES::PLANAR_HULL_TWO_TWO, {apex, p1, p3}, ES::PLANAR_HULL_TWO_TWO);
  else
    check_round_trip(tr, {apex, p1, p3}, ES::PLANAR_HULL_TWO_TWO, {apex, p0, p2}, ES::PLANAR_HULL_TWO_TWO);
}

TEST_CASE("Fig. 6(d): an interior planar configuration flips 4-4 and back", "[taxonomy][flips]")
{
  const Point p0(0, 0, 0), p1(2, 0, 0), p2(2, 2, 0), p3(0, 2, 0), top(1, 1, 2), bottom(2, 1, -2);
  Tr tr = place({p0, p1, p2, p3, top, bottom});
  REQUIRE(tr.number_of_finite_cells() == 4);
  Tr::Cell_handle c;
  int i, j;
  if(tr.is_edge(vertex_at(tr, p0), vertex_at(tr, p2), c, i, j))
    check_round_trip(tr, {top, p0, p2}, ES::PLANAR_FOUR_FOUR, {top, p1, p3}, ES::PLANAR_FOUR_FOUR);
  else
    check_round_trip(tr, {top, p1, p3}, ES::PLANAR_FOUR_FOUR, {top, p0, p2}, ES::PLANAR_FOUR_FOUR);
}

TEST_CASE("Fig. 7(a): four tetrahedra from five points are unswappable", "[taxonomy][flips]")
{
  const Point a(0, 0, 0), b(4, 0, 0), c(0, 4, 0), d(0, 0, 4), inside(1, 1, 1);
  Tr tr = place({a, b, c, d, inside});
  REQUIRE(tr.number_of_finite_cells() == 4);
  for(const auto& f : std::vector<std::array<Point, 3>>{{a, b, inside}, {b, c, inside}, {a, d, inside}})
    check_refused(tr, f, ES::FOUR_TETRAHEDRA);
}

TEST_CASE("Fig. 6(b) with a tetrahedron missing: a concave pair is unswappable", "[taxonomy][flips]")
{
  // Three tetrahedra around an edge; a point inserted into one of them
  // leaves the other two around that edge with a concave union.
  const Point a(0, 0, 0), b(4, 0, 0), c(0, 4, 0), d(1, 1, 3), e(1, 1, -3);
  Tr tr = place({a, b, c, d, e});
  auto f = facet(tr, a, b, c);
  REQUIRE(ES::flip_facet(tr, f.first, f.second)); // now abde, bcde, cade
  tr.insert(Point(1, 0.5, 0.1)); // splits the tetrahedron a b d e
  REQUIRE(tr.is_valid(true));
  std::size_t concave = 0;
  for(auto fc : tr.finite_facets())
  {
    const auto conf = ES::classify_facet(tr, fc.first, fc.second);
    if(conf.kind() != ES::CONCAVE) continue;
    ++concave;
    const auto before = cell_set(tr);
    REQUIRE_FALSE(ES::flip_facet(tr, fc.first, fc.second));
    REQUIRE(cell_set(tr) == before);
  }
  REQUIRE(concave > 0);
}

TEST_CASE("Fig. 7(b): a point on the segment between the apexes is unswappable", "[taxonomy][flips]")
{
  const Point a(4, 0, 0), b(0, 4, 0), c(1, 1, 0), d(1, 1, 3), e(1, 1, -3);
  Tr tr = place({a, b, d, e, c}); // c falls on the edge d-e
  REQUIRE(tr.number_of_finite_cells() == 2);
  check_refused(tr, {a, b, c}, ES::PLANAR_UNSWAPPABLE);
}

TEST_CASE("Fig. 7(c): coplanar with one facet - beyond another: unswappable", "[taxonomy][flips]")
{
  const Point a(0, 0, 0), b(1, 1, 3), c(4, 0, 0), d(0, 4, 0), e(6, -1, 0);
  Tr tr = place({a, b, c, d, e});
  check_refused(tr, {a, b, c}, ES::PLANAR_UNSWAPPABLE);
}

TEST_CASE("Hull facets are not interior facets", "[taxonomy]")
{
  Tr tr = place({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)});
  std::size_t hull = 0;
  for(auto f : tr.all_facets())
    if(ES::classify_facet(tr, f.first, f.second).kind() == ES::HULL_FACET) ++hull;
  REQUIRE(hull == tr.number_of_facets()); // a single tetrahedron: every facet touches the outside
}

TEST_CASE("Random flip sequences keep the triangulation valid - its vertices and its exact volume", "[flips]")
{
  for(unsigned seed = 1; seed <= 6; ++seed)
    for(const auto& family : std::vector<Family>{{"cube", random_in_cube(400, seed)},
                                                 {"grid", grid(5, 5, 5)},
                                                 {"cospherical", cospherical(50)},
                                                 {"planes", on_planes(150, 3, seed)}})
    {
      INFO("family " << family.name << ", seed " << seed);
      Tr tr;
      ES::insert_delaunay(tr, family.points);
      const auto vertices = tr.number_of_vertices();
      const auto volume = exact_volume(tr);
      const auto made = ES::scramble(tr, 3000, seed);
      REQUIRE(made[0] + made[1] + made[2] + made[3] == 3000);
      REQUIRE(tr.is_valid(true));
      REQUIRE(tr.number_of_vertices() == vertices);
      REQUIRE(exact_volume(tr) == volume);
      if(family.name == "grid" || family.name == "planes")
        REQUIRE(made[2] + made[3] > 0); // the planar flips were exercised
    }
}

namespace {

// The whole combinatorial state of a triangulation, read in storage order:
// per cell its vertices and neighbours as storage ranks and its data; per
// vertex the rank of its cell. Two triangulations copied from one and
// changed alike read the same.
template <class T, class Data>
std::vector<long> storage_state(const T& tr, Data data)
{
  std::map<const void*, long> vertex_rank, cell_rank;
  for(auto v = tr.tds().vertices().begin(); v != tr.tds().vertices().end(); ++v)
    vertex_rank.emplace(&*v, long(vertex_rank.size()));
  for(auto c = tr.tds().cells().begin(); c != tr.tds().cells().end(); ++c) cell_rank.emplace(&*c, long(cell_rank.size()));
  std::vector<long> s;
  for(auto c = tr.tds().cells().begin(); c != tr.tds().cells().end(); ++c)
  {
    for(int i = 0; i < 4; ++i)
    {
      s.push_back(vertex_rank.at(&*c->vertex(i)));
      s.push_back(cell_rank.at(&*c->neighbor(i)));
    }
    data(c, s);
  }
  for(auto v = tr.tds().vertices().begin(); v != tr.tds().vertices().end(); ++v) s.push_back(cell_rank.at(&*v->cell()));
  return s;
}

// The k-th cell in storage order.
template <class T>
typename T::Cell_handle cell_at(const T& tr, std::size_t k)
{
  auto c = tr.tds().cells().begin();
  std::advance(c, k);
  return c;
}

} // namespace

TEST_CASE("The direct 2-3 and 3-2 flips leave the triangulation as the flip by matching facets does", "[flips]")
{
  // The same random flips on two copies: the plans of `classify_facet`
  // carried out directly in one, by matching facets in the other (the way
  // every other plan is). Facet data (the boundary references) and cell data
  // must follow alike.
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                               CGAL::Triangulation_cell_base_with_info_3<ES::Domain_cell_info, K>>
    Domain_tds;
  typedef CGAL::Triangulation_3<K, Domain_tds> Domain_tr;
  auto data = [](Domain_tr::Cell_handle c, std::vector<long>& s) {
    s.push_back(c->info().subdomain);
    for(int i = 0; i < 4; ++i) s.push_back(c->info().facet_reference[i]);
  };
  std::size_t direct[2] = {0, 0};
  for(unsigned seed = 1; seed <= 3; ++seed)
  {
    INFO("random_in_cube(60, " << seed << "), placing start, random facets from seed " << seed);
    Domain_tr start;
    ES::insert_by_placing(start, random_in_cube(60, seed));
    int reference = 0;
    for(auto c : start.all_cell_handles())
    {
      c->info().subdomain = start.is_infinite(c) ? 0 : 1 + (reference % 3);
      for(int i = 0; i < 4; ++i) c->info().facet_reference[i] = reference++ % 5 == 0 ? reference : -1;
    }
    Domain_tr a = start, b = start;
    REQUIRE(storage_state(a, data) == storage_state(b, data));
    CGAL::Random rng(seed);
    for(int step = 0; step < 400; ++step)
    {
      const std::size_t k = rng.get_int(0, int(a.tds().cells().size()));
      const int i = rng.get_int(0, 4);
      const auto ca = cell_at(a, k), cb = cell_at(b, k);
      if(a.is_infinite(ca)) continue;
      const auto conf_a = ES::classify_facet(a, ca, i);
      const auto conf_b = ES::classify_facet(b, cb, i);
      REQUIRE(conf_a.kind() == conf_b.kind());
      if(!conf_a.is_swappable()) continue;
      auto plan_b = conf_b.flip_plan();
      const bool planned_at_facet = plan_b.facet_index >= 0;
      REQUIRE(planned_at_facet == (conf_a.kind() == ES::TWO_TETRAHEDRA_CONVEX || conf_a.kind() == ES::THREE_TETRAHEDRA_CONVEX));
      plan_b.facet_index = plan_b.reflex_index = -1; // by matching
      std::array<Domain_tr::Cell_handle, 4> made_a, made_b;
      const int na = ES::flip(a, conf_a, made_a, ES::Domain_constraints());
      const int nb = ES::execute_flip(b, plan_b, made_b, ES::Domain_constraints());
      REQUIRE(na == nb);
      if(planned_at_facet) ++direct[conf_a.kind()];
      REQUIRE(storage_state(a, data) == storage_state(b, data));
    }
    REQUIRE(a.is_valid());
  }
  WARN(direct[0] << " direct 2-3 flips and " << direct[1] << " direct 3-2 flips compared");
  REQUIRE(direct[0] > 20);
  REQUIRE(direct[1] > 20);
}

TEST_CASE("Kernels with exact predicates are told from those that round", "[flips]")
{
  STATIC_REQUIRE(ES::Has_exact_predicates<K>::value);
  STATIC_REQUIRE(ES::Has_exact_predicates<CGAL::Exact_predicates_exact_constructions_kernel>::value);
  STATIC_REQUIRE(ES::Has_exact_predicates<CGAL::Simple_cartesian<CGAL::Gmpq>>::value);
  STATIC_REQUIRE(!ES::Has_exact_predicates<CGAL::Simple_cartesian<double>>::value);
}
