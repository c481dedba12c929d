// SPDX-License-Identifier: GPL-3.0-or-later
// Domains in CGAL's vocabulary: facet_is_constrained_map and
// cell_is_selected_map on a plain triangulation, the subdomain and surface
// patch indices of a triangulation that Tetrahedral_remeshing has processed,
// and a user's wrapper of the Delaunay criterion that keeps its fast path.

#include "test_common.h"
#include <CGAL/Edge_swapping_3/IO/mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/mesh_with_fields_from_complex.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/tetrahedral_remeshing.h>
#include <boost/property_map/property_map.hpp>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <unordered_map>

using namespace test;

namespace {

typedef std::array<Point, 3> Facet_points;

// A vertex's point without its weight (Mesh_3's triangulation is regular).
template <class P>
Point bare(const P& p)
{
  return ES::internal::bare_point(p);
}


template <class T>
Facet_points facet_points(const T& tr, typename T::Cell_handle c, int i)
{
  Facet_points f;
  for(int k = 0; k < 3; ++k) f[k] = bare(c->vertex(tr.vertex_triple_index(i, k))->point());
  std::sort(f.begin(), f.end(), [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  return f;
}

template <class T>
Cell_points cell_points(typename T::Cell_handle c)
{
  Cell_points p = {bare(c->vertex(0)->point()), bare(c->vertex(1)->point()), bare(c->vertex(2)->point()),
                   bare(c->vertex(3)->point())};
  std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  return p;
}

template <class T>
bool has_facet(const T& tr, const Facet_points& f)
{
  typename T::Vertex_handle v[3];
  for(int k = 0; k < 3; ++k)
    if(!tr.is_vertex(f[k], v[k])) return false;
  typename T::Cell_handle c;
  int i, j, l;
  return tr.is_facet(v[0], v[1], v[2], c, i, j, l);
}

// A C3T3 triangulation's facets of the complex (from both sides), with their
// patch index, and the exact volume of each subdomain.
typedef CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<K> Remeshing_tr;

template <class T>
auto complex_facets(const T& tr)
{
  typedef std::decay_t<decltype(tr.infinite_cell()->surface_patch_index(0))> Patch;
  std::multiset<std::pair<Facet_points, Patch>> s;
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(c->is_facet_on_surface(i)) s.insert({facet_points(tr, c, i), c->surface_patch_index(i)});
  return s;
}

template <class T>
std::map<int, CGAL::Exact_rational> subdomain_volumes(const T& tr)
{
  std::map<int, CGAL::Exact_rational> v;
  for(auto c : tr.finite_cell_handles())
    v[int(c->subdomain_index())] += exact_volume(bare(c->vertex(0)->point()), bare(c->vertex(1)->point()),
                                                 bare(c->vertex(2)->point()), bare(c->vertex(3)->point()));
  return v;
}

// Mesh_3's output for the unit ball cut in two by the plane x = 0.1
// (subdomains 1 and 2), without perturbation or exudation. (With two nested
// balls, Mesh_3 5.5 found only the inner sphere: its initial points missed
// the outer one.)
typedef CGAL::Labeled_mesh_domain_3<K> Labeled_domain;
typedef CGAL::Mesh_triangulation_3<Labeled_domain>::type Mesh_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Mesh_tr> C3t3;

int halves_of_the_ball(const Point& p)
{
  const double r2 = CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
  return r2 < 1 ? (CGAL::to_double(p.x()) < 0.1 ? 1 : 2) : 0;
}

C3t3 mesh_of_two_half_balls()
{
  namespace params = CGAL::parameters;
  const Labeled_domain domain(std::function<int(const Point&)>(halves_of_the_ball), K::Sphere_3(CGAL::ORIGIN, 4.), 1e-6);
  const CGAL::Mesh_criteria_3<Mesh_tr> criteria(params::facet_angle = 25, params::facet_size = 0.15,
                                                params::facet_distance = 0.02, params::cell_radius_edge_ratio = 3,
                                                params::cell_size = 0.15);
  return CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
}

// The validity of a regular triangulation as a triangulation (combinatorics
// and positive orientations): the swaps leave it not regular, on purpose.
bool is_valid_triangulation(const Mesh_tr& tr)
{
  typedef Mesh_tr::Tr_Base Base;
  return static_cast<const Base&>(tr).is_valid();
}

// Random points in the unit cube, triangulated without flips; cells of
// centroid x < 1/2 in subdomain 1, the others in 2; the hull and the facets
// between the two subdomains in the complex (patches 1 and 2); then
// Tetrahedral_remeshing's isotropic remeshing, as a user's mesh would be.
Remeshing_tr remeshed_two_subdomains(unsigned seed)
{
  Remeshing_tr tr;
  for(const Point& p : random_in_cube(400, seed)) tr.insert(p);
  for(auto c : tr.finite_cell_handles())
  {
    double x = 0;
    for(int k = 0; k < 4; ++k) x += c->vertex(k)->point().x() / 4;
    c->set_subdomain_index(x < 0.5 ? 1 : 2);
  }
  CGAL::tetrahedral_isotropic_remeshing(tr, 0.15, CGAL::parameters::number_of_iterations(2));
  // Remeshing keeps the interface and the hull (subdomain 0 outside) in its
  // complex: the facets between different subdomains.
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      const auto n = c->neighbor(i);
      const int a = tr.is_infinite(c) ? 0 : int(c->subdomain_index()), b = tr.is_infinite(n) ? 0 : int(n->subdomain_index());
      if(tr.is_infinite(c)) c->set_subdomain_index(0);
      c->set_surface_patch_index(i, a != b ? std::max(a, b) : 0);
    }
  return tr;
}

template <class Tr>
struct Counting_delaunay_wrapper
{
  static constexpr bool is_delaunay_criterion = true; // keeps the fast path and the endings
  std::size_t* calls;
  bool operator()(const Tr& tr, const ES::Five_point_configuration<Tr>& conf) const
  {
    ++*calls;
    return ES::Delaunay_criterion()(tr, conf);
  }
};

} // namespace

TEST_CASE("CGAL's domain maps: constrained facets stay, unselected cells stay, the maps are written back",
          "[domain][cgal vocabulary]")
{
  const unsigned seed = 21;
  INFO("seed " << seed);
  Tr tr;
  ES::insert_by_placing(tr, random_in_cube(600, seed));
  // Constrained: the facets whose three vertices lie in x < 0.3; selected: the
  // cells with a vertex in x > 0.6 (the rest is frozen).
  std::map<std::pair<Tr::Cell_handle, int>, bool> constrained;
  std::unordered_map<Tr::Cell_handle, bool, CGAL::Handle_hash_function> selected;
  std::set<Facet_points> constrained_before;
  std::set<Cell_points> frozen_before;
  for(auto c : tr.finite_cell_handles())
  {
    bool sel = false;
    for(int k = 0; k < 4; ++k) sel = sel || c->vertex(k)->point().x() > 0.6;
    selected[c] = sel;
    if(!sel) frozen_before.insert(cell_points<Tr>(c));
    for(int i = 0; i < 4; ++i)
    {
      bool low = true;
      for(int k = 0; k < 3; ++k) low = low && c->vertex(tr.vertex_triple_index(i, k))->point().x() < 0.3;
      constrained[{c, i}] = low;
      if(low) constrained_before.insert(facet_points(tr, c, i));
    }
  }
  REQUIRE(!constrained_before.empty());
  REQUIRE(!frozen_before.empty());
  const auto facet_map = boost::make_assoc_property_map(constrained);
  const auto cell_map = boost::make_assoc_property_map(selected);

  const auto report = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion(),
                                       CGAL::parameters::facet_is_constrained_map(facet_map).cell_is_selected_map(cell_map));
  const auto swaps = report.total_swaps();
  REQUIRE(swaps[0] + swaps[1] > 0);
  REQUIRE(tr.is_valid());
  for(const auto& f : constrained_before) REQUIRE(has_facet(tr, f));
  const auto after = cell_set(tr);
  for(const auto& c : frozen_before) REQUIRE(std::binary_search(after.begin(), after.end(), c, [](const Cell_points& a, const Cell_points& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        [](const Point& p, const Point& q) { return CGAL::compare_xyz(p, q) == CGAL::SMALLER; });
  }));
  // Written back: every cell now in the mesh has its status in the maps.
  std::size_t unselected = 0, marked = 0;
  for(auto c : tr.finite_cell_handles())
  {
    REQUIRE(selected.count(c) == 1);
    unselected += !selected[c];
    for(int i = 0; i < 4; ++i) marked += constrained[{c, i}];
  }
  REQUIRE(unselected == frozen_before.size());
  REQUIRE(marked >= constrained_before.size());

  // Without the maps the same run changes the frozen cells and removes some of the facets.
  Tr free_tr;
  ES::insert_by_placing(free_tr, random_in_cube(600, seed));
  CGAL::swap_edges(free_tr, ES::Min_max_dihedral_angle_criterion());
  std::size_t lost = 0;
  for(const auto& f : constrained_before) lost += !has_facet(free_tr, f);
  REQUIRE(lost > 0);
}

TEST_CASE("A user's wrapper of the Delaunay criterion keeps the fast path and the repair", "[drivers][cgal vocabulary]")
{
  for(unsigned seed = 1; seed <= 3; ++seed)
  {
    INFO("seed " << seed);
    Tr tr;
    ES::insert_by_placing(tr, random_in_cube(2000, seed));
    std::size_t calls = 0;
    const auto report = CGAL::swap_edges(tr, Counting_delaunay_wrapper<Tr>{&calls});
    REQUIRE(report.ending == ES::CONVERGED);
    REQUIRE(report.non_delaunay_facets == 0); // a Delaunay ending is decided, not -1
    REQUIRE(calls == 0);                       // the in-sphere test decided every visit
    REQUIRE(ES::compare_with_delaunay(tr).identical);
  }
}

TEST_CASE("A triangulation that Tetrahedral_remeshing processed: swaps, worst first, insertion and refinement keep "
          "its complex and subdomains", "[domain][cgal vocabulary]")
{
  const unsigned seed = 8;
  INFO("seed " << seed);
  Remeshing_tr tr = remeshed_two_subdomains(seed);
  const auto facets = complex_facets(tr);
  const auto volumes = subdomain_volumes(tr);
  REQUIRE(volumes.count(1) == 1);
  REQUIRE(volumes.count(2) == 1);
  REQUIRE(facets.size() > 100);
  auto require_kept = [&] {
    REQUIRE(tr.is_valid());
    REQUIRE(complex_facets(tr) == facets);
    REQUIRE(subdomain_volumes(tr) == volumes);
  };

  // No parameter: the cells' own indices are the domain.
  const auto swapped = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion());
  REQUIRE(swapped.total_swaps()[0] + swapped.total_swaps()[1] > 0);
  require_kept();

  const auto worst = ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion());
  REQUIRE(worst.worst_after >= worst.worst_before);
  require_kept();

  // Insertion: points inside the subdomains go in; their cells take the
  // subdomain of the cell they split.
  std::size_t inserted = 0;
  for(const Point& p : random_in_cube(50, seed + 1))
  {
    const auto r = ES::insert_by_swapping(tr, p, ES::Min_max_dihedral_angle_criterion());
    inserted += r.is_new;
  }
  REQUIRE(inserted > 25);
  require_kept();

  const auto refined = ES::refine_by_aspect_ratio(tr, 2.0, ES::Min_max_dihedral_angle_criterion(),
                                                  ES::parameters::maximum_sites(200));
  REQUIRE(refined.sites_inserted > 0);
  require_kept();
}

TEST_CASE("Mesh_3's output as it is: swaps, the worst-first optimizer, insertion and refinement keep its complex "
          "and subdomains",
          "[domain][cgal vocabulary]")
{
  // Deterministic: Mesh_3 without perturbation or exudation, seeded by CGAL's default random.
  C3t3 c3t3 = mesh_of_two_half_balls();
  Mesh_tr& tr = c3t3.triangulation();
  const auto facets = complex_facets(tr);
  const auto volumes = subdomain_volumes(tr);
  REQUIRE(volumes.count(1) == 1);
  REQUIRE(volumes.count(2) == 1);
  REQUIRE(facets.size() > 100);
  auto require_kept = [&] {
    REQUIRE(is_valid_triangulation(tr));
    REQUIRE(complex_facets(tr) == facets);
    REQUIRE(subdomain_volumes(tr) == volumes);
  };

  // Weighted points, the complex's indices in the cells: no parameter needed.
  const auto swapped = CGAL::swap_edges(tr, ES::Min_max_dihedral_angle_criterion());
  const auto swaps = swapped.total_swaps();
  REQUIRE(swaps[0] + swaps[1] > 0);
  require_kept();

  // Smoothing moves interior vertices only (a weight stays with its point).
  const auto worst = ES::improve_worst_tetrahedra(tr, ES::Max_min_dihedral_angle_criterion(),
                                                  ES::parameters::operations(unsigned(ES::ALL_OPERATIONS)));
  REQUIRE(worst.worst_after > worst.worst_before);
  REQUIRE(worst.smoothing_moves > 0);
  require_kept();

  // Insertion of weighted points (weight 0) and refinement at circumcenters,
  // under MinMax: new cells take the subdomain of the cells they split.
  CGAL::Random rng(5);
  std::size_t inserted = 0;
  for(int k = 0; k < 50; ++k)
  {
    const Point p(rng.get_double(-0.7, 0.7), rng.get_double(-0.7, 0.7), rng.get_double(-0.7, 0.7));
    inserted += ES::insert_by_swapping(tr, Mesh_tr::Point(p), ES::Min_max_dihedral_angle_criterion()).is_new;
  }
  REQUIRE(inserted > 40);
  require_kept();
  const auto refined = ES::refine_by_aspect_ratio(tr, 2.0, ES::Min_max_dihedral_angle_criterion(),
                                                  ES::parameters::maximum_sites(200));
  REQUIRE(refined.sites_inserted > 0);
  require_kept();
}

namespace {

namespace {

// The cells of a numbered triangulation as sorted point numbers with their subdomain.
template <class Numbered>
std::multiset<std::pair<std::array<std::size_t, 4>, int>> numbered_cells(const Numbered& tr)
{
  std::multiset<std::pair<std::array<std::size_t, 4>, int>> cells;
  for(auto c : tr.finite_cell_handles())
  {
    std::array<std::size_t, 4> k;
    for(int i = 0; i < 4; ++i) k[i] = c->vertex(i)->info();
    std::sort(k.begin(), k.end());
    cells.insert({k, c->info().subdomain});
  }
  return cells;
}

} // namespace

TEST_CASE("Mesh_3's output as a mesh file: every cell, subdomain and surface facet kept, through all three formats",
          "[cgal vocabulary][domain]")
{
  typedef ES::Numbered_domain_triangulation_3<K> Numbered;
  const C3t3 c3t3 = mesh_of_two_half_balls();
  const auto mesh = ES::mesh_with_fields_from_complex(
      c3t3, [](int subdomain) { return subdomain; },
      [](const std::pair<int, int>& patch) { return 10 * patch.first + patch.second; });
  Numbered tr;
  REQUIRE(ES::build_numbered_mesh(tr, mesh).empty());
  REQUIRE(tr.is_valid());
  std::map<int, std::size_t> by_subdomain, expected_by_subdomain;
  for(auto c : tr.finite_cell_handles()) ++by_subdomain[c->info().subdomain];
  for(auto c : c3t3.triangulation().finite_cell_handles()) ++expected_by_subdomain[c3t3.subdomain_index(c)];
  REQUIRE(by_subdomain == expected_by_subdomain);
  REQUIRE(by_subdomain.size() == 3); // outside (0) and the two halves
  std::size_t constrained = 0;
  for(auto c : tr.all_cell_handles())
    for(int i = 0; i < 4; ++i) constrained += c->info().facet_reference[i] != ES::Domain_cell_info::no_reference;
  REQUIRE(constrained == 2 * c3t3.number_of_facets_in_complex());

  // A field, and one point inserted with its interpolated value.
  auto with_field = mesh;
  with_field.field_names = {"x"};
  with_field.fields = {{}};
  for(const auto& p : with_field.points) with_field.fields[0].push_back(CGAL::to_double(p.x()));
  Numbered grown;
  REQUIRE(ES::build_numbered_mesh(grown, with_field).empty());
  const Point site(0.31, 0.02, -0.17);
  const auto at = grown.locate(site);
  const auto where = ES::site_location(grown, at, site);
  const auto r = ES::insert_by_swapping(grown, site, ES::Delaunay_criterion(),
                                        ES::parameters::mesh_constraints(ES::Domain_constraints()));
  REQUIRE(r.is_new);
  ES::add_numbered_vertex(with_field, r.vertex, ES::interpolated_field_values(with_field, site, where,
                                                                               [](const std::string&, const Point&, double&) { return false; }));
  REQUIRE(with_field.fields[0].back() == Approx(0.31).margin(1e-12)); // a linear field is interpolated exactly

  const auto snapshot = ES::numbered_mesh_snapshot(grown, with_field);
  REQUIRE(snapshot.triangles.size() == c3t3.number_of_facets_in_complex());
  for(const std::string format : {"y.mesh", "y.vtu", "y.ele"})
  {
    INFO(format);
    std::map<std::string, std::string> files;
    ES::IO::write_mesh_with_fields(format, snapshot, [&](const std::string& name, std::function<void(std::ostream&)> write) {
      std::ostringstream out;
      write(out);
      files[name] = out.str();
    });
    REQUIRE(files.size() == (format == "y.ele" ? 2u : 1u));
    const auto back = format == "y.ele" ? ES::IO::mesh_with_fields_from_text<Point>(format, files["y.ele"], files["y.node"])
                                        : ES::IO::mesh_with_fields_from_text<Point>(format, files[format]);
    Numbered again;
    REQUIRE(ES::build_numbered_mesh(again, back).empty());
    if(format == "y.ele") // TetGen files have no subdomains: the cells are the same
    {
      REQUIRE(again.number_of_finite_cells() == grown.number_of_finite_cells());
      REQUIRE(back.fields.size() == 1);
    }
    else
      REQUIRE(numbered_cells(again) == numbered_cells(grown));
    if(format == "y.mesh") REQUIRE(back.triangles.size() == snapshot.triangles.size());
    if(format == "y.vtu") REQUIRE(back.fields == with_field.fields);
  }
}

typedef CGAL::Regular_triangulation_3<K> Regular_tr;
typedef K::Weighted_point_3 Weighted_point;

// The finite cells as sorted bare-point quadruples, and the vertices with their weights.
std::set<Cell_points> regular_cells(const Regular_tr& tr)
{
  std::set<Cell_points> s;
  for(auto c : tr.finite_cell_handles()) s.insert(cell_points<Regular_tr>(c));
  return s;
}

std::set<std::pair<Point, double>> weighted_vertices(const Regular_tr& tr)
{
  std::set<std::pair<Point, double>> s;
  for(auto v : tr.finite_vertex_handles()) s.insert({v->point().point(), CGAL::to_double(v->point().weight())});
  return s;
}

void require_cgal_regular(const std::vector<Weighted_point>& points, ES::Insertion_order order)
{
  Regular_tr tr;
  const auto report = ES::regular_by_insertion(tr, points, ES::parameters::insertion_order(order));
  const Regular_tr cgal(points.begin(), points.end());
  REQUIRE(report.stuck_facets == 0);
  REQUIRE(tr.is_valid()); // CGAL's own check: regular (the power test) and valid
  REQUIRE(tr.number_of_vertices() == cgal.number_of_vertices());
  REQUIRE(weighted_vertices(tr) == weighted_vertices(cgal));
  REQUIRE(regular_cells(tr) == regular_cells(cgal));
  std::size_t vertices = 0;
  for(auto v : report.vertices) vertices += (v != Regular_tr::Vertex_handle());
  REQUIRE(vertices == tr.number_of_vertices()); // a redundant point has no vertex
}

} // namespace

TEST_CASE("Flip insertion of weighted points equals CGAL's Regular_triangulation_3 cell for cell",
          "[insertion][exactness][regular]")
{
  for(unsigned seed = 1; seed <= 3; ++seed)
    for(double largest_weight : {0.0, 0.001, 0.01, 0.05})
    {
      // Larger weights make more points redundant: from none to most of them.
      INFO("seed " << seed << ", weights in [0, " << largest_weight << ")");
      CGAL::Random rng(seed);
      std::vector<Weighted_point> points;
      for(const Point& p : random_in_cube(1500, seed))
        points.emplace_back(p, largest_weight > 0 ? rng.get_double(0, largest_weight) : 0.0);
      require_cgal_regular(points, seed == 1 ? ES::INPUT_ORDER : ES::SPATIAL_ORDER);
    }
}

TEST_CASE("Flip insertion of weighted points on a grid: equal and alternating weights (power ties broken as CGAL does)",
          "[insertion][exactness][regular]")
{
  for(double heavy : {0.25, 0.6})
    for(auto order : {ES::INPUT_ORDER, ES::SPATIAL_ORDER})
    {
      // Equal weights: every power sphere of the grid is degenerate, as for
      // Delaunay; alternating weights 0 and 0.6: ties of another kind.
      INFO("heavy weight " << heavy << ", " << (order == ES::INPUT_ORDER ? "input" : "spatial") << " order");
      std::vector<Weighted_point> points;
      for(const Point& p : grid(6, 6, 6))
      {
        const int parity = int(CGAL::to_double(p.x() + p.y() + p.z())) % 2;
        points.emplace_back(p, heavy == 0.25 ? 0.25 : (parity ? 0.0 : heavy));
      }
      require_cgal_regular(points, order);
    }
}

TEST_CASE("Flip insertion of weighted points on grids with integer weights: redundant vertices on facets and edges",
          "[insertion][exactness][regular]")
{
  // Weights 0 to 3 on integer points: many power ties, and vertices made
  // redundant that lie on a facet or an edge of the cells replacing them
  // (removed by the degenerate forms of the 4-1 flip), on the hull too.
  for(unsigned seed = 1; seed <= 12; ++seed)
  {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    std::vector<Weighted_point> points;
    for(const Point& p : grid(5, 5, 5)) points.emplace_back(p, double(rng() % 4));
    std::shuffle(points.begin(), points.end(), rng);
    require_cgal_regular(points, seed % 2 ? ES::INPUT_ORDER : ES::SPATIAL_ORDER);
  }
  std::vector<Weighted_point> points;
  for(const Point& p : grid(6, 6, 6))
    points.emplace_back(p, double(int(CGAL::to_double(7 * p.x() + 3 * p.y() + p.z())) % 4));
  require_cgal_regular(points, ES::SPATIAL_ORDER);
}
