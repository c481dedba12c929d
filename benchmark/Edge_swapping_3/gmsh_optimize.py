# SPDX-License-Identifier: GPL-3.0-or-later
"""Gmsh's tetrahedral optimizer (swaps and vertex relocation) on a Medit mesh:
the Gmsh peer of benchmark_quality_operations. Run by Debian's interpreter,
which has Debian's python3-gmsh:

    /usr/bin/python3 gmsh_optimize.py IN.mesh OUT.txt

Each tetrahedron reference of IN.mesh becomes a discrete volume of Gmsh and
each triangle reference a discrete surface; `optimize("", force=True)` runs
Gmsh's default optimizer on them (force: the entities are discrete). Node tags stay those of the file (Mesh.Renumber 0). OUT.txt
gets the time of the optimization, the nodes by tag with every digit (Gmsh's
own Medit writer rounds the coordinates), and the tetrahedra with their
volume's tag."""

import sys
import time

import gmsh


def main(source, target):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("Mesh.Renumber", 0)  # keep the file's node tags
    gmsh.open(source)
    start = time.perf_counter()
    gmsh.model.mesh.optimize("", force=True)
    seconds = time.perf_counter() - start
    tags, coordinates, _ = gmsh.model.mesh.getNodes()
    tetrahedra = []
    for _, volume in gmsh.model.getEntities(3):
        types, _, nodes = gmsh.model.mesh.getElements(3, volume)
        for kind, corners in zip(types, nodes):
            if kind != 4:  # 4-node tetrahedra only
                continue
            for k in range(0, len(corners), 4):
                tetrahedra.append((*corners[k:k + 4], volume))
    with open(target, "w") as out:
        out.write(f"{seconds!r}\n{len(tags)}\n")
        for k, tag in enumerate(tags):
            x, y, z = coordinates[3 * k:3 * k + 3]
            out.write(f"{tag} {x!r} {y!r} {z!r}\n")
        out.write(f"{len(tetrahedra)}\n")
        for t in tetrahedra:
            out.write(" ".join(str(int(v)) for v in t) + "\n")
    gmsh.finalize()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
