#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes meshes from geometry nobody here wrote, as each mesher's own docs
# make them (make_real_meshes.sh), and runs benchmark_real_meshes on them
# (ours beside TetGen's, CGAL's and Gmsh's optimizers), then the program on
# each file to each output format:
#  - Gmsh 4.8 (Debian's gmsh, gmsh-doc): tutorials t5, t16, t18 and the
#    OpenCASCADE demos boolean, chamfer, compsolid, fillet, primitives,
#    `gmsh -3 X.geo -o X.msh` (MSH 4.1: every digit of the CAD coordinates);
#  - TetGen 1.5 (Debian's tetgen): its example.poly, `tetgen -pqQ`;
#  - CGAL 5.5 (Debian's libcgal-demo): Tetrahedral_remeshing's sphere.mesh.
#
#   bash benchmark/Edge_swapping_3/real_meshes.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
bash scripts/install_dependencies.sh gmsh gmsh-doc python3-gmsh tetgen libcgal-demo > /dev/null
cmake --build "$build" --target benchmark_real_meshes edge_swap > /dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
bash benchmark/Edge_swapping_3/make_real_meshes.sh "$dir" > "$dir/meshes.txt"
mapfile -t meshes < "$dir/meshes.txt"
echo "$(nproc) cores, $(date -u +%F), $(uname -m)"
"$build/bin/benchmark_real_meshes" "${meshes[@]}"
