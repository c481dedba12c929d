// SPDX-License-Identifier: GPL-3.0-or-later
// Optimization-based smoothing of one interior vertex: the vertex moves to
// where the worst tetrahedron around it is better, the cells and their
// connections unchanged. The objective, the worst value of the criterion's
// measure over the vertex's star, is not smooth (a minimum of smooth
// functions), so each step goes along the steepest ascent direction of the
// cells that are nearly worst, the point of least norm in the convex hull of
// their gradients (as in Freitag and Ollivier-Gooch's smoothing), with a
// backtracking line search. The smart Laplacian (centroid of the neighbours)
// is tried first. Every position taken keeps every cell of the star
// positively oriented, by the exact predicate. A move must improve the
// worst value by a relative gain of at least `smoothing_gain` (1%): the
// measures are computed in double precision, and the quality driver would
// otherwise go on polishing every vertex as its neighbours move (measured
// with MaxMin dihedral sine on the two-spheres mesh: 218,521 moves and 280 s
// to converge with a gain of 0.1%, 24,732 moves and 22 s with 1%; smallest
// dihedral angle 23.21 and 22.83 degrees). A climb that has not gained that
// much by its first ascent step ends there: such climbs creep (on the
// Delaunay triangulation of 3,000 random points under the dihedral sine,
// 48,519 of 67,214 ended without a move), and ending them took 28% to 60%
// off the quality driver's time with smoothing, with fewer bad cells on
// random points (doc/Edge_swapping_3/benchmarks.md, "Smoothing's first step").

#ifndef CGAL_EDGE_SWAPPING_3_VERTEX_SMOOTHING_H
#define CGAL_EDGE_SWAPPING_3_VERTEX_SMOOTHING_H

#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/internal/boundary_motion.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What `smooth_vertex` did.
enum Smoothing_outcome
{
  VERTEX_MOVED,            ///< the vertex moved; the worst tetrahedron around it is better
  VERTEX_ON_BOUNDARY,      ///< on the hull, on a constrained facet, between subdomains or outside the domain: kept
  NO_SMOOTHING_IMPROVEMENT ///< no position found beats the present one beyond the tolerance
};

/// The name of `o`, for reports.
inline const char* smoothing_outcome_name(Smoothing_outcome o)
{
  static const char* const names[] = {"moved", "on boundary", "no improvement"};
  return names[o];
}

/// The report of `smooth_vertex`.
struct Smoothing_report
{
  Smoothing_outcome outcome = NO_SMOOTHING_IMPROVEMENT; ///< moved, or why not
  int star_size = 0;          ///< the cells around the vertex
  double quality_before = 0;  ///< the worst value of the measure over them
  double quality_after = 0;   ///< the same at the new position (equal to before when not moved)
  int steps = 0;              ///< positions taken (the smart Laplacian counts as one)

  /// Whether the vertex moved.
  bool moved() const { return outcome == VERTEX_MOVED; }
};

namespace internal {

/// The least relative improvement of the worst value for which a vertex moves.
constexpr double smoothing_gain = 1e-2;

/// The ascent steps after the smart Laplacian, unless told otherwise.
constexpr int default_smoothing_steps = 20;

/// The star of a vertex, with the objective at a trial position.
template <class Tr, class Measure, bool larger_is_worse>
class Vertex_star
{
public:
  typedef typename Tr::Geom_traits::Point_3 Point; // bare: a regular triangulation's points are weighted
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;

  Vertex_star(const Tr& tr, Vertex_handle v, const Measure& measure) : tr_(tr), measure_(measure)
  {
    tr.incident_cells(v, std::back_inserter(cells_));
    corners_.reserve(cells_.size());
    for(Cell_handle c : cells_)
    {
      std::array<Point, 4> p;
      int index = 0;
      for(int i = 0; i < 4; ++i)
      {
        if(c->vertex(i) == v) index = i;
        else if(!tr.is_infinite(c->vertex(i))) p[i] = internal::bare_point(c->vertex(i)->point());
      }
      corners_.push_back({p, index, tr.is_infinite(c) ? SKIPPED : MEASURED});
    }
  }

  /// Cells outside the domain are kept positively oriented but not measured.
  template <class Constraints>
  void measure_only_in_domain(const Constraints& constraints)
  {
    for(std::size_t k = 0; k < cells_.size(); ++k)
      if(corners_[k].role == MEASURED && !constraints.is_in_domain(tr_, cells_[k])) corners_[k].role = ORIENTED;
  }

  const std::vector<Cell_handle>& cells() const { return cells_; }

  /// Whether cell k is measured (in the domain, finite).
  bool is_measured(std::size_t k) const { return corners_[k].role == MEASURED; }

  /// The score (larger is better) of cell k with the vertex at `p`; -inf
  /// unless the cell is positively oriented (exact predicate); +inf for a
  /// cell that is not measured.
  double score(std::size_t k, const Point& p) const
  {
    // An infinite cell stays valid while the vertex stays on its hull facet's plane.
    if(corners_[k].role == SKIPPED) return HUGE_VAL;
    std::array<Point, 4> q = corners_[k].points;
    q[corners_[k].index] = p;
    if(tr_.geom_traits().orientation_3_object()(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return -HUGE_VAL;
    if(corners_[k].role == ORIENTED) return HUGE_VAL;
    const double m = measure_(q[0], q[1], q[2], q[3]);
    return larger_is_worse ? -m : m;
  }

  /// The worst score over the star with the vertex at `p` (-inf: some cell
  /// inverted), or a score at most `floor` as soon as one is found. The
  /// cells are scored worst first (as they scored at the last position that
  /// `keep_scores` kept), so a position that fails usually fails at once; when
  /// every cell is scored, their scores are left for `keep_scores`.
  double worst(const Point& p, double floor = -HUGE_VAL)
  {
    double w = HUGE_VAL;
    for(std::size_t j = 0; j < order_.size() && w > floor; ++j)
    {
      const std::size_t k = order_[j];
      trial_[k] = score(k, p);
      w = (std::min)(w, trial_[k]);
    }
    return w;
  }

  /// The worst score over the star with the vertex at `p`, every cell scored.
  double score_all(const Point& p)
  {
    double w = HUGE_VAL;
    trial_.resize(corners_.size());
    for(std::size_t k = 0; k < corners_.size(); ++k) w = (std::min)(w, trial_[k] = score(k, p));
    return w;
  }

  /// Keeps the scores of the last call of `worst` that scored every cell, as
  /// those of the present position, and orders the cells by them.
  void keep_scores()
  {
    scores_ = trial_;
    if(order_.size() != scores_.size())
    {
      order_.resize(scores_.size());
      for(std::size_t k = 0; k < order_.size(); ++k) order_[k] = k;
    }
    // A NaN (a measure that failed) counts as worst.
    std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
      return scores_[a] < scores_[b] || (std::isnan(scores_[a]) && !std::isnan(scores_[b]));
    });
  }

  /// The score of cell k at the present position (`keep_scores`).
  double kept_score(std::size_t k) const { return scores_[k]; }

private:
  enum Role { MEASURED, ORIENTED, SKIPPED };
  struct Corners
  {
    std::array<Point, 4> points;
    int index; // of the vertex that moves
    Role role;
  };
  const Tr& tr_;
  const Measure& measure_;
  std::vector<Cell_handle> cells_;
  std::vector<Corners> corners_;
  std::vector<std::size_t> order_; // the cells, worst first at the present position
  std::vector<double> trial_, scores_;
};

/// The point of least norm in the convex hull of `g` (Frank and Wolfe's
/// iteration with exact line search; a handful of gradients).
inline Vec least_norm_point(const std::vector<Vec>& g)
{
  Vec x = g[0];
  for(int iteration = 0; iteration < 100; ++iteration)
  {
    std::size_t j = 0;
    for(std::size_t k = 1; k < g.size(); ++k)
      if(dot(x, g[k]) < dot(x, g[j])) j = k;
    const Vec d = sub(g[j], x);
    const double dd = dot(d, d), gap = -dot(x, d);
    if(dd == 0 || gap <= 1e-12 * dot(x, x)) break;
    const double t = (std::min)(1.0, gap / dd);
    x = Vec{x.x + t * d.x, x.y + t * d.y, x.z + t * d.z};
  }
  return x;
}

/// Whether vertex `v` may move: finite, not on the hull, no constrained
/// facet through it, its cells in the domain and in one subdomain.
template <class Tr, class Constraints>
bool is_smoothable(const Tr& tr, const std::vector<typename Tr::Cell_handle>& star,
                   typename Tr::Vertex_handle v, const Constraints& constraints)
{
  for(auto c : star)
  {
    if(tr.is_infinite(c) || !constraints.is_in_domain(tr, c) || !constraints.same_subdomain(c, star.front()))
      return false;
    for(int i = 0; i < 4; ++i)
      if(c->vertex(i) != v && constraints.is_facet_constrained(c, i)) return false;
  }
  return !star.empty();
}

/// `smooth_vertex` in an operation context (its ring limit and new cells
/// are not used: a move makes no cell); the cells around the vertex are
/// appended to `star_cells`.
template <class Context>
Smoothing_report smooth_vertex(const Context& op, typename Context::Triangulation::Vertex_handle v, int maximum_steps,
                               std::vector<typename Context::Triangulation::Cell_handle>& star_cells,
                               bool on_flat_boundary = false)
{
  typedef typename Context::Triangulation Tr;
  typedef typename Context::Measure Measure;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  Tr& tr = op.tr;
  const auto& criterion = op.criterion;
  const auto& constraints = op.constraints;
  auto& visitor = op.visitor;
  typedef typename Tr::Geom_traits::Point_3 Point;
  CGAL_precondition(tr.dimension() == 3 && !tr.is_infinite(v));
  Smoothing_report report;
  Vertex_star<Tr, Measure, larger_is_worse> star(tr, v, criterion.measure);
  report.star_size = int(star.cells().size());
  star_cells.insert(star_cells.end(), star.cells().begin(), star.cells().end());
  // A vertex on the boundary moves, when asked, within a flat boundary patch
  // or along a straight boundary edge.
  Boundary_motion<Point> motion;
  const bool interior = is_smoothable(tr, star.cells(), v, constraints);
  if(!interior && on_flat_boundary) motion = boundary_motion(tr, star.cells(), v, constraints);
  const bool on_boundary = !interior;
  if(on_boundary && motion.kind == Boundary_motion<Point>::FIXED)
  {
    report.outcome = VERTEX_ON_BOUNDARY;
    return report;
  }
  if(on_boundary) star.measure_only_in_domain(constraints);

  auto position = [](const Point& p) { return Vec{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}; };
  auto point = [](const Vec& x) { return Point(x.x, x.y, x.z); };
  auto measure_of = [](double score) { return larger_is_worse ? -score : score; };
  // The score that a position must beat to gain more than `tolerance` over
  // score b, as the criteria decide (the measures are positive).
  auto bar = [&](double b, double tolerance) { return larger_is_worse ? b * (1 - tolerance) : b * (1 + tolerance); };

  const Vec start = position(internal::bare_point(v->point()));
  Vec best = start;
  const double start_score = star.score_all(internal::bare_point(v->point()));
  star.keep_scores();
  double best_score = start_score;
  report.quality_before = measure_of(best_score);

  // The neighbours in the domain: their centroid, and the scale of the steps.
  std::vector<Vec> neighbours;
  for(std::size_t k = 0; k < star.cells().size(); ++k)
    if(star.is_measured(k))
      for(int i = 0; i < 4; ++i)
        if(star.cells()[k]->vertex(i) != v)
          neighbours.push_back(position(internal::bare_point(star.cells()[k]->vertex(i)->point())));
  Vec centroid{0, 0, 0};
  double shortest = HUGE_VAL, total = 0;
  for(const Vec& n : neighbours)
  {
    centroid = Vec{centroid.x + n.x, centroid.y + n.y, centroid.z + n.z};
    const double l = norm(sub(n, start));
    shortest = (std::min)(shortest, l);
    total += l;
  }
  const double count = double(neighbours.size());
  centroid = Vec{centroid.x / count, centroid.y / count, centroid.z / count};
  const double mean = total / count;

  auto try_position = [&](Vec x) {
    if(on_boundary) x = motion.project(x);
    if(!(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z))) return false;
    if(on_boundary && !motion.holds(tr.geom_traits(), point(x))) return false;
    const double needed = bar(best_score, criterion.relative_tolerance);
    const double s = star.worst(point(x), needed);
    if(!(s > needed)) return false;
    star.keep_scores();
    best = x;
    best_score = s;
    ++report.steps;
    return true;
  };
  try_position(centroid);

  // Steepest ascent of the nearly worst cells, with backtracking.
  std::vector<Vec> gradients;
  const double h = 1e-7 * mean;
  for(int step = 0; step < maximum_steps; ++step)
  {
    gradients.clear();
    const double band = 1e-3 * std::abs(best_score);
    for(std::size_t k = 0; k < star.cells().size(); ++k)
    {
      const double base = star.kept_score(k);
      if(base > best_score + band) continue;
      // Forward differences: a step of 1e-7 of the mean edge length.
      Vec g;
      double* component[3] = {&g.x, &g.y, &g.z};
      bool finite = true;
      for(int axis = 0; axis < 3 && finite; ++axis)
      {
        *component[axis] = 0;
        if(on_boundary && motion.kept[axis]) continue; // no move there
        Vec moved = best;
        double* coordinate[3] = {&moved.x, &moved.y, &moved.z};
        *coordinate[axis] += h;
        const double up = star.score(k, point(moved));
        finite = std::isfinite(up);
        *component[axis] = (up - base) / h;
      }
      if(!finite) { gradients.clear(); break; } // a cell too flat to differentiate
      gradients.push_back(on_boundary ? motion.project_direction(g) : g);
    }
    if(gradients.empty()) break;
    const Vec d = least_norm_point(gradients);
    const double length = norm(d);
    if(!(length > 0) || !std::isfinite(length)) break; // stationary: no direction improves them all
    bool moved = false;
    for(double distance = 0.5 * shortest; distance > 1e-4 * shortest && !moved; distance *= 0.5)
    {
      const double t = distance / length;
      moved = try_position(Vec{best.x + t * d.x, best.y + t * d.y, best.z + t * d.z});
    }
    if(!moved) break;
    // A climb that has not gained enough for a move by its first step ends.
    if(!(best_score > bar(start_score, smoothing_gain))) break;
  }

  if(report.steps > 0 && best_score > bar(start_score, smoothing_gain))
  {
    const typename Tr::Point old_point = v->point();
    v->set_point(internal::moved_point(old_point, point(best))); // a weight stays
    visitor_of(visitor).after_move(tr, v, old_point);
    report.outcome = VERTEX_MOVED;
    report.quality_after = measure_of(best_score);
  }
  else
    report.quality_after = report.quality_before;
  return report;
}

} // namespace internal

/// Moves the finite interior vertex `v` of `tr` to where the worst
/// tetrahedron around it is better under `criterion` (any
/// `Worst_tetrahedron_criterion`), by the smart Laplacian and then by
/// steepest ascent of its nearly worst cells. The cells around `v` stay
/// positively oriented (exact predicate), so the triangulation stays valid
/// and covers the same domain; the worst value must improve by a relative
/// gain of at least 1%, and a climb short of that gain after its first ascent
/// step ends there. Vertices on the hull, on a constrained facet, between
/// subdomains or outside the domain are not moved, unless
/// `move_on_flat_boundary` allows it: then a vertex whose boundary facets
/// lie in one plane (with one boundary reference) moves within it, and one on
/// a straight edge of the boundary moves along it, each position exactly on
/// the plane or the line (`internal/boundary_motion.h`), so the boundary keeps
/// its shape. The triangulation's cells are unchanged: only the point of `v`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} the most ascent steps after the smart Laplacian, default 20 \cgalParamNEnd
///   \cgalParamNBegin{move_on_flat_boundary} `bool`, default false: a vertex on a flat patch or a straight edge of
///     the boundary moves within it \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3` (`after_move`), default
///     `Default_replacement_visitor` \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Smoothing_report smooth_vertex(Tr& tr, typename Tr::Vertex_handle v,
                               const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int steps = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                     internal::default_smoothing_steps);
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  const bool on_flat_boundary = choose_parameter(get_parameter(np, internal_np::move_on_flat_boundary), false);
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> star, created;
    return internal::smooth_vertex(internal::make_operation_context(tr, criterion, constraints, visitor, 0, created), v,
                                   steps, star, on_flat_boundary);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_VERTEX_SMOOTHING_H
