// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh as files hold it (points with named fields, tetrahedra by point
// number, subdomain and boundary references), and its glue to a
// triangulation whose vertices carry their point numbers: build the
// triangulation from it, give new vertices their numbers and field values,
// and take a snapshot of the triangulation to write. Reading and writing
// files is in IO/mesh_with_fields.h.

#ifndef CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_H
#define CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_H

#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <CGAL/Edge_swapping_3/internal/exterior_fill.h>
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Domains
/// A mesh as a file holds it: points with named fields and, for a mesh (not a
/// bare point set), tetrahedra with subdomain references and boundary
/// triangles. Points inserted later are appended, so that `points` and
/// `fields` describe the current mesh, numbered as the vertices' `info()` of
/// a `Numbered_domain_triangulation_3`.
template <class Point>
struct Mesh_with_fields
{
  std::vector<Point> points;                            ///< by point number
  std::vector<std::string> field_names;                 ///< names of the point fields
  std::vector<std::vector<double>> fields;              ///< `fields[f][point]`
  int first_index = 1;                                  ///< the first number of TetGen files (0 or 1)
  std::vector<std::size_t> point_tags;                  ///< the file's own number of each point (Gmsh node tags), or empty
  std::vector<std::array<std::size_t, 4>> cells;        ///< tetrahedra, by point number
  std::vector<int> cell_references;                     ///< subdomain of each cell (empty: all in subdomain 1)
  std::vector<std::array<std::size_t, 3>> triangles;    ///< constrained (boundary) triangles
  std::vector<int> triangle_references;                 ///< boundary reference of each triangle
  std::vector<std::string> cell_field_names;            ///< names of the cell fields (written to VTK files)
  std::vector<std::vector<double>> cell_fields;         ///< `cell_fields[f][cell]`
  bool is_mesh = false;                                 ///< tetrahedra given (else a point set)
  bool has_references = false;                          ///< subdomains and boundaries apply (Medit, VTK `subdomain`)
  std::vector<std::size_t> removed_points;              ///< points whose vertex an operation removed: snapshots leave them out

  /// The number of the point field `name`, or -1.
  int field_index(const std::string& name) const
  {
    const auto it = std::find(field_names.begin(), field_names.end(), name);
    return it == field_names.end() ? -1 : int(it - field_names.begin());
  }
};

/// \ingroup PkgEdgeSwapping3Domains
/// The largest field value supported: differences, interpolations and the
/// gradient indicator of such values stay finite.
constexpr double max_field_value = 1e100;

/// \ingroup PkgEdgeSwapping3Domains
/// A triangulation for `Mesh_with_fields`: each vertex remembers its point
/// number (`info()`), each cell its subdomain and boundary references
/// (`Domain_cell_info`, the model `Domain_constraints`).
template <class Gt>
using Numbered_domain_triangulation_3 =
    CGAL::Triangulation_3<Gt, CGAL::Triangulation_data_structure_3<
                                  CGAL::Triangulation_vertex_base_with_info_3<std::size_t, Gt>,
                                  CGAL::Triangulation_cell_base_with_info_3<Domain_cell_info, Gt>>>;

/// \ingroup PkgEdgeSwapping3Domains
/// Whether `tr`, built by `build_numbered_mesh()`, holds cells that complete
/// its domain to a convex region (cells of subdomain `Domain_cell_info::completion`):
/// then the hull's cells are all such cells.
template <class Tr>
bool is_completed_domain(const Tr& tr)
{
  if(tr.dimension() < 3) return false;
  const auto c = tr.infinite_vertex()->cell();
  return c->neighbor(c->index(tr.infinite_vertex()))->info().subdomain == Domain_cell_info::completion;
}

/// \ingroup PkgEdgeSwapping3Domains
/// The number of finite cells of `tr` that are the mesh's own (not added by
/// `build_numbered_mesh()` to complete its domain).
template <class Tr>
std::size_t number_of_mesh_cells(const Tr& tr)
{
  if(!is_completed_domain(tr)) return tr.number_of_finite_cells();
  std::size_t n = 0;
  for(auto c : tr.finite_cell_handles()) n += c->info().subdomain != Domain_cell_info::completion;
  return n;
}

/// \ingroup PkgEdgeSwapping3Domains
/// The number of finite vertices of `tr` that are the mesh's own (not added
/// by `build_numbered_mesh()` to complete its domain).
template <class Tr>
std::size_t number_of_mesh_vertices(const Tr& tr)
{
  if(!is_completed_domain(tr)) return tr.number_of_vertices();
  std::size_t n = 0;
  for(auto v : tr.finite_vertex_handles()) n += v->info() < std::size_t(-1) / 2;
  return n;
}

/// \ingroup PkgEdgeSwapping3Domains
/// Builds in `tr` (empty) the tetrahedra of the mesh `mesh`, each vertex
/// numbered by its point, each cell with its subdomain (1 without
/// references, 0 for the infinite cells), and the boundary references of the
/// triangles on their facets.
///
/// A mesh of a domain of any shape is accepted: when the tetrahedra do not
/// make a triangulation of the convex hull of their points (the domain is
/// not convex, has cavities or several parts), the outside of the domain is
/// filled up to a box around it with cells of subdomain
/// `Domain_cell_info::completion` (by TetGen's library, the domain's
/// boundary kept: points are added only strictly outside the domain, their
/// vertices numbered from `std::size_t(-1)` down), and the whole is checked
/// exactly as one triangulation of the box. The boundary of the domain
/// then separates cells of different subdomains, so no operation removes it;
/// `numbered_mesh_snapshot()` writes back the domain's cells alone.
/// Points that no tetrahedron uses (those of lines or surfaces meshed alone)
/// are kept in the mesh, out of the triangulation.
///
/// Returns an empty string, or what is wrong with the mesh (see
/// `build_triangulation_from_cells()`; a facet of more than two tetrahedra;
/// a boundary that intersects itself; a triangle that is not a facet of the
/// tetrahedra).
/// \tparam Tr a `Numbered_domain_triangulation_3`, or a triangulation with the same `info()` types
template <class Tr, class Point>
std::string build_numbered_mesh(Tr& tr, const Mesh_with_fields<Point>& mesh)
{
  typedef typename Tr::Point Tr_point;
  std::vector<typename Tr::Vertex_handle> vertices;
  std::vector<typename Tr::Cell_handle> cells;
  for(int r : mesh.cell_references)
    if(r == Domain_cell_info::completion)
      return "the subdomain reference " + std::to_string(r) + " is reserved (the package's mark of cells outside "
             "the domain): renumber the subdomains";
  // Points that no tetrahedron uses (of lines or surfaces meshed alone)
  // stay in the mesh, out of the triangulation: its point k is `own[k]`.
  const std::vector<Tr_point>* points = &mesh.points;
  const std::vector<std::array<std::size_t, 4>>* tetrahedra = &mesh.cells;
  std::vector<Tr_point> used_points;
  std::vector<std::array<std::size_t, 4>> renumbered;
  std::vector<std::size_t> own, number(mesh.points.size(), std::size_t(-1));
  for(const auto& t : mesh.cells)
    for(auto v : t)
      if(v < number.size()) number[v] = 0;
  if(!mesh.cells.empty() && std::count(number.begin(), number.end(), std::size_t(-1)) > 0)
  {
    for(std::size_t v = 0; v < number.size(); ++v)
      if(number[v] == 0)
      {
        number[v] = own.size();
        own.push_back(v);
        used_points.push_back(mesh.points[v]);
      }
    renumbered = mesh.cells;
    for(auto& t : renumbered)
      for(auto& v : t) v = v < number.size() ? number[v] : std::size_t(-1) / 2; // out of range: refused below
    points = &used_points;
    tetrahedra = &renumbered;
  }
  else
    for(std::size_t v = 0; v < number.size(); ++v) number[v] = v;

  // Messages name the points as the file numbers them.
  const internal::Point_names names{own.empty() ? nullptr : &own};
  bool boundary_shape = false;
  std::string problem = internal::build_triangulation_from_cells(tr, *points, *tetrahedra, vertices, cells, 100000,
                                                                 &boundary_shape, names);
  if(!problem.empty())
  {
    if(!boundary_shape) return problem;
    // Not the triangulation of its convex hull: fill the outside.
    internal::Exterior_fill fill = internal::fill_exterior(*points, *tetrahedra, names);
    if(!fill.problem.empty()) return fill.problem;
    std::vector<Tr_point> all_points(points->begin(), points->end());
    for(const auto& p : fill.added_points) all_points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::array<std::size_t, 4>> all = *tetrahedra;
    // The added cells take the orientation of the domain's.
    auto orientation = tr.geom_traits().orientation_3_object();
    auto sign = [&](const std::array<std::size_t, 4>& t) {
      return orientation(all_points[t[0]], all_points[t[1]], all_points[t[2]], all_points[t[3]]);
    };
    const Orientation domain_sign = sign(tetrahedra->front());
    for(auto t : fill.cells)
    {
      if(sign(t) != domain_sign) std::swap(t[0], t[1]);
      all.push_back(t);
    }
    problem = internal::build_triangulation_from_cells(tr, all_points, all, vertices, cells, 100000, nullptr, names);
    if(!problem.empty())
      return "the domain's boundary could not be kept while filling its outside (" + problem +
             "): the tetrahedra overlap, or the mesh is not conforming";
    for(std::size_t k = tetrahedra->size(); k < cells.size(); ++k)
      cells[k]->info().subdomain = Domain_cell_info::completion;
  }
  const std::size_t n = points->size();
  for(std::size_t k = 0; k < vertices.size(); ++k)
    vertices[k]->info() = k >= n ? std::size_t(-1) - (k - n) : own.empty() ? k : own[k];
  const bool one_subdomain = mesh.cell_references.empty();
  for(auto c : tr.all_cell_handles())
  {
    const bool added = c->info().subdomain == Domain_cell_info::completion;
    c->info() = Domain_cell_info();
    if(tr.is_infinite(c)) c->info().subdomain = 0;
    else if(added) c->info().subdomain = Domain_cell_info::completion;
    else if(one_subdomain) c->info().subdomain = 1;
  }
  // The cells come in the order of the tetrahedra read (a jump in memory
  // for each, in the Hilbert order of a large mesh: only when needed).
  if(!one_subdomain)
    for(std::size_t k = 0; k < mesh.cells.size(); ++k) cells[k]->info().subdomain = mesh.cell_references[k];
  for(std::size_t k = 0; k < mesh.triangles.size(); ++k)
  {
    const auto& t = mesh.triangles[k];
    typename Tr::Cell_handle c;
    int i, j, l;
    auto on_tetrahedra = [&](std::size_t v) { return v < number.size() && number[v] < n; };
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !on_tetrahedra(t[0]) || !on_tetrahedra(t[1]) ||
       !on_tetrahedra(t[2]) ||
       !tr.is_facet(vertices[number[t[0]]], vertices[number[t[1]]], vertices[number[t[2]]], c, i, j, l))
      return "triangle " + std::to_string(k + 1) + " is not a facet of the tetrahedra";
    const int f = 6 - i - j - l;
    c->info().facet_reference[f] = mesh.triangle_references[k];
    c->neighbor(f)->info().facet_reference[c->neighbor(f)->index(c)] = mesh.triangle_references[k];
  }
  return {};
}

/// \ingroup PkgEdgeSwapping3Domains
/// Gives the cells of `tr`, the triangulation of a point set, its domain:
/// every finite cell in subdomain 1, no constrained facet.
template <class Tr>
void mark_point_set_domain(Tr& tr)
{
  for(auto c : tr.all_cell_handles())
  {
    c->info() = Domain_cell_info();
    c->info().subdomain = tr.is_infinite(c) ? 0 : 1;
  }
}

/// \ingroup PkgEdgeSwapping3Domains
/// Returns `run(constraints)` for `tr`, built from `mesh` by
/// `build_numbered_mesh()`: `Domain_constraints` when `mesh` has references
/// (subdomains, boundary triangles) or `tr` completes a domain that is not convex, else `No_constraints`.
template <class Tr, class Point, class Run>
auto with_mesh_constraints(const Tr& tr, const Mesh_with_fields<Point>& mesh, Run run)
{
  if(mesh.has_references || is_completed_domain(tr)) return run(Domain_constraints());
  return run(No_constraints());
}

/// \ingroup PkgEdgeSwapping3Domains
/// Numbers the new vertex `v` after the points of `mesh` and appends its
/// point and its field values (`values[f]` for field `f`).
template <class Point, class Vertex_handle>
void add_numbered_vertex(Mesh_with_fields<Point>& mesh, Vertex_handle v, const std::vector<double>& values)
{
  v->info() = mesh.points.size();
  mesh.points.push_back(v->point());
  for(std::size_t f = 0; f < mesh.fields.size(); ++f) mesh.fields[f].push_back(values[f]);
}

/// \ingroup PkgEdgeSwapping3Domains
/// Renumbers the points from `first_added` on (those vertex insertion
/// appended) in the order `tr` stores their vertices, those removed since
/// last: the numbers then depend on the mesh, not on the order in which the
/// threads of a run in parts told the visitor of them.
template <class Tr, class Point>
void renumber_added_points(const Tr& tr, Mesh_with_fields<Point>& mesh, std::size_t first_added)
{
  const std::size_t n = mesh.points.size();
  if(first_added >= n) return;
  std::vector<std::size_t> order; // old numbers, in their new order
  std::vector<char> placed(n - first_added, 0);
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    if(v->info() >= first_added && v->info() < n)
    {
      order.push_back(v->info());
      placed[v->info() - first_added] = 1;
    }
  for(std::size_t k = first_added; k < n; ++k)
    if(!placed[k - first_added]) order.push_back(k);
  std::vector<std::size_t> number(n - first_added);
  for(std::size_t k = 0; k < order.size(); ++k) number[order[k] - first_added] = first_added + k;
  auto permuted = [&](auto& values) {
    auto old = values;
    for(std::size_t k = 0; k < order.size(); ++k) values[first_added + k] = old[order[k]];
  };
  permuted(mesh.points);
  for(auto& field : mesh.fields) permuted(field);
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    if(v->info() >= first_added && v->info() < n) v->info() = number[v->info() - first_added];
  for(std::size_t& k : mesh.removed_points)
    if(k >= first_added && k < n) k = number[k - first_added];
}

/// \ingroup PkgEdgeSwapping3Domains
/// The values of the point fields of `mesh` at `p`, a new vertex that fell
/// in the cell `where` describes (a `Site_location`, whose vertices are
/// numbered by `info()`): a field for which `computed(name, p, value)` returns
/// true takes that value (an analytic field such as
/// `two_spheres_flow_field()`); the others are interpolated linearly.
template <class Point, class Location, class Computed>
std::vector<double> interpolated_field_values(const Mesh_with_fields<Point>& mesh, const Point& p,
                                              const Location& where, Computed computed)
{
  std::vector<double> values(mesh.fields.size(), 0.0);
  for(std::size_t f = 0; f < mesh.fields.size(); ++f)
  {
    if(computed(mesh.field_names[f], p, values[f])) continue;
    for(int k = 0; k < 4; ++k)
      if(where.weights[k] != 0) values[f] += where.weights[k] * mesh.fields[f][where.vertices[k]->info()];
  }
  return values;
}

namespace internal {

/// Leaves the points `removed` (used by no cell or triangle) out of `mesh`,
/// and renumbers the others in their order.
template <class Point>
void leave_out_points(Mesh_with_fields<Point>& mesh, const std::vector<std::size_t>& removed)
{
  std::vector<char> gone(mesh.points.size(), 0);
  for(std::size_t k : removed) gone[k] = 1;
  std::vector<std::size_t> number(mesh.points.size());
  // Points added after reading have no tag yet (the writer numbers them on).
  std::size_t n = 0, tagged = 0;
  for(std::size_t k = 0; k < mesh.points.size(); ++k)
  {
    number[k] = n;
    if(gone[k]) continue;
    mesh.points[n] = mesh.points[k];
    for(auto& f : mesh.fields) f[n] = f[k];
    if(k < mesh.point_tags.size()) mesh.point_tags[tagged++] = mesh.point_tags[k];
    ++n;
  }
  mesh.points.resize(n);
  for(auto& f : mesh.fields) f.resize(n);
  mesh.point_tags.resize((std::min)(tagged, mesh.point_tags.size()));
  for(auto& t : mesh.cells)
    for(auto& k : t) k = number[k];
  for(auto& t : mesh.triangles)
    for(auto& k : t) k = number[k];
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Domains
/// The part of a `ReplacementVisitor_3` that keeps `mesh` (the mesh a
/// `Numbered_domain_triangulation_3` was built from) in step with vertex
/// insertion and removal: a new vertex is numbered after the points and takes
/// the field values that `computed(name, p, value)` gives or, where it
/// returns false, those interpolated linearly in the old cell that held it;
/// a removed vertex's point goes to `mesh.removed_points`. Derive from it, or
/// pass it as the `visitor`; `mesh` must outlive the run.
template <class Point, class Computed = bool (*)(const std::string&, const Point&, double&)>
class Numbered_vertex_visitor : public Default_replacement_visitor
{
public:
  /// Keeps `mesh` in step; `computed` gives the fields it knows (by default none).
  explicit Numbered_vertex_visitor(Mesh_with_fields<Point>& mesh,
                                   Computed computed = [](const std::string&, const Point&, double&) { return false; })
      : mesh_(&mesh), computed_(computed) {}

  /// Numbers `v` after the points and gives it its field values.
  template <class Tr>
  void after_insertion(const Tr&, typename Tr::Vertex_handle v, const std::array<typename Tr::Vertex_handle, 4>& corners,
                       const std::array<double, 4>& weights) const
  {
    struct
    {
      std::array<typename Tr::Vertex_handle, 4> vertices;
      std::array<double, 4> weights;
    } where{corners, weights};
    add_numbered_vertex(*mesh_, v, interpolated_field_values(*mesh_, Point(v->point()), where, computed_));
  }
  /// Records the point of `v` as removed.
  template <class Tr>
  void before_removal(const Tr&, typename Tr::Vertex_handle v, typename Tr::Vertex_handle) const
  {
    mesh_->removed_points.push_back(v->info());
  }

private:
  Mesh_with_fields<Point>* mesh_;
  Computed computed_;
};

/// \ingroup PkgEdgeSwapping3Domains
/// The mesh that `tr` is now, numbered as `mesh` (the mesh it was built from,
/// with its added vertices): the points where they are (smoothing moves
/// interior ones), the point fields of `mesh`, the finite cells with their
/// subdomains (all 1 without references), each constrained facet once (seen
/// from the cell whose sorted point numbers come first, or from the finite
/// side, so that the output does not depend on addresses), and the cell
/// field `subdomain`. `add_quality_cell_fields()` adds the cells' quality.
/// The points of `mesh.removed_points` are left out and the others renumbered
/// in their order.
template <class Tr, class Point>
Mesh_with_fields<Point> numbered_mesh_snapshot(const Tr& tr, const Mesh_with_fields<Point>& mesh)
{
  Mesh_with_fields<Point> out;
  out.points = mesh.points;
  for(auto v : tr.finite_vertex_handles())
    if(v->info() < out.points.size()) out.points[v->info()] = v->point();
  out.field_names = mesh.field_names;
  out.fields = mesh.fields;
  out.first_index = mesh.first_index;
  out.point_tags = mesh.point_tags;
  out.is_mesh = true;
  out.has_references = mesh.has_references;
  out.cells.reserve(tr.number_of_finite_cells());
  out.cell_references.reserve(tr.number_of_finite_cells());
  auto added = [](typename Tr::Cell_handle c) { return c->info().subdomain == Domain_cell_info::completion; };
  for(auto c : tr.finite_cell_handles())
  {
    if(added(c)) continue;
    out.cells.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    out.cell_references.push_back(mesh.has_references ? c->info().subdomain : 1);
  }
  out.cell_field_names = {"subdomain"};
  out.cell_fields = {std::vector<double>(out.cell_references.begin(), out.cell_references.end())};
  auto key = [&](typename Tr::Cell_handle c) {
    std::array<std::size_t, 4> k;
    for(int i = 0; i < 4; ++i) k[i] = tr.is_infinite(c->vertex(i)) ? std::size_t(-1) : c->vertex(i)->info();
    std::sort(k.begin(), k.end());
    return k;
  };
  for(auto c : tr.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      if(added(c) || c->info().facet_reference[i] == Domain_cell_info::no_reference) continue;
      const auto n = c->neighbor(i);
      if(!tr.is_infinite(n) && !added(n) && !(key(c) < key(n))) continue;
      out.triangles.push_back(
          {c->vertex((i + 1) & 3)->info(), c->vertex((i + 2) & 3)->info(), c->vertex((i + 3) & 3)->info()});
      out.triangle_references.push_back(c->info().facet_reference[i]);
    }
  if(!mesh.removed_points.empty()) internal::leave_out_points(out, mesh.removed_points);
  return out;
}

/// \ingroup PkgEdgeSwapping3Domains
/// Adds to `mesh` the quality of each of its cells as cell fields
/// (`edge_length_ratio`, `circumradius_over_inradius` R/r, `radius_ratio`
/// 3r/R, `min_dihedral_angle`, `max_dihedral_angle`), for viewers such as
/// ParaView (VTK files keep cell fields).
template <class Point>
void add_quality_cell_fields(Mesh_with_fields<Point>& mesh)
{
  std::array<std::vector<double>, 5> q;
  for(auto& values : q) values.reserve(mesh.cells.size());
  for(const auto& t : mesh.cells)
  {
    const Point& a = mesh.points[t[0]];
    const Point& b = mesh.points[t[1]];
    const Point& d = mesh.points[t[2]];
    const Point& e = mesh.points[t[3]];
    const auto angles = dihedral_angles(a, b, d, e);
    const double radii = circumradius_over_inradius(a, b, d, e);
    q[0].push_back(edge_length_ratio(a, b, d, e));
    q[1].push_back(radii);
    q[2].push_back(3 / radii);
    q[3].push_back(*std::min_element(angles.begin(), angles.end()));
    q[4].push_back(*std::max_element(angles.begin(), angles.end()));
  }
  const char* names[5] = {"edge_length_ratio", "circumradius_over_inradius", "radius_ratio", "min_dihedral_angle",
                          "max_dihedral_angle"};
  for(int k = 0; k < 5; ++k)
  {
    mesh.cell_field_names.push_back(names[k]);
    mesh.cell_fields.push_back(std::move(q[k]));
  }
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_MESH_WITH_FIELDS_H
