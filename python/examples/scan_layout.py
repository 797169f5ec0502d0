"""A (V, F) mesh uniformized and laid out in its canonical domain.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/scan_layout.py MESH.off [OUT.svg]

Reads the mesh into NumPy arrays (any reader would do; conformesh.read is used here), builds the Triangulation
from them, uniformizes it and writes the layout picture.
"""

import sys

import numpy as np

import conformesh


def main():
    path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else "layout.svg"
    mesh = conformesh.read(path)
    V, F = np.asarray(mesh.positions), np.asarray(mesh.faces)
    tri = conformesh.Triangulation.from_positions(V, F)
    print(tri, "boundary loops", tri.boundary_loops)
    u = conformesh.uniformize(tri)
    print("uniformized:", u.geometry, "lambda in", u.conformal_factor.min(), "..", u.conformal_factor.max())
    lay = conformesh.layout(tri)
    print("layout target:", lay.target, {k: v for k, v in lay.report.items() if k in ("tau", "relation")})
    lay.write(out)
    print("wrote", out)


if __name__ == "__main__":
    main()
