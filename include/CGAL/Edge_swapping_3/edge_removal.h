// SPDX-License-Identifier: GPL-3.0-or-later
// Edge removal (Shewchuk, "Two discrete optimization algorithms for the
// topological improvement of tetrahedral meshes", 2002): the n tetrahedra
// around an edge ab are replaced by the 2n-4 tetrahedra that join a and b to
// a triangulation of the ring of vertices around the edge. Of the
// triangulations of the ring polygon, the one whose worst tetrahedron is best
// is found by Klincsek's dynamic program (O(n^3)). n = 3 is the 3-2 flip and
// n = 4 the 4-4 flip; edge removal is their generalization. An edge on the
// hull has the infinite vertex in its ring: a triangle of the ring through it
// stands for two hull facets, which must keep the hull convex (they can only
// where the hull is flat around the edge).

#ifndef CGAL_EDGE_SWAPPING_3_EDGE_REMOVAL_H
#define CGAL_EDGE_SWAPPING_3_EDGE_REMOVAL_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/failed_attempts.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <boost/container/small_vector.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What `remove_edge` did.
enum Edge_removal_outcome
{
  EDGE_REMOVED,           ///< the edge is gone: 2n-4 tetrahedra replace its n
  RING_TOO_LARGE,         ///< more tetrahedra around the edge than `maximum_ring_size`
  EDGE_CONSTRAINED,       ///< a facet around the edge is constrained, or two subdomains meet there
  NO_VALID_TRIANGULATION, ///< no triangulation of the ring gives positive tetrahedra only
  NO_IMPROVEMENT          ///< the best triangulation of the ring is not better than the tetrahedra there
};

/// The name of `o`, for reports.
inline const char* edge_removal_outcome_name(Edge_removal_outcome o)
{
  static const char* names[] = {"removed", "ring too large", "constrained", "no valid triangulation", "no improvement"};
  return names[o];
}

/// The report of `remove_edge`.
struct Edge_removal_report
{
  Edge_removal_outcome outcome = NO_VALID_TRIANGULATION; ///< removed, or why not
  int ring_size = 0;            ///< n: the cells around the edge (infinite ones included)
  bool on_hull = false;         ///< whether the edge is on the hull (two of those cells are infinite)
  double quality_before = 0;    ///< the worst value of the measure over the finite ones
  double quality_after = 0;     ///< the worst over the best triangulation's finite cells (when one is valid)
  int new_cells = 0;            ///< 2n-4 (infinite ones included) when removed, else 0
  int steps = 0;                ///< 1 when removed, 2 when removed in two steps (`remove_edge_in_two_steps`)

  /// Whether the edge was removed.
  bool removed() const { return outcome == EDGE_REMOVED; }
};

namespace internal {

/// The storage of stars and ring triangulations: on the stack up to a ring
/// of 16 (the default ring limit is 10), so that the many attempts that
/// fail allocate nothing.
template <class T, std::size_t n = 16>
using Star_vector = boost::container::small_vector<T, n>;

/// The cells around edge (a, b) and the ring of vertices s_0 ... s_{n-1}
/// around it, turning so that cell k is (a, b, s_k, s_{k+1}) with
/// orientation(a, b, s_k, s_{k+1}) NEGATIVE (decided from the cells' own
/// vertex order, which is positive, not from coordinates). On the hull, the
/// ring is rotated so that the infinite vertex is last.
template <class Tr>
struct Edge_star
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;

  Vertex_handle a, b;
  Star_vector<Cell_handle> cells;
  Star_vector<Vertex_handle> ring;
  bool on_hull = false;

  /// A star to be filled by hand (a ring that the mesh does not hold yet).
  Edge_star() = default;

  Edge_star(const Tr& tr, const typename Tr::Edge& e, int maximum)
    : a(e.first->vertex(e.second)), b(e.first->vertex(e.third))
  {
    // Around the edge through the cells' neighbours: cell k holds s_k and
    // s_{k+1}, and the next cell lies across s_k, where the vertex off the
    // facet they share is s_{k+2} (two index lookups a cell).
    const Cell_handle start = e.first;
    int behind = 0;
    while(behind == e.second || behind == e.third) ++behind;
    Vertex_handle ahead = start->vertex(6 - e.second - e.third - behind);
    ring.push_back(start->vertex(behind));
    cells.push_back(start);
    on_hull = tr.is_infinite(a) || tr.is_infinite(b) || tr.is_infinite(ring.back()) || tr.is_infinite(ahead);
    for(Cell_handle cur = start, next = start->neighbor(behind); next != start;
        next = cur->neighbor(cur->index(ring.back())))
    {
      if(int(cells.size()) > maximum) break;
      ring.push_back(ahead);
      cells.push_back(next);
      ahead = next->vertex(next->index(cur));
      on_hull = on_hull || tr.is_infinite(ahead);
      cur = next;
    }
    if(int(cells.size()) > maximum)
    {
      ring.clear(); // too many cells: no ring
      return;
    }
    const std::size_t n = cells.size();
    if(permutation_sign<Tr>(cells[0], {a, b, ring[0], ring[1 % n]}) > 0)
    {
      // Turn the other way: cell k must hold s_k and s_{k+1}.
      std::reverse(ring.begin(), ring.end());
      std::reverse(cells.begin(), cells.end());
      std::rotate(ring.rbegin(), ring.rbegin() + 1, ring.rend());
    }
    // The infinite vertex last: s_{n-1} = infinite, cell n-1 is (a, b, inf,
    // s_0). Inside, the smallest point first (lexicographically): the ring
    // then does not depend on the cell the edge was given by, nor do the
    // removals planned on it (equally good triangulations are told apart by
    // their order in the ring), so a failure remembered holds for the edge.
    std::size_t first = 0;
    for(std::size_t k = 0; k < n; ++k)
      if(tr.is_infinite(ring[k]))
      {
        first = (k + 1) % n;
        break;
      }
      else if(tr.geom_traits().compare_xyz_3_object()(bare_point(ring[k]->point()), bare_point(ring[first]->point())) ==
              SMALLER)
        first = k;
    std::rotate(ring.begin(), ring.begin() + first, ring.end());
    std::rotate(cells.begin(), cells.begin() + first, cells.end());
  }

  /// A hash of the ring's edges (s_k, s_{k+1}), which fix the cells around
  /// the edge, and of the positions: equal for the same star at the same
  /// place, whatever cell the ring starts at.
  std::uint64_t signature(const Tr& tr) const
  {
    std::uint64_t h = mix_bits(vertex_signature(tr, a) ^ (vertex_signature(tr, b) << 1));
    for(std::size_t k = 0; k < ring.size(); ++k)
    {
      std::uint64_t u = vertex_signature(tr, ring[k]), v = vertex_signature(tr, ring[(k + 1) % ring.size()]);
      if(v < u) std::swap(u, v);
      h += mix_bits(u ^ mix_bits(v));
    }
    return h;
  }
};

/// Klincsek's dynamic program over the triangulations of the ring polygon
/// s_0 ... s_{n-1}: the triangulation whose worst tetrahedron (the two
/// joining each triangle to a and to b) scores highest, among those whose
/// every tetrahedron is positively oriented (exact predicate). A cell with
/// the infinite vertex is valid when no vertex of the star lies strictly
/// beyond its hull facet (`planned_cell_orientation`), and has no score.
/// With a `floor`, only the triangulations whose every scored tetrahedron
/// scores above it are considered (fewer tetrahedra measured and oriented).
template <class Tr, class Score>
class Ring_triangulation
{
public:
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 4> Tuple;
  typedef Star_vector<Tuple, 32> Tuples;

  Ring_triangulation(const Tr& tr, const Edge_star<Tr>& star, const Score& score, double floor = -HUGE_VAL)
    : n_(int(star.ring.size())), best_(n_ * n_, -HUGE_VAL), split_(n_ * n_, -1)
  {
    const auto& s = star.ring;
    Star_vector<Vertex_handle, 18> others(s.begin(), s.end());
    others.push_back(star.a);
    others.push_back(star.b);
    auto valued = [&](const Tuple& t) {
      for(const auto& v : t)
        if(tr.is_infinite(v)) return HUGE_VAL;
      return double(score(t));
    };
    // The two tetrahedra of triangle (i, k, j), i < k < j, positively
    // oriented as tuples; -inf when either is not positive or does not
    // score above `bound` (the floor, or what the polygon has already: no
    // worse triangle changes the result, so the second tetrahedron and the
    // orientations are left unmeasured).
    auto triangle_score = [&](int i, int k, int j, double bound) {
      const Tuple ta = {star.a, s[j], s[k], s[i]}, tb = {star.b, s[i], s[k], s[j]};
      const double first = valued(ta);
      if(!(first > bound)) return -HUGE_VAL;
      const double value = (std::min)(first, valued(tb));
      if(!(value > bound)) return -HUGE_VAL;
      for(const Tuple& t : {ta, tb})
        if(planned_cell_orientation(tr, t, others.data(), int(others.size())) != POSITIVE) return -HUGE_VAL;
      return value;
    };
    for(int i = 0; i + 1 < n_; ++i) best_[i * n_ + i + 1] = HUGE_VAL; // an edge of the polygon
    for(int gap = 2; gap < n_; ++gap)
      for(int i = 0; i + gap < n_; ++i)
      {
        const int j = i + gap;
        for(int k = i + 1; k < j; ++k)
        {
          const double sides = (std::min)(best_[i * n_ + k], best_[k * n_ + j]);
          if(!(sides > floor) || !(sides > best_[i * n_ + j])) continue;
          const double value = (std::min)(sides, triangle_score(i, k, j, (std::max)(floor, best_[i * n_ + j])));
          if(value > -HUGE_VAL && value > best_[i * n_ + j])
          {
            best_[i * n_ + j] = value;
            split_[i * n_ + j] = k;
          }
        }
      }
    if(n_ >= 3 && split_[n_ - 1] >= 0) collect(star, 0, n_ - 1);
  }

  bool exists() const { return !cells_.empty(); }
  /// The worst score of the best triangulation (+inf: no finite cell).
  double score() const { return best_[n_ - 1]; }
  /// Its 2n-4 tetrahedra, positively oriented.
  const Tuples& cells() const { return cells_; }

private:
  void collect(const Edge_star<Tr>& star, int i, int j)
  {
    if(j - i < 2) return;
    const int k = split_[i * n_ + j];
    const auto& s = star.ring;
    cells_.push_back({star.a, s[j], s[k], s[i]});
    cells_.push_back({star.b, s[i], s[k], s[j]});
    collect(star, i, k);
    collect(star, k, j);
  }

  int n_;
  Star_vector<double, 256> best_; // n * n, indexed i * n + j
  Star_vector<int, 256> split_;
  Tuples cells_;
};


/// Whether a facet around the star's edge is constrained or two subdomains
/// meet there: then the edge stays.
template <class Tr, class Constraints>
bool star_is_constrained(const Tr& tr, const Edge_star<Tr>& star, const Constraints& constraints)
{
  const std::size_t n = star.cells.size();
  for(std::size_t k = 0; k < n; ++k)
  {
    const auto c = star.cells[k];
    // The facet (a, b, s_{k+1}) lies between cells k and k+1 (cell 0 is finite).
    const int f = c->index(star.ring[k]);
    if((!tr.is_infinite(c) && !constraints.same_subdomain(c, star.cells.front())) ||
       (!tr.is_infinite(star.ring[(k + 1) % n]) &&
        (constraints.is_facet_constrained(c, f) || constraints.is_facet_constrained(c->neighbor(f), c->neighbor(f)->index(c)))))
      return true;
  }
  return false;
}

/// `remove_edge` on a star already gathered. The best triangulation of the
/// ring must beat `required` (a value of the measure) beyond the
/// tolerance; by default, the worst of the cells it replaces.
template <class Context>
Edge_removal_report remove_edge_star(const Context& op, const Edge_star<typename Context::Triangulation>& star,
                                     bool better_only = false)
{
  typedef typename Context::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  Tr& tr = op.tr;
  const auto& criterion = op.criterion;
  typedef std::array<Vertex_handle, 4> Tuple;
  CGAL_precondition(tr.dimension() == 3);

  Edge_removal_report report;
  report.ring_size = int(star.cells.size());
  report.on_hull = star.on_hull;
  if(star_is_constrained(tr, star, op.constraints))
  {
    report.outcome = EDGE_CONSTRAINED;
    return report;
  }

  // Scores: larger is better.
  auto value = [&](const Tuple& t) { return criterion.measure(internal::bare_point(t[0]->point()), internal::bare_point(t[1]->point()), internal::bare_point(t[2]->point()), internal::bare_point(t[3]->point())); };
  auto score = [&](const Tuple& t) { return larger_is_worse ? -value(t) : value(t); };
  double before = HUGE_VAL;
  for(const auto c : star.cells)
    if(!tr.is_infinite(c)) before = (std::min)(before, score(tuple_of<Tr>(c)));
  report.quality_before = larger_is_worse ? -before : before;

  // With `better_only`, the dynamic program looks only for triangulations
  // that beat the cells around the edge, which prunes most of its work; it
  // finds the same best one when there is one (the best beats the floor, so
  // no triangle of it was left out), and a failure is then NO_IMPROVEMENT
  // with no `quality_after`.
  const double tolerance = criterion.relative_tolerance;
  const double bar = report.quality_before;
  const double floor = !better_only ? -HUGE_VAL : larger_is_worse ? -bar * (1 - tolerance) : bar * (1 + tolerance);
  const Ring_triangulation<Tr, decltype(score)> best(tr, star, score, floor);
  if(!best.exists()) { report.outcome = better_only ? NO_IMPROVEMENT : NO_VALID_TRIANGULATION; return report; }
  report.quality_after = larger_is_worse ? -best.score() : best.score();
  const bool better = larger_is_worse ? report.quality_after < bar * (1 - tolerance)
                                      : report.quality_after > bar * (1 + tolerance);
  if(!better) { report.outcome = NO_IMPROVEMENT; return report; }

  const auto cells = replace_cells(tr, star.cells, best.cells(), op.constraints, op.visitor);
  op.created.insert(op.created.end(), cells.begin(), cells.end());
  report.new_cells = int(cells.size());
  report.steps = 1;
  report.outcome = EDGE_REMOVED;
  return report;
}

/// The edges whose removal failed, with the signature of their star then
/// (a fixed amount of memory: see `Failure_cache`).
template <class Tr>
using Edge_removal_failures = Failure_cache<Edge_key<Tr>, Edge_key_hash, Edge_removal_report>;

/// `remove_edge` in an operation context; the new cells (finite and
/// infinite) are appended to `op.created`.
template <class Context>
Edge_removal_report remove_edge(const Context& op, const typename Context::Triangulation::Edge& e)
{
  typedef typename Context::Triangulation Tr;
  CGAL_precondition(op.tr.dimension() == 3 && !op.tr.is_infinite(e));
  const Edge_star<Tr> star(op.tr, e, op.maximum_ring);
  if(int(star.cells.size()) <= op.maximum_ring) return remove_edge_star(op, star);
  Edge_removal_report report;
  report.ring_size = int(star.cells.size());
  report.on_hull = star.on_hull;
  report.outcome = RING_TOO_LARGE;
  return report;
}

/// `remove_edge`, its failures remembered in `failures` under `signature`,
/// which the caller makes so that it changes whenever a cell through both
/// ends of `e` changes (the quality driver's stamps of the two ends): a
/// failure remembered there is returned without a look at the star, and
/// only triangulations that beat the star are looked for
/// (`remove_edge_star`'s `better_only`).
template <class Context>
Edge_removal_report remove_edge(const Context& op, const typename Context::Triangulation::Edge& e,
                                Edge_removal_failures<typename Context::Triangulation>& failures,
                                std::uint64_t signature)
{
  typedef typename Context::Triangulation Tr;
  CGAL_precondition(op.tr.dimension() == 3 && !op.tr.is_infinite(e));
  const Edge_key<Tr> key = edge_key<Tr>(e.first->vertex(e.second), e.first->vertex(e.third));
  if(const Edge_removal_report* known = failures.find(key, signature)) return *known;
  const Edge_star<Tr> star(op.tr, e, op.maximum_ring);
  Edge_removal_report report;
  report.ring_size = int(star.cells.size());
  report.on_hull = star.on_hull;
  if(report.ring_size > op.maximum_ring) report.outcome = RING_TOO_LARGE;
  else report = remove_edge_star(op, star, true);
  failures.record(key, signature, report, report.removed());
  return report;
}

} // namespace internal

/// Removes the finite edge `e` of `tr` when a triangulation of its ring
/// makes the worst tetrahedron there better under `criterion` (MinMax or
/// MaxMin dihedral angle, an aspect ratio, or any
/// `Worst_tetrahedron_criterion`): the n cells around the edge are
/// replaced by the 2n-4 of the best triangulation of the ring (Klincsek's
/// dynamic program), each new tetrahedron positively oriented by the exact
/// predicate. On the hull, the ring holds the infinite vertex, and the new
/// hull facets must keep the hull convex: possible only where the hull is
/// flat around the edge. The improvement must exceed the criterion's
/// relative tolerance, as for a flip. Cell handles around the edge are
/// invalidated.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints`:
///     an edge with a constrained facet around it, or between two subdomains, is kept \cgalParamNEnd
///   \cgalParamNBegin{maximum_ring_size} the largest ring considered, default 10 \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor` \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Edge_removal_report remove_edge(Tr& tr, const typename Tr::Edge& e,
                                const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int maximum = choose_parameter(get_parameter(np, internal_np::maximum_ring_size), 10);
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> created;
    return internal::remove_edge(internal::make_operation_context(tr, criterion, constraints, visitor, maximum, created), e);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_EDGE_REMOVAL_H
