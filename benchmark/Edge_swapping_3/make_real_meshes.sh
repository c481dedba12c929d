#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes meshes from geometry nobody here wrote, as each mesher's own docs
# make them, in DIR, and prints their paths, one a line:
#  - Gmsh 4.8 (Debian's gmsh, gmsh-doc): the .geo files named (default: the
#    tutorials t5, t16, t18 and the OpenCASCADE demos boolean, chamfer,
#    compsolid, fillet, primitives), `gmsh -3 X.geo -o X.msh` (MSH 4.1:
#    every digit of the CAD coordinates);
#  - TetGen 1.5 (Debian's tetgen): its example.poly, `tetgen -pqQ`;
#  - CGAL 5.5 (Debian's libcgal-demo): Tetrahedral_remeshing's sphere.mesh.
# Needs those packages (the callers install them).
#
#   bash benchmark/Edge_swapping_3/make_real_meshes.sh DIR [tutorial/t5 demos/boolean/boolean ...]
set -euo pipefail
dir=$1
shift
geos=("$@")
[ ${#geos[@]} -gt 0 ] || geos=(tutorial/t5 tutorial/t16 tutorial/t18 demos/boolean/boolean demos/boolean/chamfer
                               demos/boolean/compsolid demos/boolean/fillet demos/boolean/primitives)
doc=/usr/share/doc/gmsh-doc/doc/gmsh
for geo in "${geos[@]}"; do
  name=$(basename "$geo")
  if [ -f "$doc/$geo.geo.gz" ]; then zcat "$doc/$geo.geo.gz" > "$dir/$name.geo"; else cp "$doc/$geo.geo" "$dir/$name.geo"; fi
  (cd "$dir" && gmsh -3 "$name.geo" -o "$name.msh" > "$name.log" 2>&1)
  echo "$dir/$name.msh"
done
cp /usr/share/doc/tetgen/examples/example.poly "$dir/"
(cd "$dir" && tetgen -pqQ example.poly > /dev/null)
echo "$dir/example.1.ele"
tar -xzf /usr/share/doc/libcgal-dev/examples.tar.gz -C "$dir" examples/Tetrahedral_remeshing/data/sphere.mesh
echo "$dir/examples/Tetrahedral_remeshing/data/sphere.mesh"
