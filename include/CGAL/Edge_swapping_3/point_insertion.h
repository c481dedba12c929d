// SPDX-License-Identifier: GPL-3.0-or-later
// Point insertion by swapping (paper section 5, "Mesh Refinement Operation"):
// locate the point by walking, split the simplex it falls in (1-4 in a cell,
// 2-6 on a facet, n-2n on an edge; joined to the visible hull facets outside),
// then swap outward from the new vertex under any criterion.
//
// For the Delaunay criterion the front only moves outward: only the facets
// opposite the new vertex (its link) are tested, and a flip puts new link
// facets in the queue. For any other criterion every facet of a changed cell
// is tested again (back-propagation), as the paper prescribes.

#ifndef CGAL_EDGE_SWAPPING_3_POINT_INSERTION_H
#define CGAL_EDGE_SWAPPING_3_POINT_INSERTION_H

#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Regular_criterion.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/internal/replace_cells.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/internal/common_flips.h>
#include <CGAL/Edge_swapping_3/internal/split_with_data.h>
#include <array>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// What one insertion did.
template <class Tr>
struct Insertion_result
{
  /// The vertex at the point: new, or the existing one at an equal point;
  /// the default handle when the point was refused (outside the domain, or on
  /// a constrained facet or edge, or not locatable in dimension 3).
  typename Tr::Vertex_handle vertex;
  typename Tr::Locate_type location = Tr::CELL;           ///< where the walk found the point
  bool is_new = false;                                    ///< whether a vertex was made
  std::array<std::size_t, number_of_flip_kinds> swaps{};  ///< the swaps after the split, by kind
  /// Delaunay only: link facets left not locally Delaunay with no flip to
  /// make (never observed; Joe 1991 proves it cannot happen).
  std::size_t stuck_facets = 0;
  /// Other criteria: the swap limit was reached (the front did not settle).
  bool swap_limit_reached = false;
  /// Regular criterion: the point is redundant (hidden, as in `Regular_triangulation_3`); nothing changed.
  bool hidden = false;
  /// Regular criterion: the vertices the point made redundant, removed by 4-1 flips.
  std::size_t removed_vertices = 0;

  /// The swaps of every kind.
  std::size_t total_swaps() const { return swaps[0] + swaps[1] + swaps[2] + swaps[3]; }
};

namespace internal {

// The link of v is kept as a queue of cells that hold v, each standing for
// its facet opposite v. The cells' TDS mark (which CGAL's own operations
// clear after use) keeps each cell queued at most once: a cell is marked
// queued, or set aside (its facet could not be flipped yet), or clear. A flip
// may reuse a queued cell for another tetrahedron through v: the entry then
// stands for the new link facet, which needs the test anyway. Every cell a
// link flip creates or reuses holds v, so a cell taken off the queue that is
// still in use and no longer holds v can only come from the general flip, and
// is skipped.
template <class Tr>
using Link_queue = std::vector<typename Tr::Cell_handle>;

template <class Tr>
void push_link_cell(Link_queue<Tr>& queue, typename Tr::Cell_handle c)
{
  if(c->tds_data().is_in_conflict()) return; // queued already
  c->tds_data().mark_in_conflict();
  queue.push_back(c);
}

template <class Tr>
void set_link_cell_aside(Link_queue<Tr>& aside, typename Tr::Cell_handle c)
{
  c->tds_data().mark_on_boundary();
  aside.push_back(c);
}

// Takes a cell off the queue: the index of v in it, or -1 if it was deleted
// or no longer holds v.
template <class Tr>
int pop_link_cell(const Tr& tr, typename Tr::Cell_handle c, typename Tr::Vertex_handle v)
{
  if(!tr.tds().cells().is_used(c)) return -1;
  c->tds_data().clear();
  int i;
  return c->has_vertex(v, i) ? i : -1;
}

// Whether a cell set aside is still waiting: not deleted, nor queued again
// (and maybe tested) since.
template <class Tr>
bool is_set_aside(const Tr& tr, typename Tr::Cell_handle c)
{
  return tr.tds().cells().is_used(c) && c->tds_data().is_on_boundary();
}

// The end of a pass over the link queue: when flips were made, the facets
// set aside go back into the queue for another pass (true); else the
// flipping is over (false).
template <class Tr>
bool retry_set_aside(const Tr& tr, Link_queue<Tr>& queue, Link_queue<Tr>& aside, bool progress)
{
  queue.clear();
  if(!progress) return false;
  for(auto c : aside)
    if(is_set_aside(tr, c)) push_link_cell<Tr>(queue, c);
  aside.clear();
  return true;
}

// The link facets of v still set aside that the test `holds(c, i)` fails:
// left unflipped (Joe's and Edelsbrunner and Shah's theorems say none).
template <class Tr, class Test>
std::size_t count_stuck_link_facets(const Tr& tr, typename Tr::Vertex_handle v, const Link_queue<Tr>& aside,
                                    const Test& holds)
{
  std::size_t stuck = 0;
  for(auto c : aside)
  {
    if(!is_set_aside(tr, c)) continue;
    c->tds_data().clear();
    int i;
    if(c->has_vertex(v, i) && !holds(c, i)) ++stuck;
  }
  return stuck;
}

// The flip that makes the link facet (c, i) of v Delaunay, if it can be made
// now: the flip of the five-point configuration for a finite facet; for the
// facet between two infinite cells (v and the apex across on a coplanar hull),
// the hull 2-2 flip of the edge they share.
template <class Tr>
bool plan_link_flip(const Tr& tr, typename Tr::Cell_handle c, int i, Flip_plan<Tr>& plan)
{
  const auto n = c->neighbor(i);
  if(!tr.is_infinite(c) && !tr.is_infinite(n))
  {
    const auto conf = classify_facet(tr, c, i);
    if(!conf.is_swappable()) return false;
    plan = conf.flip_plan();
    return true;
  }
  if(!tr.is_infinite(c)) return false; // a hull facet seen from inside is always Delaunay
  const int inf = c->index(tr.infinite_vertex());
  int a = -1, b = -1;
  for(int k = 0; k < 4; ++k)
    if(k != i && k != inf) (a < 0 ? a : b) = k;
  const Edge_ring<Tr> ring(tr, c, a, b);
  const auto apex = n->vertex(n->index(c));
  return ring.size() == 4 && ring.plan_flip(plan, ring.diagonal_through(c->vertex(i), apex)) &&
         worst_orientation(tr, plan) == POSITIVE;
}

enum Link_flip_outcome { LINK_DELAUNAY, LINK_FLIPPED, LINK_NOT_FLIPPABLE_NOW, LINK_NEEDS_GENERAL_FLIP };

// The finite link facet (c, i) of v, tested and, in the two common cases,
// flipped in place (internal/common_flips.h), for a triangulation whose cells
// carry no data. A degenerate or hull case is left to the general planned flip.
template <class Tr>
Link_flip_outcome flip_common_link_facet(Tr& tr, typename Tr::Cell_handle c, int i,
                                         typename Tr::Vertex_handle v, Perturbation perturbation,
                                         Link_queue<Tr>& queue,
                                         Insertion_result<Tr>& result)
{
  const auto n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n)) return LINK_NEEDS_GENERAL_FLIP;
  // v in the sphere of n, as CGAL's conflict test asks: for a shared facet,
  // the same answer as the apex in the sphere of c, perturbed or not.
  if(side_of_oriented_sphere(tr.geom_traits(), n->vertex(0)->point(), n->vertex(1)->point(),
                             n->vertex(2)->point(), n->vertex(3)->point(), v->point(),
                             perturbation == CGAL_PERTURBATION) != ON_POSITIVE_SIDE)
    return LINK_DELAUNAY;
  const internal::Common_flip flip = internal::common_flip_at(tr, c, i);
  if(flip.kind == internal::NEEDS_GENERAL_FLIP) return LINK_NEEDS_GENERAL_FLIP;
  if(flip.kind == internal::NOT_FLIPPABLE_NOW) return LINK_NOT_FLIPPABLE_NOW;
  std::array<typename Tr::Cell_handle, 4> made;
  const int m = internal::make_common_flip(tr, c, i, flip, made);
  for(int k = 0; k < m; ++k) push_link_cell<Tr>(queue, made[k]); // a 3-2 cell may be queued already
  ++result.swaps[m == 3 ? FLIP_2_3 : FLIP_3_2];
  return LINK_FLIPPED;
}

// Flips outward from the new vertex v until its link is locally Delaunay.
template <class Tr, class Constraints>
void flip_link_to_delaunay(Tr& tr, typename Tr::Vertex_handle v, Perturbation perturbation,
                           const Constraints& constraints, Insertion_result<Tr>& result)
{
  typedef typename Tr::Cell_handle Cell_handle;
  // Kept from one insertion to the next: an insertion allocates nothing.
  thread_local Link_queue<Tr> queue, unflipped, star;
  queue.clear();
  unflipped.clear();
  star.clear();
  tr.incident_cells(v, std::back_inserter(star));
  for(Cell_handle c : star) push_link_cell<Tr>(queue, c);

  Flip_plan<Tr> plan;
  std::array<Cell_handle, 4> created;
  // First in, first out: fewer facets are met before they can be flipped than
  // with a stack. A facet that cannot be flipped now is kept aside and tried
  // again once the queue is done, as long as flips are still being made.
  for(bool progress = true; progress;)
  {
    progress = false;
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const Cell_handle c = queue[head];
      const int i = pop_link_cell(tr, c, v);
      if(i < 0) continue;
      if constexpr(std::is_same<Constraints, No_constraints>::value)
      {
        const auto outcome = flip_common_link_facet(tr, c, i, v, perturbation, queue, result);
        if(outcome == LINK_DELAUNAY) continue;
        if(outcome == LINK_FLIPPED) { progress = true; continue; }
        if(outcome == LINK_NOT_FLIPPABLE_NOW) { set_link_cell_aside<Tr>(unflipped, c); continue; }
      }
      if(is_locally_delaunay(tr, c, i, perturbation)) continue;
      if(!plan_link_flip(tr, c, i, plan) || !flip_respects_constraints(tr, plan, constraints))
      {
        set_link_cell_aside<Tr>(unflipped, c);
        continue;
      }
      const int n = execute_flip(tr, plan, created, constraints);
      ++result.swaps[plan.kind];
      progress = true;
      for(int k = 0; k < n; ++k)
        if(created[k]->has_vertex(v)) push_link_cell<Tr>(queue, created[k]);
    }
    if(!retry_set_aside(tr, queue, unflipped, progress)) break;
  }
  result.stuck_facets += count_stuck_link_facets(tr, v, unflipped, [&](Cell_handle c, int i) {
    return is_locally_delaunay(tr, c, i, perturbation);
  });
}

// The removal of a vertex u of the link facet (c, i) of v that the new
// weights made redundant: Edelsbrunner and Shah's 4-1 flip when u lies inside
// the tetrahedron of v, the facet's other vertices and the apex across, and
// its degenerate forms when u lies on a facet or an edge of it (on the
// segment from v to the apex, say): the cells around u are replaced by the
// cone from v over the facets of their union that v is not on, when every
// cone cell is positively oriented and u conflicts with none that holds it.
template <class Tr>
bool plan_vertex_removal(const Tr& tr, typename Tr::Cell_handle c, int i, Perturbation perturbation,
                         typename Tr::Vertex_handle& u, std::vector<typename Tr::Cell_handle>& old_cells,
                         std::vector<std::array<typename Tr::Vertex_handle, 4>>& new_cells)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const Cell_handle n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n)) return false;
  const Vertex_handle v = c->vertex(i);
  auto orientation = [&](const std::array<Vertex_handle, 4>& t) {
    return tr.geom_traits().orientation_3_object()(bare_point(t[0]->point()), bare_point(t[1]->point()),
                                                   bare_point(t[2]->point()), bare_point(t[3]->point()));
  };
  const Vertex_handle e = n->vertex(n->index(c));
  // The apex's place seen from c: the candidate u must be in the closed
  // tetrahedron of v, the facet's two other vertices and the apex, so the
  // apex is beyond no facet of c through u and on u's side of the facet
  // opposite it (three orientation tests before any walk).
  std::array<Orientation, 4> apex_side;
  for(int m = 0; m < 4; ++m)
  {
    if(m == i) continue;
    std::array<Vertex_handle, 4> t = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    t[m] = e;
    apex_side[m] = orientation(t);
  }
  for(int k = 0; k < 4; ++k)
  {
    if(k == i || apex_side[k] != POSITIVE) continue;
    bool inside = true;
    for(int m = 0; m < 4; ++m)
      if(m != i && m != k && apex_side[m] == POSITIVE) inside = false;
    if(!inside) continue;
    const Vertex_handle candidate = c->vertex(k);
    // The cells around the candidate, by their facets through it (no TDS
    // mark: the link queue keeps its state there).
    old_cells.assign(1, c);
    bool usable = true;
    for(std::size_t head = 0; head < old_cells.size() && usable; ++head)
    {
      const Cell_handle d = old_cells[head];
      const int j = d->index(candidate);
      for(int f = 0; f < 4 && usable; ++f)
      {
        if(f == j) continue;
        const Cell_handle m = d->neighbor(f);
        if(old_cells.size() > 64) usable = false;
        else if(std::find(old_cells.begin(), old_cells.end(), m) == old_cells.end()) old_cells.push_back(m);
      }
    }
    if(!usable) continue;
    new_cells.clear();
    bool valid = true;
    for(Cell_handle d : old_cells)
    {
      if(d->has_vertex(v)) continue;
      std::array<Vertex_handle, 4> t;
      for(int m = 0; m < 4; ++m) t[m] = (d->vertex(m) == candidate) ? v : d->vertex(m);
      if(!tr.is_infinite(d))
        valid = orientation(t) == POSITIVE;
      else
      {
        // A hull cell: v must take the candidate's place in the hull's plane,
        // on the same side of the facet's other edge.
        const int inf = d->index(tr.infinite_vertex());
        std::array<Vertex_handle, 2> xy;
        int found = 0;
        for(int m = 0; m < 4; ++m)
          if(m != inf && d->vertex(m) != candidate) xy[found++] = d->vertex(m);
        const auto& gt = tr.geom_traits();
        const auto& x = bare_point(xy[0]->point());
        const auto& y = bare_point(xy[1]->point());
        const auto& a = bare_point(candidate->point());
        const auto& b = bare_point(v->point());
        valid = gt.orientation_3_object()(x, y, a, b) == COPLANAR &&
                gt.coplanar_orientation_3_object()(x, y, a) != COLLINEAR &&
                gt.coplanar_orientation_3_object()(x, y, a) == gt.coplanar_orientation_3_object()(x, y, b);
      }
      if(!valid) break;
      new_cells.push_back(t);
    }
    if(!valid || new_cells.empty()) continue;
    // Redundant: not in conflict with a cone cell whose closure holds it.
    const auto& q = candidate->point();
    for(const auto& t : new_cells)
    {
      if(tr.is_infinite(t[0]) || tr.is_infinite(t[1]) || tr.is_infinite(t[2]) || tr.is_infinite(t[3])) continue;
      bool holds = true;
      for(int m = 0; m < 4 && holds; ++m)
      {
        auto s = t;
        s[m] = candidate;
        holds = orientation(s) != NEGATIVE;
      }
      if(holds && side_of_oriented_power_sphere(tr.geom_traits(), t[0]->point(), t[1]->point(), t[2]->point(),
                                                t[3]->point(), q, perturbation == CGAL_PERTURBATION) ==
                      ON_POSITIVE_SIDE)
      {
        valid = false;
        break;
      }
    }
    if(!valid) continue;
    u = candidate;
    return true;
  }
  return false;
}

// Flips outward from v, a new vertex or one whose weight grew, until its link
// is locally regular: 2-3, 3-2 and the coplanar flips as for Delaunay, and
// the removal of a vertex made redundant (4-1, or its degenerate forms).
template <class Tr, class Constraints>
void flip_link_to_regular(Tr& tr, typename Tr::Vertex_handle v, Perturbation perturbation,
                          const Constraints& constraints, Insertion_result<Tr>& result)
{
  typedef typename Tr::Cell_handle Cell_handle;
  Link_queue<Tr> queue, unflipped, star;
  tr.incident_cells(v, std::back_inserter(star));
  for(Cell_handle c : star) push_link_cell<Tr>(queue, c);

  Flip_plan<Tr> plan;
  std::array<Cell_handle, 4> created;
  std::vector<Cell_handle> old_cells;
  std::vector<std::array<typename Tr::Vertex_handle, 4>> new_cells;
  Default_replacement_visitor no_visitor;
  for(bool progress = true; progress;)
  {
    progress = false;
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const Cell_handle c = queue[head];
      const int i = pop_link_cell(tr, c, v);
      if(i < 0) continue;
      if(is_locally_regular(tr, c, i, perturbation)) continue;
      typename Tr::Vertex_handle u;
      if(plan_link_flip(tr, c, i, plan) && flip_respects_constraints(tr, plan, constraints))
      {
        const int n = execute_flip(tr, plan, created, constraints);
        ++result.swaps[plan.kind];
        for(int k = 0; k < n; ++k)
          if(created[k]->has_vertex(v)) push_link_cell<Tr>(queue, created[k]);
      }
      else if(std::is_same<Constraints, No_constraints>::value &&
              plan_vertex_removal(tr, c, i, perturbation, u, old_cells, new_cells))
      {
        for(Cell_handle d : replace_cells(tr, old_cells, new_cells, constraints, no_visitor))
          push_link_cell<Tr>(queue, d);
        tr.tds().delete_vertex(u);
        ++result.removed_vertices;
      }
      else
      {
        set_link_cell_aside<Tr>(unflipped, c);
        continue;
      }
      progress = true;
    }
    if(!retry_set_aside(tr, queue, unflipped, progress)) break;
  }
  result.stuck_facets += count_stuck_link_facets(tr, v, unflipped, [&](Cell_handle c, int i) {
    return is_locally_regular(tr, c, i, perturbation);
  });
}

// Flip insertion of a weighted point, as Regular_triangulation_3 inserts it:
// a point with the weight of the vertex at its place changes nothing; a
// point not in conflict with the cell it falls in is redundant (hidden); a
// heavier point at a vertex's place replaces its point.
template <class Tr, class Constraints>
Insertion_result<Tr> insert_weighted(Tr& tr, const typename Tr::Point& p, typename Tr::Cell_handle hint,
                                     const Constraints& constraints, Perturbation perturbation)
{
  Insertion_result<Tr> result;
  const bool perturb = (perturbation == CGAL_PERTURBATION);
  int li, lj;
  const auto c = tr.locate(p, result.location, li, lj, hint);
  if(result.location == Tr::VERTEX && c->vertex(li)->point().weight() == p.weight())
  {
    result.vertex = c->vertex(li);
    return result;
  }
  if(side_of_power_sphere(tr, c, p, perturb) != ON_BOUNDED_SIDE)
  {
    result.hidden = true;
    return result;
  }
  if(result.location == Tr::VERTEX)
  {
    if(!std::is_same<Constraints, No_constraints>::value) return result;
    result.vertex = c->vertex(li);
    result.vertex->set_point(p); // the lighter point it had is hidden now
  }
  else
  {
    if(!split_is_allowed(tr, c, result.location, li, lj, constraints)) return result;
    result.vertex = split_with_data(tr, p, c, result.location, li, lj, constraints);
    result.is_new = true;
  }
  flip_link_to_regular(tr, result.vertex, perturbation, constraints, result);
  return result;
}

// Swaps from the new vertex v under any criterion, with back-propagation:
// after a flip, every facet of the new cells is tested again.
template <class Tr, class Criterion, class Constraints>
void swap_around(Tr& tr, typename Tr::Vertex_handle v, const Criterion& criterion,
                 const Constraints& constraints, std::size_t max_swaps, Insertion_result<Tr>& result)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef std::array<Vertex_handle, 3> Triple;
  std::vector<Triple> stack;
  auto push_facets = [&](Cell_handle c) {
    for(int i = 0; i < 4; ++i)
      stack.push_back({c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)});
  };
  std::vector<Cell_handle> star;
  tr.incident_cells(v, std::back_inserter(star));
  for(Cell_handle c : star) push_facets(c);

  std::array<Cell_handle, 4> created;
  while(!stack.empty())
  {
    const Triple t = stack.back();
    stack.pop_back();
    Cell_handle c;
    int i, j, k;
    if(!tr.is_facet(t[0], t[1], t[2], c, i, j, k)) continue;
    const int l = 6 - i - j - k;
    if(tr.is_infinite(c) || tr.is_infinite(c->neighbor(l))) continue;
    const auto conf = classify_facet(tr, c, l);
    if(!conf.is_swappable() || !flip_respects_constraints(tr, conf.flip_plan(), constraints) ||
       !criterion(tr, conf))
      continue;
    if(result.total_swaps() >= max_swaps)
    {
      result.swap_limit_reached = true;
      return;
    }
    const int n = flip(tr, conf, created, constraints);
    ++result.swaps[conf.flip_kind()];
    for(int m = 0; m < n; ++m) push_facets(created[m]);
  }
}

} // namespace internal

namespace internal {

/// `insert_by_swapping` with its settings spelled out.
template <class Tr, class Criterion, class Constraints>
Insertion_result<Tr> insert_by_swapping(Tr& tr, const typename Tr::Point& p, const Criterion& criterion,
                                        typename Tr::Cell_handle hint, const Constraints& constraints,
                                        Perturbation perturbation, std::size_t max_swaps)
{
  CGAL_precondition(tr.dimension() == 3);
  if constexpr(Is_regular_criterion<Criterion>::value)
    return insert_weighted(tr, p, hint, constraints, perturbation);
  else
  {
    Insertion_result<Tr> result;
    int li, lj;
    // CGAL's walk: exact orientation tests, remembering and stochastic.
    const auto c = tr.locate(p, result.location, li, lj, hint);
    if(result.location == Tr::VERTEX)
    {
      result.vertex = c->vertex(li);
      return result;
    }
    if(!split_is_allowed(tr, c, result.location, li, lj, constraints))
      return result;
    result.vertex = split_with_data(tr, p, c, result.location, li, lj, constraints);
    result.is_new = true;
    if constexpr(Is_delaunay_criterion<Criterion>::value)
      flip_link_to_delaunay(tr, result.vertex, perturbation, constraints, result);
    else
      swap_around(tr, result.vertex, criterion, constraints, max_swaps, result);
    return result;
  }
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Functions
/// \brief Inserts `p` into `tr` by splitting the simplex it falls in, then
/// swapping outward from the new vertex under `criterion`.
///
/// With a Delaunay criterion (`Is_delaunay_criterion`), inserting into a
/// Delaunay triangulation gives the Delaunay triangulation of the points with
/// `p` (with `CGAL_PERTURBATION`: CGAL's own, cell for cell); only the link of
/// the new vertex is tested. Other criteria test every facet of a changed
/// cell again and stop after `maximum_swaps` swaps. With `Regular_criterion`
/// on a `Regular_triangulation_3` (weighted points), inserting into a regular
/// triangulation gives the regular triangulation with `p`, CGAL's cell for
/// cell: a redundant `p` is hidden (`result.hidden`), and the vertices that
/// `p` makes redundant are removed by 4-1 flips (`result.removed_vertices`).
/// In a domain mesh a point
/// outside the domain, or on a constrained facet or on an edge of one, is
/// refused and `tr` is left unchanged.
///
/// \tparam Tr a `CGAL::Triangulation_3`
/// \tparam Criterion a model of `SwapCriterion_3`
/// \tparam NamedParameters a sequence of named parameters (`CGAL::Named_function_parameters`)
/// \param tr the triangulation, of dimension 3
/// \param p the point to insert
/// \param criterion decides the swaps after the split
/// \param np an optional sequence of named parameters among the ones listed below
/// \pre `tr.dimension() == 3`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{hint}
///     \cgalParamDescription{the cell where the walk to `p` starts}
///     \cgalParamType{`Tr::Cell_handle`}
///     \cgalParamDefault{anywhere}
///   \cgalParamNEnd
///   \cgalParamNBegin{perturbation}
///     \cgalParamDescription{how a Delaunay criterion breaks cospherical ties}
///     \cgalParamType{`Edge_swapping_3::Perturbation`}
///     \cgalParamDefault{`Edge_swapping_3::CGAL_PERTURBATION`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_swaps}
///     \cgalParamDescription{criteria other than Delaunay: the most swaps after the split}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{100000}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_is_constrained_map, cell_is_selected_map, mesh_constraints}
///     \cgalParamDescription{the domain, as for `swap_edges()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the new vertex (or the vertex already at `p`, or the default handle when refused) and the swaps made
template <class Tr, class Criterion, class NamedParameters = CGAL::parameters::Default_named_parameters>
Insertion_result<Tr> insert_by_swapping(Tr& tr, const typename Tr::Point& p, const Criterion& criterion,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto hint = choose_parameter(get_parameter(np, internal_np::hint), typename Tr::Cell_handle());
  const Perturbation perturbation = choose_parameter(get_parameter(np, internal_np::perturbation), CGAL_PERTURBATION);
  const std::size_t max_swaps = choose_parameter(get_parameter(np, internal_np::maximum_swaps), std::size_t(100000));
  return internal::with_domain_constraints(tr, np, [&](const auto& constraints) {
    return internal::insert_by_swapping(tr, p, criterion, typename Tr::Cell_handle(hint), constraints, perturbation,
                                        max_swaps);
  });
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_POINT_INSERTION_H
