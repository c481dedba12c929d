#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes meshes from geometry nobody here wrote, as each mesher's own docs
# make them, and runs benchmark_real_meshes on them (ours beside TetGen's,
# CGAL's and Gmsh's optimizers), then the program on each file to each
# output format:
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
doc=/usr/share/doc/gmsh-doc/doc/gmsh
meshes=()
for geo in tutorial/t5 tutorial/t16 tutorial/t18 demos/boolean/boolean demos/boolean/chamfer demos/boolean/compsolid \
           demos/boolean/fillet demos/boolean/primitives; do
  name=$(basename "$geo")
  if [ -f "$doc/$geo.geo.gz" ]; then zcat "$doc/$geo.geo.gz" > "$dir/$name.geo"; else cp "$doc/$geo.geo" "$dir/$name.geo"; fi
  (cd "$dir" && gmsh -3 "$name.geo" -o "$name.msh" > "$name.log" 2>&1)
  meshes+=("$dir/$name.msh")
done
cp /usr/share/doc/tetgen/examples/example.poly "$dir/"
(cd "$dir" && tetgen -pqQ example.poly)
meshes+=("$dir/example.1.ele")
tar -xzf /usr/share/doc/libcgal-dev/examples.tar.gz -C "$dir" examples/Tetrahedral_remeshing/data/sphere.mesh
meshes+=("$dir/examples/Tetrahedral_remeshing/data/sphere.mesh")
echo "$(nproc) cores, $(date -u +%F), $(uname -m)"
"$build/bin/benchmark_real_meshes" "${meshes[@]}"
