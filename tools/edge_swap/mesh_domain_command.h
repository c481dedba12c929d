// SPDX-License-Identifier: GPL-3.0-or-later
// edge_swap mesh-domain: a domain mesh made by CGAL's Mesh_3 (in a
// translation unit of its own: Mesh_3 is heavy to compile).

#ifndef EDGE_SWAP_MESH_DOMAIN_COMMAND_H
#define EDGE_SWAP_MESH_DOMAIN_COMMAND_H

#include <string>

namespace edge_swap {

/// Meshes the domain `name` ("two-spheres") with target size `size` and
/// writes `output` (.mesh, .msh, .vtu or .ele). 0 on success; bad options throw.
int run_mesh_domain(const std::string& name, const std::string& output, double size);

} // namespace edge_swap

#endif
