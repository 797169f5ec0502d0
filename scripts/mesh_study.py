#!/usr/bin/env python3
"""mesh_study.py — the mesh-input study (docs/studies.md): remesh one triangle mesh at several eps with
`conformesh remesh MESHFILE --eps E --json` and tabulate, per mesh: vertices, smallest and mean smallest angle in the
input's metric (and the smallest in the uniformized metric, the refinement's own bound), circumradii, Gauss–Bonnet
residual, inverted triangles, area against the input's, the curvature-measure error e_G against the input's own
angle deficits, and time; then the least-squares log–log slopes of e_G and of the area error against the mean
circumradius, and of the mean circumradius against the vertex count.

Usage: python3 scripts/mesh_study.py MESHFILE [--vertices 1k,2k,... | --eps 0.04,0.03,...] [--conformesh PATH]
                                             [--csv OUT.csv]
By default eps is chosen from the input's area A for about 1k, 2k, 4k, 8k and 16k output vertices (eps =
sqrt(A / (1.1 N)), the density of Ruppert-quality meshes; the counts land near the targets, not on them).
Example (the genus-2 study): python3 scripts/mesh_study.py build/tests/data/meshes/eight.off
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def slope(xs, ys):
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mesh")
    p.add_argument("--eps", default=None, help="comma-separated eps values (overrides --vertices)")
    p.add_argument("--vertices", default="1k,2k,4k,8k,16k", help="target vertex counts (default 1k,2k,4k,8k,16k)")
    p.add_argument("--conformesh", default=None, help="the conformesh executable (default: build*/apps/conformesh)")
    p.add_argument("--csv", default=None)
    a = p.parse_args()
    exe = a.conformesh
    if exe is None:
        here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        for d in sorted(os.listdir(here)):
            cand = os.path.join(here, d, "apps", "conformesh")
            if d.startswith("build") and os.access(cand, os.X_OK):
                exe = cand
                break
    if exe is None:
        sys.exit("mesh_study.py: no conformesh executable found; pass --conformesh")
    if a.eps:
        epsilons = [float(e) for e in a.eps.split(",")]
    else:
        info = subprocess.run([exe, "-q", "info", a.mesh, "--json"], capture_output=True, text=True)
        if info.returncode != 0:
            sys.exit(info.stderr.strip())
        area = json.loads(info.stdout)["total_area"]
        counts = [float(v[:-1]) * 1000 if v.lower().endswith("k") else float(v) for v in a.vertices.split(",")]
        epsilons = [math.sqrt(area / (1.1 * n)) for n in counts]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for eps in epsilons:
            out = os.path.join(tmp, "out.ply")
            r = subprocess.run([exe, "-q", "remesh", a.mesh, "--eps", repr(eps), "-o", out, "--json"],
                               capture_output=True, text=True)
            if r.returncode != 0:
                print(f"eps {eps}: {r.stderr.strip()}", file=sys.stderr)
                continue
            j = json.loads(r.stdout)
            q, g = j["quality"], j["gaussian_curvature_measure"]
            rows.append({
                "eps": eps, "vertices": q["vertices"], "triangles": q["triangles"],
                "min_angle": q["min_angle_deg"], "mean_min_angle": q["mean_min_angle_deg"],
                "min_angle_uniformized": j["quality_uniformized"]["min_angle_deg"],
                "max_circumradius": q["max_circumradius"], "mean_circumradius": q["mean_circumradius"],
                "gauss_bonnet": q["gauss_bonnet_residual"], "inverted": j["inverted_triangles"],
                "area": j["total_area"], "area_error": abs(j["total_area"] - j["input_mesh"]["area"]),
                "e_G": g["mean_abs_error"], "max_error": g["max_abs_error"], "within": g["fraction_within"],
                "seconds": sum(j["seconds"].values())})
    if not rows:
        sys.exit("mesh_study.py: every run failed")
    cols = ["eps", "vertices", "min_angle", "mean_min_angle", "min_angle_uniformized", "mean_circumradius",
            "gauss_bonnet", "inverted", "area_error", "e_G", "max_error", "within", "seconds"]
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))
    for r in rows:
        print("| " + " | ".join(f"{r[c]:.4g}" if isinstance(r[c], float) else str(r[c]) for c in cols) + " |")
    R = [r["mean_circumradius"] for r in rows]
    print(f"\nslope log e_G / log mean circumradius: {slope(R, [r['e_G'] for r in rows]):.3f}")
    print(f"slope log |area - input area| / log mean circumradius: {slope(R, [r['area_error'] for r in rows]):.3f}")
    print(f"slope log mean circumradius / log vertices: {slope([r['vertices'] for r in rows], R):.3f}")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
