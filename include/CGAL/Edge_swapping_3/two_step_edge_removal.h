// SPDX-License-Identifier: GPL-3.0-or-later
// Two-step edge removal: when no triangulation of an edge's ring beats the
// tetrahedra around it, first remove an edge of its star (from one of its
// ends to a ring vertex), which changes the ring, then the edge itself.
// This is what TetGen's edge flip does at its first "link level" (Si, "TetGen,
// a Delaunay-based quality tetrahedral mesh generator", 2015): a sequence
// whose second step no single edge or multi-face removal makes. Both steps
// must make cells better than the worst around the edge, so the worst of the
// region gets better, as for every operation of the quality driver. The
// second step is planned on the ring the first would leave, and nothing
// changes until both are known to succeed.

#ifndef CGAL_EDGE_SWAPPING_3_TWO_STEP_EDGE_REMOVAL_H
#define CGAL_EDGE_SWAPPING_3_TWO_STEP_EDGE_REMOVAL_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/edge_removal.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The ring of (a, b) once the star of an edge (x, s), x = a or b,
/// s = ring[k], is replaced by `new_cells`: s gives way to the
/// vertices that the new cells through a and b join it to. In the order
/// and orientation of `Edge_star`, from the cells' own vertex order; empty
/// when the new cells close no ring. (Written in place: a small vector
/// returned by value draws a false -Wstringop-overread from GCC 12.)
template <class Tr, class New_cells>
void ring_after(const Tr& tr, const Edge_star<Tr>& star, std::size_t k, const New_cells& new_cells,
                Star_vector<typename Tr::Vertex_handle>& ring)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  const std::size_t n = star.ring.size();
  // The next vertex in the ring, as pairs (from, to).
  Star_vector<std::pair<Vertex_handle, Vertex_handle>, 32> next;
  for(std::size_t j = 0; j < n; ++j)
    if(j != k && (j + 1) % n != k) next.emplace_back(star.ring[j], star.ring[(j + 1) % n]);
  for(const auto& t : new_cells)
  {
    int pa = -1, pb = -1, pu = -1, pw = -1;
    for(int m = 0; m < 4; ++m)
      if(t[m] == star.a) pa = m;
      else if(t[m] == star.b) pb = m;
      else if(pu < 0) pu = m;
      else pw = m;
    if(pa < 0 || pb < 0) continue;
    // (a, b, t[pu], t[pw]) is positive when its positions in t make an even
    // permutation; the ring turns the other way.
    const int p[4] = {pa, pb, pu, pw};
    int inversions = 0;
    for(int x = 0; x < 4; ++x)
      for(int y = x + 1; y < 4; ++y) inversions += p[x] > p[y];
    if(inversions % 2 == 0) next.emplace_back(t[pw], t[pu]);
    else next.emplace_back(t[pu], t[pw]);
  }
  ring.clear();
  Vertex_handle v = star.ring[(k + n - 1) % n];
  do
  {
    ring.push_back(v);
    const auto it = std::find_if(next.begin(), next.end(), [&](const auto& e) { return e.first == v; });
    if(it == next.end() || ring.size() > next.size())
    {
      ring.clear();
      return;
    }
    v = it->second;
  } while(v != ring.front());
  if(ring.size() != next.size())
  {
    ring.clear();
    return;
  }
  for(std::size_t j = 0; j < ring.size(); ++j)
    if(tr.is_infinite(ring[j]))
    {
      std::rotate(ring.begin(), ring.begin() + (j + 1) % ring.size(), ring.end());
      break;
    }
}

/// A bound on the best worst score of the triangulations of an edge's ring
/// (the best is at most the bound), by the edge and the signature of its
/// star. The quality driver tries the steps of two-step removal (the
/// removals of the edges around the edge's ends, then of the edge in the
/// ring the first leaves) again and again, with floors that mostly rise.
template <class Tr>
using Edge_removal_bounds = Value_cache<Edge_key<Tr>, Edge_key_hash>;

/// The two-step removal of `e` alone (the plain removal is not tried): for
/// each edge (x, s) with x an end of `e` and s a finite vertex of its ring,
/// in ring order, whether a triangulation of the ring of (x, s) whose cells
/// beat the worst around `e` leaves a ring around `e` that has one too;
/// the first such pair is made. Nothing changes until both steps are known
/// to succeed. `created` receives the cells of both steps that remain. The
/// attempt reads only cells through an end of `e` (and their points). With
/// `bounds`, a bound on the best of each star of either step is remembered.
template <class Context>
Edge_removal_report remove_edge_in_two_steps(const Context& op, const typename Context::Triangulation::Edge& e,
                                             Edge_removal_bounds<typename Context::Triangulation>* bounds = nullptr)
{
  typedef typename Context::Triangulation Tr;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  Tr& tr = op.tr;
  const auto& criterion = op.criterion;
  const auto& constraints = op.constraints;
  const int maximum = op.maximum_ring;
  std::vector<typename Tr::Cell_handle>& created = op.created;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Edge Edge;
  typedef std::array<Vertex_handle, 4> Tuple;
  CGAL_precondition(tr.dimension() == 3 && !tr.is_infinite(e));
  Edge_removal_report report;
  const Edge_star<Tr> star(tr, e, maximum);
  report.ring_size = int(star.cells.size());
  report.on_hull = star.on_hull;
  if(report.ring_size > maximum) { report.outcome = RING_TOO_LARGE; return report; }
  // A facet around e that the first step keeps stays around e.
  if(star_is_constrained(tr, star, constraints)) { report.outcome = EDGE_CONSTRAINED; return report; }
  report.outcome = NO_IMPROVEMENT;
  const Vertex_handle a = star.a, b = star.b;

  // Scores: larger is better; both steps must score above `floor`.
  auto value = [&](const Tuple& t) {
    return criterion.measure(internal::bare_point(t[0]->point()), internal::bare_point(t[1]->point()), internal::bare_point(t[2]->point()), internal::bare_point(t[3]->point()));
  };
  auto score = [&](const Tuple& t) { return larger_is_worse ? -value(t) : value(t); };
  double worst = HUGE_VAL;
  for(Cell_handle c : star.cells)
    if(!tr.is_infinite(c)) worst = (std::min)(worst, score(tuple_of<Tr>(c)));
  const double bar = larger_is_worse ? -worst : worst;
  report.quality_before = bar;
  const double tolerance = criterion.relative_tolerance;
  const double floor = larger_is_worse ? -bar * (1 - tolerance) : bar * (1 + tolerance);

  // Whether a triangulation of the star's ring beats the floor; the best
  // one, when it does, in `best`. With `bounds`, a bound on the best of each
  // star (a star of the mesh, or the ring the first step would leave) is
  // remembered: a failure tells that the best is at most the floor, a
  // success what it is; a star whose bound is not above the floor is not
  // solved again.
  auto beats_floor = [&](const Edge_star<Tr>& around, std::optional<Ring_triangulation<Tr, decltype(score)>>& best) {
    Edge_key<Tr> key;
    std::uint64_t signature = 0;
    if(bounds != nullptr)
    {
      key = edge_key<Tr>(around.a, around.b);
      signature = around.signature(tr);
      double bound;
      if(bounds->find(key, signature, bound) && !(bound > floor)) return false;
    }
    best.emplace(tr, around, score, floor);
    if(bounds != nullptr) bounds->record(key, signature, best->exists() ? best->score() : floor);
    return best->exists();
  };
  // The first steps, in turn: the edge from x to s_k, the ring vertex at
  // position k (cell k of the star holds x and s_k).
  for(std::size_t first_step = 0; first_step < 2 * star.ring.size(); ++first_step)
  {
    const std::size_t k = first_step / 2;
    if(tr.is_infinite(star.ring[k])) continue;
    const Vertex_handle x = first_step % 2 == 0 ? a : b;
    const Cell_handle around = star.cells[k];
    const Edge_star<Tr> inner(tr, Edge(around, around->index(x), around->index(star.ring[k])), maximum);
    if(int(inner.cells.size()) > maximum || star_is_constrained(tr, inner, constraints)) continue;
    std::optional<Ring_triangulation<Tr, decltype(score)>> step1, step2;
    if(!beats_floor(inner, step1)) continue;
    Edge_star<Tr> after;
    after.a = a;
    after.b = b;
    ring_after(tr, star, k, step1->cells(), after.ring);
    if(after.ring.size() < 3 || int(after.ring.size()) > maximum || !beats_floor(after, step2)) continue;
    // Both steps are known to succeed: make them.
    const std::vector<Cell_handle> first = replace_cells(tr, inner.cells, step1->cells(), constraints, op.visitor);
    const Cell_handle through = *std::find_if(first.begin(), first.end(),
                                              [&](Cell_handle c) { return c->has_vertex(a) && c->has_vertex(b); });
    const Edge_star<Tr> second(tr, Edge(through, through->index(a), through->index(b)), maximum);
    CGAL_assertion(second.ring.size() == after.ring.size() &&
                   std::is_permutation(second.ring.begin(), second.ring.end(), after.ring.begin()));
    const std::vector<Cell_handle> last = replace_cells(tr, second.cells, step2->cells(), constraints, op.visitor);
    const std::size_t before_count = created.size();
    for(Cell_handle c : first)
      if(std::find(second.cells.begin(), second.cells.end(), c) == second.cells.end()) created.push_back(c);
    created.insert(created.end(), last.begin(), last.end());
    report.outcome = EDGE_REMOVED;
    report.ring_size = int(after.ring.size());
    report.on_hull = second.on_hull;
    double after_score = HUGE_VAL;
    for(std::size_t m = before_count; m < created.size(); ++m)
      if(!tr.is_infinite(created[m])) after_score = (std::min)(after_score, score(tuple_of<Tr>(created[m])));
    report.quality_after = larger_is_worse ? -after_score : after_score;
    report.new_cells = int(first.size() + last.size());
    report.steps = 2;
    break;
  }
  return report;
}

} // namespace internal

/// Removes the finite edge `e` of `tr` as `remove_edge` does, and when no
/// triangulation of its ring makes the worst tetrahedron there better,
/// tries it in two steps: first an edge from an end of `e` to a vertex of
/// its ring, then `e`, each step replacing its cells by cells better than
/// the worst around `e` under `criterion` (beyond its tolerance). A first
/// step is made only when the second is known to follow; the mesh is
/// unchanged otherwise. Cell handles around the edges removed are
/// invalidated. The report is
/// that of the plain removal when it succeeds; after two steps,
/// `ring_size` is that of `e` at the second step and `new_cells` counts the
/// cells of both.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints`:
///     an edge with a constrained facet around it, or between two subdomains, is kept \cgalParamNEnd
///   \cgalParamNBegin{maximum_ring_size} the largest ring considered at either step, default 10 \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor`: each
///     step is a replacement of its own \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Edge_removal_report remove_edge_in_two_steps(Tr& tr, const typename Tr::Edge& e,
                                             const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int maximum = choose_parameter(get_parameter(np, internal_np::maximum_ring_size), 10);
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> created;
    const auto op = internal::make_operation_context(tr, criterion, constraints, visitor, maximum, created);
    const Edge_removal_report plain = internal::remove_edge(op, e);
    if(plain.removed() || plain.outcome == RING_TOO_LARGE || plain.outcome == EDGE_CONSTRAINED) return plain;
    return internal::remove_edge_in_two_steps(op, e);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TWO_STEP_EDGE_REMOVAL_H
