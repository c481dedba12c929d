// SPDX-License-Identifier: GPL-3.0-or-later
// Vertex removal for quality, by edge contraction: an interior vertex v goes,
// and each cell around it that does not hold the edge vw takes the
// neighbour w in its place; the cells that hold vw vanish. Every neighbour
// is tried, and the one whose worst new cell is best is taken if it beats
// the worst cell around v.
//
// The new cells fill the star of v exactly once when they are all positively
// oriented (exact predicate): the boundary of the star, a sphere, winds
// once around each point inside it, and the cells joining w to the triangles
// of that sphere which do not hold w count each point once each, with their
// signs. The link condition (no vertex of the star is a neighbour of w
// outside it unless the two are joined in the star) keeps the triangulation
// free of repeated edges.

#ifndef CGAL_EDGE_SWAPPING_3_VERTEX_REMOVAL_H
#define CGAL_EDGE_SWAPPING_3_VERTEX_REMOVAL_H

#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/vertex_smoothing.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <algorithm>
#include <array>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What `remove_vertex` did.
enum Vertex_removal_outcome
{
  VERTEX_REMOVED,                ///< the vertex went; the worst new cell is better than the worst around it
  VERTEX_NOT_REMOVABLE,          ///< on the hull, on a constrained facet, between subdomains or outside the domain: kept
  NO_VERTEX_REMOVAL_IMPROVEMENT  ///< no contraction valid and better beyond the tolerance
};

/// The report of `remove_vertex`.
struct Vertex_removal_report
{
  Vertex_removal_outcome outcome = NO_VERTEX_REMOVAL_IMPROVEMENT; ///< removed, or why not
  int star_size = 0;         ///< the cells around the vertex
  int new_cells = 0;         ///< the cells made
  double quality_before = 0; ///< the worst measure around the vertex
  double quality_after = 0;  ///< the worst measure of the new cells (equal to before when not removed)

  /// Whether the vertex went.
  bool removed() const { return outcome == VERTEX_REMOVED; }
};

namespace internal {

/// `remove_vertex` with its settings spelled out; the new cells are appended
/// to `created`.
template <class Context>
Vertex_removal_report remove_vertex(const Context& op, typename Context::Triangulation::Vertex_handle v)
{
  typedef typename Context::Triangulation Tr;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  Tr& tr = op.tr;
  const auto& criterion = op.criterion;
  const auto& constraints = op.constraints;
  auto& visitor = op.visitor;
  std::vector<typename Tr::Cell_handle>& created = op.created;
  typedef typename Tr::Geom_traits::Point_3 Point;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  CGAL_precondition(tr.dimension() == 3 && !tr.is_infinite(v));
  Vertex_removal_report report;
  std::vector<Cell_handle> star;
  tr.incident_cells(v, std::back_inserter(star));
  report.star_size = int(star.size());
  if(!is_smoothable(tr, star, v, constraints))
  {
    report.outcome = VERTEX_NOT_REMOVABLE;
    return report;
  }
  auto at = [&](Vertex_handle u) -> decltype(auto) { return internal::bare_point(u->point()); };
  auto to_score = [](double m) { return larger_is_worse ? -m : m; };
  double before = HUGE_VAL;
  for(Cell_handle c : star)
    before = (std::min)(before, to_score(criterion.measure(at(c->vertex(0)), at(c->vertex(1)), at(c->vertex(2)),
                                                           at(c->vertex(3)))));
  report.quality_before = report.quality_after = to_score(before);
  const double tolerance = criterion.relative_tolerance;
  const double needed = larger_is_worse ? before * (1 - tolerance) : before * (1 + tolerance);
  const auto orientation = tr.geom_traits().orientation_3_object();

  // The neighbours, in the order met (no address decides).
  std::vector<Vertex_handle> neighbours;
  for(Cell_handle c : star)
    for(int i = 0; i < 4; ++i)
      if(c->vertex(i) != v && std::find(neighbours.begin(), neighbours.end(), c->vertex(i)) == neighbours.end())
        neighbours.push_back(c->vertex(i));

  // The worst new cell when v goes to w; -inf when one is not positive, or
  // as soon as one is no better than `needed`.
  auto contracted = [&](Vertex_handle w) {
    double worst = HUGE_VAL;
    for(Cell_handle c : star)
    {
      if(c->has_vertex(w)) continue;
      std::array<Point, 4> q;
      for(int i = 0; i < 4; ++i) q[i] = c->vertex(i) == v ? Point(at(w)) : Point(at(c->vertex(i)));
      if(orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return -HUGE_VAL;
      const double s = to_score(criterion.measure(q[0], q[1], q[2], q[3]));
      if(!(s > needed)) return -HUGE_VAL;
      worst = (std::min)(worst, s);
    }
    return worst;
  };
  // The link condition: a vertex of the star that no cell holding vw holds
  // must not already be a neighbour of w, nor an edge ab of the star (a cell
  // vab.. holds it) that no cell vwab holds already make a triangle with w.
  std::vector<Vertex_handle> around_w, joined;
  auto link_holds = [&](Vertex_handle w) {
    joined.clear();
    for(Cell_handle c : star)
      if(c->has_vertex(w))
        for(int i = 0; i < 4; ++i) joined.push_back(c->vertex(i));
    auto is_joined = [&](Vertex_handle u) { return std::find(joined.begin(), joined.end(), u) != joined.end(); };
    around_w.clear();
    tr.adjacent_vertices(w, std::back_inserter(around_w));
    for(Vertex_handle u : neighbours)
      if(u != w && !is_joined(u) && std::find(around_w.begin(), around_w.end(), u) != around_w.end()) return false;
    for(Cell_handle c : star)
    {
      if(c->has_vertex(w)) continue;
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
        {
          const Vertex_handle a = c->vertex(i), b = c->vertex(j);
          if(a == v || b == v || !is_joined(a) || !is_joined(b)) continue;
          bool in_vw_cell = false;
          for(Cell_handle d : star) in_vw_cell = in_vw_cell || (d->has_vertex(w) && d->has_vertex(a) && d->has_vertex(b));
          Cell_handle f;
          int fi = 0, fj = 0, fk = 0;
          if(!in_vw_cell && tr.is_facet(w, a, b, f, fi, fj, fk)) return false;
        }
    }
    return true;
  };

  double best = -HUGE_VAL;
  Vertex_handle onto;
  for(Vertex_handle w : neighbours)
  {
    if(tr.is_infinite(w)) continue;
    const double s = contracted(w);
    if(s > best && s > needed && link_holds(w))
    {
      best = s;
      onto = w;
    }
  }
  if(onto == Vertex_handle()) return report;

  std::vector<Cell_handle> old_cells;
  std::vector<std::array<Vertex_handle, 4>> cells;
  for(Cell_handle c : star)
  {
    old_cells.push_back(c);
    if(c->has_vertex(onto)) continue;
    std::array<Vertex_handle, 4> t{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    t[std::size_t(c->index(v))] = onto;
    cells.push_back(t);
  }
  tell_removal(visitor, tr, v, onto);
  const std::vector<Cell_handle> made = internal::replace_cells(tr, old_cells, cells, constraints, visitor);
  tr.tds().delete_vertex(v);
  created.insert(created.end(), made.begin(), made.end());
  report.outcome = VERTEX_REMOVED;
  report.new_cells = int(made.size());
  report.quality_after = to_score(best);
  return report;
}

} // namespace internal

/// Removes the finite interior vertex `v` of `tr` by contracting one of its
/// edges, if that makes the worst tetrahedron around `v` better under
/// `criterion` (any `Worst_tetrahedron_criterion`) beyond its relative
/// tolerance. Every neighbour is tried; each new cell is positively oriented
/// (exact predicate) and the link condition holds, so the triangulation stays
/// valid and covers the same domain. Vertices on the hull, on a constrained
/// facet, between subdomains or outside the domain are kept. The visitor's
/// `before_removal`, if it has one, is told before `v` goes.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor` \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Vertex_removal_report remove_vertex(Tr& tr, typename Tr::Vertex_handle v,
                                    const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> created;
    return internal::remove_vertex(internal::make_operation_context(tr, criterion, constraints, visitor, 0, created), v);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_VERTEX_REMOVAL_H
