#!/usr/bin/env python3
"""render_mesh.py — a PNG of a mesh written by `conformesh remesh --vtk`, in R³, coloured by one of its point fields.

The VTK's points are the surface's embedding where the metric family has one (ellipsoid, teapot patch, Kerr a/M ≤ √3/2
through its surface of revolution, ...) and otherwise the chart's reference surface (the unit sphere for sphere
charts), so surfaces without an embedding are drawn on their reference surface — the picture then shows where the
field lives, not the shape. Each triangle takes the mean of its three vertices' values; the colour scale is symmetric
about 0 for signed error fields.

  python3 scripts/render_mesh.py kerr.vtk --field relative_error -o kerr_error.png
  python3 scripts/render_mesh.py teapot.vtk --field smooth_curvature --elev 30 --azim -60 -o teapot_K.png

Fields written by `remesh`: lambda, curvature (angle deficit per vertex), smooth_curvature (K of the metric at the
vertex), error and relative_error (Gaussian-curvature-measure check, paper eq. 5), u, v (chart coordinates).
"""
import argparse
import sys


def _missing_module(error):
    """Exits naming the missing module and the Debian package that provides it (status 1, message on stderr)."""
    import os
    module = (error.name or "?").split(".")[0]
    package = {"numpy": "python3-numpy", "matplotlib": "python3-matplotlib",
               "mpl_toolkits": "python3-matplotlib"}.get(module, "python3-" + module)
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: no Python module '{module}' for {sys.executable}: install "
             f"Debian's {package} (apt-get install {package}) and run this script with /usr/bin/python3, the "
             f"interpreter CMake configures (CONFORMESH_PYTHON)")


try:
    import numpy as np
except ModuleNotFoundError as missing:
    _missing_module(missing)


def read_vtk(path):
    """Legacy ASCII POLYDATA as conformesh's vtk_writer writes it: POINTS, POLYGONS (triangles), POINT_DATA scalars.
    Returns points, triangles, fields and the title line."""
    with open(path) as f:
        f.readline()
        title = f.readline().strip()
        tokens = f.read().split()
    points, triangles, fields = None, None, {}
    i = 0
    try:
        while i < len(tokens):
            t = tokens[i]
            if t == "POINTS":
                n = int(tokens[i + 1])
                points = np.array(tokens[i + 3:i + 3 + 3 * n], dtype=float).reshape(n, 3)
                i += 3 + 3 * n
            elif t == "POLYGONS":
                m = int(tokens[i + 1])
                rows = np.array(tokens[i + 3:i + 3 + 4 * m], dtype=int).reshape(m, 4)
                if np.any(rows[:, 0] != 3):
                    raise ValueError("a polygon that is not a triangle")
                triangles = rows[:, 1:]
                i += 3 + 4 * m
            elif t == "SCALARS":
                name, n = tokens[i + 1], len(points)
                j = i + 3
                if tokens[j] == "1":  # optional component count
                    j += 1
                j += 2  # LOOKUP_TABLE default
                fields[name] = np.array(tokens[j:j + n], dtype=float)
                i = j + n
            else:
                i += 1
    except (IndexError, ValueError) as e:
        sys.exit(f"render_mesh.py: {path}: not a legacy ASCII VTK polydata of triangles as conformesh writes it ({e})")
    if points is None or triangles is None:
        sys.exit(f"render_mesh.py: {path}: expected POINTS and POLYGONS sections, found "
                 f"{'no POINTS' if points is None else 'no POLYGONS'}")
    return points, triangles, fields, title


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vtk", help="a .vtk written by conformesh remesh --vtk")
    ap.add_argument("--field", default="relative_error", help="point field to colour by (default relative_error)")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--elev", type=float, default=20, help="view elevation in degrees (default 20)")
    ap.add_argument("--azim", type=float, default=-50, help="view azimuth in degrees (default -50)")
    ap.add_argument("--pixels", type=int, default=900, help="image width and height (default 900)")
    ap.add_argument("--no-edges", action="store_true", help="do not draw the triangles' edges")
    a = ap.parse_args()

    points, triangles, fields, title = read_vtk(a.vtk)
    if a.field not in fields:
        sys.exit(f"render_mesh.py: {a.vtk}: no point field '{a.field}'; it has: {', '.join(sorted(fields))}")
    values = fields[a.field][triangles].mean(axis=1)

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    except ModuleNotFoundError as missing:
        _missing_module(missing)

    signed = a.field in ("error", "relative_error", "curvature", "smooth_curvature") and values.min() < 0 < values.max()
    if signed:
        vmax = np.percentile(np.abs(values), 99) or 1.0
        norm, cmap = matplotlib.colors.Normalize(-vmax, vmax), "coolwarm"
    else:
        lo, hi = np.percentile(values, [1, 99])
        norm, cmap = matplotlib.colors.Normalize(lo, hi if hi > lo else lo + 1), "viridis"
    colours = matplotlib.colormaps[cmap](norm(values))

    fig = plt.figure(figsize=(a.pixels / 100, a.pixels / 100), dpi=100)
    ax = fig.add_subplot(projection="3d")
    poly = Poly3DCollection(points[triangles], facecolors=colours,
                            edgecolors=(0, 0, 0, 0.25) if not a.no_edges else "none", linewidths=0.1)
    ax.add_collection3d(poly)
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(a.elev, a.azim)
    ax.set_axis_off()
    sm = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
    fig.colorbar(sm, ax=ax, shrink=0.6, label=a.field + (" (triangle mean; scale clipped at 99th percentile)"))
    caption = f"{len(points)} vertices, {len(triangles)} triangles"
    if "no embedding in R3" in title:  # remesh_output.cpp's kDrawnOnReferenceSurface
        caption += ("\nno embedding in R³: drawn on the chart's reference surface (its canonical domain),"
                    "\nnot the surface's shape; lengths and fields are those of the metric")
    ax.set_title(caption, fontsize=10)
    fig.savefig(a.output, bbox_inches="tight")
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
