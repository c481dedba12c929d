// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's five-point taxonomy (Figs. 6 and 7, appendix B): what the five
// vertices of the two tetrahedra on either side of an interior facet look
// like, whether they admit a second triangulation, and which one. This is the
// first half of the EDGE_SWAP primitive (Algorithm 2); `flip()` is the second.

#ifndef CGAL_EDGE_SWAPPING_3_FIVE_POINT_CONFIGURATION_H
#define CGAL_EDGE_SWAPPING_3_FIVE_POINT_CONFIGURATION_H

#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/Exact_predicates.h>
#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <CGAL/Edge_swapping_3/internal/edge_ring.h>

namespace CGAL {
namespace Edge_swapping_3 {

/// The configurations of Figs. 6 and 7. The first four are swappable.
enum Configuration_kind
{
  TWO_TETRAHEDRA_CONVEX,    ///< Fig. 6(a): convex pair, 2-3 flip to three tetrahedra
  THREE_TETRAHEDRA_CONVEX,  ///< Fig. 6(b): three around an edge, 3-2 flip to two
  PLANAR_HULL_TWO_TWO,      ///< Fig. 6(c): four coplanar points on the hull, 2-2 flip
  PLANAR_FOUR_FOUR,         ///< Fig. 6(d): four coplanar points inside, 4-4 flip
  FOUR_TETRAHEDRA,          ///< Fig. 7(a): one point inside the tetrahedron of the others
  CONCAVE,                  ///< a concave pair (or triple): no second triangulation here
  PLANAR_UNSWAPPABLE,       ///< Figs. 7(b), 7(c) and the other coplanar or collinear cases
  HULL_FACET                ///< not an interior facet: one side is outside the hull
};

/// The name of `k`, for reports.
inline const char* configuration_kind_name(Configuration_kind k)
{
  static const char* names[] = {"two tetrahedra convex", "three tetrahedra convex",
                                "planar hull 2-2", "planar 4-4", "four tetrahedra",
                                "concave", "planar unswappable", "hull facet"};
  return names[k];
}

/// The configuration at one facet: its kind, the tetrahedra of the mesh made
/// of its five vertices, and, when it is swappable, the flip to the alternative.
template <class Tr>
class Five_point_configuration
{
public:
  typedef typename Tr::Cell_handle Cell_handle;     ///< the triangulation's cell handle
  typedef typename Tr::Vertex_handle Vertex_handle; ///< the triangulation's vertex handle
  typedef Flip_plan<Tr> Plan;                       ///< the flip to the alternative

  /// Which of the paper's configurations (Figs. 6 and 7) the five points form.
  Configuration_kind kind() const { return kind_; }
  /// Whether the alternative triangulation exists and a flip reaches it.
  bool is_swappable() const { return kind_ <= PLANAR_FOUR_FOUR; }

  /// The cell of the facet that was inspected.
  Cell_handle cell() const { return cell_; }
  /// The index of the facet that was inspected in `cell()`.
  int index() const { return index_; }

  /// The number of tetrahedra of the mesh whose four vertices are among the five (two to four).
  int number_of_tetrahedra() const { return n_tets_; }
  /// The `k`-th of them, `0 <= k < number_of_tetrahedra()`.
  Cell_handle tetrahedron(int k) const { return tets_[k]; }

  /// The flip to the alternative triangulation; meaningful when swappable.
  /// Its old cells are the current triangulation of the configuration (for the
  /// planar cases, with the cells on the other side of the plane), its new
  /// cells the alternative.
  const Plan& flip_plan() const { return plan_; }
  /// The kind of that flip.
  Flip_kind flip_kind() const { return plan_.kind; }

  /// Whether the answer also depends on the cells around one edge of the
  /// facet (the 3-2 and the planar cases: how many cells the edge has); if so,
  /// `a` and `b` are its vertices. Otherwise it depends on the two cells alone.
  /// \param a set to the first vertex of the edge, or the default handle
  /// \param b set to the second vertex of the edge, or the default handle
  /// \return whether there is such an edge
  bool depends_on_edge_ring(Vertex_handle& a, Vertex_handle& b) const
  {
    a = ring_edge_[0];
    b = ring_edge_[1];
    return a != Vertex_handle();
  }

  /// \cond SKIP_IN_MANUAL
  template <class T>
  friend Five_point_configuration<T> classify_facet(const T&, typename T::Cell_handle, int);
  /// \endcond

private:
  Configuration_kind kind_ = HULL_FACET;
  Cell_handle cell_;
  int index_ = 0;
  int n_tets_ = 0;
  std::array<Cell_handle, 4> tets_;
  std::array<Vertex_handle, 2> ring_edge_;
  Plan plan_;
};

/// Classifies the configuration of facet `(c, i)` with exact predicates.
/// Requires a valid triangulation of dimension 3.
template <class Tr>
Five_point_configuration<Tr> classify_facet(const Tr& tr, typename Tr::Cell_handle c, int i)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  internal::require_exact_predicates<typename Tr::Geom_traits>();
  CGAL_precondition(tr.dimension() == 3);

  Five_point_configuration<Tr> conf;
  conf.cell_ = c;
  conf.index_ = i;
  const Cell_handle n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n))
    return conf; // HULL_FACET

  const Vertex_handle e = n->vertex(n->index(c));
  conf.tets_[conf.n_tets_++] = c;
  for(int k = 0; k < 4; ++k)
    if(c->neighbor(k)->has_vertex(e))
      conf.tets_[conf.n_tets_++] = c->neighbor(k);

  // Signs of the barycentric coordinates of e in c (appendix A): replacing
  // vertex k of c by e gives the sign of b_k.
  auto orientation = tr.geom_traits().orientation_3_object();
  int pos = 0, zero = 0, neg = 0, k_zero = -1, k_neg = -1;
  for(int k = 0; k < 4; ++k)
  {
    if(k == i) continue;
    std::array<const typename Tr::Geom_traits::Point_3*, 4> p;
    for(int m = 0; m < 4; ++m)
      p[m] = (m == k) ? &internal::bare_point(e->point()) : &internal::bare_point(c->vertex(m)->point());
    const Orientation o = orientation(*p[0], *p[1], *p[2], *p[3]);
    if(o == POSITIVE) ++pos;
    else if(o == ZERO) { ++zero; k_zero = k; }
    else { ++neg; k_neg = k; }
  }

  auto& plan = conf.plan_;
  if(pos == 3)
  {
    internal::plan_flip_2_3(plan, c, i);
    conf.kind_ = TWO_TETRAHEDRA_CONVEX;
    return conf;
  }

  // The edge of the facet that lies opposite the vertex k.
  auto edge_opposite = [&](int k, int& a, int& b) {
    a = -1;
    for(int m = 0; m < 4; ++m)
      if(m != i && m != k) { if(a < 0) a = m; else b = m; }
  };

  if(pos == 2 && neg == 1)
  {
    // Concave at the edge opposite k_neg; convex if a third tetrahedron fills it.
    // The edge has three cells exactly when the cell across the facet of c
    // opposite k_neg also holds e. The 3-2 flip then replaces the three by c
    // with a, and c with b, replaced by e: the two cells whose orientations
    // were just found positive, so it is valid.
    int a, b;
    edge_opposite(k_neg, a, b);
    const Cell_handle t = c->neighbor(k_neg);
    conf.kind_ = CONCAVE;
    conf.ring_edge_ = {c->vertex(a), c->vertex(b)};
    if(t->has_vertex(e))
    {
      internal::plan_flip_3_2(plan, c, i, k_neg);
      conf.kind_ = THREE_TETRAHEDRA_CONVEX;
    }
    return conf;
  }

  if(pos == 2 && zero == 1)
  {
    // e lies in the plane of d and the edge opposite k_zero: four coplanar points.
    int a, b;
    edge_opposite(k_zero, a, b);
    internal::Edge_ring<Tr> ring(tr, c, a, b);
    conf.kind_ = PLANAR_UNSWAPPABLE;
    conf.ring_edge_ = {c->vertex(a), c->vertex(b)};
    if(ring.size() == 4 && ring.plan_flip(plan, ring.diagonal_through(c->vertex(i), e)) &&
       worst_orientation(tr, plan) == POSITIVE)
      conf.kind_ = (plan.kind == FLIP_2_2) ? PLANAR_HULL_TWO_TWO : PLANAR_FOUR_FOUR;
    return conf;
  }

  if(pos == 1 && neg == 2)
    conf.kind_ = (conf.n_tets_ == 4) ? FOUR_TETRAHEDRA : CONCAVE;
  else
    conf.kind_ = PLANAR_UNSWAPPABLE; // collinear (7b), mixed (7c)
  return conf;
}

/// Carries out the swap of a swappable configuration, which must be fresh (no
/// change to the triangulation since it was classified). Writes the handles
/// of the new cells to `created` and returns their number. Cell and facet data
/// follow the tetrahedra as `constraints` says (see `execute_flip`).
template <class Tr, class Constraints = No_constraints>
int flip(Tr& tr, const Five_point_configuration<Tr>& conf,
         std::array<typename Tr::Cell_handle, 4>& created,
         const Constraints& constraints = Constraints())
{
  CGAL_precondition(conf.is_swappable());
  return execute_flip(tr, conf.flip_plan(), created, constraints);
}

/// Carries out the swap of a swappable, fresh configuration.
template <class Tr>
void flip(Tr& tr, const Five_point_configuration<Tr>& conf)
{
  std::array<typename Tr::Cell_handle, 4> created;
  flip(tr, conf, created);
}

/// Swaps the configuration of facet `(c, i)` into its alternative if it has one.
/// Returns false, leaving `tr` untouched, for an unswappable configuration.
template <class Tr>
bool flip_facet(Tr& tr, typename Tr::Cell_handle c, int i)
{
  const auto conf = classify_facet(tr, c, i);
  if(!conf.is_swappable()) return false;
  flip(tr, conf);
  return true;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_FIVE_POINT_CONFIGURATION_H
