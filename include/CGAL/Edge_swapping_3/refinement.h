// SPDX-License-Identifier: GPL-3.0-or-later
// Refinement at circumcenters (paper section 5): incremental mesh generation
// by aspect ratio, and adaptive refinement by a solution gradient. Both keep
// a heap of cells, insert a site at the circumcenter of the top cell with
// `insert_by_swapping`, and swap under a criterion (Delaunay by default).
//
// Heap entries name cells by their four vertices, never by handle: swaps
// reuse and free cells, and vertices are never removed, so an entry is
// re-found (`is_cell`) when it reaches the top and dropped if its cell is gone.

#ifndef CGAL_EDGE_SWAPPING_3_REFINEMENT_H
#define CGAL_EDGE_SWAPPING_3_REFINEMENT_H

#include <CGAL/Real_timer.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/point_insertion.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <cmath>
#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// One round of refinement: for aspect ratio, one pass over the cells that
/// were above the target at its start (the paper's "cycle over all cells");
/// for gradients, one batch of sites.
struct Refinement_round
{
  std::size_t round = 0;            ///< 0 for the mesh before refinement
  std::size_t sites_inserted = 0;   ///< in this round
  std::size_t vertices = 0;         ///< in the mesh after the round
  double worst_refinable = 0;       ///< aspect ratio: worst over refinable cells after the round
  double worst = 0;                 ///< aspect ratio: worst over all cells of the domain after the round
};

/// What a refinement (`refine_by_aspect_ratio()`, `refine_by_gradient()`) did.
struct Refinement_report
{
  std::vector<Refinement_round> rounds; ///< rounds[0] is the mesh before refinement
  std::size_t sites_inserted = 0;       ///< new vertices
  std::size_t sites_refused = 0;        ///< circumcenters outside the domain, on a constraint or encroaching upon one
  std::array<std::size_t, number_of_flip_kinds> swaps{}; ///< the swaps after the insertions, by kind
  bool target_met = false;              ///< aspect ratio only
  double seconds = 0;                   ///< the time of the run
};

/// Where a new site fell: the cell that contained it and the site's
/// barycentric coordinates in it, for interpolating vertex values.
template <class Tr>
struct Site_location
{
  std::array<typename Tr::Vertex_handle, 4> vertices; ///< the vertices of the cell the site fell in
  std::array<double, 4> weights;                      ///< the site's barycentric coordinates in it
};

/// Where `p` falls in the finite cell `c`: its vertices and the barycentric
/// coordinates of `p` in it (computed in double precision from volumes; a
/// flat cell gives a quarter each), for interpolating vertex values.
template <class Tr>
Site_location<Tr> site_location(const Tr& tr, typename Tr::Cell_handle c, const typename Tr::Point& p)
{
  CGAL_precondition(!tr.is_infinite(c));
  auto volume = tr.geom_traits().compute_volume_3_object();
  Site_location<Tr> where{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}, {}};
  double total = 0;
  for(int k = 0; k < 4; ++k)
  {
    std::array<const typename Tr::Geom_traits::Point_3*, 4> q;
    for(int m = 0; m < 4; ++m)
      q[m] = (m == k) ? &internal::bare_point(p) : &internal::bare_point(c->vertex(m)->point());
    where.weights[k] = CGAL::to_double(volume(*q[0], *q[1], *q[2], *q[3]));
    total += where.weights[k];
  }
  for(auto& x : where.weights) x = (total != 0) ? x / total : 0.25;
  return where;
}

/// The paper's cell-wise gradient indicator: the largest difference of the
/// vertex values along the six edges, times the cube root of the volume.
template <class Tr, class Value>
double gradient_indicator(const Tr& tr, typename Tr::Cell_handle c, const Value& value)
{
  double largest = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      largest = (std::max)(largest, std::abs(value(c->vertex(i)) - value(c->vertex(j))));
  const double volume = std::abs(CGAL::to_double(tr.geom_traits().compute_volume_3_object()(
      internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()), internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point()))));
  return largest * std::cbrt(volume);
}

namespace internal {

/// The settings of a refinement, from its named parameters.
template <class Tr>
struct Refinement_settings
{
  std::function<void(typename Tr::Vertex_handle, const Site_location<Tr>&)> new_vertex;
  std::function<void(const Refinement_round&)> round_visitor;
  std::size_t max_rounds = 1000;
  Perturbation perturbation = CGAL_PERTURBATION;
};

template <class Tr, class NamedParameters>
Refinement_settings<Tr> refinement_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Refinement_settings<Tr> s;
  s.new_vertex = choose_parameter(get_parameter(np, internal_np::new_vertex_visitor), s.new_vertex);
  s.round_visitor = choose_parameter(get_parameter(np, internal_np::round_visitor), s.round_visitor);
  s.max_rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), s.max_rounds);
  s.perturbation = choose_parameter(get_parameter(np, internal_np::perturbation), s.perturbation);
  return s;
}

template <class Tr>
struct Heap_entry
{
  double priority;
  std::array<typename Tr::Vertex_handle, 4> v;
  bool operator<(const Heap_entry& o) const { return priority < o.priority; }
};

template <class Tr>
Heap_entry<Tr> heap_entry(typename Tr::Cell_handle c, double priority)
{
  return {priority, {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
}

template <class Tr>
bool find_cell(const Tr& tr, const Heap_entry<Tr>& e, typename Tr::Cell_handle& c)
{
  int i, j, k, l;
  return tr.is_cell(e.v[0], e.v[1], e.v[2], e.v[3], c, i, j, k, l);
}

// Whether the site p, in cell `at`, encroaches upon a constrained facet: lies
// strictly inside the facet's diametral ball (Shewchuk). The facets looked at
// bound the cells whose circumsphere holds p, found from `at` without
// crossing a constraint: the facets the site would see. A Delaunay refiner
// would split such a facet; here the boundary must stay as it is, so the site
// is refused instead, which keeps sites away from constraints and the
// refinement from cascading into ever smaller cells along them.
template <class Tr, class Constraints>
bool encroaches_constrained_facet(const Tr& tr, typename Tr::Cell_handle at, const typename Tr::Point& p,
                                  const Constraints& constraints)
{
  if constexpr(std::is_same<Constraints, No_constraints>::value)
    return false;
  else
  {
    typedef typename Tr::Cell_handle Cell_handle;
    auto diametral_side = tr.geom_traits().side_of_bounded_sphere_3_object();
    std::vector<Cell_handle> cavity{at};
    for(std::size_t k = 0; k < cavity.size(); ++k)
    {
      const Cell_handle d = cavity[k];
      for(int i = 0; i < 4; ++i)
      {
        if(constraints.is_facet_constrained(d, i))
        {
          if(diametral_side(bare_point(d->vertex((i + 1) & 3)->point()), bare_point(d->vertex((i + 2) & 3)->point()),
                            bare_point(d->vertex((i + 3) & 3)->point()), bare_point(p)) == ON_BOUNDED_SIDE)
            return true;
          continue;
        }
        const Cell_handle n = d->neighbor(i);
        if(tr.is_infinite(n) || std::find(cavity.begin(), cavity.end(), n) != cavity.end()) continue;
        if(side_of_sphere(tr, n, bare_point(p), false) == ON_BOUNDED_SIDE) cavity.push_back(n);
      }
    }
    return false;
  }
}

// Where the circumcenter of finite cell c falls (the walk starts at c: the
// paper notes the site need not lie in it); true when a site may go there
// (the paper's "refinable" cells: circumcenter in the domain, and, in a
// domain mesh, encroaching upon no constrained facet).
template <class Tr, class Constraints>
bool locate_circumcenter(const Tr& tr, typename Tr::Cell_handle c, const Constraints& constraints,
                         typename Tr::Point& p, typename Tr::Cell_handle& at)
{
  // The site of a regular triangulation's cell is a weighted point of weight 0.
  const auto center = tr.geom_traits().construct_circumcenter_3_object()(
      bare_point(internal::bare_point(c->vertex(0)->point())), bare_point(internal::bare_point(c->vertex(1)->point())), bare_point(internal::bare_point(c->vertex(2)->point())),
      bare_point(internal::bare_point(c->vertex(3)->point())));
  // The circumcenter of a cell too flat for double precision can be far off,
  // or not a number: such a site is refused (a far one lies outside the hull).
  for(int k = 0; k < 3; ++k)
    if(!std::isfinite(CGAL::to_double(center[k]))) return false;
  p = point_at<typename Tr::Point>(center);
  typename Tr::Locate_type lt;
  int li, lj;
  at = tr.locate(p, lt, li, lj, c);
  return lt != Tr::VERTEX && lt != Tr::OUTSIDE_CONVEX_HULL && lt != Tr::OUTSIDE_AFFINE_HULL &&
         split_is_allowed(tr, at, lt, li, lj, constraints) &&
         !encroaches_constrained_facet(tr, at, p, constraints);
}

template <class Tr, class Constraints>
bool is_refinable(const Tr& tr, typename Tr::Cell_handle c, const Constraints& constraints)
{
  typename Tr::Point p;
  typename Tr::Cell_handle at;
  return locate_circumcenter(tr, c, constraints, p, at);
}

// Inserts a site at the circumcenter of finite cell c; returns the new vertex
// or the default handle when the site is refused.
template <class Tr, class Criterion, class Constraints>
typename Tr::Vertex_handle insert_circumcenter(Tr& tr, typename Tr::Cell_handle c, const Criterion& criterion,
                                               const Constraints& constraints,
                                               const Refinement_settings<Tr>& options,
                                               Refinement_report& report)
{
  typename Tr::Point p;
  typename Tr::Cell_handle at;
  if(!locate_circumcenter(tr, c, constraints, p, at))
  {
    ++report.sites_refused;
    return typename Tr::Vertex_handle();
  }
  const Site_location<Tr> where = site_location(tr, at, p);
  const auto r = insert_by_swapping(tr, p, criterion, at, constraints, options.perturbation, 100000);
  CGAL_assertion(r.is_new);
  for(int k = 0; k < number_of_flip_kinds; ++k) report.swaps[k] += r.swaps[k];
  ++report.sites_inserted;
  if(options.new_vertex) options.new_vertex(r.vertex, where);
  return r.vertex;
}

template <class Tr>
double cell_aspect_ratio(typename Tr::Cell_handle c, Aspect_ratio_definition definition)
{
  Aspect_ratio measure;
  measure.definition = definition;
  return measure(internal::bare_point(c->vertex(0)->point()), internal::bare_point(c->vertex(1)->point()), internal::bare_point(c->vertex(2)->point()), internal::bare_point(c->vertex(3)->point()));
}

template <class Tr, class Criterion, class Constraints>
Refinement_report refine_by_aspect_ratio(Tr& tr, double target, Aspect_ratio_definition definition,
                                         std::size_t max_sites, const Refinement_settings<Tr>& options,
                                         const Criterion& criterion, const Constraints& constraints)
{
  typedef typename Tr::Cell_handle Cell_handle;
  CGAL_precondition(tr.dimension() == 3);
  CGAL::Real_timer timer;
  timer.start();
  Refinement_report report;

  // The heap of the next round is filled while measuring the current mesh.
  std::priority_queue<internal::Heap_entry<Tr>> heap;
  auto survey = [&](std::size_t round, std::size_t inserted) {
    Refinement_round r;
    r.round = round;
    r.sites_inserted = inserted;
    r.vertices = tr.number_of_vertices();
    for(Cell_handle c : tr.finite_cell_handles())
    {
      if(!constraints.is_in_domain(tr, c)) continue;
      const double ratio = internal::cell_aspect_ratio<Tr>(c, definition);
      r.worst = (std::max)(r.worst, ratio);
      // The walk to the circumcenter only for a cell that could matter.
      if((ratio <= target && ratio <= r.worst_refinable) || !internal::is_refinable(tr, c, constraints)) continue;
      r.worst_refinable = (std::max)(r.worst_refinable, ratio);
      if(ratio > target) heap.push(internal::heap_entry<Tr>(c, ratio));
    }
    report.rounds.push_back(r);
    if(options.round_visitor) options.round_visitor(r);
  };

  survey(0, 0);
  for(std::size_t round = 1; !heap.empty() && round <= options.max_rounds && report.sites_inserted < max_sites; ++round)
  {
    std::size_t inserted = 0;
    while(!heap.empty() && report.sites_inserted < max_sites)
    {
      const auto top = heap.top();
      heap.pop();
      Cell_handle c;
      if(!internal::find_cell(tr, top, c)) continue; // destroyed by an earlier site of this round
      if(internal::insert_circumcenter(tr, c, criterion, constraints, options, report) != typename Tr::Vertex_handle())
        ++inserted;
    }
    heap = {};
    survey(round, inserted);
    if(inserted == 0) break;
  }
  report.target_met = report.rounds.back().worst_refinable <= target;
  report.seconds = timer.time();
  return report;
}

template <class Tr, class Value, class Criterion, class Constraints>
Refinement_report refine_by_gradient(Tr& tr, const Value& value, std::size_t sites,
                                     const Refinement_settings<Tr>& options, const Criterion& criterion,
                                     const Constraints& constraints)
{
  typedef typename Tr::Cell_handle Cell_handle;
  CGAL_precondition(tr.dimension() == 3);
  CGAL::Real_timer timer;
  timer.start();
  Refinement_report report;
  std::priority_queue<internal::Heap_entry<Tr>> heap;
  for(Cell_handle c : tr.finite_cell_handles())
    if(constraints.is_in_domain(tr, c)) heap.push(internal::heap_entry<Tr>(c, gradient_indicator(tr, c, value)));

  std::vector<Cell_handle> star;
  while(!heap.empty() && report.sites_inserted < sites)
  {
    const auto top = heap.top();
    heap.pop();
    Cell_handle c;
    if(!internal::find_cell(tr, top, c)) continue;
    const auto v = internal::insert_circumcenter(tr, c, criterion, constraints, options, report);
    if(v == typename Tr::Vertex_handle()) continue;
    star.clear();
    tr.incident_cells(v, std::back_inserter(star));
    for(Cell_handle d : star)
      if(!tr.is_infinite(d) && constraints.is_in_domain(tr, d))
        heap.push(internal::heap_entry<Tr>(d, gradient_indicator(tr, d, value)));
  }
  Refinement_round r;
  r.round = 1;
  r.sites_inserted = report.sites_inserted;
  r.vertices = tr.number_of_vertices();
  report.rounds.push_back(r);
  if(options.round_visitor) options.round_visitor(r);
  report.seconds = timer.time();
  return report;
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Incremental mesh generation (paper section 5, Fig. 13): inserts
/// sites at the circumcenters of refinable cells (circumcenter in the domain,
/// not encroaching upon a constrained facet) whose aspect ratio exceeds
/// `target`, worst first, swapping under `criterion`.
///
/// It ends when every refinable cell meets the target, `maximum_sites` sites
/// were inserted, or a round inserts nothing. One round is one pass over the
/// cells above the target at its start; cells made during the round wait for
/// the next.
///
/// \tparam Tr a `CGAL::Triangulation_3`
/// \tparam Criterion a model of `SwapCriterion_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr the triangulation, of dimension 3
/// \param target the aspect ratio every refinable cell should meet
/// \param criterion decides the swaps after each insertion
/// \param np an optional sequence of named parameters among the ones listed below
/// \pre `tr.dimension() == 3`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{aspect_ratio_definition}
///     \cgalParamDescription{the measure}
///     \cgalParamType{`Edge_swapping_3::Aspect_ratio_definition`}
///     \cgalParamDefault{`Edge_swapping_3::EDGE_LENGTH_RATIO`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_sites}
///     \cgalParamDescription{the most sites inserted}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most rounds}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{new_vertex_visitor}
///     \cgalParamDescription{called for each new vertex, before the next site is chosen: set its data there}
///     \cgalParamType{a callable `void(Tr::Vertex_handle, const Edge_swapping_3::Site_location<Tr>&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{round_visitor}
///     \cgalParamDescription{called after each round}
///     \cgalParamType{a callable `void(const Edge_swapping_3::Refinement_round&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{perturbation}
///     \cgalParamDescription{how a Delaunay criterion breaks cospherical ties}
///     \cgalParamType{`Edge_swapping_3::Perturbation`}
///     \cgalParamDefault{`Edge_swapping_3::CGAL_PERTURBATION`}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_is_constrained_map, cell_is_selected_map, mesh_constraints}
///     \cgalParamDescription{the domain, as for `swap_edges()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the rounds, the sites inserted and refused, the swaps, whether the target was met
template <class Tr, class Criterion, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_report refine_by_aspect_ratio(Tr& tr, double target, const Criterion& criterion,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Aspect_ratio_definition definition =
    choose_parameter(get_parameter(np, internal_np::aspect_ratio_definition), EDGE_LENGTH_RATIO);
  const std::size_t max_sites = choose_parameter(get_parameter(np, internal_np::maximum_sites),
                                                 (std::numeric_limits<std::size_t>::max)());
  const auto settings = internal::refinement_settings<Tr>(np);
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    return internal::refine_by_aspect_ratio(tr, target, definition, max_sites, settings, criterion, constraints);
  });
}

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Adaptive refinement (paper section 5, Fig. 12): inserts
/// `number_of_sites` sites, each at the circumcenter of the refinable cell of
/// largest `gradient_indicator()` for `value`, swapping under `criterion`.
///
/// After each insertion the cells around the new vertex enter the heap. The
/// `new_vertex_visitor` must give the new vertex its value (interpolated from
/// the `Site_location`, or from a user function). One call is one round.
///
/// \tparam Tr a `CGAL::Triangulation_3`
/// \tparam Value a callable `double(Tr::Vertex_handle)`
/// \tparam Criterion a model of `SwapCriterion_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr the triangulation, of dimension 3
/// \param value the solution at a vertex
/// \param number_of_sites the sites to insert
/// \param criterion decides the swaps after each insertion
/// \param np the named parameters of `refine_by_aspect_ratio()` but
///   `aspect_ratio_definition`, `maximum_sites` and `number_of_iterations`
/// \pre `tr.dimension() == 3`
/// \return the round, the sites inserted and refused, the swaps
template <class Tr, class Value, class Criterion, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_report refine_by_gradient(Tr& tr, const Value& value, std::size_t number_of_sites, const Criterion& criterion,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto settings = internal::refinement_settings<Tr>(np);
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    return internal::refine_by_gradient(tr, value, number_of_sites, settings, criterion, constraints);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_REFINEMENT_H
