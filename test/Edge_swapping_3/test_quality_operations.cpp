// SPDX-License-Identifier: GPL-3.0-or-later
// The quality operations. Edge removal: hand-built rings of 3 to 7
// tetrahedra with exact coordinates, Klincsek's dynamic program against every
// triangulation of the ring, constraints, the hull, and random sequences of
// removals on a Delaunay mesh. Multi-face removal: hand-built sandwiches of 1
// to 6 triangles, constraints, random sequences. Vertex smoothing: a star with
// a known best place, the boundary kept, random sequences. The quality driver
// (worst first): validity, exact volume, the worst value, its ending,
// determinism, domain meshes.

#include "test_common.h"
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/edge_removal.h>
#include <CGAL/Edge_swapping_3/improve_worst_tetrahedra.h>
#include <CGAL/Edge_swapping_3/internal/worst_cell_queue.h>
#include <CGAL/Edge_swapping_3/multi_face_removal.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <CGAL/Edge_swapping_3/two_step_edge_removal.h>
#include <CGAL/Edge_swapping_3/vertex_insertion.h>
#include <CGAL/Edge_swapping_3/vertex_removal.h>
#include <CGAL/Edge_swapping_3/vertex_smoothing.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <optional>
#include <set>
#include <thread>

using namespace test;

namespace {

typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                             CGAL::Triangulation_cell_base_with_info_3<ES::Domain_cell_info, K>>
  Domain_tds;
typedef CGAL::Triangulation_3<K, Domain_tds> Domain_tr;

/// The n tetrahedra around the edge from a = (0, 0, h) to b = (0, 0, -h), its
/// ring the points `ring` (in turning order). Point 0 is a, 1 is b.
template <class T>
std::vector<typename T::Vertex_handle> build_star(T& tr, double h, const std::vector<Point>& ring)
{
  std::vector<Point> points = {Point(0, 0, h), Point(0, 0, -h)};
  points.insert(points.end(), ring.begin(), ring.end());
  std::vector<std::array<std::size_t, 4>> cells;
  const std::size_t n = ring.size();
  for(std::size_t k = 0; k < n; ++k) cells.push_back({0, 1, 2 + k, 2 + (k + 1) % n});
  std::vector<typename T::Vertex_handle> vertices;
  const std::string problem = ES::build_triangulation_from_cells(tr, points, cells, vertices);
  INFO(problem);
  REQUIRE(problem.empty());
  return vertices;
}

std::vector<Point> regular_ring(int n, double radius = 1)
{
  std::vector<Point> ring;
  for(int k = 0; k < n; ++k)
  {
    const double t = 2 * 3.14159265358979323846 * k / n;
    ring.emplace_back(radius * std::cos(t), radius * std::sin(t), 0.0);
  }
  return ring;
}

template <class T>
typename T::Edge edge_of(const T& tr, typename T::Vertex_handle u, typename T::Vertex_handle v)
{
  typename T::Cell_handle c;
  int i, j;
  REQUIRE(tr.is_edge(u, v, c, i, j));
  return typename T::Edge(c, i, j);
}

template <class T>
bool every_cell_positive(const T& tr)
{
  for(auto c : tr.finite_cell_handles())
    if(CGAL::orientation(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                         c->vertex(3)->point()) != CGAL::POSITIVE)
      return false;
  return true;
}

/// Whether the finite cells, read back as a mesh, form a valid triangulation
/// of the convex hull (the builder checks convexity, which is_valid does not).
bool rebuilds_as_convex_mesh(const Tr& tr)
{
  std::map<Tr::Vertex_handle, std::size_t> index;
  std::vector<Point> points;
  for(auto v : tr.finite_vertex_handles())
  {
    index[v] = points.size();
    points.push_back(v->point());
  }
  std::vector<std::array<std::size_t, 4>> cells;
  for(auto c : tr.finite_cell_handles())
    cells.push_back({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
  Tr copy;
  std::vector<Tr::Vertex_handle> vertices;
  const std::string problem = ES::build_triangulation_from_cells(copy, points, cells, vertices);
  INFO(problem);
  return problem.empty();
}

/// A valid triangulation of the convex hull, every cell positive, with the
/// exact volume it had: what every operation must leave.
void require_same_region(const Tr& tr, const CGAL::Exact_rational& volume)
{
  REQUIRE(tr.is_valid());
  REQUIRE(every_cell_positive(tr));
  REQUIRE(rebuilds_as_convex_mesh(tr));
  REQUIRE(exact_volume(tr) == volume);
}

double smallest_angle(const Point& p, const Point& q, const Point& r, const Point& s)
{
  return ES::Smallest_dihedral_angle()(p, q, r, s);
}

template <class T>
double worst_smallest_angle(const T& tr)
{
  double worst = HUGE_VAL;
  for(auto c : tr.finite_cell_handles())
    worst = std::min(worst, smallest_angle(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                           c->vertex(3)->point()));
  return worst;
}

template <class T>
double worst_largest_angle(const T& tr)
{
  double worst = 0;
  for(auto c : tr.finite_cell_handles())
    worst = std::max(worst, ES::Largest_dihedral_angle()(c->vertex(0)->point(), c->vertex(1)->point(),
                                                         c->vertex(2)->point(), c->vertex(3)->point()));
  return worst;
}

/// The cells with a dihedral angle above 165 degrees (MinMax) or below 10 (MaxMin).
/// The smallest value of a larger-is-better criterion's measure over the finite cells.
template <class T, class Criterion>
double smallest_measure(const T& tr, const Criterion& criterion)
{
  double w = HUGE_VAL;
  for(auto c : tr.finite_cell_handles())
    w = std::min(w, criterion.measure(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                      c->vertex(3)->point()));
  return w;
}

template <class T>
std::size_t poor_cells(const T& tr, bool largest)
{
  std::size_t n = 0;
  for(auto c : tr.finite_cell_handles())
  {
    const auto& p0 = c->vertex(0)->point(); const auto& p1 = c->vertex(1)->point();
    const auto& p2 = c->vertex(2)->point(); const auto& p3 = c->vertex(3)->point();
    if(largest ? ES::Largest_dihedral_angle()(p0, p1, p2, p3) > 165 : smallest_angle(p0, p1, p2, p3) < 10) ++n;
  }
  return n;
}

/// A sandwich: the fan triangulation from s_0 of the convex polygon `ring`
/// (in the plane z = 0), each triangle joined to u = (0, 0, h) and to
/// w = (0, 0, -h). Point 0 is u, 1 is w, 2 + k is s_k; `references` (when
/// given) constrains the fan triangle k with reference k + 1 where nonzero.
template <class T>
std::vector<typename T::Vertex_handle> build_sandwich(T& tr, double h, const std::vector<Point>& ring)
{
  std::vector<Point> points = {Point(0, 0, h), Point(0, 0, -h)};
  points.insert(points.end(), ring.begin(), ring.end());
  std::vector<std::array<std::size_t, 4>> cells;
  for(std::size_t k = 1; k + 1 < ring.size(); ++k)
    for(std::size_t apex : {0, 1})
    {
      std::array<std::size_t, 4> t = {apex, 2, 2 + k, 2 + k + 1};
      if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
        std::swap(t[2], t[3]);
      cells.push_back(t);
    }
  std::vector<typename T::Vertex_handle> vertices;
  const std::string problem = ES::build_triangulation_from_cells(tr, points, cells, vertices);
  INFO(problem);
  REQUIRE(problem.empty());
  return vertices;
}

/// The facet (s_0, s_k, s_{k+1}) of a sandwich, seen from its cell with u.
template <class T>
typename T::Facet fan_facet(const T& tr, const std::vector<typename T::Vertex_handle>& v, std::size_t k)
{
  typename T::Cell_handle c;
  REQUIRE(tr.is_cell(v[0], v[2], v[2 + k], v[2 + k + 1], c));
  return typename T::Facet(c, c->index(v[0]));
}

/// Every triangulation of the polygon s_i ... s_j: the best worst score, or
/// -inf when none has positive tetrahedra only (written apart from the
/// dynamic program: plain recursion over the triangle on edge (i, j)).
double best_by_enumeration(const ES::internal::Edge_star<Tr>& star, int i, int j)
{
  if(j - i < 2) return HUGE_VAL;
  double best = -HUGE_VAL;
  for(int k = i + 1; k < j; ++k)
  {
    const Point a = star.a->point(), b = star.b->point();
    const Point si = star.ring[i]->point(), sk = star.ring[k]->point(), sj = star.ring[j]->point();
    double here = HUGE_VAL;
    // The triangle (i, k, j) seen from a and from b: both must be positive.
    if(CGAL::orientation(a, sj, sk, si) != CGAL::POSITIVE || CGAL::orientation(b, si, sk, sj) != CGAL::POSITIVE)
      continue;
    here = std::min(smallest_angle(a, sj, sk, si), smallest_angle(b, si, sk, sj));
    here = std::min({here, best_by_enumeration(star, i, k), best_by_enumeration(star, k, j)});
    best = std::max(best, here);
  }
  return best;
}

/// `n` random points in the unit cube and `m` on its faces x = 0, x = 1,
/// z = 0, z = 1, where the hull is flat: hull edges can be removed there.
std::vector<Point> in_cube_and_on_faces(std::size_t n, int m, unsigned seed)
{
  auto points = random_in_cube(n, seed);
  CGAL::Random random(seed);
  for(int k = 0; k < m; ++k)
  {
    const double x = random.get_double(), y = random.get_double(), side = double(k % 2);
    points.push_back(k % 4 < 2 ? Point(x, y, side) : Point(side, x, y));
  }
  return points;
}

/// The finite edges of `tr` by coordinates, then shuffled: the sequence
/// depends on the seed only, not on the storage order (which CGAL's spatial
/// sort draws at random).
std::vector<std::pair<Tr::Vertex_handle, Tr::Vertex_handle>> shuffled_edges(const Tr& tr, unsigned seed)
{
  std::vector<std::pair<Tr::Vertex_handle, Tr::Vertex_handle>> edges;
  for(auto e : tr.finite_edges())
  {
    auto u = e.first->vertex(e.second), w = e.first->vertex(e.third);
    if(CGAL::compare_xyz(w->point(), u->point()) == CGAL::SMALLER) std::swap(u, w);
    edges.emplace_back(u, w);
  }
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
    const auto c = CGAL::compare_xyz(x.first->point(), y.first->point());
    return c == CGAL::SMALLER ||
           (c == CGAL::EQUAL && CGAL::compare_xyz(x.second->point(), y.second->point()) == CGAL::SMALLER);
  });
  std::shuffle(edges.begin(), edges.end(), std::mt19937(seed));
  return edges;
}

} // namespace

TEST_CASE("Edge removal replaces the n tetrahedra of a ring by the best 2n-4", "[edge removal]")
{
  for(int n = 3; n <= 7; ++n)
  {
    CAPTURE(n);
    Tr tr;
    // A long edge: its n tetrahedra are needles with dihedral angles near
    // 180 degrees at the ring; those of the ring's triangulation are better.
    const auto v = build_star(tr, 5.0, regular_ring(n));
    const auto volume = exact_volume(tr);
    const double before = worst_largest_angle(tr);
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Min_max_dihedral_angle_criterion());
    INFO(ES::edge_removal_outcome_name(r.outcome));
    REQUIRE(r.outcome == ES::EDGE_REMOVED);
    REQUIRE(r.ring_size == n);
    REQUIRE(r.new_cells == 2 * n - 4);
    REQUIRE(tr.number_of_finite_cells() == std::size_t(2 * n - 4));
    REQUIRE(tr.is_valid());
    REQUIRE(every_cell_positive(tr));
    REQUIRE(exact_volume(tr) == volume);
    Tr::Cell_handle c;
    int i, j;
    REQUIRE_FALSE(tr.is_edge(v[0], v[1], c, i, j));
    REQUIRE(r.quality_before == before);
    REQUIRE(r.quality_after == worst_largest_angle(tr));
    REQUIRE(r.quality_after < r.quality_before);
  }
}

TEST_CASE("Edge removal - the dynamic program finds the best valid triangulation of the ring", "[edge removal]")
{
  // The rings of a Delaunay mesh of random points: not planar, often not
  // convex, so many triangulations of a ring have inverted tetrahedra.
  const unsigned seed = 29;
  INFO("seed " << seed);
  Tr tr;
  ES::insert_delaunay(tr, random_in_cube(300, seed));
  int valid = 0, invalid = 0;
  for(auto e : tr.finite_edges())
  {
    bool hull = false;
    int n = 0;
    auto circ = tr.incident_cells(e), done = circ;
    do { hull = hull || tr.is_infinite(circ); ++n; } while(++circ != done);
    if(hull || n > 8) continue;
    CAPTURE(n);
    const ES::internal::Edge_star<Tr> star(tr, e, 10);
    REQUIRE(int(star.ring.size()) == n);
    auto score = [](const std::array<Tr::Vertex_handle, 4>& t) {
      return smallest_angle(t[0]->point(), t[1]->point(), t[2]->point(), t[3]->point());
    };
    const ES::internal::Ring_triangulation<Tr, decltype(score)> dp(tr, star, score);
    const double enumerated = best_by_enumeration(star, 0, n - 1);
    if(!(enumerated > -HUGE_VAL))
    {
      ++invalid;
      REQUIRE_FALSE(dp.exists());
      continue;
    }
    ++valid;
    REQUIRE(dp.exists());
    REQUIRE(dp.score() == enumerated);
    REQUIRE(dp.cells().size() == std::size_t(2 * n - 4));
    for(const auto& t : dp.cells())
      REQUIRE(CGAL::orientation(t[0]->point(), t[1]->point(), t[2]->point(), t[3]->point()) == CGAL::POSITIVE);
  }
  WARN(valid << " rings with a valid triangulation, " << invalid << " without");
  REQUIRE(valid > 100);
  REQUIRE(invalid > 100);
}

TEST_CASE("Edge removal keeps constrained facets - subdomains - the hull", "[edge removal]")
{
  SECTION("a constrained facet around the edge")
  {
    Domain_tr tr;
    const auto v = build_star(tr, 2.0, regular_ring(5));
    for(auto c : tr.all_cell_handles()) c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
    // The facet (a, b, s_2), seen from both of its cells.
    Domain_tr::Cell_handle c;
    int i, j, k;
    REQUIRE(tr.is_facet(v[0], v[1], v[4], c, i, j, k));
    const int f = 6 - i - j - k;
    c->info().facet_reference[f] = 7;
    c->neighbor(f)->info().facet_reference[c->neighbor(f)->index(c)] = 7;
    const auto cells = cell_set(tr);
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion(),
                                   ES::parameters::mesh_constraints(ES::Domain_constraints()));
    REQUIRE(r.outcome == ES::EDGE_CONSTRAINED);
    REQUIRE(cell_set(tr) == cells);
  }
  SECTION("two subdomains around the edge")
  {
    Domain_tr tr;
    const auto v = build_star(tr, 2.0, regular_ring(6));
    int k = 0;
    for(auto c : tr.all_cell_handles()) c->info().subdomain = tr.is_infinite(c) ? 0 : 1 + (k++ % 2);
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion(),
                                   ES::parameters::mesh_constraints(ES::Domain_constraints()));
    REQUIRE(r.outcome == ES::EDGE_CONSTRAINED);
  }
  SECTION("boundary references and the subdomain go to the new cells")
  {
    Domain_tr tr;
    const auto v = build_star(tr, 5.0, regular_ring(6));
    for(auto c : tr.all_cell_handles())
    {
      c->info().subdomain = tr.is_infinite(c) ? 0 : 3;
      // Every hull facet is a boundary with reference 5, on both sides.
      for(int i = 0; i < 4; ++i)
        if(tr.is_infinite(c) != tr.is_infinite(c->neighbor(i))) c->info().facet_reference[i] = 5;
    }
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Min_max_dihedral_angle_criterion(),
                                   ES::parameters::mesh_constraints(ES::Domain_constraints()));
    REQUIRE(r.outcome == ES::EDGE_REMOVED);
    REQUIRE(tr.is_valid());
    for(auto c : tr.finite_cell_handles())
    {
      REQUIRE(c->info().subdomain == 3);
      for(int i = 0; i < 4; ++i)
        REQUIRE(c->info().facet_reference[i] == (tr.is_infinite(c->neighbor(i)) ? 5 : ES::Domain_cell_info::no_reference));
    }
  }
  SECTION("an edge where the hull is not flat, a ring too large")
  {
    Tr tr;
    const auto v = build_star(tr, 2.0, regular_ring(7));
    const auto cells = cell_set(tr);
    const auto r = ES::remove_edge(tr, edge_of(tr, v[2], v[3]), ES::Max_min_dihedral_angle_criterion());
    REQUIRE(r.on_hull);
    REQUIRE(r.outcome == ES::NO_VALID_TRIANGULATION);
    REQUIRE(cell_set(tr) == cells);
    const auto big = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion(),
                                     ES::parameters::maximum_ring_size(6));
    REQUIRE(big.outcome == ES::RING_TOO_LARGE);
    REQUIRE(tr.number_of_finite_cells() == 7);
  }
  SECTION("no improvement: the best ring triangulation is worse")
  {
    // A short edge through a wide ring: the smallest angle of its tetrahedra
    // (at the ring's edges) is about twice that of the ring's triangulation.
    Tr tr;
    const auto v = build_star(tr, 0.05, regular_ring(4));
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion());
    INFO(r.quality_before << " " << r.quality_after);
    REQUIRE(r.outcome == ES::NO_IMPROVEMENT);
    REQUIRE(r.quality_after < r.quality_before);
    REQUIRE(tr.number_of_finite_cells() == 4);
  }
}

TEST_CASE("Edge removal on the hull - where the hull is flat around the edge", "[edge removal]")
{
  // a and b on the hull plane z = 0, with s_0 and s_3: the square (a, s_0, b,
  // s_3) is split by ab; s_1 and s_2 above. Removing ab splits the square by
  // s_0 s_3 instead: 3 tetrahedra become 4, 2 infinite cells stay 2.
  for(const double lift : {0.0, 0.2, -0.2})
  {
    CAPTURE(lift);
    const std::vector<Point> points = {Point(-5, 0, 0), Point(5, 0, 0),     Point(0, -1, 0),
                                       Point(0, -0.5, 1), Point(0, 0.5, 1), Point(0, 1, lift)};
    const std::vector<std::array<std::size_t, 4>> cells = {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}};
    Tr tr;
    std::vector<Tr::Vertex_handle> v;
    const std::string problem = ES::build_triangulation_from_cells(tr, points, cells, v);
    if(lift < 0)
    {
      REQUIRE_FALSE(problem.empty()); // the hull would not be convex at ab
      continue;
    }
    REQUIRE(problem.empty());
    const auto volume = exact_volume(tr);
    const auto before = cell_set(tr);
    const auto r = ES::remove_edge(tr, edge_of(tr, v[0], v[1]), ES::Min_max_dihedral_angle_criterion());
    INFO(ES::edge_removal_outcome_name(r.outcome) << " " << r.quality_before << " " << r.quality_after);
    REQUIRE(r.on_hull);
    REQUIRE(r.ring_size == 5);
    if(lift > 0)
    {
      // Not flat: the new hull facets would not be convex.
      REQUIRE(r.outcome == ES::NO_VALID_TRIANGULATION);
      REQUIRE(cell_set(tr) == before);
      continue;
    }
    REQUIRE(r.outcome == ES::EDGE_REMOVED);
    REQUIRE(r.new_cells == 6);
    REQUIRE(tr.number_of_finite_cells() == 4);
    require_same_region(tr, volume);
    REQUIRE(r.quality_after == worst_largest_angle(tr));
  }
}

TEST_CASE("Random sequences of edge removals keep validity - exact volume - and never worsen the worst angle",
          "[edge removal]")
{
  for(unsigned seed : {3u, 4u})
  {
    INFO("seed " << seed);
    // Points on the cube's faces too: the hull is flat there, so hull edges
    // can be removed.
    const auto points = in_cube_and_on_faces(400, 120, seed);
    Tr tr;
    ES::insert_delaunay(tr, points);
    const auto volume = exact_volume(tr);
    double worst = worst_smallest_angle(tr);
    std::size_t removed = 0, attempts = 0, on_hull = 0;
    for(int pass = 0; pass < 3; ++pass)
    {
      for(const auto& [u, w] : shuffled_edges(tr, seed + unsigned(pass)))
      {
        Tr::Cell_handle c;
        int i, j;
        if(!tr.is_edge(u, w, c, i, j)) continue;
        const Tr::Edge e(c, i, j);
        ++attempts;
        const auto r = ES::remove_edge(tr, e, ES::Max_min_dihedral_angle_criterion());
        if(!r.removed()) continue;
        ++removed;
        if(r.on_hull) ++on_hull;
        REQUIRE(r.quality_after > r.quality_before);
        const double now = worst_smallest_angle(tr);
        REQUIRE(now >= worst);
        worst = now;
      }
      require_same_region(tr, volume);
    }
    WARN("seed " << seed << ": " << removed << " edges removed (" << on_hull << " on the hull) in " << attempts
                 << " attempts; worst smallest angle " << worst);
    REQUIRE(removed > 0);
    REQUIRE(on_hull > 0);
  }
}

TEST_CASE("Two-step edge removal - where no ring triangulation helps, an edge of the star goes first",
          "[edge removal][two-step]")
{
  for(unsigned seed : {5u, 6u})
  {
    INFO("seed " << seed);
    // Points on the cube's faces too: edges on the flat hull, and rings
    // with the infinite vertex.
    const auto points = in_cube_and_on_faces(300, 80, seed);
    Tr tr;
    ES::insert_delaunay(tr, points);
    const auto volume = exact_volume(tr);
    const ES::Min_max_dihedral_angle_criterion criterion;
    double worst = worst_largest_angle(tr);
    std::size_t one_step = 0, two_steps = 0, plain_fails = 0;
    for(int pass = 0; pass < 3; ++pass)
    {
      for(const auto& [u, w] : shuffled_edges(tr, seed + unsigned(pass)))
      {
        Tr::Cell_handle c;
        int i, j;
        if(!tr.is_edge(u, w, c, i, j)) continue;
        // What one step can do here: the plain removal on a copy.
        Tr copy = tr;
        Tr::Vertex_handle cu, cw;
        for(auto v : copy.finite_vertex_handles())
        {
          if(v->point() == u->point()) cu = v;
          if(v->point() == w->point()) cw = v;
        }
        const bool plain = ES::remove_edge(copy, edge_of(copy, cu, cw), criterion).removed();
        const auto r = ES::remove_edge_in_two_steps(tr, edge_of(tr, u, w), criterion);
        if(!plain) ++plain_fails;
        if(!r.removed()) continue;
        REQUIRE(r.steps == (plain ? 1 : 2));
        (plain ? one_step : two_steps) += 1;
        REQUIRE(!tr.is_edge(u, w, c, i, j));
        REQUIRE(r.quality_after < r.quality_before);
        const double now = worst_largest_angle(tr);
        REQUIRE(now <= worst);
        worst = now;
      }
      require_same_region(tr, volume);
    }
    WARN("seed " << seed << ": " << one_step << " edges removed in one step, " << two_steps << " in two (of "
                 << plain_fails << " that one step could not remove); worst largest angle " << worst);
    REQUIRE(two_steps > 0);
  }
}

TEST_CASE("Two-step edge removal on eight integer points - where one step cannot", "[edge removal][two-step]")
{
  // Found by search over small integer sets: the edge from (6, 3, 4) to
  // (6, 7, 5) of their Delaunay triangulation is interior, has four
  // tetrahedra around it (largest dihedral angle 164.50 degrees), and no
  // triangulation of its ring does better; removing an edge of its star
  // first leaves three, whose 3-2 flip does.
  const std::vector<Point> points = {Point(7, 0, 6), Point(6, 7, 5), Point(6, 7, 3), Point(6, 3, 4),
                                     Point(6, 3, 2), Point(6, 5, 7), Point(0, 4, 0), Point(5, 3, 4)};
  auto vertex_at = [](const Tr& t, const Point& p) -> Tr::Vertex_handle {
    for(Tr::Vertex_handle v : t.finite_vertex_handles())
      if(v->point() == p) return v;
    FAIL("no vertex at " << p);
    return Tr::Vertex_handle();
  };
  const ES::Min_max_dihedral_angle_criterion criterion;
  Tr one, two;
  ES::insert_delaunay(one, points);
  ES::insert_delaunay(two, points);
  const auto volume = exact_volume(two);
  const auto plain = ES::remove_edge(one, edge_of(one, vertex_at(one, Point(6, 3, 4)), vertex_at(one, Point(6, 7, 5))),
                                     criterion);
  REQUIRE(!plain.removed());
  REQUIRE(plain.ring_size == 4);
  REQUIRE(!plain.on_hull);
  const auto a = vertex_at(two, Point(6, 3, 4)), b = vertex_at(two, Point(6, 7, 5));
  const double worst_before = worst_largest_angle(two);
  const auto r = ES::remove_edge_in_two_steps(two, edge_of(two, a, b), criterion);
  REQUIRE(r.removed());
  REQUIRE(r.steps == 2);
  REQUIRE(r.ring_size == 3);
  REQUIRE(std::abs(r.quality_before - 164.499) < 1e-3);
  REQUIRE(r.quality_after < r.quality_before);
  Tr::Cell_handle c;
  int i, j;
  REQUIRE(!two.is_edge(a, b, c, i, j));
  REQUIRE(two.is_valid());
  REQUIRE(every_cell_positive(two));
  REQUIRE(rebuilds_as_convex_mesh(two));
  REQUIRE(exact_volume(two) == volume);
  REQUIRE(worst_largest_angle(two) <= worst_before);
  WARN("two steps: largest angle around the edge " << r.quality_before << " -> " << r.quality_after << ", "
                                                    << r.new_cells << " new cells");
}

TEST_CASE("Two-step edge removal keeps constrained facets and subdomains", "[edge removal][two-step]")
{
  // A star of 5 around an edge, with a constrained facet around it, or two
  // subdomains: the edge stays, whatever a first step could do.
  Domain_tr tr;
  const auto v = build_star(tr, 2.0, regular_ring(5));
  for(auto c : tr.all_cell_handles()) c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
  const auto cells = cell_set(tr);
  const auto np = ES::parameters::mesh_constraints(ES::Domain_constraints());
  SECTION("a constrained facet around the edge")
  {
    Domain_tr::Cell_handle c;
    int i, j, k;
    REQUIRE(tr.is_facet(v[0], v[1], v[4], c, i, j, k));
    const int f = 6 - i - j - k;
    c->info().facet_reference[f] = 7;
    c->neighbor(f)->info().facet_reference[c->neighbor(f)->index(c)] = 7;
    const auto r = ES::remove_edge_in_two_steps(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion(), np);
    REQUIRE(r.outcome == ES::EDGE_CONSTRAINED);
    REQUIRE(cell_set(tr) == cells);
  }
  SECTION("two subdomains around the edge")
  {
    Domain_tr::Cell_handle c;
    REQUIRE(tr.is_cell(v[0], v[1], v[2], v[3], c));
    c->info().subdomain = 2;
    const auto r = ES::remove_edge_in_two_steps(tr, edge_of(tr, v[0], v[1]), ES::Max_min_dihedral_angle_criterion(), np);
    REQUIRE(r.outcome == ES::EDGE_CONSTRAINED);
    REQUIRE(cell_set(tr) == cells);
  }
}

TEST_CASE("Multi-face removal replaces the 2m tetrahedra of a sandwich by the m + 2 around the new edge",
          "[multi-face removal]")
{
  // A regular polygon of m + 2 points, u and w at height 0.3 above and below
  // its centre: the sandwich's tetrahedra are flat, and removing the m fan
  // triangles gives the star of edge uw, which is better (MinMax).
  for(int m = 1; m <= 6; ++m)
    for(std::size_t root = 1; root <= std::size_t(m); ++root)
    {
      CAPTURE(m, root);
      Tr tr;
      const auto v = build_sandwich(tr, 0.3, regular_ring(m + 2));
      const auto volume = exact_volume(tr);
      REQUIRE(tr.number_of_finite_cells() == std::size_t(2 * m));
      const auto r = ES::remove_faces(tr, fan_facet(tr, v, root), ES::Min_max_dihedral_angle_criterion());
      INFO(ES::multi_face_removal_outcome_name(r.outcome) << " " << r.quality_before << " -> " << r.quality_after);
      REQUIRE(r.outcome == ES::FACES_REMOVED);
      REQUIRE(r.faces == m);
      REQUIRE(r.new_cells == m + 2);
      REQUIRE(r.quality_after < r.quality_before);
      require_same_region(tr, volume);
      REQUIRE(r.quality_after == worst_largest_angle(tr));
      // The result is the star of uw: edge removal's input.
      Tr star;
      build_star(star, 0.3, regular_ring(m + 2));
      REQUIRE(cell_set(tr) == cell_set(star));
    }
  // MaxMin on a flatter sandwich of 6 triangles: the best disk stops short of
  // the thin fan triangles at the ends (its new tetrahedra on the diagonals
  // are better than those on the polygon's sides there).
  Tr tr;
  const auto v = build_sandwich(tr, 0.1, regular_ring(8));
  const auto volume = exact_volume(tr);
  const double worst = worst_smallest_angle(tr);
  const auto r = ES::remove_faces(tr, fan_facet(tr, v, 3), ES::Max_min_dihedral_angle_criterion());
  INFO(ES::multi_face_removal_outcome_name(r.outcome) << " " << r.quality_before << " -> " << r.quality_after);
  REQUIRE(r.removed());
  REQUIRE(r.faces > 1);
  REQUIRE(r.faces < 6);
  REQUIRE(r.new_cells == r.faces + 2);
  REQUIRE(tr.number_of_finite_cells() == std::size_t(12 - 2 * r.faces + r.faces + 2));
  REQUIRE(tr.is_valid());
  REQUIRE(every_cell_positive(tr));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(r.quality_after > r.quality_before);
  REQUIRE(worst_smallest_angle(tr) >= worst);
}

TEST_CASE("Multi-face removal stops at constrained facets and subdomains - needs the pierced triangle",
          "[multi-face removal]")
{
  // A regular pentagon, fan from s_0: triangles 1 = (s0 s1 s2), 2 = (s0 s2 s3)
  // (it holds the centre, where uw crosses), 3 = (s0 s3 s4).
  auto constrain = [](Domain_tr& tr, const std::vector<Domain_tr::Vertex_handle>& v, std::size_t k, int reference) {
    const auto f = fan_facet(tr, v, k);
    const auto n = f.first->neighbor(f.second);
    f.first->info().facet_reference[f.second] = reference;
    n->info().facet_reference[n->index(f.first)] = reference;
  };
  auto make = [](Domain_tr& tr) {
    const auto v = build_sandwich(tr, 0.3, regular_ring(5));
    for(auto c : tr.all_cell_handles()) c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
    return v;
  };
  const auto np = ES::parameters::mesh_constraints(ES::Domain_constraints());
  SECTION("triangle 3 constrained: the disk of triangles 1 and 2 goes, triangle 3 stays")
  {
    Domain_tr tr;
    const auto v = make(tr);
    constrain(tr, v, 3, 9);
    const auto volume = exact_volume(tr);
    const auto r = ES::remove_faces(tr, fan_facet(tr, v, 2), ES::Min_max_dihedral_angle_criterion(), np);
    INFO(ES::multi_face_removal_outcome_name(r.outcome));
    REQUIRE(r.outcome == ES::FACES_REMOVED);
    REQUIRE(r.faces == 2);
    REQUIRE(r.new_cells == 4);
    REQUIRE(tr.is_valid());
    REQUIRE(exact_volume(tr) == volume);
    const auto f = fan_facet(tr, v, 3); // still there, with its reference on both sides
    REQUIRE(f.first->info().facet_reference[f.second] == 9);
    REQUIRE(f.first->neighbor(f.second)->info().facet_reference[f.first->neighbor(f.second)->index(f.first)] == 9);
    // From the constrained facet itself: nothing.
    const auto again = ES::remove_faces(tr, f, ES::Min_max_dihedral_angle_criterion(), np);
    REQUIRE(again.outcome == ES::FACET_CONSTRAINED);
  }
  SECTION("triangle 2 constrained: a disk without the pierced triangle is not valid")
  {
    Domain_tr tr;
    const auto v = make(tr);
    constrain(tr, v, 2, 4);
    const auto before = cell_set(tr);
    const auto r = ES::remove_faces(tr, fan_facet(tr, v, 1), ES::Min_max_dihedral_angle_criterion(), np);
    INFO(ES::multi_face_removal_outcome_name(r.outcome));
    REQUIRE(r.outcome == ES::NO_VALID_REMOVAL);
    REQUIRE(cell_set(tr) == before);
  }
  SECTION("triangle 3 in another subdomain: it stays, and so does its subdomain")
  {
    Domain_tr tr;
    const auto v = make(tr);
    const auto f3 = fan_facet(tr, v, 3);
    f3.first->info().subdomain = 2;
    f3.first->neighbor(f3.second)->info().subdomain = 2;
    const auto r = ES::remove_faces(tr, fan_facet(tr, v, 2), ES::Min_max_dihedral_angle_criterion(), np);
    REQUIRE(r.outcome == ES::FACES_REMOVED);
    REQUIRE(r.faces == 2);
    std::size_t second = 0;
    for(auto c : tr.finite_cell_handles()) second += c->info().subdomain == 2;
    REQUIRE(second == 2);
    REQUIRE(tr.is_valid());
  }
  SECTION("a hull facet is not interior")
  {
    Domain_tr tr;
    const auto v = make(tr);
    Domain_tr::Cell_handle c;
    REQUIRE(tr.is_cell(v[0], v[2], v[3], v[4], c));
    const int i = c->index(v[4]); // the facet (u, s0, s1) on the hull
    REQUIRE(tr.is_infinite(c->neighbor(i)));
    REQUIRE(ES::remove_faces(tr, Domain_tr::Facet(c, i), ES::Min_max_dihedral_angle_criterion(), np).outcome ==
            ES::FACET_NOT_INTERIOR);
  }
}

TEST_CASE("Random sequences of multi-face removals keep validity - exact volume - and never worsen the worst angle",
          "[multi-face removal]")
{
  for(unsigned seed : {5u, 6u})
  {
    INFO("seed " << seed);
    Tr tr;
    ES::insert_delaunay(tr, random_in_cube(400, seed));
    const auto volume = exact_volume(tr);
    double worst = worst_largest_angle(tr);
    std::size_t removals = 0, larger = 0, attempts = 0;
    for(int pass = 0; pass < 3; ++pass)
    {
      // The facets by their vertices' coordinates, then shuffled: the
      // sequence depends on the seed only.
      std::vector<std::array<Tr::Vertex_handle, 3>> facets;
      for(auto f : tr.finite_facets())
      {
        std::array<Tr::Vertex_handle, 3> t = {f.first->vertex((f.second + 1) & 3), f.first->vertex((f.second + 2) & 3),
                                              f.first->vertex((f.second + 3) & 3)};
        auto less = [](Tr::Vertex_handle a, Tr::Vertex_handle b) { return CGAL::compare_xyz(a->point(), b->point()) == CGAL::SMALLER; };
        std::sort(t.begin(), t.end(), less);
        facets.push_back(t);
      }
      std::sort(facets.begin(), facets.end(), [](const auto& x, const auto& y) {
        for(int k = 0; k < 3; ++k)
        {
          const auto c = CGAL::compare_xyz(x[k]->point(), y[k]->point());
          if(c != CGAL::EQUAL) return c == CGAL::SMALLER;
        }
        return false;
      });
      std::shuffle(facets.begin(), facets.end(), std::mt19937(seed + unsigned(pass)));
      for(const auto& t : facets)
      {
        Tr::Cell_handle c;
        int i, j, k;
        if(!tr.is_facet(t[0], t[1], t[2], c, i, j, k)) continue;
        ++attempts;
        const auto r = ES::remove_faces(tr, Tr::Facet(c, 6 - i - j - k), ES::Min_max_dihedral_angle_criterion());
        if(!r.removed()) continue;
        ++removals;
        if(r.faces > 1) ++larger;
        REQUIRE(r.new_cells == r.faces + 2);
        REQUIRE(r.quality_after < r.quality_before);
        const double now = worst_largest_angle(tr);
        REQUIRE(now <= worst);
        worst = now;
      }
      require_same_region(tr, volume);
    }
    WARN("seed " << seed << ": " << removals << " multi-face removals (" << larger << " of more than one face) in "
                 << attempts << " attempts; worst largest angle " << worst);
    REQUIRE(larger > 0);
  }
}

TEST_CASE("The quality driver improves the worst tetrahedra - keeps the mesh - and ends where no operation helps",
          "[quality driver]")
{
  const unsigned seed = 8;
  INFO("seed " << seed);
  const auto points = random_in_cube(500, seed);
  for(unsigned operations : {unsigned(ES::FLIPS), unsigned(ES::EDGE_REMOVAL), unsigned(ES::MULTI_FACE_REMOVAL),
                             unsigned(ES::TWO_STEP_EDGE_REMOVAL), unsigned(ES::EDGE_REMOVAL | ES::MULTI_FACE_REMOVAL),
                             unsigned(ES::TOPOLOGICAL_OPERATIONS), unsigned(ES::ALL_OPERATIONS)})
    for(bool minmax : {false, true})
    {
      CAPTURE(operations, minmax);
      Tr tr;
      ES::insert_delaunay(tr, points);
      const auto volume = exact_volume(tr);
      const std::size_t poor_before = poor_cells(tr, minmax);
      const auto np = ES::parameters::operations(operations);
      const auto r = minmax ? ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(), np)
                            : ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(), np);
      REQUIRE(r.ending == ES::CONVERGED);
      REQUIRE(r.number_of_operations() > 0);
      const bool removals = (operations & ES::EDGE_REMOVAL) != 0, flips = (operations & ES::FLIPS) != 0,
                 face_removals = (operations & ES::MULTI_FACE_REMOVAL) != 0;
      REQUIRE((removals || r.edge_removals == 0));
      REQUIRE((face_removals || r.face_removals == 0));
      REQUIRE(((operations & ES::TWO_STEP_EDGE_REMOVAL) || r.two_step_removals == 0));
      REQUIRE(((operations & ES::SMOOTHING) || r.smoothing_moves == 0));
      REQUIRE((flips || r.number_of_operations() ==
                            r.edge_removals + r.two_step_removals + r.face_removals + r.smoothing_moves));
      const double worst_now = minmax ? worst_largest_angle(tr) : worst_smallest_angle(tr);
      REQUIRE(r.worst_after == worst_now);
      // The worst cells of a random point set are slivers on the hull, which
      // no operation reaches: the worst value may stay; the poor cells go.
      if(minmax) REQUIRE(r.worst_after <= r.worst_before);
      else REQUIRE(r.worst_after >= r.worst_before);
      REQUIRE(poor_cells(tr, minmax) < poor_before);
      require_same_region(tr, volume);
      WARN("operations " << operations << (minmax ? " MinMax: " : " MaxMin: ") << r.worst_before << " -> "
                         << r.worst_after << ", poor cells " << poor_before << " -> " << poor_cells(tr, minmax)
                         << " by " << r.edge_removals << " edge removals, " << r.two_step_removals
                         << " in two steps, " << r.face_removals << " multi-face removals, " << r.smoothing_moves << " smoothing moves and "
                         << r.number_of_operations() - r.edge_removals - r.two_step_removals - r.face_removals -
                                r.smoothing_moves
                         << " flips; " << r.visits << " visits, "
                         << r.stuck << " stuck");
      // Converged: no cell has an operation that helps, so a second run
      // changes nothing (with smoothing, no topological operation: a vertex
      // that made its 20 moves may move again in a new run).
      REQUIRE(r.smoothing_moves <= 20 * tr.number_of_vertices());
      const auto cells = cell_set(tr);
      const auto again_np = ES::parameters::operations(operations & ES::TOPOLOGICAL_OPERATIONS);
      const auto again = minmax ? ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion(), again_np)
                                : ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(), again_np);
      REQUIRE(again.number_of_operations() == 0);
      REQUIRE(cell_set(tr) == cells);
      // The same start gives the same mesh (no address decides).
      Tr other;
      ES::insert_delaunay(other, points);
      if(minmax) ES::improve_worst_tetrahedra(other, ES::Min_max_dihedral_angle_criterion(), np);
      else ES::improve_worst_tetrahedra(other, ES::Max_min_dihedral_angle_criterion(), np);
      REQUIRE(cell_set(other) == cells);
    }
}

TEST_CASE("The quality driver's result depends on the mesh only - not on where its cells are in memory",
          "[quality driver]")
{
  // The driver forgets failed attempts in tables placed by address, so a
  // copy of the mesh elsewhere in memory forgets others: every attempt must
  // give the same answer when made again. (Were an edge's ring to start at
  // the cell the edge was reached by, a two-step removal could take another
  // of equally good triangulations; these 2,000 points then end as another
  // mesh in the copy.)
  const unsigned seed = 1;
  INFO("seed " << seed);
  Tr tr;
  ES::insert_delaunay(tr, random_in_cube(2000, seed));
  std::vector<Tr> elsewhere(3);
  for(Tr& other : elsewhere) ES::insert_delaunay(other, random_in_cube(700, seed + 1));
  Tr copy(tr);
  REQUIRE(cell_set(copy) == cell_set(tr));
  const auto r = ES::improve_worst_tetrahedra(tr, ES::Min_max_dihedral_angle_criterion());
  const auto s = ES::improve_worst_tetrahedra(copy, ES::Min_max_dihedral_angle_criterion());
  REQUIRE(r.two_step_removals > 0);
  REQUIRE(s.visits == r.visits);
  REQUIRE(cell_set(copy) == cell_set(tr));
}

TEST_CASE("The worst-first queue hands out the waiting cells in the order of one heap of all, a batch at a time",
          "[quality driver]")
{
  // Cells by slot with scores (few values, so ties are many); a random mix
  // of waits, changes and visits. Every cell taken must be the least
  // (score, slot) of the waiting cells, as a heap of all would give.
  for(unsigned seed : {1u, 2u, 3u})
    for(std::size_t batch : {std::size_t(1), std::size_t(7), std::size_t(64), std::size_t(100000)})
    {
      CAPTURE(seed, batch);
      std::mt19937 random(seed);
      const std::size_t slots = 500;
      std::vector<float> score(slots);
      std::set<std::pair<float, std::size_t>> waiting;
      ES::internal::Worst_cell_queue queue(batch);
      auto wait = [&](std::size_t k) {
        if(queue.waits(k)) return;
        score[k] = float(random() % 40) / 4.0f - 5.0f;
        queue.add(k, score[k], slots);
        waiting.emplace(score[k], k);
      };
      auto change = [&](std::size_t k) {
        if(queue.waits(k)) waiting.erase({score[k], k});
        queue.forget(k);
        wait(k);
      };
      for(std::size_t k = 0; k < slots; ++k) wait(k);
      std::size_t taken = 0, refills = 0;
      for(;;)
      {
        if(queue.empty_heap())
        {
          const bool any = queue.refill([&](std::size_t k) { return std::optional<float>(score[k]); });
          REQUIRE(any == !waiting.empty());
          if(!any) break;
          ++refills;
          continue;
        }
        const auto e = queue.pop();
        if(!queue.queued_at(e.slot) || e.score != score[e.slot]) continue; // stale
        REQUIRE(!waiting.empty());
        REQUIRE(std::make_pair(e.score, std::size_t(e.slot)) == *waiting.begin());
        waiting.erase(waiting.begin());
        queue.forget(e.slot);
        ++taken;
        // What a change does: some cells change (new score), others wait again.
        if(taken < 3000)
          for(int n = int(random() % 4); n > 0; --n)
          {
            const std::size_t k = random() % slots;
            if(random() % 2) change(k);
            else wait(k);
          }
      }
      REQUIRE(taken >= 3000);
      REQUIRE(waiting.empty());
      if(batch < slots) REQUIRE(refills > 1);
      WARN("batch " << batch << ": " << taken << " cells taken, " << refills << " refills");
    }
}

TEST_CASE("The quality driver with a quality target works only on the cells worse than it", "[quality driver]")
{
  const unsigned seed = 10;
  INFO("seed " << seed);
  const auto points = random_in_cube(400, seed);
  const ES::Min_max_dihedral_angle_criterion criterion;
  auto run = [&](Tr& tr, double target) {
    return ES::improve_worst_tetrahedra(tr, criterion, ES::parameters::quality_target(target));
  };
  Tr all, some, none;
  for(Tr* t : {&all, &some, &none}) ES::insert_delaunay(*t, points);
  const auto volume = exact_volume(all);
  const auto cells = cell_set(none);
  // No cell has an angle of 180 degrees or more: nothing to do.
  REQUIRE(run(none, 180).number_of_operations() == 0);
  REQUIRE(cell_set(none) == cells);
  const auto everywhere = ES::improve_worst_tetrahedra(all, criterion);
  const auto above_165 = run(some, 165);
  REQUIRE(above_165.number_of_operations() > 0);
  REQUIRE(above_165.number_of_operations() < everywhere.number_of_operations());
  REQUIRE(above_165.visits < everywhere.visits);
  REQUIRE(above_165.worst_after <= above_165.worst_before);
  REQUIRE(poor_cells(some, true) < poor_cells(none, true));
  REQUIRE(some.is_valid());
  REQUIRE(exact_volume(some) == volume);
  // Converged for its target: a second run with it changes nothing.
  const auto again = cell_set(some);
  REQUIRE(run(some, 165).number_of_operations() == 0);
  REQUIRE(cell_set(some) == again);
  // A larger mesh, where most visits are of cells visited before: an
  // attempt skipped because no cell it reads changed would succeed here.
  Tr larger;
  ES::insert_delaunay(larger, random_in_cube(1500, seed));
  const auto at_140 = run(larger, 140);
  REQUIRE(at_140.two_step_removals > 0);
  REQUIRE(at_140.face_removals > 0);
  REQUIRE(at_140.visits > 2 * at_140.number_of_operations());
  const auto at_140_cells = cell_set(larger);
  REQUIRE(run(larger, 140).number_of_operations() == 0);
  REQUIRE(cell_set(larger) == at_140_cells);
  WARN("MinMax on 400 random points: " << everywhere.number_of_operations() << " operations and "
                                        << everywhere.visits << " visits everywhere, "
                                        << above_165.number_of_operations() << " and " << above_165.visits
                                        << " above 165 degrees; cells above 165: " << poor_cells(none, true)
                                        << " -> " << poor_cells(all, true) << " and " << poor_cells(some, true));
}

namespace {

// Sets a stop flag at the `after`-th change (a replacement or a move), and
// sleeps `pause` at each: Ctrl-C and a slow run, at places the test fixes.
struct Stopping_visitor : ES::Default_replacement_visitor
{
  std::atomic<bool>* flag = nullptr;
  std::size_t after = std::size_t(-1);
  std::chrono::milliseconds pause{0};
  std::size_t changes = 0;

  void change()
  {
    if(++changes >= after) flag->store(true);
    if(pause.count() > 0) std::this_thread::sleep_for(pause);
  }
  template <class T>
  void after_replacement(const T&, const std::vector<typename T::Cell_handle>&) { change(); }
  template <class T>
  void after_move(const T&, typename T::Vertex_handle, const typename T::Point&) { change(); }
};

} // namespace

TEST_CASE("The quality driver ends at a stop flag or a time limit - the mesh valid - its vertices and region kept - "
          "never worse",
          "[quality driver][time limit]")
{
  const unsigned seed = 12;
  INFO("seed " << seed);
  const auto points = random_in_cube(500, seed);
  const ES::Max_min_dihedral_angle_criterion criterion;
  for(unsigned operations : {unsigned(ES::TOPOLOGICAL_OPERATIONS), unsigned(ES::ALL_OPERATIONS)})
  {
    CAPTURE(operations);
    Tr full;
    ES::insert_delaunay(full, points);
    const auto volume = exact_volume(full);
    const auto start = cell_set(full);
    const auto whole = ES::improve_worst_tetrahedra(full, criterion, ES::parameters::operations(operations));
    REQUIRE(whole.ending == ES::CONVERGED);
    REQUIRE(whole.number_of_operations() > 40);

    // Stopped at the 20th change: the operation under way ends, no other begins.
    auto stopped = [&](Tr& tr) {
      std::atomic<bool> flag{false};
      Stopping_visitor visitor;
      visitor.flag = &flag;
      visitor.after = 20;
      const auto r = ES::improve_worst_tetrahedra(
          tr, criterion, ES::parameters::operations(operations, ES::parameters::stop_flag(&flag)).visitor(std::ref(visitor)));
      REQUIRE(r.ending == ES::INTERRUPTED);
      // A two-step removal is two changes: the 20th may be its first step.
      REQUIRE((visitor.changes == 20 || visitor.changes == 21));
      return r;
    };
    Tr tr, again;
    ES::insert_delaunay(tr, points);
    ES::insert_delaunay(again, points);
    const auto r = stopped(tr);
    REQUIRE(r.number_of_operations() <= 20);
    REQUIRE(r.number_of_operations() < whole.number_of_operations());
    REQUIRE(tr.is_valid());
    REQUIRE(tr.number_of_vertices() == points.size());
    require_same_region(tr, volume);
    REQUIRE(r.worst_after >= r.worst_before);
    REQUIRE(r.worst_after == worst_smallest_angle(tr));
    REQUIRE(cell_set(tr) != start);
    // The same input and flag give the same mesh.
    stopped(again);
    REQUIRE(cell_set(again) == cell_set(tr));

    // A time limit that has passed before the first visit: nothing changes.
    Tr untouched;
    ES::insert_delaunay(untouched, points);
    const auto none = ES::improve_worst_tetrahedra(
        untouched, criterion, ES::parameters::operations(operations).maximum_running_time(0.0));
    REQUIRE(none.ending == ES::TIME_LIMIT_REACHED);
    REQUIRE(none.number_of_operations() == 0);
    REQUIRE(cell_set(untouched) == start);

    // A run slowed to 20 ms a change reaches a limit of 0.2 s partway.
    Tr slow;
    ES::insert_delaunay(slow, points);
    Stopping_visitor sleeper;
    sleeper.pause = std::chrono::milliseconds(20);
    const auto cut = ES::improve_worst_tetrahedra(
        slow, criterion, ES::parameters::operations(operations).maximum_running_time(0.2).visitor(std::ref(sleeper)));
    REQUIRE(cut.ending == ES::TIME_LIMIT_REACHED);
    REQUIRE(cut.number_of_operations() > 0);
    REQUIRE(cut.number_of_operations() < whole.number_of_operations());
    REQUIRE(cut.seconds >= 0.2);
    REQUIRE(slow.is_valid());
    REQUIRE(slow.number_of_vertices() == points.size());
    require_same_region(slow, volume);
    REQUIRE(cut.worst_after >= cut.worst_before);
  }
}

namespace {

/// The exact volume of each subdomain (0, 1, 2).
std::array<CGAL::Exact_rational, 3> subdomain_volumes(const Domain_tr& tr)
{
  std::array<CGAL::Exact_rational, 3> v;
  for(auto c : tr.finite_cell_handles())
    v[c->info().subdomain] +=
      exact_volume(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
  return v;
}

/// The constrained facets, each by its sorted points and its reference, sorted.
std::vector<std::pair<std::array<Point, 3>, int>> constrained_facets(const Domain_tr& tr)
{
  std::vector<std::pair<std::array<Point, 3>, int>> facets;
  for(auto c : tr.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(c->info().facet_reference[i] != ES::Domain_cell_info::no_reference)
      {
        std::array<Point, 3> p = {c->vertex((i + 1) & 3)->point(), c->vertex((i + 2) & 3)->point(),
                                  c->vertex((i + 3) & 3)->point()};
        std::sort(p.begin(), p.end());
        facets.emplace_back(p, c->info().facet_reference[i]);
      }
  std::sort(facets.begin(), facets.end());
  return facets;
}

} // namespace

TEST_CASE("The quality driver keeps the subdomains and the constrained facets of a domain mesh", "[quality driver]")
{
  const unsigned seed = 12;
  INFO("seed " << seed);
  Domain_tr tr;
  ES::insert_delaunay(tr, random_in_cube(600, seed));
  // Two subdomains, split by x = 0.5 at the cells' centroids; their interface
  // and the hull are constrained.
  auto side = [&](Domain_tr::Cell_handle c) {
    double x = 0;
    for(int i = 0; i < 4; ++i) x += c->vertex(i)->point().x();
    return x < 2 ? 1 : 2;
  };
  for(auto c : tr.all_cell_handles()) c->info().subdomain = tr.is_infinite(c) ? 0 : side(c);
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(c->info().subdomain != c->neighbor(i)->info().subdomain)
        c->info().facet_reference[i] = (tr.is_infinite(c) || tr.is_infinite(c->neighbor(i))) ? 5 : 7;
  const auto volumes = subdomain_volumes(tr);
  const auto facets = constrained_facets(tr);
  const Domain_tr start = tr;
  for(unsigned operations :
      {unsigned(ES::TOPOLOGICAL_OPERATIONS), unsigned(ES::ALL_OPERATIONS), unsigned(ES::ALL_WITH_VERTEX_CHANGES)})
  {
    CAPTURE(operations);
    tr = start;
    // No bound on the moves of a vertex: the run ends where no move gains 1%.
    const auto np = ES::parameters::maximum_moves_per_vertex(
        1000000, ES::parameters::operations(operations, ES::parameters::mesh_constraints(ES::Domain_constraints())));
    const auto r = ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(), np);
    REQUIRE(r.ending == ES::CONVERGED);
    REQUIRE(r.number_of_operations() > 0);
    REQUIRE(r.worst_after >= r.worst_before);
    REQUIRE(tr.is_valid());
    REQUIRE(every_cell_positive(tr));
    // Exact: the interface and the hull keep their vertices where they were.
    REQUIRE(subdomain_volumes(tr) == volumes);
    REQUIRE(constrained_facets(tr) == facets);
    for(auto c : tr.finite_cell_handles()) REQUIRE((c->info().subdomain == 1 || c->info().subdomain == 2));
    WARN("domain mesh: " << r.edge_removals << " edge removals, " << r.two_step_removals << " in two steps, "
                         << r.face_removals << " multi-face removals, "
                         << r.smoothing_moves << " smoothing moves, " << r.vertex_removals << " vertices removed, "
                         << r.vertex_insertions << " inserted; worst smallest angle " << r.worst_before << " -> "
                         << r.worst_after);
    if(operations & ES::SMOOTHING)
    {
      REQUIRE(r.smoothing_moves > 0);
      if(operations & ES::VERTEX_INSERTION) REQUIRE(r.vertex_insertions > 0);
      // A second run with the vertices kept changes nothing (one with vertex
      // insertion may insert again: the rule against inserting in a cell of
      // inserted vertices holds within a run).
      const auto cells = cell_set(tr);
      const auto again = ES::parameters::maximum_moves_per_vertex(
          1000000, ES::parameters::operations(operations & ES::ALL_OPERATIONS,
                                              ES::parameters::mesh_constraints(ES::Domain_constraints())));
      REQUIRE(ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(), again).number_of_operations() == 0);
      REQUIRE(cell_set(tr) == cells);
    }
  }
}

namespace {

/// Counts the calls it gets, and fails when two overlap.
struct Overlap_visitor : ES::Default_replacement_visitor
{
  std::shared_ptr<std::atomic<int>> inside = std::make_shared<std::atomic<int>>(0);
  std::shared_ptr<std::size_t> calls = std::make_shared<std::size_t>(0);
  std::shared_ptr<bool> overlapped = std::make_shared<bool>(false);
  void call() const
  {
    if(inside->fetch_add(1) != 0) *overlapped = true;
    ++*calls;
    inside->fetch_sub(1);
  }
  template <class T>
  void after_replacement(const T&, const std::vector<typename T::Cell_handle>&) const { call(); }
  template <class T>
  void after_move(const T&, typename T::Vertex_handle, const typename T::Point&) const { call(); }
  template <class T>
  void after_insertion(const T&, typename T::Vertex_handle, const std::array<typename T::Vertex_handle, 4>&,
                       const std::array<double, 4>&) const { call(); }
};

/// The points of the cells and of the vertices in the order the containers hold them.
template <class T>
std::vector<Point> storage_order(const T& tr)
{
  std::vector<Point> order;
  for(auto v = tr.tds().vertices().begin(); v != tr.tds().vertices().end(); ++v)
    order.push_back(tr.is_infinite(v) ? Point(-1, -1, -1) : v->point());
  for(auto c = tr.tds().cells().begin(); c != tr.tds().cells().end(); ++c)
    for(int i = 0; i < 4; ++i) order.push_back(tr.is_infinite(c->vertex(i)) ? Point(-1, -1, -1) : c->vertex(i)->point());
  return order;
}

} // namespace

TEST_CASE("The quality driver on several threads - valid - regions and constrained facets kept - the same mesh for "
          "the same number of threads",
          "[quality driver][threads]")
{
  const unsigned seed = 21;
  INFO("seed " << seed);
  Domain_tr start;
  ES::insert_delaunay(start, random_in_cube(2600, seed));
  // A ball of subdomain 2 in a cube of subdomain 1: the interface crosses
  // the parts' frontiers. The interface and the hull are constrained.
  auto side = [&](Domain_tr::Cell_handle c) {
    double d = 0;
    for(int a = 0; a < 3; ++a)
    {
      double x = 0;
      for(int i = 0; i < 4; ++i) x += c->vertex(i)->point()[a] / 4;
      d += (x - 0.5) * (x - 0.5);
    }
    return d < 0.1 ? 2 : 1;
  };
  for(auto c : start.all_cell_handles()) c->info().subdomain = start.is_infinite(c) ? 0 : side(c);
  for(auto c : start.all_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(c->info().subdomain != c->neighbor(i)->info().subdomain)
        c->info().facet_reference[i] = (start.is_infinite(c) || start.is_infinite(c->neighbor(i))) ? 5 : 7;
  REQUIRE(start.number_of_finite_cells() >= 3 * 5000);
  const auto volumes = subdomain_volumes(start);
  const auto facets = constrained_facets(start);
  const ES::Max_min_dihedral_angle_criterion criterion;
  // Vertex changes without smoothing: vertices made and removed in the
  // copies come back, and the run stays short.
  for(unsigned operations : {unsigned(ES::TOPOLOGICAL_OPERATIONS),
                             unsigned(ES::TOPOLOGICAL_OPERATIONS | ES::VERTEX_REMOVAL | ES::VERTEX_INSERTION)})
  {
    CAPTURE(operations);
    // With vertex changes, only the cells under 20 degrees: the run stays short.
    const double target = (operations & ES::VERTEX_INSERTION) ? 20 : HUGE_VAL;
    auto run = [&](Domain_tr& tr, unsigned threads, const Overlap_visitor& visitor) {
      return ES::improve_worst_tetrahedra(
          tr, criterion,
          ES::parameters::quality_target(
              target, ES::parameters::number_of_threads(
                          threads, ES::parameters::operations(
                                       operations, ES::parameters::mesh_constraints(ES::Domain_constraints())
                                                       .visitor(visitor)))));
    };
    Domain_tr one = start;
    const auto alone = run(one, 1, Overlap_visitor());
    for(unsigned threads : {2u, 3u})
    {
      CAPTURE(threads);
      if(threads == 3 && operations != unsigned(ES::TOPOLOGICAL_OPERATIONS)) continue;
      Domain_tr tr = start, again = start;
      const Overlap_visitor visitor;
      const auto r = run(tr, threads, visitor);
      REQUIRE(r.ending == ES::CONVERGED);
      REQUIRE(r.number_of_operations() > 100);
      // One part at a time: every change told, never two calls at once.
      REQUIRE(!*visitor.overlapped);
      REQUIRE(*visitor.calls >= r.number_of_operations());
      REQUIRE(tr.is_valid());
      REQUIRE(every_cell_positive(tr));
      REQUIRE(tr.number_of_vertices() == start.number_of_vertices() + r.vertex_insertions - r.vertex_removals);
      if(operations & ES::VERTEX_INSERTION) REQUIRE(r.vertex_insertions + r.vertex_removals > 0);
      REQUIRE(subdomain_volumes(tr) == volumes);
      REQUIRE(constrained_facets(tr) == facets);
      for(auto c : tr.finite_cell_handles()) REQUIRE((c->info().subdomain == 1 || c->info().subdomain == 2));
      REQUIRE(r.worst_after >= r.worst_before);
      REQUIRE(r.worst_after == worst_smallest_angle(tr));
      WARN(threads << " threads: worst smallest angle " << r.worst_before << " -> " << r.worst_after << " ("
                   << alone.worst_after << " on one), " << r.number_of_operations() << " operations ("
                   << alone.number_of_operations() << ")");
      // The same number of threads: the same mesh, in the same storage order.
      run(again, threads, Overlap_visitor());
      REQUIRE(storage_order(again) == storage_order(tr));
    }
  }
}

TEST_CASE("Quality measures - 1 for the regular tetrahedron - 0 when flat - the sliver that the edge ratio misses",
          "[quality measures]")
{
  const Point a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  const double regular_angle = std::acos(1.0 / 3) * 180 / 3.14159265358979323846;
  REQUIRE(std::abs(smallest_angle(a, b, c, d) - regular_angle) < 1e-9);
  for(const double value : {ES::Normalized_radius_ratio()(a, b, c, d), ES::Minimum_dihedral_sine()(a, b, c, d),
                            ES::Volume_length_ratio()(a, b, c, d)})
    REQUIRE(std::abs(value - 1) < 1e-12);
  // Flat: four points in a plane.
  const Point e(0, 0, 0), f(1, 0, 0), g(0, 1, 0), h(1, 1, 0);
  REQUIRE(ES::Normalized_radius_ratio()(e, f, g, h) < 1e-300);
  REQUIRE(ES::Minimum_dihedral_sine()(e, f, g, h) == 0);
  REQUIRE(ES::Volume_length_ratio()(e, f, g, h) == 0);
  // A sliver: a square's corners lifted a little, alternately. Its edges are
  // all alike (ratio sqrt 2), its volume nearly nothing.
  const Point s0(0, 0, 0), s1(1, 0, 1e-3), s2(1, 1, 0), s3(0, 1, 1e-3);
  REQUIRE(ES::edge_length_ratio(s0, s1, s2, s3) < 1.5);
  REQUIRE(ES::Normalized_radius_ratio()(s0, s1, s2, s3) < 1e-2);
  REQUIRE(ES::Minimum_dihedral_sine()(s0, s1, s2, s3) < 1e-2);
  REQUIRE(ES::Volume_length_ratio()(s0, s1, s2, s3) < 1e-2);
  // Invariant under scaling and translation; the sine agrees with the angles.
  const unsigned seed = 41;
  INFO("seed " << seed);
  const auto p = random_in_cube(400, seed);
  for(std::size_t k = 0; k + 3 < p.size(); k += 4)
  {
    auto moved = [&](const Point& q) { return Point(1e6 * q.x() - 3e5, 1e6 * q.y() + 7, 1e6 * q.z()); };
    const Point q0 = moved(p[k]), q1 = moved(p[k + 1]), q2 = moved(p[k + 2]), q3 = moved(p[k + 3]);
    for(const auto& [before, after] :
        {std::make_pair(ES::Normalized_radius_ratio()(p[k], p[k + 1], p[k + 2], p[k + 3]), ES::Normalized_radius_ratio()(q0, q1, q2, q3)),
         std::make_pair(ES::Minimum_dihedral_sine()(p[k], p[k + 1], p[k + 2], p[k + 3]), ES::Minimum_dihedral_sine()(q0, q1, q2, q3)),
         std::make_pair(ES::Volume_length_ratio()(p[k], p[k + 1], p[k + 2], p[k + 3]), ES::Volume_length_ratio()(q0, q1, q2, q3))})
      REQUIRE(std::abs(before - after) <= 1e-9 * std::max(1.0, before));
    const auto angles = ES::dihedral_angles(p[k], p[k + 1], p[k + 2], p[k + 3]);
    double sine = 1;
    for(double angle : angles) sine = std::min(sine, std::sin(angle * 3.14159265358979323846 / 180));
    REQUIRE(std::abs(ES::Minimum_dihedral_sine()(p[k], p[k + 1], p[k + 2], p[k + 3]) - sine / (2 * std::sqrt(2.0) / 3)) < 1e-9);
  }
}

TEST_CASE("The guarded dihedral sine - the guard's cosines and the sine from one set of normals - bit for bit",
          "[quality measures][angle range]")
{
  // In any vertex order: the guard's extremes and the sine of the points in
  // lexicographic order, computed apart, equal the fused values exactly; flat
  // and nearly flat tetrahedra included.
  const unsigned seed = 43;
  INFO("seed " << seed);
  auto p = random_in_cube(400, seed);
  p.insert(p.end(), {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)});
  p.insert(p.end(), {Point(0, 0, 0), Point(1, 0, 1e-9), Point(1, 1, 0), Point(0, 1, 1e-9)});
  std::mt19937 shuffle(seed);
  for(std::size_t k = 0; k + 3 < p.size(); k += 4)
  {
    std::array<Point, 4> t = {p[k], p[k + 1], p[k + 2], p[k + 3]};
    std::shuffle(t.begin(), t.end(), shuffle);
    const auto fused = ES::internal::dihedral_cosine_extremes_and_minimum_sine(t[0], t[1], t[2], t[3]);
    const auto [lo, hi] = ES::internal::dihedral_cosine_extremes(t[0], t[1], t[2], t[3]);
    std::array<Point, 4> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    REQUIRE(fused[0] == lo);
    REQUIRE(fused[1] == hi);
    REQUIRE(fused[2] == ES::minimum_dihedral_sine(sorted[0], sorted[1], sorted[2], sorted[3]));
    ES::Dihedral_angle_guarded<ES::Minimum_dihedral_sine, false> guarded;
    guarded.range = ES::Dihedral_angle_range{std::cos(0.3), std::cos(2.8)};
    REQUIRE(guarded(t[0], t[1], t[2], t[3]) == (guarded.range.contains_cosines(lo, hi) ? fused[2] : -HUGE_VAL));
  }
}

TEST_CASE("The quality driver with each measure - never worse - converged - valid", "[quality measures]")
{
  const unsigned seed = 9;
  INFO("seed " << seed);
  const auto points = random_in_cube(400, seed);
  auto run = [&](const auto& criterion, const char* name) {
    Tr tr;
    ES::insert_delaunay(tr, points);
    const auto volume = exact_volume(tr);
    auto worst = [&]() { return smallest_measure(tr, criterion); };
    const double before = worst();
    const auto r = ES::improve_worst_tetrahedra(tr, criterion);
    INFO(name);
    REQUIRE(r.ending == ES::CONVERGED);
    REQUIRE(r.number_of_operations() > 0);
    REQUIRE(r.worst_before == before);
    REQUIRE(r.worst_after == worst());
    REQUIRE(r.worst_after >= before);
    REQUIRE(tr.is_valid());
    REQUIRE(exact_volume(tr) == volume);
    REQUIRE(ES::improve_worst_tetrahedra(tr, criterion).number_of_operations() == 0);
  };
  run(ES::Max_min_radius_ratio_criterion(), "radius ratio");
  run(ES::Max_min_dihedral_sine_criterion(), "dihedral sine");
  run(ES::Max_min_volume_length_criterion(), "volume-length");
}

TEST_CASE("Vertex smoothing moves an interior vertex to the best place of its star - keeps the hull", "[smoothing]")
{
  // The octahedron's six vertices and one point inside: every cell is a cone
  // from that point over a facet of the hull (the six are cospherical, and
  // the sphere holds the point). At the centre, the smart Laplacian, the
  // eight cells are trirectangular, the best MaxMin place by symmetry; the
  // smallest dihedral angle there is acos(1 / sqrt(3)).
  Tr tr;
  ES::insert_delaunay(tr, std::vector<Point>{Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0),
                                             Point(0, 0, 1), Point(0, 0, -1), Point(0.4, 0.3, -0.2)});
  Tr::Vertex_handle inside, corner;
  for(auto v : tr.finite_vertex_handles())
  {
    if(v->point() == Point(0.4, 0.3, -0.2)) inside = v;
    if(v->point() == Point(1, 0, 0)) corner = v;
  }
  REQUIRE(tr.degree(inside) == 6);
  const auto volume = exact_volume(tr);
  const auto r = ES::smooth_vertex(tr, inside, ES::Max_min_dihedral_angle_criterion());
  REQUIRE(r.outcome == ES::VERTEX_MOVED);
  REQUIRE(r.star_size == 8);
  REQUIRE(inside->point() == Point(0, 0, 0));
  REQUIRE(std::abs(r.quality_after - std::acos(1 / std::sqrt(3.0)) * 180 / CGAL_PI) < 1e-9);
  REQUIRE(r.quality_after > r.quality_before);
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(every_cell_positive(tr));
  // Nothing better is left, and a hull vertex never moves.
  REQUIRE(ES::smooth_vertex(tr, inside, ES::Max_min_dihedral_angle_criterion()).outcome == ES::NO_SMOOTHING_IMPROVEMENT);
  REQUIRE(inside->point() == Point(0, 0, 0));
  REQUIRE(ES::smooth_vertex(tr, corner, ES::Max_min_dihedral_angle_criterion()).outcome == ES::VERTEX_ON_BOUNDARY);
  REQUIRE(corner->point() == Point(1, 0, 0));
}

TEST_CASE("Smoothing on the boundary moves vertices within flat faces and along straight edges - the boundary keeps "
          "its shape", "[smoothing][boundary smoothing]")
{
  // The unit cube's corners, points on its faces and edges, and points
  // inside: its Delaunay triangulation's hull is the cube. A vertex on a face
  // may slide within it, one on an edge along it; a corner stays.
  const unsigned seed = 47;
  INFO("seed " << seed);
  CGAL::Random random(seed);
  std::vector<Point> points = random_in_cube(300, seed);
  for(int k = 0; k < 8; ++k) points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  auto draw = [&](int fixed, double side, double other) {
    std::array<double, 3> x = {random.get_double(0.05, 0.95), random.get_double(0.05, 0.95),
                               random.get_double(0.05, 0.95)};
    x[fixed] = side;
    if(other >= 0) x[(fixed + 1) % 3] = other;
    return Point(x[0], x[1], x[2]);
  };
  for(int k = 0; k < 150; ++k) points.push_back(draw(k % 3, (k / 3) % 2, -1));
  for(int k = 0; k < 48; ++k) points.push_back(draw(k % 3, (k / 3) % 2, (k / 6) % 2));
  // How many coordinates put p on the cube's boundary.
  auto on_sides = [](const Point& p) {
    int n = 0;
    for(int a = 0; a < 3; ++a) n += (p[a] == 0 || p[a] == 1);
    return n;
  };
  Tr tr;
  ES::insert_delaunay(tr, points);
  const auto volume = exact_volume(tr);
  std::map<Tr::Vertex_handle, Point> before;
  for(auto v : tr.finite_vertex_handles()) before[v] = v->point();
  const ES::Max_min_dihedral_sine_criterion criterion;
  const auto r = ES::improve_worst_tetrahedra(
      tr, criterion, ES::parameters::operations(ES::ALL_OPERATIONS | ES::BOUNDARY_SMOOTHING));
  INFO("worst " << r.worst_before << " -> " << r.worst_after << ", " << r.smoothing_moves << " moves");
  REQUIRE(tr.is_valid(true));
  REQUIRE(every_cell_positive(tr));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(r.worst_after >= r.worst_before);
  std::array<std::size_t, 4> moved{}; // by the number of boundary coordinates
  for(const auto& [v, p] : before)
  {
    const Point q = v->point();
    REQUIRE(on_sides(q) == on_sides(p));
    for(int a = 0; a < 3; ++a)
      if(p[a] == 0 || p[a] == 1) REQUIRE(q[a] == p[a]); // the same face, the same edge
    moved[std::size_t(on_sides(p))] += (q != p);
  }
  INFO("moved: " << moved[0] << " inside, " << moved[1] << " on faces, " << moved[2] << " on edges");
  REQUIRE(moved[0] > 0);
  REQUIRE(moved[1] > 0);
  REQUIRE(moved[2] > 0);
  REQUIRE(moved[3] == 0);

  // Without the boundary moves no boundary vertex moves; on a hull that is
  // nowhere flat (random points alone) none moves even with them.
  for(const bool cube : {true, false})
  {
    Tr again;
    ES::insert_delaunay(again, cube ? points : random_in_cube(300, seed));
    std::map<Tr::Vertex_handle, Point> start;
    for(auto v : again.finite_vertex_handles()) start[v] = v->point();
    ES::improve_worst_tetrahedra(again, criterion,
                                 ES::parameters::operations(cube ? unsigned(ES::ALL_OPERATIONS)
                                                                 : unsigned(ES::ALL_OPERATIONS | ES::BOUNDARY_SMOOTHING)));
    std::set<Tr::Vertex_handle> hull;
    again.adjacent_vertices(again.infinite_vertex(), std::inserter(hull, hull.end()));
    for(auto v : hull) REQUIRE(v->point() == start[v]);
  }
}

TEST_CASE("Vertex smoothing climbs past the smart Laplacian to the best place on the axis", "[smoothing]")
{
  // An octahedron stretched upwards: the centroid of the six neighbours,
  // (0, 0, 1/2), is not the best place (44.71 degrees); by symmetry the
  // best is on the z axis (45.87 degrees, on a stretch of it), found here
  // by scanning it.
  const std::vector<Point> hull = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 4),
                                   Point(0, 0, -1)};
  auto worst_at = [&](double z) {
    double w = HUGE_VAL;
    for(int k = 0; k < 8; ++k)
    {
      const Point& a = hull[k & 1];
      const Point& b = hull[2 + ((k >> 1) & 1)];
      const Point& c = hull[4 + ((k >> 2) & 1)];
      w = std::min(w, smallest_angle(a, b, c, Point(0, 0, z)));
    }
    return w;
  };
  double best_scan = 0;
  for(int k = 1; k < 5000; ++k) best_scan = std::max(best_scan, worst_at(-1 + 5.0 * k / 5000));
  for(const double z0 : {-0.5, 0.1, 1.2})
  {
    CAPTURE(z0);
    // The eight cones from the inside point over the octahedron's facets.
    std::vector<Point> points = hull;
    points.emplace_back(0.05, -0.03, z0);
    std::vector<std::array<std::size_t, 4>> cells;
    for(std::size_t k = 0; k < 8; ++k)
    {
      std::array<std::size_t, 4> t = {k & 1, 2 + ((k >> 1) & 1), 4 + ((k >> 2) & 1), 6};
      if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
        std::swap(t[0], t[1]);
      cells.push_back(t);
    }
    Tr tr;
    std::vector<Tr::Vertex_handle> vertices;
    std::vector<Tr::Cell_handle> handles;
    REQUIRE(ES::build_triangulation_from_cells(tr, points, cells, vertices, handles).empty());
    const Tr::Vertex_handle inside = vertices[6];
    REQUIRE(tr.degree(inside) == 6);
    const auto r = ES::smooth_vertex(tr, inside, ES::Max_min_dihedral_angle_criterion());
    REQUIRE(r.outcome == ES::VERTEX_MOVED);
    REQUIRE(r.steps >= 2);
    WARN("from z = " << z0 << ": " << r.quality_before << " -> " << r.quality_after << " deg in " << r.steps
                     << " steps at " << inside->point() << "; best on the axis " << best_scan);
    REQUIRE(r.quality_after > best_scan - 0.05);
    REQUIRE(every_cell_positive(tr));
  }
}

TEST_CASE("Random sequences of smoothing keep validity - exact volume - the hull - and never worsen the worst",
          "[smoothing]")
{
  for(unsigned seed : {21u, 22u})
  {
    INFO("seed " << seed);
    Tr tr;
    ES::insert_delaunay(tr, random_in_cube(300, seed));
    const auto volume = exact_volume(tr);
    auto hull_points = [&]() {
      std::vector<Point> points;
      Tr::Cell_handle c;
      int i, j;
      for(auto v : tr.finite_vertex_handles())
        if(tr.is_edge(v, tr.infinite_vertex(), c, i, j)) points.push_back(v->point());
      return points;
    };
    const auto hull = hull_points();
    const ES::Max_min_dihedral_sine_criterion criterion;
    auto worst = [&]() { return smallest_measure(tr, criterion); };
    // The vertices in the order of their points: the sequence depends on the seed only.
    std::vector<Tr::Vertex_handle> vertices(tr.finite_vertex_handles().begin(), tr.finite_vertex_handles().end());
    std::sort(vertices.begin(), vertices.end(), [](Tr::Vertex_handle a, Tr::Vertex_handle b) {
      return CGAL::compare_xyz(a->point(), b->point()) == CGAL::SMALLER;
    });
    double w = worst();
    std::size_t moves = 0, boundary = 0, cut_short = 0;
    for(int pass = 0; pass < 3; ++pass)
    {
      for(auto v : vertices)
      {
        const auto r = ES::smooth_vertex(tr, v, criterion);
        if(r.outcome == ES::VERTEX_ON_BOUNDARY) ++boundary;
        if(r.outcome == ES::NO_SMOOTHING_IMPROVEMENT && r.steps > 0)
        {
          // A climb short of the 1% gain after its first ascent step ends
          // there: the smart Laplacian and that step at most.
          REQUIRE(r.steps <= 2);
          ++cut_short;
        }
        if(!r.moved()) continue;
        ++moves;
        REQUIRE(r.quality_after > r.quality_before * 1.01);
        const double now = worst();
        REQUIRE(now >= w);
        w = now;
      }
      REQUIRE(tr.is_valid());
      REQUIRE(every_cell_positive(tr));
      REQUIRE(exact_volume(tr) == volume);
    }
    REQUIRE(hull_points() == hull);
    WARN("seed " << seed << ": " << moves << " moves, " << boundary << " refusals on the hull, " << cut_short
                  << " climbs cut short; worst dihedral sine " << w);
    REQUIRE(moves > 0);
    REQUIRE(cut_short > 0);
    REQUIRE(boundary > 0);
  }
}

namespace {

/// A visitor that checks what it is told: the old cells are intact before a
/// replacement and the new ones fill the same region (equal exact volumes;
/// the infinite cells, on the hull, are only counted), and every move moves.
struct Checking_visitor
{
  std::size_t replacements = 0, moves = 0, insertions = 0, removals = 0, mismatches = 0;
  CGAL::Exact_rational old_volume = 0;

  template <class T>
  static CGAL::Exact_rational volume(const T& tr, const std::vector<typename T::Cell_handle>& cells)
  {
    CGAL::Exact_rational v = 0;
    for(auto c : cells)
      if(!tr.is_infinite(c))
        v += exact_volume(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
    return v;
  }
  template <class T>
  void before_replacement(const T& tr, const std::vector<typename T::Cell_handle>& old_cells)
  {
    old_volume = volume(tr, old_cells);
  }
  template <class T>
  void after_replacement(const T& tr, const std::vector<typename T::Cell_handle>& new_cells)
  {
    ++replacements;
    if(volume(tr, new_cells) != old_volume) ++mismatches;
  }
  template <class T>
  void after_move(const T&, typename T::Vertex_handle v, const typename T::Point& old_point)
  {
    ++moves;
    if(v->point() == old_point) ++mismatches;
  }
  // The new vertex is where its weights put it among the corners, up to rounding.
  template <class T>
  void after_insertion(const T& tr, typename T::Vertex_handle v, const std::array<typename T::Vertex_handle, 4>& corners,
                       const std::array<double, 4>& weights)
  {
    ++insertions;
    double sum = 0, x = 0, y = 0, z = 0, size = 0;
    for(int k = 0; k < 4; ++k)
    {
      if(tr.is_infinite(corners[k]) || weights[k] < -1e-9) ++mismatches;
      sum += weights[k];
      x += weights[k] * corners[k]->point().x();
      y += weights[k] * corners[k]->point().y();
      z += weights[k] * corners[k]->point().z();
      size = (std::max)(size, std::sqrt(CGAL::squared_distance(corners[k]->point(), corners[0]->point())));
    }
    if(std::abs(sum - 1) > 1e-9 || std::sqrt(CGAL::squared_distance(v->point(), Point(x, y, z))) > 1e-6 * size)
      ++mismatches;
  }
  template <class T>
  void before_removal(const T& tr, typename T::Vertex_handle v, typename T::Vertex_handle onto)
  {
    ++removals;
    typename T::Cell_handle c;
    int i = 0, j = 0;
    if(tr.is_infinite(v) || v == onto || !tr.is_edge(v, onto, c, i, j)) ++mismatches;
  }
};

} // namespace

TEST_CASE("The replacement visitor sees every operation of the quality driver - old cells before - new after - moves",
          "[quality driver][visitor]")
{
  const unsigned seed = 9;
  INFO("seed " << seed);
  const auto points = random_in_cube(300, seed);
  for(unsigned operations : {unsigned(ES::FLIPS), unsigned(ES::ALL_OPERATIONS), unsigned(ES::ALL_WITH_VERTEX_CHANGES)})
  {
    CAPTURE(operations);
    Tr tr;
    ES::insert_delaunay(tr, points);
    Checking_visitor visitor;
    const auto r = ES::improve_worst_tetrahedra(
        tr, ES::Max_min_dihedral_angle_criterion(),
        ES::parameters::operations(operations).visitor(std::ref(visitor)));
    std::size_t flips = 0;
    for(std::size_t f : r.flips) flips += f;
    REQUIRE(r.number_of_operations() > 0);
    REQUIRE(visitor.mismatches == 0);
    // A two-step removal is two replacements.
    REQUIRE(visitor.replacements == flips + r.edge_removals + 2 * r.two_step_removals + r.face_removals +
                                        r.vertex_removals + r.vertex_insertions);
    REQUIRE(visitor.moves == r.smoothing_moves);
    REQUIRE(visitor.insertions == r.vertex_insertions);
    REQUIRE(visitor.removals == r.vertex_removals);
    if(operations & ES::SMOOTHING) REQUIRE(visitor.moves > 0);
    if(operations & ES::VERTEX_INSERTION) REQUIRE(visitor.insertions > 0);
    if(operations & ES::VERTEX_REMOVAL) REQUIRE(visitor.removals > 0);
    REQUIRE(tr.number_of_vertices() == points.size() + r.vertex_insertions - r.vertex_removals);
  }
  SECTION("each operation alone, through std::ref")
  {
    Tr tr;
    ES::insert_delaunay(tr, points);
    Checking_visitor visitor;
    const ES::Max_min_dihedral_angle_criterion criterion;
    std::size_t removed = 0, moved = 0;
    for(auto v : std::vector<Tr::Vertex_handle>(tr.finite_vertex_handles().begin(), tr.finite_vertex_handles().end()))
    {
      Tr::Cell_handle c = v->cell();
      if(tr.is_infinite(c)) continue;
      const int i = c->index(v), j = (i + 1) & 3;
      removed += ES::remove_edge_in_two_steps(tr, Tr::Edge(c, i, j), criterion,
                                              CGAL::parameters::visitor(std::ref(visitor))).removed();
      c = v->cell();
      removed += ES::remove_faces(tr, Tr::Facet(c, c->index(v)), criterion,
                                  CGAL::parameters::visitor(std::ref(visitor))).removed();
      moved += ES::smooth_vertex(tr, v, criterion, CGAL::parameters::visitor(std::ref(visitor))).moved();
    }
    REQUIRE(removed > 0);
    REQUIRE(moved > 0);
    REQUIRE(visitor.replacements >= removed);
    REQUIRE(visitor.moves == moved);
    REQUIRE(visitor.mismatches == 0);
    REQUIRE(tr.is_valid());
  }
}

namespace {

// The points of the hull's vertices, in lexicographic order.
std::vector<Point> sorted_hull_points(const Tr& tr)
{
  std::vector<Point> h;
  std::vector<Tr::Vertex_handle> around;
  tr.adjacent_vertices(tr.infinite_vertex(), std::back_inserter(around));
  for(auto v : around) h.push_back(v->point());
  std::sort(h.begin(), h.end(), [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  return h;
}

} // namespace

TEST_CASE("Vertex insertion in bad cells - a cavity filled exactly once - the worst new cell better - hull kept",
          "[vertex insertion]")
{
  const unsigned seed = 21;
  INFO("seed " << seed);
  Tr tr;
  ES::insert_delaunay(tr, random_in_cube(400, seed));
  const auto volume = exact_volume(tr);
  const auto hull = sorted_hull_points(tr);
  const ES::Max_min_dihedral_sine_criterion criterion;
  // The 40 worst cells, by their points (handles die as cells are replaced).
  std::vector<std::pair<double, std::array<Point, 4>>> worst;
  for(auto c : tr.finite_cell_handles())
    worst.push_back({criterion.measure(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                       c->vertex(3)->point()),
                     {c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point()}});
  std::sort(worst.begin(), worst.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  worst.resize(40);
  std::size_t inserted = 0, refused = 0;
  Checking_visitor visitor;
  for(const auto& [measure, p] : worst)
  {
    Tr::Vertex_handle v[4];
    Tr::Cell_handle c;
    bool found = true;
    for(int i = 0; i < 4 && found; ++i) found = tr.is_vertex(p[i], v[i]);
    if(!found || !tr.is_cell(v[0], v[1], v[2], v[3], c)) continue;
    const std::size_t vertices = tr.number_of_vertices();
    std::set<Tr::Vertex_handle> before;
    for(auto u : tr.finite_vertex_handles()) before.insert(u);
    const auto r = ES::insert_vertex(tr, c, criterion, CGAL::parameters::visitor(std::ref(visitor)));
    REQUIRE(r.quality_before == measure);
    if(!r.inserted())
    {
      REQUIRE(r.outcome == ES::NO_INSERTION_IMPROVEMENT);
      REQUIRE(tr.number_of_vertices() == vertices);
      ++refused;
      continue;
    }
    ++inserted;
    REQUIRE(tr.number_of_vertices() == vertices + 1);
    REQUIRE(r.quality_after > r.quality_before);
    REQUIRE(r.new_cells > r.cavity_size);
    // The new cells are the new vertex's star, and their worst is the reported one.
    Tr::Vertex_handle made;
    for(auto u : tr.finite_vertex_handles())
      if(!before.count(u)) made = u;
    std::vector<Tr::Cell_handle> star;
    tr.incident_cells(made, std::back_inserter(star));
    REQUIRE(star.size() == std::size_t(r.new_cells));
    double lowest = HUGE_VAL;
    for(auto d : star)
      lowest = (std::min)(lowest, criterion.measure(d->vertex(0)->point(), d->vertex(1)->point(), d->vertex(2)->point(),
                                                    d->vertex(3)->point()));
    REQUIRE(lowest == r.quality_after);
  }
  INFO(inserted << " inserted, " << refused << " refused");
  REQUIRE(inserted > 0);
  REQUIRE(visitor.insertions == inserted);
  REQUIRE(visitor.mismatches == 0);
  REQUIRE(tr.is_valid());
  REQUIRE(every_cell_positive(tr));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(sorted_hull_points(tr) == hull);
  // An infinite cell is not a place for a vertex.
  REQUIRE(ES::insert_vertex(tr, tr.infinite_cell(), criterion).outcome == ES::CELL_NOT_IN_DOMAIN);
}

TEST_CASE("Vertex removal contracts an interior vertex onto the neighbour that makes the best cells - the hull stays",
          "[vertex removal]")
{
  // The octahedron, its centre and a point near the centre: the two make
  // flat cells between them; contracting the near point onto the centre
  // leaves the eight trirectangular cells.
  Tr tr;
  const Point near(0.05, 0.03, -0.02);
  ES::insert_delaunay(tr, std::vector<Point>{Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0),
                                             Point(0, 0, 1), Point(0, 0, -1), Point(0, 0, 0), near});
  Tr::Vertex_handle extra, corner;
  REQUIRE(tr.is_vertex(near, extra));
  REQUIRE(tr.is_vertex(Point(1, 0, 0), corner));
  const auto volume = exact_volume(tr);
  const ES::Max_min_dihedral_angle_criterion criterion;
  Checking_visitor visitor;
  REQUIRE(ES::remove_vertex(tr, corner, criterion).outcome == ES::VERTEX_NOT_REMOVABLE);
  const auto r = ES::remove_vertex(tr, extra, criterion, CGAL::parameters::visitor(std::ref(visitor)));
  REQUIRE(r.outcome == ES::VERTEX_REMOVED);
  REQUIRE(r.quality_after > r.quality_before);
  REQUIRE(std::abs(r.quality_after - std::acos(1 / std::sqrt(3.0)) * 180 / CGAL_PI) < 1e-9);
  REQUIRE(tr.number_of_vertices() == 7);
  REQUIRE(tr.number_of_finite_cells() == 8);
  REQUIRE(tr.is_valid());
  REQUIRE(every_cell_positive(tr));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(visitor.removals == 1);
  REQUIRE(visitor.mismatches == 0);
  // Nothing better is left: the centre stays.
  Tr::Vertex_handle centre;
  REQUIRE(tr.is_vertex(Point(0, 0, 0), centre));
  REQUIRE(ES::remove_vertex(tr, centre, criterion).outcome == ES::NO_VERTEX_REMOVAL_IMPROVEMENT);
}

TEST_CASE("The quality driver with vertex changes - valid - the hull and the volume kept - never worse - off by default",
          "[quality driver][vertex insertion][vertex removal]")
{
  const unsigned seed = 33;
  INFO("seed " << seed);
  const auto points = random_in_cube(500, seed);
  Tr tr;
  ES::insert_delaunay(tr, points);
  const auto volume = exact_volume(tr);
  const auto hull = sorted_hull_points(tr);
  const ES::Max_min_dihedral_sine_criterion criterion;
  Tr kept = tr;
  const auto without = ES::improve_worst_tetrahedra(kept, criterion, ES::parameters::operations(ES::ALL_OPERATIONS));
  REQUIRE(kept.number_of_vertices() == points.size());
  REQUIRE(without.vertex_insertions + without.vertex_removals == 0);
  const auto r = ES::improve_worst_tetrahedra(tr, criterion, ES::parameters::operations(ES::ALL_WITH_VERTEX_CHANGES));
  INFO(r.vertex_insertions << " inserted, " << r.vertex_removals << " removed; worst " << r.worst_before << " -> "
                           << r.worst_after << " (without: " << without.worst_after << ")");
  REQUIRE(r.ending == ES::CONVERGED);
  REQUIRE(r.vertex_insertions > 0);
  REQUIRE(r.vertex_removals > 0);
  REQUIRE(tr.number_of_vertices() == points.size() + r.vertex_insertions - r.vertex_removals);
  REQUIRE(r.worst_after >= r.worst_before);
  REQUIRE(tr.is_valid());
  REQUIRE(every_cell_positive(tr));
  REQUIRE(exact_volume(tr) == volume);
  REQUIRE(sorted_hull_points(tr) == hull);
  // No vertex came or went in a cell within the angles (30 and 140 by
  // default): with bounds that every cell meets, none does.
  Tr again;
  ES::insert_delaunay(again, points);
  const auto none = ES::improve_worst_tetrahedra(
      again, criterion,
      ES::parameters::vertex_change_angles(std::pair<double, double>(0, 180),
                                           ES::parameters::operations(ES::ALL_WITH_VERTEX_CHANGES)));
  REQUIRE(none.vertex_insertions + none.vertex_removals == 0);
}

TEST_CASE("Delaunay repair of a domain mesh whose failing facets are all constrained ends stuck on both schedules", "[drivers]")
{
  // Every facet is a boundary facet: no flip is allowed, so the helper's
  // first round tags and its second changes nothing. No state can progress.
  for(auto schedule : {ES::WORK_QUEUE, ES::PAPER_CYCLES})
  {
    const unsigned seed = 3;
    INFO("random_in_cube(200, " << seed << "), placing start, "
                                << (schedule == ES::WORK_QUEUE ? "work queue" : "paper cycles"));
    Domain_tr tr;
    ES::insert_by_placing(tr, random_in_cube(200, seed));
    for(auto c : tr.all_cell_handles())
    {
      c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
      for(int i = 0; i < 4; ++i) c->info().facet_reference[i] = 1;
    }
    const auto cells = cell_set(tr);
    const long long failing = (long long)ES::internal::number_of_non_delaunay_facets(tr, ES::CGAL_PERTURBATION);
    REQUIRE(failing > 0);
    const auto r = CGAL::swap_edges(tr, ES::Delaunay_criterion(),
                                    ES::parameters::mesh_constraints(ES::Domain_constraints(), ES::parameters::schedule(schedule)));
    REQUIRE(r.ending == ES::STUCK);
    REQUIRE(r.non_delaunay_facets == failing);
    REQUIRE(r.repair_path == ES::HELPER_FLIPS);
    REQUIRE(r.helper_rounds == 2);
    REQUIRE(r.cycles.back().rule == ES::HELPER_RULE);
    REQUIRE(r.cycles.back().total_swaps() == 0);
    REQUIRE(r.cycles.back().new_tags == 0);
    REQUIRE(cell_set(tr) == cells);
  }
}
