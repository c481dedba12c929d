// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge_swapping_3: the 3-D edge-swapping method of Gandhi and Barth (1993) on
// CGAL::Triangulation_3. The umbrella header: it brings in the whole public
// API except the file readers and writers (CGAL/Edge_swapping_3/IO/). The
// conjecture laboratory is a project of its own (laboratory/ in the sources).
//
//   CGAL::swap_edges(tr, criterion, np)                 Algorithm 3, any criterion
//   CGAL::swap_edges_with_helper(tr, np)                Algorithm 4, the helper strategy
//   ES::insert_by_swapping(tr, p, criterion, np)        flip insertion of one point
//   ES::delaunay_by_insertion(tr, points, np)           Delaunay by flip insertion
//   ES::refine_by_aspect_ratio(tr, target, criterion, np), ES::refine_by_gradient(tr, value, criterion, np)
//   ES::remove_edge, ES::remove_edge_in_two_steps, ES::remove_faces, ES::smooth_vertex
//   ES::improve_worst_tetrahedra(tr, criterion, np)     worst first, every operation
//   ES::Mesh_with_fields, ES::build_numbered_mesh(tr, mesh)          meshes as files hold them
//
// CGAL/Edge_swapping_3/make_two_spheres_mesh.h (the demonstration domain,
// meshed by Mesh_3) is left out: it brings all of Mesh_3 into a translation unit.
//
// (ES is CGAL::Edge_swapping_3.)

#ifndef CGAL_EDGE_SWAPPING_3_H
#define CGAL_EDGE_SWAPPING_3_H

#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/Exact_predicates.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/Five_point_configuration.h>
#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <CGAL/Edge_swapping_3/Flip_visitor.h>
#include <CGAL/Edge_swapping_3/Replacement_visitor.h>
#include <CGAL/Edge_swapping_3/Mesh_constraints.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Regular_criterion.h>
#include <CGAL/Edge_swapping_3/Quality_criteria.h>
#include <CGAL/Edge_swapping_3/tetrahedron_quality.h>
#include <CGAL/Edge_swapping_3/mesh_statistics.h>
#include <CGAL/Edge_swapping_3/swap_edges.h>
#include <CGAL/Edge_swapping_3/point_insertion.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Edge_swapping_3/refinement.h>
#include <CGAL/Edge_swapping_3/edge_removal.h>
#include <CGAL/Edge_swapping_3/two_step_edge_removal.h>
#include <CGAL/Edge_swapping_3/multi_face_removal.h>
#include <CGAL/Edge_swapping_3/vertex_smoothing.h>
#include <CGAL/Edge_swapping_3/vertex_removal.h>
#include <CGAL/Edge_swapping_3/vertex_insertion.h>
#include <CGAL/Edge_swapping_3/improve_worst_tetrahedra.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/Mesh_with_fields.h>
#include <CGAL/Edge_swapping_3/mesh_with_fields_from_complex.h>
#include <CGAL/Edge_swapping_3/Two_spheres_domain.h>

#endif // CGAL_EDGE_SWAPPING_3_H
