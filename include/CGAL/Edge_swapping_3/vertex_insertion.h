// SPDX-License-Identifier: GPL-3.0-or-later
// Vertex insertion for quality: a new vertex inside a bad cell, joined to the
// boundary of a cavity chosen to make the worst new cell as good as possible.
//
// The point is tried at the cell's centroid, at the centroid of each of its
// facets and at the middle of each of its edges. For each point the cavity
// holds the cells the point lies in (the root cells) and grows through
// facets into a tree of the cells nearby; each cell of the tree is either
// kept out (the new cell is the point joined to the facet it was reached
// through) or taken in (its other facets are decided the same way). The best
// choice for each subtree follows from its children's, leaves first, as in
// Stellar's cavity improvement (Klingner and Shewchuk, "Aggressive
// tetrahedral mesh improvement", 2007). A new cell must be positively
// oriented (exact predicate); when all are, the point sees every facet of the
// cavity's boundary from inside, so the new cells fill the cavity exactly
// once: the triangulation stays valid and covers the same domain. A cell
// reached twice by different branches is never taken in by the second
// (the two new cells on the facet between them cannot both be positive), so
// the choice is optimal over the tree, not over every cavity.
//
// The cavity stays in the cell's subdomain and does not cross a constrained
// facet or the hull: boundaries and interfaces keep their triangles, and no
// vertex is made on them.

#ifndef CGAL_EDGE_SWAPPING_3_VERTEX_INSERTION_H
#define CGAL_EDGE_SWAPPING_3_VERTEX_INSERTION_H

#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/operation_context.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What `insert_vertex` did.
enum Vertex_insertion_outcome
{
  VERTEX_INSERTED,         ///< a vertex was made; the worst new cell is better than the cell was
  CELL_NOT_IN_DOMAIN,      ///< the cell is infinite or outside the domain
  NO_INSERTION_IMPROVEMENT ///< no point and cavity tried beats the cell beyond the tolerance
};

/// The report of `insert_vertex`.
struct Vertex_insertion_report
{
  Vertex_insertion_outcome outcome = NO_INSERTION_IMPROVEMENT; ///< inserted, or why not
  int cavity_size = 0;       ///< the cells replaced
  int new_cells = 0;         ///< the cells made
  double quality_before = 0; ///< the measure of the cell
  double quality_after = 0;  ///< the worst measure of the new cells (equal to before when not inserted)

  /// Whether a vertex was made.
  bool inserted() const { return outcome == VERTEX_INSERTED; }
};

namespace internal {

/// How far beyond its root cells a cavity grows, in steps through facets.
constexpr int default_cavity_depth = 2;


/// The cavity tree of one point: its cells, and the best choice of each.
template <class Tr>
struct Cavity_tree
{
  typedef typename Tr::Cell_handle Cell_handle;
  struct Node
  {
    Cell_handle cell;
    int parent = -1;                     // -1 for a root cell
    int facet_to_parent = -1;            // of `cell`, toward the parent
    int depth = 0;
    std::array<int, 4> child{{-1, -1, -1, -1}}; // by facet; -2: another root cell across it
    double best = 0;                     // of the subtree, with the cell taken in or kept out
    bool taken = false;
  };
  std::vector<Node> nodes;
  int roots = 0;

  int find(Cell_handle c) const
  {
    for(std::size_t k = 0; k < nodes.size(); ++k)
      if(nodes[k].cell == c) return int(k);
    return -1;
  }
};

/// `insert_vertex` with its settings spelled out; the new cells are
/// appended to `created`.
template <class Context>
Vertex_insertion_report insert_vertex(const Context& op, typename Context::Triangulation::Cell_handle c, int depth,
                                      typename Context::Triangulation::Vertex_handle* made_vertex = nullptr)
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
  CGAL_precondition(tr.dimension() == 3);
  Vertex_insertion_report report;
  if(tr.is_infinite(c) || !constraints.is_in_domain(tr, c))
  {
    report.outcome = CELL_NOT_IN_DOMAIN;
    return report;
  }
  auto at = [&](Cell_handle d, int i) -> decltype(auto) { return internal::bare_point(d->vertex(i)->point()); };
  auto to_score = [](double m) { return larger_is_worse ? -m : m; };
  const double before = to_score(criterion.measure(at(c, 0), at(c, 1), at(c, 2), at(c, 3)));
  report.quality_before = report.quality_after = to_score(before);
  const double tolerance = criterion.relative_tolerance;
  const double needed = larger_is_worse ? before * (1 - tolerance) : before * (1 + tolerance);
  const auto orientation = tr.geom_traits().orientation_3_object();

  // The score of cell d with its vertex i replaced by p; -inf unless
  // positively oriented, or when the measure fails (NaN).
  auto cone = [&](Cell_handle d, int i, const Point& p) {
    std::array<Point, 4> q;
    for(int k = 0; k < 4; ++k) q[k] = k == i ? p : Point(at(d, k));
    if(orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return -HUGE_VAL;
    const double s = to_score(criterion.measure(q[0], q[1], q[2], q[3]));
    return s == s ? s : -HUGE_VAL;
  };
  auto may_take = [&](Cell_handle from, int facet) {
    const Cell_handle n = from->neighbor(facet);
    return !tr.is_infinite(n) && constraints.is_in_domain(tr, n) && constraints.same_subdomain(n, c) &&
           !constraints.is_facet_constrained(from, facet);
  };

  // The tree around the root cells; false if a root cell may not be taken.
  Cavity_tree<Tr> tree;
  auto grow = [&](const std::vector<Cell_handle>& roots) {
    tree.nodes.clear();
    for(Cell_handle r : roots)
    {
      typename Cavity_tree<Tr>::Node node;
      node.cell = r;
      tree.nodes.push_back(node);
    }
    tree.roots = int(roots.size());
    for(std::size_t k = 0; k < tree.nodes.size(); ++k)
      for(int i = 0; i < 4; ++i)
      {
        if(i == tree.nodes[k].facet_to_parent) continue;
        const Cell_handle n = tree.nodes[k].cell->neighbor(i);
        const int known = tree.find(n);
        if(known >= 0)
        {
          if(known < tree.roots && int(k) < tree.roots)
          {
            if(constraints.is_facet_constrained(tree.nodes[k].cell, i)) return false;
            tree.nodes[k].child[i] = -2;
          }
          continue;
        }
        if(tree.nodes[k].depth >= depth || !may_take(tree.nodes[k].cell, i)) continue;
        typename Cavity_tree<Tr>::Node node;
        node.cell = n;
        node.parent = int(k);
        node.facet_to_parent = n->index(tree.nodes[k].cell);
        node.depth = tree.nodes[k].depth + 1;
        tree.nodes[k].child[i] = int(tree.nodes.size());
        tree.nodes.push_back(node);
      }
    return true;
  };
  // The worst new cell of the best cavity for p, leaves first; -inf when no
  // cavity beats `floor`.
  auto evaluate = [&](const Point& p, double floor) {
    double worst = HUGE_VAL;
    for(int k = int(tree.nodes.size()) - 1; k >= 0; --k)
    {
      auto& node = tree.nodes[std::size_t(k)];
      double taken = HUGE_VAL;
      for(int i = 0; i < 4 && taken > floor; ++i)
      {
        if(i == node.facet_to_parent || node.child[i] == -2) continue;
        taken = (std::min)(taken, node.child[i] >= 0 ? tree.nodes[std::size_t(node.child[i])].best : cone(node.cell, i, p));
      }
      if(!(taken > floor)) taken = -HUGE_VAL;
      if(k < tree.roots)
      {
        worst = (std::min)(worst, taken);
        node.taken = true;
        continue;
      }
      const auto& parent = tree.nodes[std::size_t(node.parent)];
      const double kept = cone(parent.cell, parent.cell->index(node.cell), p);
      node.taken = taken > kept;
      node.best = node.taken ? taken : kept;
    }
    return worst;
  };

  // The candidate points: centroid, facet centroids, edge middles, each with
  // its root cells and barycentric weights in c.
  struct Candidate
  {
    std::array<double, 4> weights;
    int facet = -1, i = -1, j = -1; // the facet or the edge of c it lies on
  };
  std::vector<Candidate> candidates;
  candidates.push_back({{{0.25, 0.25, 0.25, 0.25}}});
  for(int f = 0; f < 4; ++f)
  {
    Candidate k{{{1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0 / 3}}};
    k.weights[std::size_t(f)] = 0;
    k.facet = f;
    candidates.push_back(k);
  }
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      Candidate k{{{0, 0, 0, 0}}};
      k.weights[std::size_t(i)] = k.weights[std::size_t(j)] = 0.5;
      k.i = i;
      k.j = j;
      candidates.push_back(k);
    }
  auto point_of = [&](const Candidate& k) {
    double x = 0, y = 0, z = 0;
    for(int i = 0; i < 4; ++i)
    {
      x += k.weights[std::size_t(i)] * CGAL::to_double(at(c, i).x());
      y += k.weights[std::size_t(i)] * CGAL::to_double(at(c, i).y());
      z += k.weights[std::size_t(i)] * CGAL::to_double(at(c, i).z());
    }
    return Point(x, y, z);
  };
  std::vector<Cell_handle> roots;
  auto roots_of = [&](const Candidate& k) {
    roots.assign(1, c);
    if(k.facet >= 0)
    {
      if(!may_take(c, k.facet)) return false;
      roots.push_back(c->neighbor(k.facet));
    }
    else if(k.i >= 0)
    {
      auto circ = tr.incident_cells(c, k.i, k.j), done = circ;
      for(++circ; circ != done; ++circ)
      {
        const Cell_handle d = circ;
        if(tr.is_infinite(d) || !constraints.is_in_domain(tr, d) || !constraints.same_subdomain(d, c)) return false;
        roots.push_back(d);
      }
    }
    return grow(roots);
  };

  // The best candidate, by the worst new cell of its best cavity.
  double best = -HUGE_VAL;
  std::size_t chosen = 0;
  for(std::size_t k = 0; k < candidates.size(); ++k)
  {
    if(!roots_of(candidates[k])) continue;
    const double w = evaluate(point_of(candidates[k]), best);
    if(w > best)
    {
      best = w;
      chosen = k;
    }
  }
  if(!(best > -HUGE_VAL)) return report;

  // Its cavity: the roots and the cells taken in under a taken cell, and the
  // facets of its boundary (cell, index) that the new vertex is joined to.
  roots_of(candidates[chosen]);
  Point p = point_of(candidates[chosen]);
  evaluate(p, -HUGE_VAL);
  std::vector<char> in(tree.nodes.size(), 0);
  std::vector<Cell_handle> cavity;
  std::vector<std::pair<Cell_handle, int>> joined;
  for(std::size_t k = 0; k < tree.nodes.size(); ++k)
  {
    const auto& node = tree.nodes[k];
    in[k] = k < std::size_t(tree.roots) || (node.taken && in[std::size_t(node.parent)]);
    if(in[k]) cavity.push_back(node.cell);
  }
  for(std::size_t k = 0; k < tree.nodes.size(); ++k)
    if(in[k])
      for(int i = 0; i < 4; ++i)
      {
        const auto& node = tree.nodes[k];
        const int next = i == node.facet_to_parent ? node.parent : node.child[i];
        if(next == -2 || (next >= 0 && in[std::size_t(next)])) continue;
        joined.emplace_back(node.cell, i);
      }

  // The point then moves where the worst new cell of that cavity is best: a
  // compass search from a quarter of the cell's shortest edge down to a
  // thousandth of it (Stellar smooths the new vertex likewise).
  auto worst_joined = [&](const Point& q, double floor) {
    double w = HUGE_VAL;
    for(std::size_t k = 0; k < joined.size() && w > floor; ++k)
      w = (std::min)(w, cone(joined[k].first, joined[k].second, q));
    return w;
  };
  const auto squared_distance = tr.geom_traits().compute_squared_distance_3_object();
  double shortest = HUGE_VAL;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      shortest = (std::min)(shortest, std::sqrt(CGAL::to_double(squared_distance(at(c, i), at(c, j)))));
  for(double step = 0.25 * shortest; step > 1e-3 * shortest;)
  {
    bool moved = false;
    for(int axis = 0; axis < 6 && !moved; ++axis)
    {
      const double d = axis < 3 ? step : -step;
      const Point q(CGAL::to_double(p.x()) + (axis % 3 == 0 ? d : 0), CGAL::to_double(p.y()) + (axis % 3 == 1 ? d : 0),
                    CGAL::to_double(p.z()) + (axis % 3 == 2 ? d : 0));
      const double w = worst_joined(q, best);
      if(w > best)
      {
        best = w;
        p = q;
        moved = true;
      }
    }
    if(!moved) step *= 0.5;
  }
  if(!(best > needed)) return report;

  // The new vertex's barycentric coordinates in the old cell it lies in,
  // for the visitor's interpolation of vertex data.
  auto volume = tr.geom_traits().compute_volume_3_object();
  std::array<Vertex_handle, 4> corners{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
  std::array<double, 4> weights{{0.25, 0.25, 0.25, 0.25}};
  for(Cell_handle d : cavity)
  {
    std::array<double, 4> w;
    double total = 0;
    bool inside = true;
    for(int k = 0; k < 4 && inside; ++k)
    {
      std::array<Point, 4> q{{at(d, 0), at(d, 1), at(d, 2), at(d, 3)}};
      q[std::size_t(k)] = p;
      w[std::size_t(k)] = CGAL::to_double(volume(q[0], q[1], q[2], q[3]));
      inside = orientation(q[0], q[1], q[2], q[3]) != CGAL::NEGATIVE;
      total += w[std::size_t(k)];
    }
    if(!inside || !(total > 0)) continue;
    for(int k = 0; k < 4; ++k)
    {
      corners[std::size_t(k)] = d->vertex(k);
      weights[std::size_t(k)] = w[std::size_t(k)] / total;
    }
    break;
  }

  const Vertex_handle v = tr.tds().create_vertex();
  v->set_point(internal::point_at<typename Tr::Point>(p));
  std::vector<std::array<Vertex_handle, 4>> cells;
  for(const auto& [d, i] : joined)
  {
    std::array<Vertex_handle, 4> t{{d->vertex(0), d->vertex(1), d->vertex(2), d->vertex(3)}};
    t[std::size_t(i)] = v;
    cells.push_back(t);
  }
  const std::vector<Cell_handle> made = internal::replace_cells(tr, cavity, cells, constraints, visitor);
  tell_insertion(visitor, tr, v, corners, weights);
  if(made_vertex != nullptr) *made_vertex = v;
  created.insert(created.end(), made.begin(), made.end());
  report.outcome = VERTEX_INSERTED;
  report.cavity_size = int(cavity.size());
  report.new_cells = int(made.size());
  report.quality_after = to_score(best);
  return report;
}

} // namespace internal

/// Inserts a vertex in the finite cell `c` of `tr` if that makes the worst
/// tetrahedron there better under `criterion` (any
/// `Worst_tetrahedron_criterion`) beyond its relative tolerance: the point
/// is the cell's centroid, the centroid of one of its facets or the middle of
/// one of its edges, joined to the boundary of a cavity of nearby cells
/// chosen to make the worst new cell best; every new cell is positively
/// oriented (exact predicate), so the triangulation stays valid and covers
/// the same domain. The cavity keeps to the cell's subdomain and does not
/// cross the hull or a constrained facet. The visitor's `after_insertion`,
/// if it has one, gives the new vertex its data.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_constraints} a model of `MeshConstraints_3`, default `No_constraints` \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of `ReplacementVisitor_3`, default `Default_replacement_visitor` \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Tr, class Measure, bool larger_is_worse, class NamedParameters = CGAL::parameters::Default_named_parameters>
Vertex_insertion_report insert_vertex(Tr& tr, typename Tr::Cell_handle c,
                               const Worst_tetrahedron_criterion<Measure, larger_is_worse>& criterion,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Default_replacement_visitor());
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    std::vector<typename Tr::Cell_handle> created;
    return internal::insert_vertex(internal::make_operation_context(tr, criterion, constraints, visitor, 0, created), c,
                                   internal::default_cavity_depth);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_VERTEX_INSERTION_H
