#!/usr/bin/env python3
"""plot_layout.py — draws a canonical-domain layout (written as JSON by `conformesh layout ... -o OUT.png`) to PNG with
matplotlib: the fundamental domain's triangles, the tiles of the universal cover in a lighter colour, the outline of
the cut and the generator loops, and the unit circle for the Poincaré disk and disk domains.

Usage: plot_layout.py LAYOUT.json OUT.png [PIXELS]
JSON: {"title": str, "unit_circle": bool, "triangles": [[x0, y0, x1, y1, x2, y2, layer, shade], ...],
       "lines": [{"points": [[x, y], ...], "colour": int, "closed": bool}, ...]}
"""
import json
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
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.patches import Circle
except ModuleNotFoundError as missing:
    _missing_module(missing)

# Outline dark grey, then one colour per generator loop (Okabe–Ito), as in the SVG (layout_picture.cpp).
PALETTE = ["#333333", "#D55E00", "#0072B2", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"]


def legend(ax, d):
    """What the colours mean: the fundamental domain and the cover's tiles, the outline, and generator loop i
    (line colour i, layout_picture.cpp: the i-th basis loop of the fundamental group, drawn on its edges in D)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    handles = [Patch(facecolor=(0.70, 0.78, 1.0), edgecolor="#1f3b73", label="fundamental domain")]
    if any(t[6] == 1 for t in d["triangles"]):
        handles.append(Patch(facecolor=(0.86, 0.90, 1.0), edgecolor="#9aa7bf", label="tiles of the universal cover"))
    for c in sorted({line["colour"] for line in d["lines"]}):
        name = "outline (cut boundary)" if c == 0 else "loop of generator g%d" % c
        handles.append(Line2D([], [], color=PALETTE[c % len(PALETTE)], lw=1.0 if c == 0 else 2.0, label=name))
    ax.legend(handles=handles, loc="upper right", fontsize=8, framealpha=0.85)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: plot_layout.py LAYOUT.json OUT.png [PIXELS]")
    with open(sys.argv[1]) as f:
        d = json.load(f)
    pixels = int(sys.argv[3]) if len(sys.argv) > 3 else 900
    fig = plt.figure(figsize=(pixels / 100, pixels / 100), dpi=100)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.92])
    ax.set_aspect("equal")
    ax.axis("off")
    if d.get("unit_circle"):
        ax.add_patch(Circle((0, 0), 1, facecolor="#f4f4f4", edgecolor="black", linewidth=0.8))
    tris = d["triangles"]
    n = max(1, len(tris))
    width = max(0.05, min(0.6, 60.0 / n ** 0.5))
    for layer, edge, base in ((1, "#9aa7bf", (0.86, 0.90, 1.0)), (0, "#1f3b73", (0.70, 0.78, 1.0))):
        polys = [[(t[0], t[1]), (t[2], t[3]), (t[4], t[5])] for t in tris if t[6] == layer]
        shades = [t[7] for t in tris if t[6] == layer]
        if not polys:
            continue
        faces = [tuple(c * s + (1 - s) * 0.15 for c in base) for s in shades]
        ax.add_collection(PolyCollection(polys, facecolors=faces, edgecolors=edge, linewidths=width))
    for line in d["lines"]:
        pts = line["points"] + ([line["points"][0]] if line.get("closed") else [])
        colour = PALETTE[line["colour"] % len(PALETTE)]
        lw = 1.0 if line["colour"] == 0 else 2.0
        ax.add_collection(LineCollection([pts], colors=colour, linewidths=lw))
    ax.autoscale_view()
    legend(ax, d)
    if d.get("unit_circle"):
        ax.set_xlim(-1.02, 1.02)
        ax.set_ylim(-1.02, 1.02)
    fig.suptitle(d.get("title", ""), fontsize=11)
    fig.savefig(sys.argv[2], dpi=100)


if __name__ == "__main__":
    main()
