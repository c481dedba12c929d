// SPDX-License-Identifier: GPL-3.0-or-later
// The peers of the quality benchmark (benchmark_quality_operations): each takes the same mesh as
// lists of points and tetrahedra with a subdomain per tetrahedron, and gives
// its result back the same way, so that one quality code measures every row.
//  - TetGen 1.5's optimizer through libtet (when CMake found it): the mesh is
//    reconstructed (`-r`) with its boundary triangles as subfaces, then
//    `optimizemesh` runs with the thresholds set in `tetgenbehavior` directly
//    (the program cannot lower its 165 degree target without `-q`, which
//    inserts points); `facet_ang_tol = 180` so that no boundary face flips.
//  - CGAL's Tetrahedral_remeshing: its remesher's flip step alone, or its flip
//    and smoothing steps in the order of its own loop, repeated; or its
//    public function as its examples call it; boundaries (facets between
//    subdomains, the hull) protected.
//  - Gmsh 4.8's optimizer (Debian's python3-gmsh), through a Medit file and
//    gmsh_optimize.py: each subdomain a discrete volume, the boundary
//    triangles a discrete surface.

#ifndef EDGE_SWAPPING_3_BENCHMARK_QUALITY_PEERS_H
#define EDGE_SWAPPING_3_BENCHMARK_QUALITY_PEERS_H

#include <CGAL/Real_timer.h>
#include <CGAL/tetrahedral_remeshing.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <CGAL/Edge_swapping_3/internal/exterior_fill.h>
#include <CGAL/Edge_swapping_3/IO/medit.h>
#include <array>
#include <cstdlib>
#include <fstream>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>
#ifdef EDGE_SWAPPING_3_WITH_TETGEN
#include <tetgen.h>
#endif

namespace quality_peers {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

/// A mesh as lists; `subdomains[k]` is that of `cells[k]`.
struct Cell_mesh
{
  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 4>> cells;
  std::vector<int> subdomains;
};

/// What a peer did: its result, its time (optimization only, no conversion)
/// and the number of points it moved.
struct Peer_result
{
  Cell_mesh mesh;
  double seconds = 0;
  std::size_t moved = 0;
  std::string error; ///< empty when it ran
};

/// The cells of `tr`, its vertices numbered by `index`; `subdomain(c)` names
/// a finite cell's subdomain.
template <class Tr, class Index, class Subdomain>
Cell_mesh cell_mesh_of(const Tr& tr, const std::vector<K::Point_3>& points, const Index& index,
                       const Subdomain& subdomain)
{
  Cell_mesh m;
  m.points = points;
  for(auto c : tr.finite_cell_handles())
  {
    m.cells.push_back({index(c->vertex(0)), index(c->vertex(1)), index(c->vertex(2)), index(c->vertex(3))});
    m.subdomains.push_back(subdomain(c));
  }
  return m;
}

/// The triangles kept fixed by every optimizer: facets between two
/// subdomains, or on the hull, as sorted index triples.
inline std::vector<std::array<std::size_t, 3>> boundary_triangles(const Cell_mesh& m)
{
  std::map<std::array<std::size_t, 3>, std::pair<int, int>> faces; // subdomain on each side (0: none)
  for(std::size_t k = 0; k < m.cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      std::array<std::size_t, 3> t;
      for(int j = 0, n = 0; j < 4; ++j)
        if(j != i) t[n++] = m.cells[k][j];
      std::sort(t.begin(), t.end());
      auto& sides = faces[t];
      (sides.first == 0 ? sides.first : sides.second) = m.subdomains[k];
    }
  std::vector<std::array<std::size_t, 3>> boundary;
  for(const auto& [t, sides] : faces)
    if(sides.first != sides.second) boundary.push_back(t);
  return boundary;
}

/// How CGAL's Tetrahedral_remeshing is run.
enum Cgal_remeshing_mode
{
  /// its flip step alone, repeated
  CGAL_FLIPS,
  /// its flip step then its smoothing step, repeated: the order of its own
  /// loop (`Adaptive_remesher::remesh`), without split and collapse
  CGAL_FLIPS_THEN_SMOOTHING,
  /// `tetrahedral_isotropic_remeshing` as its examples call it (default
  /// iterations, that is one round of split, collapse, flip and smoothing and
  /// three more of flip and smoothing), the boundaries protected
  /// (`remesh_boundaries(false)`) and the input's mean edge length as target:
  /// it adds and removes vertices
  CGAL_ISOTROPIC_REMESHING
};

/// The mean length of the edges of the cells of `m`.
inline double mean_edge_length(const Cell_mesh& m)
{
  std::set<std::pair<std::size_t, std::size_t>> edges;
  for(const auto& t : m.cells)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) edges.insert(std::minmax(t[i], t[j]));
  double sum = 0;
  for(const auto& [a, b] : edges) sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(m.points[a], m.points[b])));
  return edges.empty() ? 0 : sum / double(edges.size());
}

/// CGAL's Tetrahedral_remeshing on `in` (`mode`; `passes` for the first two
/// modes); boundaries protected. The points of the result are those its
/// cells use, the input's first, in their order, then those it added.
inline Peer_result cgal_remeshing(const Cell_mesh& in, Cgal_remeshing_mode mode, int passes)
{
  typedef CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<K> Tr;
  typedef std::pair<Tr::Vertex_handle, Tr::Vertex_handle> Edge_vv;
  typedef CGAL::Tetrahedral_remeshing::internal::No_constraint_pmap<Edge_vv> No_edge;
  typedef CGAL::Tetrahedral_remeshing::internal::No_constraint_pmap<Tr::Facet> No_facet;
  typedef CGAL::Tetrahedral_remeshing::internal::All_cells_selected<Tr> All_cells;
  typedef CGAL::Tetrahedral_remeshing::internal::Default_remeshing_visitor Visitor;
  typedef CGAL::Uniform_sizing_field<K> Sizing;
  typedef CGAL::Tetrahedral_remeshing::internal::Adaptive_remesher<Tr, Sizing, No_edge, No_facet, All_cells, Visitor>
      Remesher;

  Peer_result r;
  Tr tr;
  std::vector<Tr::Vertex_handle> vertices;
  std::vector<Tr::Cell_handle> cells;
  r.error = CGAL::Edge_swapping_3::build_triangulation_from_cells(tr, in.points, in.cells, vertices, cells);
  std::vector<K::Point_3> all_points = in.points;
  if(!r.error.empty())
  {
    // A domain that is not convex: its outside filled as the package does,
    // those cells in subdomain 0 (CGAL's outside), which the remesher keeps apart.
    auto fill = CGAL::Edge_swapping_3::internal::fill_exterior(in.points, in.cells);
    if(!fill.problem.empty()) return r;
    for(const auto& p : fill.added_points) all_points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::array<std::size_t, 4>> all = in.cells;
    const auto sign = [&](const std::array<std::size_t, 4>& t) {
      return CGAL::orientation(all_points[t[0]], all_points[t[1]], all_points[t[2]], all_points[t[3]]);
    };
    for(auto t : fill.cells)
    {
      if(sign(t) != sign(in.cells.front())) std::swap(t[0], t[1]);
      all.push_back(t);
    }
    r.error = CGAL::Edge_swapping_3::build_triangulation_from_cells(tr, all_points, all, vertices, cells);
    if(!r.error.empty()) return r;
  }
  for(auto c : tr.all_cell_handles()) c->set_subdomain_index(0);
  for(std::size_t k = 0; k < in.cells.size(); ++k) cells[k]->set_subdomain_index(in.subdomains[k]);
  std::map<Tr::Vertex_handle, std::size_t> index;
  for(std::size_t k = 0; k < vertices.size(); ++k) index[vertices[k]] = k;

  CGAL::Real_timer timer;
  timer.start();
  if(mode == CGAL_ISOTROPIC_REMESHING)
    CGAL::tetrahedral_isotropic_remeshing(tr, mean_edge_length(in), CGAL::parameters::remesh_boundaries(false));
  else
  {
    Visitor visitor;
    // The sizing is read by split and collapse only, which are not called.
    Remesher remesher(tr, Sizing(1.0), true, No_edge(), No_facet(), false, All_cells(), visitor);
    for(int k = 0; k < passes; ++k)
    {
      remesher.flip();
      if(mode == CGAL_FLIPS_THEN_SMOOTHING) remesher.smooth();
    }
    remesher.finalize();
  }
  r.seconds = timer.time();

  // The input's vertices keep their numbers (moved or not); the vertices the
  // remesher made follow.
  std::vector<K::Point_3> points = all_points;
  std::map<Tr::Vertex_handle, std::size_t> number;
  for(const auto v : tr.finite_vertex_handles())
  {
    const auto at = index.find(v);
    if(at == index.end())
    {
      number[v] = points.size();
      points.push_back(v->point());
      continue;
    }
    number[v] = at->second;
    points[at->second] = v->point();
    r.moved += (v->point() != all_points[at->second]);
  }
  r.mesh = cell_mesh_of(tr, points, [&](Tr::Vertex_handle v) { return number.at(v); },
                        [](Tr::Cell_handle c) { return int(c->subdomain_index()); });
  // The domain's cells alone (the filled outside is subdomain 0).
  Cell_mesh domain;
  domain.points = std::move(r.mesh.points);
  for(std::size_t k = 0; k < r.mesh.cells.size(); ++k)
    if(r.mesh.subdomains[k] != 0 || all_points.size() == in.points.size())
    {
      domain.cells.push_back(r.mesh.cells[k]);
      domain.subdomains.push_back(r.mesh.subdomains[k]);
    }
  // The points no cell uses (those the remesher removed, and a filled
  // outside's) left out, the others renumbered in order.
  std::vector<std::size_t> renumbered(domain.points.size(), 0);
  for(const auto& t : domain.cells)
    for(std::size_t v : t) renumbered[v] = 1;
  r.mesh = Cell_mesh();
  for(std::size_t k = 0; k < renumbered.size(); ++k)
    if(renumbered[k] != 0)
    {
      renumbered[k] = r.mesh.points.size();
      r.mesh.points.push_back(domain.points[k]);
    }
  for(auto t : domain.cells)
  {
    for(auto& v : t) v = renumbered[v];
    r.mesh.cells.push_back(t);
  }
  r.mesh.subdomains = std::move(domain.subdomains);
  return r;
}

#ifdef EDGE_SWAPPING_3_WITH_TETGEN
/// TetGen's `optimizemesh` on the mesh, flips only (`optscheme` 1) or with
/// smoothing (3), aiming at `max_dihedral` degrees.
inline Peer_result tetgen_optimizer(const Cell_mesh& in, int optscheme, double max_dihedral)
{
  Peer_result r;
  tetgenio io; // frees its arrays with delete[]
  io.firstnumber = 0;
  io.numberofpoints = int(in.points.size());
  io.pointlist = new REAL[3 * in.points.size()];
  for(std::size_t k = 0; k < in.points.size(); ++k)
    for(int d = 0; d < 3; ++d) io.pointlist[3 * k + d] = in.points[k][d];
  io.numberoftetrahedra = int(in.cells.size());
  io.numberofcorners = 4;
  io.tetrahedronlist = new int[4 * in.cells.size()];
  io.numberoftetrahedronattributes = 1;
  io.tetrahedronattributelist = new REAL[in.cells.size()];
  for(std::size_t k = 0; k < in.cells.size(); ++k)
  {
    for(int i = 0; i < 4; ++i) io.tetrahedronlist[4 * k + i] = int(in.cells[k][i]);
    io.tetrahedronattributelist[k] = in.subdomains[k];
  }
  const auto boundary = boundary_triangles(in);
  io.numberoftrifaces = int(boundary.size());
  io.trifacelist = new int[3 * boundary.size()];
  io.trifacemarkerlist = new int[boundary.size()];
  for(std::size_t k = 0; k < boundary.size(); ++k)
  {
    for(int i = 0; i < 3; ++i) io.trifacelist[3 * k + i] = int(boundary[k][i]);
    io.trifacemarkerlist[k] = 1;
  }

  tetgenbehavior b;
  b.refine = 1;
  b.quiet = 1;
  b.optlevel = 2;
  b.optscheme = optscheme;
  b.optmaxdihedral = max_dihedral;
  b.facet_ang_tol = 180;
  b.steinerleft = 0;

  tetgenmesh m;
  m.b = &b;
  m.in = &io;
  m.initializepools();
  m.transfernodes();
  exactinit(b.verbose, b.noexact, b.nostaticfilter, m.xmax - m.xmin, m.ymax - m.ymin, m.zmax - m.zmin);
  m.reconstructmesh();
  CGAL::Real_timer timer;
  timer.start();
  m.optimizemesh();
  r.seconds = timer.time();

  tetgenio out;
  m.outnodes(&out);
  m.outelements(&out);
  if(out.numberofpoints != io.numberofpoints)
  {
    r.error = "TetGen changed the number of points";
    return r;
  }
  for(int k = 0; k < out.numberofpoints; ++k)
  {
    const K::Point_3 p(out.pointlist[3 * k], out.pointlist[3 * k + 1], out.pointlist[3 * k + 2]);
    r.mesh.points.push_back(p);
    r.moved += (p != in.points[std::size_t(k)]);
  }
  const int first = out.firstnumber;
  for(int k = 0; k < out.numberoftetrahedra; ++k)
  {
    std::array<std::size_t, 4> t;
    for(int i = 0; i < 4; ++i) t[i] = std::size_t(out.tetrahedronlist[4 * k + i] - first);
    r.mesh.cells.push_back(t);
    r.mesh.subdomains.push_back(out.numberoftetrahedronattributes > 0 ? int(out.tetrahedronattributelist[k]) : 1);
  }
  return r;
}
#endif

/// Gmsh's optimizer, `gmsh_optimize.py` at `script` run by `python` on a
/// Medit file of the mesh in `directory`: the tetrahedra with their
/// subdomain as reference, the boundary triangles with reference 1. Gmsh
/// keeps the node numbering of the file; a point not where the input has it
/// counts as moved.
inline Peer_result gmsh_optimizer(const Cell_mesh& in, const std::string& python, const std::string& script,
                                  const std::string& directory)
{
  Peer_result r;
  namespace IO = CGAL::Edge_swapping_3::IO;
  IO::Medit_mesh m;
  for(const auto& p : in.points) m.points.push_back({p.x(), p.y(), p.z()});
  m.triangles = boundary_triangles(in);
  m.triangle_references.assign(m.triangles.size(), 1);
  m.tetrahedra = in.cells;
  // Gmsh names entities from 1: subdomain 0 (outside the domain) is shifted.
  for(int s : in.subdomains) m.tetrahedron_references.push_back(s + 1);
  const std::string source = directory + "/gmsh_in.mesh", target = directory + "/gmsh_out.txt";
  {
    std::ofstream out(source);
    IO::write_medit_file(out, m);
  }
  const std::string command = python + " '" + script + "' '" + source + "' '" + target + "' > /dev/null 2>&1";
  if(std::system(command.c_str()) != 0)
  {
    r.error = "'" + python + " " + script + "' failed (is Debian's python3-gmsh installed?)";
    return r;
  }
  std::ifstream text(target);
  std::size_t nodes = 0, cells = 0;
  text >> r.seconds >> nodes;
  if(nodes != in.points.size())
  {
    r.error = "Gmsh changed the number of points";
    return r;
  }
  r.mesh.points = in.points;
  for(std::size_t k = 0; k < nodes; ++k)
  {
    std::size_t tag = 0;
    double x, y, z;
    text >> tag >> x >> y >> z;
    if(tag < 1 || tag > nodes)
    {
      r.error = "Gmsh renumbered the points";
      return r;
    }
    const K::Point_3 p(x, y, z);
    r.moved += (p != in.points[tag - 1]);
    r.mesh.points[tag - 1] = p;
  }
  text >> cells;
  for(std::size_t k = 0; k < cells && text; ++k)
  {
    std::array<std::size_t, 4> t;
    int volume;
    text >> t[0] >> t[1] >> t[2] >> t[3] >> volume;
    for(auto& i : t)
      if(i < 1 || i > nodes)
      {
        r.error = "Gmsh named a node that its output does not hold";
        return r;
      }
      else --i;
    r.mesh.cells.push_back(t);
    r.mesh.subdomains.push_back(volume - 1);
  }
  if(!text) r.error = "the output of " + script + " is cut short";
  return r;
}

} // namespace quality_peers

#endif // EDGE_SWAPPING_3_BENCHMARK_QUALITY_PEERS_H
