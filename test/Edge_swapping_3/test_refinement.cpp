// SPDX-License-Identifier: GPL-3.0-or-later
// Refinement at circumcenters (aspect ratio and gradient) and domain meshes:
// targets reached, sites only inside the domain, constrained facets and
// subdomains unchanged by swaps and insertions.

#include "test_common.h"
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/refinement.h>
#include <map>

using namespace test;

namespace {

typedef CGAL::Triangulation_cell_base_with_info_3<ES::Domain_cell_info, K> Domain_cell_base;
typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>, Domain_cell_base> Domain_tds;
typedef CGAL::Triangulation_3<K, Domain_tds> Domain_tr;

// The Delaunay triangulation of a 5x5x5 grid with two subdomains (x < 2 and
// x > 2) separated by the constrained plane x = 2 (reference 7), and the hull
// facets constrained (reference 9).
void make_two_subdomains(Domain_tr& tr)
{
  // A grid of step 1/2 in [0,4]^3: cells away from the constraints exist, whose
  // circumcenters encroach upon no constrained facet.
  std::vector<Point> points;
  for(const Point& p : grid(9, 9, 9)) points.emplace_back(p.x() / 2, p.y() / 2, p.z() / 2);
  ES::delaunay_by_insertion(tr, points);
  for(auto c : tr.all_cell_handles())
  {
    c->info() = ES::Domain_cell_info();
    if(tr.is_infinite(c)) continue;
    const double x = (c->vertex(0)->point().x() + c->vertex(1)->point().x() + c->vertex(2)->point().x() +
                      c->vertex(3)->point().x()) / 4;
    c->info().subdomain = (x < 2) ? 1 : 2;
  }
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      const auto n = c->neighbor(i);
      if(c->info().subdomain != n->info().subdomain)
        c->info().facet_reference[i] = (tr.is_infinite(c) || tr.is_infinite(n)) ? 9 : 7;
    }
}

typedef std::pair<std::array<Point, 3>, int> Constrained_facet;

// Constrained facets as sorted point triples with their reference, seen from both sides.
std::multiset<Constrained_facet> constrained_facets(const Domain_tr& tr)
{
  std::multiset<Constrained_facet> s;
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(c->info().facet_reference[i] != ES::Domain_cell_info::no_reference)
      {
        std::array<Point, 3> p;
        for(int k = 0; k < 3; ++k)
        {
          const auto v = c->vertex((i + 1 + k) & 3);
          p[k] = tr.is_infinite(v) ? Point(-1e9, -1e9, -1e9) : v->point();
        }
        std::sort(p.begin(), p.end());
        s.insert({p, c->info().facet_reference[i]});
      }
  return s;
}

std::map<int, CGAL::Exact_rational> subdomain_volumes(const Domain_tr& tr)
{
  std::map<int, CGAL::Exact_rational> v;
  for(auto c : tr.finite_cell_handles())
    v[c->info().subdomain] += exact_volume(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                           c->vertex(3)->point());
  return v;
}

} // namespace

TEST_CASE("Refinement by aspect ratio reaches its target on a random-point mesh", "[refinement]")
{
  const unsigned seed = 4;
  INFO("seed " << seed);
  Tr tr;
  ES::delaunay_by_insertion(tr, random_in_cube(200, seed));
  const auto report = ES::refine_by_aspect_ratio(tr, 3.0, ES::Delaunay_criterion(),
                                                 ES::parameters::aspect_ratio_definition(ES::EDGE_LENGTH_RATIO,
                                                                                         ES::parameters::maximum_sites(5000)));
  REQUIRE(report.target_met);
  REQUIRE(report.rounds.front().worst_refinable > 3.0);
  REQUIRE(report.rounds.back().worst_refinable <= 3.0);
  REQUIRE(report.sites_inserted > 0);
  REQUIRE(tr.number_of_vertices() == 200 + report.sites_inserted);
  // Every site inside the hull (the domain of a point set), the hull unchanged,
  // and insertion with Delaunay swaps leaves CGAL's Delaunay triangulation.
  REQUIRE(exact_volume(tr) == [&] { Tr t; ES::delaunay_by_insertion(t, random_in_cube(200, seed)); return exact_volume(t); }());
  REQUIRE(tr.is_valid(true));
  REQUIRE(ES::compare_with_delaunay(tr).identical);
}

TEST_CASE("Refinement by gradient puts the sites where the field varies and interpolates values", "[refinement]")
{
  const unsigned seed = 5;
  INFO("seed " << seed);
  Tr tr;
  const auto points = random_in_cube(500, seed);
  ES::delaunay_by_insertion(tr, points);
  std::map<Tr::Vertex_handle, double> value; // a front at x = 0.5
  for(auto v : tr.finite_vertex_handles()) value[v] = std::tanh(40 * (v->point().x() - 0.5));
  std::size_t near_front = 0;
  const auto new_vertex = [&](Tr::Vertex_handle v, const ES::Site_location<Tr>& where) {
    double x = 0;
    for(int k = 0; k < 4; ++k) x += where.weights[k] * value.at(where.vertices[k]);
    value[v] = x;
    if(std::abs(v->point().x() - 0.5) < 0.1) ++near_front;
  };
  const auto report = ES::refine_by_gradient(tr, [&](Tr::Vertex_handle v) { return value.at(v); }, 300,
                                             ES::Delaunay_criterion(), ES::parameters::new_vertex_visitor(new_vertex));
  REQUIRE(report.sites_inserted == 300);
  REQUIRE(tr.number_of_vertices() == 800);
  REQUIRE(near_front > 250); // a fifth of the volume holds most of the sites
  REQUIRE(ES::compare_with_delaunay(tr).identical);
}

TEST_CASE("Domain mesh: swaps and refinement keep constrained facets and subdomains", "[refinement][domain]")
{
  Domain_tr tr;
  make_two_subdomains(tr);
  const auto facets_before = constrained_facets(tr);
  const auto volumes_before = subdomain_volumes(tr);
  REQUIRE(facets_before.size() == 2 * 2 * 64 + 2 * 6 * 128); // the plane x = 2 from both sides, the hull twice
  ES::Domain_constraints constraints;

  // A scrambled start, then the helper strategy: neither may cross x = 2.
  CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion(),
                   ES::parameters::mesh_constraints(constraints, CGAL::parameters::random_seed(2)));
  REQUIRE(constrained_facets(tr) == facets_before);

  std::vector<Point> sites;
  const auto new_vertex = [&](Domain_tr::Vertex_handle v, const ES::Site_location<Domain_tr>&) { sites.push_back(v->point()); };
  const auto report = ES::refine_by_aspect_ratio(
      tr, 1.6, ES::Delaunay_criterion(),
      ES::parameters::maximum_sites(400, ES::parameters::new_vertex_visitor(new_vertex,
                                                                            ES::parameters::mesh_constraints(constraints))));
  REQUIRE(report.sites_inserted > 0);
  INFO("sites " << report.sites_inserted << ", refused " << report.sites_refused << ", worst refinable "
                << report.rounds.back().worst_refinable << ", worst " << report.rounds.back().worst);
  // Cells along x = 2 and the hull, whose circumcenters encroach upon a
  // constrained facet, stay as they are: the worst cell is one of them.
  REQUIRE(report.target_met);
  REQUIRE(report.rounds.back().worst > 1.6);
  for(const Point& p : sites)
  {
    REQUIRE(p.x() > 0); REQUIRE(p.x() < 4); REQUIRE(p.y() > 0); REQUIRE(p.y() < 4); REQUIRE(p.z() > 0); REQUIRE(p.z() < 4);
    REQUIRE(p.x() != 2);
    // No site encroaches upon a constrained facet (its diametral ball).
    for(const auto& f : facets_before)
      if(f.first[0].x() > -1e9)
        REQUIRE(CGAL::side_of_bounded_sphere(f.first[0], f.first[1], f.first[2], p) != CGAL::ON_BOUNDED_SIDE);
  }
  REQUIRE(tr.is_valid(true));
  REQUIRE(constrained_facets(tr) == facets_before);
  REQUIRE(subdomain_volumes(tr) == volumes_before);
}
