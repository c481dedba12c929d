// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap insert, refine and stats: flip-based insertion of given points,
// refinement at circumcenters (by aspect ratio or by a field's gradient),
// and the quality figures of a mesh.

#ifndef EDGE_SWAP_REFINE_COMMANDS_H
#define EDGE_SWAP_REFINE_COMMANDS_H

#include <CGAL/Edge_swapping_3/Two_spheres_domain.h>
#include "mesh_files.h"
#include "optimize_command.h"
#include <CGAL/Edge_swapping_3/mesh_statistics.h>
#include <CGAL/Edge_swapping_3/refinement.h>
#include <nlohmann/json.hpp>
#include <iostream>
#include <sstream>

namespace edge_swap {

/// Reads a mesh input (not a bare point set) and builds it.
inline Input read_mesh(const std::string& path, Triangulation& tr)
{
  Input in = read_input(path);
  if(!in.is_mesh) throw Usage_error("'" + path + "' is a point set; this command needs a mesh (.ele, .mesh, .msh or .vtu)");
  const std::string problem = ES::build_numbered_mesh(tr, in);
  if(!problem.empty()) throw IO::Input_error(path + ": " + problem);
  return in;
}

/// The values of every field at a new vertex: a synthetic field from its
/// function, the others interpolated linearly in the cell that held the site.
inline std::vector<double> field_values(const Input& in, const Point& p, const ES::Site_location<Triangulation>& where)
{
  return ES::interpolated_field_values(in, p, where, [](const std::string& name, const Point& q, double& value) {
    return ES::two_spheres_flow_field(name, q, value);
  });
}

inline void write_rounds(Output_files& files, const std::string& path, const ES::Refinement_report& report)
{
  if(path.empty()) return;
  files.add(path, [report](std::ostream& out) {
    out << "round,sites_inserted,vertices,worst_refinable_aspect_ratio,worst_aspect_ratio\n"; // ratios: aspect-ratio only
    for(const auto& r : report.rounds)
      out << r.round << ',' << r.sites_inserted << ',' << r.vertices << ',' << r.worst_refinable << ',' << r.worst << '\n';
  });
}

struct Insert_options
{
  std::string mesh, points, output, criterion = "delaunay";
};

inline int run_insert(const Insert_options& o)
{
  check_output_paths(mesh_output_paths(o.output));
  Triangulation tr;
  Input in = read_mesh(o.mesh, tr);
  const IO::Node_file node = IO::read_node_file(o.points);
  std::size_t inserted = 0, existing = 0, refused = 0;
  std::array<std::size_t, ES::number_of_flip_kinds> swaps{};
  ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
    return with_criterion(o.criterion, [&](const auto& criterion) {
      Triangulation::Cell_handle hint;
      for(const auto& q : node.points)
      {
        const Point p(q[0], q[1], q[2]);
        Triangulation::Locate_type lt;
        int li, lj;
        const auto at = tr.locate(p, lt, li, lj, hint);
        // Interpolation weights in the cell that holds the point (outside the hull: none).
        ES::Site_location<Triangulation> where{{at->vertex(0), at->vertex(1), at->vertex(2), at->vertex(3)}, {0, 0, 0, 0}};
        if(!tr.is_infinite(at)) where = ES::site_location(tr, at, p);
        const auto r = ES::insert_by_swapping(tr, p, criterion,
                                              ES::parameters::hint(at, ES::parameters::mesh_constraints(constraints)));
        if(r.vertex == Triangulation::Vertex_handle()) { ++refused; continue; }
        hint = r.vertex->cell();
        if(!r.is_new) { ++existing; continue; }
        ++inserted;
        for(int k = 0; k < ES::number_of_flip_kinds; ++k) swaps[k] += r.swaps[k];
        ES::add_numbered_vertex(in, r.vertex, field_values(in, p, where));
      }
      return 0;
    });
  });
  Output_files files;
  add_mesh_files(files, o.output, tr, in);
  files.commit();
  std::cout << "inserted " << inserted << " points (" << existing << " on existing vertices, " << refused
            << " refused: outside the domain or on a constrained face); swaps 2-3 " << swaps[0] << ", 3-2 "
            << swaps[1] << ", 2-2 " << swaps[2] << ", 4-4 " << swaps[3] << "; vertices " << ES::number_of_mesh_vertices(tr)
            << ", cells " << ES::number_of_mesh_cells(tr) << '\n';
  return 0;
}

struct Refine_options
{
  std::string mesh, output, by, field, sites, ratio = "edge", criterion = "delaunay", history;
  double target = 0;
  std::size_t max_sites = 1000000;
};

inline std::vector<std::size_t> parse_site_counts(const std::string& text)
{
  std::vector<std::size_t> counts;
  std::stringstream s(text);
  std::string item;
  while(std::getline(s, item, ','))
  {
    counts.push_back(whole_number(item, "--sites (a list such as 2000,2000)"));
  }
  if(counts.empty()) throw Usage_error("--sites is empty");
  return counts;
}

inline int run_refine(const Refine_options& o)
{
  std::vector<std::string> outputs = mesh_output_paths(o.output);
  outputs.push_back(o.history);
  check_output_paths(outputs);
  if(o.by != "aspect-ratio" && o.by != "gradient") throw Usage_error("--by is aspect-ratio or gradient");
  if(o.ratio != "edge" && o.ratio != "circumradius-inradius")
    throw Usage_error("--ratio is edge (longest over shortest edge) or circumradius-inradius (R/r, 3 for a regular "
                      "tetrahedron; the radius ratio 3r/R is 3 over it)");
  if(o.by == "aspect-ratio" && !(o.target >= 1)) throw Usage_error("--by aspect-ratio needs --target R with R >= 1");
  if(o.by == "gradient" && (o.field.empty() || o.sites.empty()))
    throw Usage_error("--by gradient needs --field NAME and --sites N[,N...]");
  const std::vector<std::size_t> rounds = o.by == "gradient" ? parse_site_counts(o.sites) : std::vector<std::size_t>();

  Triangulation tr;
  Input in = read_mesh(o.mesh, tr);
  int field = -1;
  if(o.by == "gradient")
  {
    field = in.field_index(o.field);
    double probe;
    if(field < 0 && ES::two_spheres_flow_field(o.field, Point(0, 0, 0), probe))
    {
      // A synthetic field not in the input: evaluate it at every vertex.
      in.field_names.push_back(o.field);
      in.fields.emplace_back();
      for(const auto& p : in.points) { ES::two_spheres_flow_field(o.field, p, probe); in.fields.back().push_back(probe); }
      field = int(in.fields.size()) - 1;
    }
    if(field < 0)
    {
      std::string known;
      for(const auto& n : in.field_names) known += " " + n;
      throw Usage_error("no field '" + o.field + "' in '" + o.mesh + "' (it has:" + (known.empty() ? " none" : known) +
                        "; synthetic: flow-density flow-speed)");
    }
  }

  const auto new_vertex = [&](Triangulation::Vertex_handle v, const ES::Site_location<Triangulation>& where) {
    ES::add_numbered_vertex(in, v, field_values(in, v->point(), where));
  };
  CGAL::Real_timer clock;
  clock.start();
  // The vertices that complete the domain outside: no site is inserted
  // outside it, so their count stays, and the counts shown leave them out.
  const std::size_t completion = tr.number_of_vertices() - ES::number_of_mesh_vertices(tr);
  auto progress = [&](const ES::Refinement_round& r) {
    if(quiet) return;
    std::cerr << "refine: round " << r.round << ", " << r.sites_inserted << " sites, " << r.vertices - completion
              << " vertices";
    if(o.by == "aspect-ratio") std::cerr << ", worst refinable aspect ratio " << r.worst_refinable;
    std::cerr << " (" << clock.time() << " s)\n";
  };
  std::function<void(const ES::Refinement_round&)> round_visitor;
  if(o.by == "aspect-ratio") round_visitor = progress;

  ES::Refinement_report total;
  ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
    namespace np = ES::parameters;
    const auto settings = np::new_vertex_visitor(new_vertex, np::round_visitor(round_visitor, np::mesh_constraints(constraints)));
    return with_criterion(o.criterion, [&](const auto& criterion) {
      if(o.by == "aspect-ratio")
        total = ES::refine_by_aspect_ratio(
            tr, o.target, criterion,
            np::aspect_ratio_definition(o.ratio == "edge" ? ES::EDGE_LENGTH_RATIO : ES::CIRCUMRADIUS_OVER_INRADIUS,
                                        np::maximum_sites(o.max_sites, settings)));
      else
      {
        const std::size_t f = std::size_t(field);
        auto value = [&](Triangulation::Vertex_handle v) { return in.fields[f][v->info()]; };
        for(std::size_t k = 0; k < rounds.size(); ++k)
        {
          auto r = ES::refine_by_gradient(tr, value, rounds[k], criterion, settings);
          r.rounds.back().round = k + 1;
          progress(r.rounds.back());
          total.rounds.push_back(r.rounds.back());
          total.sites_inserted += r.sites_inserted;
          total.sites_refused += r.sites_refused;
          for(int s = 0; s < ES::number_of_flip_kinds; ++s) total.swaps[s] += r.swaps[s];
        }
      }
      return 0;
    });
  });

  for(auto& r : total.rounds) r.vertices -= completion;
  Output_files files;
  add_mesh_files(files, o.output, tr, in);
  write_rounds(files, o.history, total);
  files.commit();
  std::cout << "refine by " << o.by << ": " << total.sites_inserted << " sites inserted, " << total.sites_refused
            << " refused (outside the domain, on a constrained face, or encroaching upon one); vertices " << ES::number_of_mesh_vertices(tr)
            << ", cells " << ES::number_of_mesh_cells(tr);
  if(o.by == "aspect-ratio")
    std::cout << "; worst refinable aspect ratio " << total.rounds.front().worst_refinable << " -> "
              << total.rounds.back().worst_refinable << (total.target_met ? " (target met)" : " (target not met)");
  std::cout << '\n';
  return 0;
}

/// The counts of the cells of `tr` that the mesh read holds (its own, not
/// those that complete its domain), and of their vertices, edges and faces.
inline ES::Mesh_statistics domain_counts(const Triangulation& tr)
{
  struct Own_cells : ES::Domain_constraints
  {
    bool is_in_domain(const Triangulation& t, Triangulation::Cell_handle c) const
    {
      return !t.is_infinite(c) && c->info().subdomain != ES::Domain_cell_info::completion;
    }
  };
  return ES::mesh_statistics(tr, ES::parameters::mesh_constraints(Own_cells()));
}

/// edge_swap stats: counts, extremes and histograms of dihedral angles and
/// aspect ratios (over the cells of the domain), to standard output and, with
/// `json`, to a file.
inline int run_stats(const std::string& path, const std::string& json)
{
  check_output_paths({json});
  Triangulation tr;
  const Input in = read_mesh(path, tr);
  const ES::Quality_histograms h = ES::with_mesh_constraints(tr, in, [&](const auto& constraints) {
    return ES::quality_histograms(tr, ES::parameters::mesh_constraints(constraints));
  });
  const std::size_t cells = h.cells;
  if(cells == 0) throw IO::Input_error(path + ": no tetrahedron in the domain (every reference is 0)");
  const double amin = h.dihedral_angle.min, amax = h.dihedral_angle.max;
  const double emin = h.edge_length_ratio.min, emax = h.edge_length_ratio.max;
  const double rmin = h.circumradius_over_inradius.min, rmax = h.circumradius_over_inradius.max;
  const auto& angle_histogram = h.dihedral_angle.counts;
  const auto& edge_histogram = h.edge_length_ratio.counts;
  const auto& radius_histogram = h.circumradius_over_inradius.counts;

  // The counts of the mesh as read (without the cells that complete a domain that is not convex).
  const ES::Mesh_statistics counts = ES::is_completed_domain(tr) ? domain_counts(tr) : ES::Mesh_statistics();
  const std::size_t vertices = counts.cells ? counts.vertices : tr.number_of_vertices();
  const std::size_t all_cells = counts.cells ? counts.cells : tr.number_of_finite_cells();
  std::cout << path << ": vertices " << vertices << ", edges " << (counts.cells ? counts.edges : tr.number_of_finite_edges())
            << ", faces " << (counts.cells ? counts.faces : tr.number_of_finite_facets()) << ", cells " << all_cells
            << " (in the domain: " << cells << ")\n"
            << "  dihedral angles: min " << amin << ", max " << amax << " degrees\n"
            << "  edge length ratio: min " << emin << ", max " << emax << "\n"
            << "  circumradius over inradius R/r (3 for a regular tetrahedron): min " << rmin << ", max " << rmax << "\n"
            << "  radius ratio 3r/R (1 for a regular tetrahedron): min " << 3 / rmax << ", max " << 3 / rmin << "\n"
            << "  dihedral angle histogram (5-degree bins from 0):";
  for(auto n : angle_histogram) std::cout << ' ' << n;
  std::cout << "\n  edge length ratio histogram (0.25 bins from 1):";
  for(auto n : edge_histogram) std::cout << ' ' << n;
  std::cout << '\n';
  if(!json.empty())
  {
    Output_files files;
    files.add(json, [&](std::ostream& out) {
      nlohmann::json j = {{"mesh", path},
                          {"vertices", vertices},
                          {"cells", all_cells},
                          {"cells_in_domain", cells},
                          {"dihedral_angle", {{"min", amin}, {"max", amax}, {"bin_start", 0}, {"bin_width", 5}, {"histogram", angle_histogram}}},
                          {"edge_length_ratio", {{"min", emin}, {"max", emax}, {"bin_start", 1}, {"bin_width", 0.25}, {"histogram", edge_histogram}}},
                          {"circumradius_over_inradius", {{"min", rmin}, {"max", rmax}, {"bin_start", 3}, {"bin_width", 1}, {"histogram", radius_histogram}}},
                          {"radius_ratio", {{"min", 3 / rmax}, {"max", 3 / rmin}}}};
      out << j.dump(1) << '\n';
    });
    files.commit();
  }
  return 0;
}

} // namespace edge_swap

#endif
