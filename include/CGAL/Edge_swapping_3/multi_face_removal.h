// SPDX-License-Identifier: GPL-3.0-or-later
// Multi-face removal (Shewchuk, "Two discrete optimization algorithms for the
// topological improvement of tetrahedral meshes", 2002), the inverse of edge
// removal. Two vertices u and w lie on either side of a facet abc; a triangle
// is "sandwiched" when both (t, u) and (t, w) are tetrahedra of the mesh. A
// disk of m sandwiched triangles around abc, whose 2m tetrahedra are
// removed, is replaced by the m + 2 tetrahedra joining the new edge uw to the
// edges of the disk's boundary. m = 1 is the 2-3 flip. Of the disks reachable
// from abc, the one whose worst new tetrahedron is best is found by dynamic
// programming over the tree of sandwiched triangles: beyond each boundary
// edge, either stop there (one new tetrahedron) or go on into the sandwiched
// triangle across it.

#ifndef CGAL_EDGE_SWAPPING_3_MULTI_FACE_REMOVAL_H
#define CGAL_EDGE_SWAPPING_3_MULTI_FACE_REMOVAL_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/internal/failed_attempts.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What `remove_faces` did.
enum Multi_face_removal_outcome
{
  FACES_REMOVED,          ///< m sandwiched triangles are gone: m + 2 tetrahedra replace their 2m
  FACET_NOT_INTERIOR,     ///< a cell of the facet is infinite (a hull facet)
  FACET_CONSTRAINED,      ///< the facet is constrained, or its two cells lie in different subdomains
  NO_VALID_REMOVAL,       ///< no disk of sandwiched triangles gives positive tetrahedra only
  NO_FACE_IMPROVEMENT     ///< the best disk is not better than the tetrahedra it removes
};

/// The name of `o`, for reports.
inline const char* multi_face_removal_outcome_name(Multi_face_removal_outcome o)
{
  static const char* names[] = {"removed", "not interior", "constrained", "no valid removal", "no improvement"};
  return names[o];
}

/// The report of `remove_faces`.
struct Multi_face_removal_report
{
  Multi_face_removal_outcome outcome = NO_VALID_REMOVAL; ///< removed, or why not
  int faces = 0;               ///< m, the triangles removed (when removed), or the sandwiched triangles explored
  double quality_before = 0;   ///< the worst value of the measure over the 2m removed tetrahedra
  double quality_after = 0;    ///< the worst over the m + 2 new ones (when a disk is valid)
  int new_cells = 0;           ///< m + 2 when removed, else 0

  /// Whether the faces were removed.
  bool removed() const { return outcome == FACES_REMOVED; }
};

namespace internal {

/// The sandwiched triangles reachable from a facet, as a tree, and the best
/// disk among them.
template <class Tr, class Score, class May_go_on>
class Face_sandwich
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 4> Tuple;

  /// A sandwiched triangle t = (t0, t1, t2), oriented so that (t0, t1, t2, u)
  /// is positive, with its cells on the u side and on the w side. Edge k is
  /// (t_k, t_{k+1}); edge 0 of a triangle other than the root leads back to
  /// its parent.
  struct Node
  {
    std::array<Vertex_handle, 3> t;
    Cell_handle cu, cw;
    std::array<int, 3> child{{-1, -1, -1}}; // the node across edge k, -1: none
    std::array<bool, 3> goes_on{{false, false, false}}; // the best disk goes on across edge k
  };

  /// Explores the sandwiched triangles around `root`, depth first, at most
  /// `maximum_faces` of them.
  Face_sandwich(const Tr& tr, Vertex_handle u, Vertex_handle w, const Node& root, int maximum_faces,
                const Score& score, const May_go_on& may_go_on)
    : tr_(tr), u_(u), w_(w), maximum_(maximum_faces), score_(score), may_go_on_(may_go_on)
  {
    nodes_.push_back(root);
    for(int k = 0; k < 3; ++k) explore(0, k);
  }

  /// Finds the best disk (dynamic programming over the tree).
  void solve()
  {
    value_ = HUGE_VAL;
    for(int k = 0; k < 3 && value_ > -HUGE_VAL; ++k) value_ = (std::min)(value_, beyond(0, k));
  }

  /// Whether some disk gives positive tetrahedra only.
  bool exists() const { return value_ > -HUGE_VAL; }
  /// The worst score of the best disk's new tetrahedra.
  double score() const { return value_; }
  const std::vector<Node>& nodes() const { return nodes_; }

  /// The best disk: its triangles' nodes and its new tetrahedra.
  void best(std::vector<int>& triangles, std::vector<Tuple>& new_cells) const { collect(0, triangles, new_cells); }

private:
  // The subtree beyond edge k of node n.
  void explore(int n, int k)
  {
    const int c = child_across(n, k);
    if(c < 0) return;
    explore(c, 1);
    explore(c, 2);
  }

  // The best worst score beyond edge k of node n: stop there, or go on into
  // the sandwiched triangle across it.
  double beyond(int n, int k)
  {
    const Vertex_handle p = nodes_[n].t[k], q = nodes_[n].t[(k + 1) % 3];
    const Tuple stop_cell = {p, q, w_, u_};
    double stop = -HUGE_VAL;
    if(tr_.geom_traits().orientation_3_object()(internal::bare_point(p->point()), internal::bare_point(q->point()), internal::bare_point(w_->point()), internal::bare_point(u_->point())) == POSITIVE)
      stop = score_(stop_cell);
    double go_on = -HUGE_VAL;
    const int c = nodes_[n].child[k];
    if(c >= 0)
      go_on = (std::min)(beyond(c, 1), beyond(c, 2));
    nodes_[n].goes_on[k] = go_on > stop;
    return (std::max)(stop, go_on);
  }

  // The sandwiched triangle across edge k of node n, made a node; -1 if none
  // (or the size limit is reached, or the constraints forbid going on).
  int child_across(int n, int k)
  {
    if(int(nodes_.size()) >= maximum_) return -1;
    const Node& node = nodes_[n];
    const Vertex_handle p = node.t[k], q = node.t[(k + 1) % 3], r0 = node.t[(k + 2) % 3];
    const Cell_handle cu = node.cu->neighbor(node.cu->index(r0)), cw = node.cw->neighbor(node.cw->index(r0));
    if(tr_.is_infinite(cu) || tr_.is_infinite(cw)) return -1;
    const Vertex_handle r = cu->vertex(6 - cu->index(p) - cu->index(q) - cu->index(u_));
    if(!cw->has_vertex(r)) return -1;
    for(const Node& other : nodes_)
      if(other.cu == cu) return -1; // around a vertex, back to a triangle already taken
    if(!may_go_on_(node, k, cu, cw)) return -1;
    Node child;
    child.t = {q, p, r};
    child.cu = cu;
    child.cw = cw;
    nodes_.push_back(child);
    const int c = int(nodes_.size()) - 1;
    nodes_[n].child[k] = c;
    return c;
  }

  void collect(int n, std::vector<int>& triangles, std::vector<Tuple>& new_cells) const
  {
    triangles.push_back(n);
    for(int k = (n == 0 ? 0 : 1); k < 3; ++k)
    {
      if(nodes_[n].goes_on[k])
        collect(nodes_[n].child[k], triangles, new_cells);
      else
        new_cells.push_back({nodes_[n].t[k], nodes_[n].t[(k + 1) % 3], w_, u_});
    }
  }

  const Tr& tr_;
  Vertex_handle u_, w_;
  int maximum_;
  const Score& score_;
  const May_go_on& may_go_on_;
  std::vector<Node> nodes_;
  double value_ = -HUGE_VAL;
};

/// The facets where multi-face removal failed, with the signature of the
/// cells it read then.
template <class Tr>
using Multi_face_removal_failures = Failure_cache<Facet_key<Tr>, Facet_key_hash, Multi_face_removal_report>;

/// The best disk of an explored sandwich, made when it improves.
template <class Context, class Sandwich, class Score>
Multi_face_removal_report decide_removal(const Context& op, Sandwich& sandwich, const Score& score)
{
  typedef typename Context::Triangulation Tr;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  const double tolerance = op.criterion.relative_tolerance;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 4> Tuple;
  Multi_face_removal_report report;
  sandwich.solve();
  report.faces = int(sandwich.nodes().size());
  if(!sandwich.exists()) { report.outcome = NO_VALID_REMOVAL; return report; }

  std::vector<int> triangles;
  std::vector<Tuple> new_cells;
  sandwich.best(triangles, new_cells);
  std::vector<Cell_handle> old_cells;
  double before = HUGE_VAL;
  for(int n : triangles)
    for(Cell_handle x : {sandwich.nodes()[n].cu, sandwich.nodes()[n].cw})
    {
      old_cells.push_back(x);
      before = (std::min)(before, score(tuple_of<Tr>(x)));
    }
  report.quality_before = larger_is_worse ? -before : before;
  report.quality_after = larger_is_worse ? -sandwich.score() : sandwich.score();
  // A disk: m triangles with m + 2 boundary edges and no vertex inside.
  const int m = int(triangles.size());
  std::map<Vertex_handle, int> on_boundary;
  for(const Tuple& t : new_cells) ++on_boundary[t[0]];
  if(int(new_cells.size()) != m + 2 || int(on_boundary.size()) != m + 2)
  {
    report.outcome = NO_VALID_REMOVAL;
    return report;
  }
  const bool better = larger_is_worse ? report.quality_after < report.quality_before * (1 - tolerance)
                                      : report.quality_after > report.quality_before * (1 + tolerance);
  if(!better) { report.outcome = NO_FACE_IMPROVEMENT; return report; }

  const auto cells = replace_cells(op.tr, old_cells, new_cells, op.constraints, op.visitor);
  op.created.insert(op.created.end(), cells.begin(), cells.end());
  report.faces = m;
  report.new_cells = int(cells.size());
  report.outcome = FACES_REMOVED;
  return report;
}

/// `remove_faces` in an operation context (its ring limit is the most
/// triangles explored); the new cells are appended to `op.created`.
template <class Context>
Multi_face_removal_report remove_faces(const Context& op, const typename Context::Triangulation::Facet& f)
{
  typedef typename Context::Triangulation Tr;
  constexpr bool larger_is_worse = Context::larger_is_worse;
  Tr& tr = op.tr;
  const auto& criterion = op.criterion;
  const auto& constraints = op.constraints;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 4> Tuple;
  CGAL_precondition(tr.dimension() == 3);

  Multi_face_removal_report report;
  const Cell_handle c = f.first, d = c->neighbor(f.second);
  if(tr.is_infinite(c) || tr.is_infinite(d)) { report.outcome = FACET_NOT_INTERIOR; return report; }
  if(constraints.is_facet_constrained(c, f.second) || !constraints.same_subdomain(c, d))
  {
    report.outcome = FACET_CONSTRAINED;
    return report;
  }
  const Vertex_handle u = c->vertex(f.second), w = d->vertex(d->index(c));

  auto value = [&](const Tuple& t) { return criterion.measure(internal::bare_point(t[0]->point()), internal::bare_point(t[1]->point()), internal::bare_point(t[2]->point()), internal::bare_point(t[3]->point())); };
  auto score = [&](const Tuple& t) { return larger_is_worse ? -value(t) : value(t); };
  // Going on across edge k of a node removes the facets (p, q, u) and
  // (p, q, w) and the triangle across: none may be constrained, and the
  // cells must lie in the subdomain of the first.
  auto may_go_on = [&](const auto& node, int k, Cell_handle cu, Cell_handle cw) {
    const Vertex_handle r0 = node.t[(k + 2) % 3];
    const int iu = node.cu->index(r0), iw = node.cw->index(r0);
    return constraints.same_subdomain(cu, c) && constraints.same_subdomain(cw, c) &&
           !constraints.is_facet_constrained(node.cu, iu) && !constraints.is_facet_constrained(node.cw, iw) &&
           !constraints.is_facet_constrained(cu, cu->index(u));
  };
  typedef Face_sandwich<Tr, decltype(score), decltype(may_go_on)> Sandwich;
  typename Sandwich::Node root;
  {
    // (t0, t1, t2, u) positive: an even permutation of c's own vertex order.
    std::array<Vertex_handle, 3> t = {c->vertex((f.second + 1) & 3), c->vertex((f.second + 2) & 3),
                                      c->vertex((f.second + 3) & 3)};
    if(permutation_sign<Tr>(c, {t[0], t[1], t[2], u}) < 0) std::swap(t[0], t[1]);
    root.t = t;
    root.cu = c;
    root.cw = d;
  }
  Sandwich sandwich(tr, u, w, root, op.maximum_ring, score, may_go_on);
  return decide_removal(op, sandwich, score);
}

/// `remove_faces`, its failures remembered in `failures` under `signature`,
/// which the caller makes so that it changes whenever a cell through either
/// vertex off the facet changes (the quality driver's stamps of the two;
/// the removal reads no other cell): a failure remembered there is returned
/// without exploring the sandwich. Both sides of a facet share it.
template <class Context>
Multi_face_removal_report remove_faces(const Context& op, const typename Context::Triangulation::Facet& f,
                                       Multi_face_removal_failures<typename Context::Triangulation>& failures,
                                       std::uint64_t signature)
{
  typedef typename Context::Triangulation Tr;
  if(op.tr.is_infinite(f.first) || op.tr.is_infinite(f.first->neighbor(f.second))) return remove_faces(op, f);
  const Facet_key<Tr> key = facet_key<Tr>(f.first, f.second);
  if(const Multi_face_removal_report* known = failures.find(key, signature)) return *known;
  const Multi_face_removal_report report = remove_faces(op, f);
  failures.record(key, signature, report, report.removed());
  return report;
}

} // namespace internal

/// Multi-face removal at the interior facet `f` of `tr`: with u and w the
/// vertices of its two cells off the facet, the disk of triangles
/// sandwiched between u and w around `f` whose replacement by tetrahedra
/// around the new edge uw makes the worst tetrahedron there best under
/// `criterion` is found (dynamic programming over the sandwiched triangles);
/// its 2m tetrahedra are replaced by m + 2 when that improves the worst of
/// them beyond the criterion's relative tolerance. Every new tetrahedron is
/// positively oriented (exact predicate). Cell handles of the removed cells
/// are invalidated.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints`:
///     no constrained facet is removed, no two subdomains joined \cgalParamNEnd
///   \cgalParamNBegin{maximum_ring_size} the most sandwiched triangles explored, default 10 \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor` \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Multi_face_removal_report remove_faces(Tr& tr, const typename Tr::Facet& f,
                                       const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int maximum = choose_parameter(get_parameter(np, internal_np::maximum_ring_size), 10);
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> created;
    return internal::remove_faces(internal::make_operation_context(tr, criterion, constraints, visitor, maximum, created), f);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MULTI_FACE_REMOVAL_H
