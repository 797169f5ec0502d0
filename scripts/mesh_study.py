#!/usr/bin/env python3
"""mesh_study.py — the mesh-input study (docs/studies.md): remesh one triangle mesh at several eps with
`conformesh remesh MESHFILE --eps E --refine-in ROUTE --json`, for each refinement metric (the paper's uniformized
route, and the input's own flat cone metric), and tabulate per route: vertices, smallest and mean smallest angle in
the input's metric, % of triangles whose smallest angle is under 30 deg (and the smallest in the uniformized metric,
the refinement's own bound there), circumradii, Gauss–Bonnet residual, inverted triangles, relative area error
against the input, the curvature-measure error e_G against the input's own angle deficits, and CPU time (user + sys
of the conformesh process); then the least-squares log–log slopes of e_G and of the area error against the mean
circumradius, and of the mean circumradius against the vertex count.

With --where E1,E2,... it also shows, for the uniformized route at those eps, WHERE the input-metric angles are lost:
it writes T1 (`remesh`, input-metric lengths) and the same refinement T1* (`uniformize` + `refine`, uniformized
lengths, the same vertices and faces), and compares every triangle's angles in the two metrics: the input's cone
angles, the scaling of the output corners at the input (cone) vertices against theta / 2 pi, and the triangles under
20.7 deg in the input metric (how many touch an input vertex, and the worst ratio of input-metric to uniformized
smallest angle away from the input vertices).

Usage: python3 scripts/mesh_study.py MESHFILE [--vertices 1k,2k,... | --eps 0.04,0.03,...] [--routes uniformized,input]
                                             [--smoothing N] [--where E,...] [--conformesh PATH] [--csv OUT.csv]
By default eps is chosen from the input's area A for about 1k, 2k, 4k, 8k and 16k output vertices (eps =
sqrt(A / (1.1 N)), the density of Ruppert-quality meshes; the counts land near the targets, not on them).
--smoothing applies to the input route only (the uniformized route of a mesh is refined unsmoothed).
Example (the genus-2 study): python3 scripts/mesh_study.py build/tests/data/meshes/eight.off
"""
import argparse
import csv
import json
import math
import os
import resource
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


def run_timed(cmd):
    """Runs cmd; returns (CompletedProcess, user + sys CPU seconds of the child)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def read_ascii_ply(path):
    """Vertex properties (dict name -> list), faces (vertex triples) and per-face side lengths (side k: corner k ->
    k+1), from an ASCII PLY written by conformesh (edges with lengths; faces with edge_index where pairs repeat)."""
    with open(path) as f:
        elements, order = {}, []
        while True:
            line = f.readline().split()
            if line == ["end_header"]:
                break
            if line[0] == "element":
                order.append(line[1])
                elements[line[1]] = {"count": int(line[2]), "props": []}
            elif line[0] == "property":
                elements[order[-1]]["props"].append(line[-1])
        data = {}
        for name in order:
            data[name] = [f.readline().split() for _ in range(elements[name]["count"])]
    vprops = elements["vertex"]["props"]
    vertex = {p: [float(row[i]) for row in data["vertex"]] for i, p in enumerate(vprops)}
    faces, face_edges = [], []
    has_edge_index = "edge_index" in elements["face"]["props"]
    for row in data["face"]:
        n = int(row[0])
        faces.append([int(x) for x in row[1:1 + n]])
        face_edges.append([int(x) for x in row[2 + n:2 + 2 * n]] if has_edge_index else None)
    edges = [(int(r[0]), int(r[1]), float(r[2])) for r in data["edge"]]
    by_pair = {}
    for e, (a, b, _) in enumerate(edges):
        by_pair[(min(a, b), max(a, b))] = e
    sides = []
    for face, fe in zip(faces, face_edges):
        s = []
        for k in range(3):
            if fe is not None:
                e = fe[k]
            else:
                a, b = face[k], face[(k + 1) % 3]
                e = by_pair[(min(a, b), max(a, b))]
            s.append(edges[e][2])
        sides.append(s)
    return vertex, faces, sides


def corner_angles(sides, hyperbolic):
    """Angles at corners 0, 1, 2 of a triangle with sides[k] from corner k to k+1, flat or of curvature -1, by the
    half-angle forms (stable for small triangles)."""
    out = []
    for k in range(3):
        a, c, b = sides[k], sides[(k + 2) % 3], sides[(k + 1) % 3]  # corner k between a and c, opposite b
        if hyperbolic:
            s = math.sinh((b - a + c) / 2) * math.sinh((b + a - c) / 2) / (math.sinh(a) * math.sinh(c))
        else:
            s = (b - a + c) * (b + a - c) / (4 * a * c)
        out.append(math.degrees(2 * math.asin(math.sqrt(min(max(s, 0.0), 1.0)))))
    return out


def off_face_min_angles(path, n_vertices):
    """(vertices, smallest corner angle in deg, area) of each face of an all-triangle OFF file, in file order; None
    for other inputs."""
    if not path.lower().endswith(".off"):
        return None
    toks = []
    with open(path) as f:
        for line in f:
            toks += line.split("#")[0].split()
    nv, nf = int(toks[1]), int(toks[2])
    if nv != n_vertices:
        return None
    pos = [[float(t) for t in toks[4 + 3 * i:7 + 3 * i]] for i in range(nv)]
    i, out = 4 + 3 * nv, []
    for _ in range(nf):
        if toks[i] != "3":
            return None
        face = [int(t) for t in toks[i + 1:i + 4]]
        i += 4
        sides = [math.dist(pos[face[k]], pos[face[(k + 1) % 3]]) for k in range(3)]
        a, b, c = sides
        area = 0.25 * math.sqrt(max((a + b + c) * (-a + b + c) * (a - b + c) * (a + b - c), 0.0))
        out.append((face, min(corner_angles(sides, False)), area))
    return out


def where(exe, mesh, eps, tmp):
    """The uniformized route at eps: T1 against T1*, triangle by triangle (see the module docstring)."""
    t1, star, t1star = (os.path.join(tmp, n) for n in ("t1.ply", "t0star.ply", "t1star.ply"))
    for cmd in ([exe, "-q", "remesh", mesh, "--eps", repr(eps), "--refine-in", "uniformized", "--no-check", "--ascii",
                 "-o", t1, "--json"],
                [exe, "-q", "uniformize", mesh, "-o", star, "--json"],
                [exe, "-q", "refine", star, "--eps", repr(eps), "--ascii", "-o", t1star, "--json"]):
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: {r.stderr.strip()}")
    n_input = json.loads(subprocess.run([exe, "-q", "info", mesh, "--json"], capture_output=True,
                                        text=True).stdout)["vertices"]
    va, fa, sa = read_ascii_ply(t1)
    vb, fb, sb = read_ascii_ply(t1star)
    if fa != fb:
        sys.exit("mesh_study.py --where: remesh and uniformize + refine did not give the same refinement")
    cone = [360 - math.degrees(k) for k in va["curvature"][:n_input]]  # angle sum = 2 pi - deficit
    corner_ratio = [[] for _ in range(n_input)]  # per input vertex: input-metric / uniformized angle of its corners
    bad = bad_at_vertex = bad_smallest_at_vertex = 0
    worst_away, worst_at, smallest = float("inf"), float("inf"), 180.0
    for face, s1, s2 in zip(fa, sa, sb):
        a1, a2 = corner_angles(s1, False), corner_angles(s2, True)
        for k in range(3):
            if face[k] < n_input:
                corner_ratio[face[k]].append(a1[k] / a2[k])
        touches = any(v < n_input for v in face)
        ratio = min(a1) / min(a2)
        if touches:
            worst_at = min(worst_at, ratio)
        else:
            worst_away = min(worst_away, ratio)
        smallest = min(smallest, min(a1))
        if min(a1) < 20.7:
            bad += 1
            bad_at_vertex += touches
            k = a1.index(min(a1))
            bad_smallest_at_vertex += face[k] < n_input
    ratios = [x for r in corner_ratio for x in r]
    spread = [max(r) / min(r) for r in corner_ratio if r]
    print(f"\nwhere (uniformized route, eps {eps:g}, {len(fa)} triangles, smallest angle {smallest:.2f} deg in the "
          f"input metric):")
    print(f"  input vertex angle sums theta: {min(cone):.2f} ... {max(cone):.2f} deg "
          f"(theta / 2 pi: {min(cone) / 360:.3f} ... {max(cone) / 360:.3f}); "
          f"{sum(c < 3 * 20.7 for c in cone)} below 3 x 20.7 deg")
    print(f"  corners at input vertices, input-metric / uniformized angle: {min(ratios):.3f} ... {max(ratios):.3f} "
          f"(largest / smallest at one vertex: up to {max(spread):.2f}, median {sorted(spread)[len(spread) // 2]:.2f})")
    print(f"  triangles under 20.7 deg in the input metric: {bad} ({100 * bad / len(fa):.2f} %), {bad_at_vertex} with "
          f"an input vertex as a corner, {bad_smallest_at_vertex} with their smallest corner there")
    print(f"  smallest angle ratio, input metric / uniformized: {worst_at:.3f} at input vertices, "
          f"{worst_away:.3f} away from them")
    # The input faces the bad triangles lie in (where their vertices are located), by the faces' own smallest corner.
    faces = off_face_min_angles(mesh, n_input)
    if faces is not None and all(v in faces[int(va["input_face"][v])][0] for v in range(n_input)):
        bad_faces = [faces[int(va["input_face"][v])][1] for face, s1 in zip(fa, sa)
                     if min(corner_angles(s1, False)) < 20.7 for v in face if v >= n_input]
        share = sum(x < 20 for x in bad_faces) / max(len(bad_faces), 1)
        area = sum(f[2] for f in faces if f[1] < 20) / sum(f[2] for f in faces)
        print(f"  input faces with a corner under 20 deg: {sum(f[1] < 20 for f in faces)} of {len(faces)} "
              f"({100 * area:.0f} % of the area); they hold {100 * share:.0f} % of the inserted vertices of the "
              f"triangles under 20.7 deg")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mesh")
    p.add_argument("--eps", default=None, help="comma-separated eps values (overrides --vertices)")
    p.add_argument("--vertices", default="1k,2k,4k,8k,16k", help="target vertex counts (default 1k,2k,4k,8k,16k)")
    p.add_argument("--routes", default="uniformized,input", help="refinement metrics (default uniformized,input)")
    p.add_argument("--smoothing", type=int, default=0, help="smoothing passes on the input route (default 0)")
    p.add_argument("--where", default=None, help="comma-separated eps for the uniformized-route analysis")
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
    print(f"load average {os.getloadavg()[0]:.2f} (1 min) at the start")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for route in a.routes.split(","):
            route_rows = []
            for eps in epsilons:
                out = os.path.join(tmp, "out.ply")
                cmd = [exe, "-q", "remesh", a.mesh, "--eps", repr(eps), "--refine-in", route, "-o", out, "--json"]
                if route == "input":
                    cmd += ["--smoothing", str(a.smoothing)]
                r, cpu = run_timed(cmd)
                if r.returncode != 0:
                    print(f"{route}, eps {eps}: {r.stderr.strip()}", file=sys.stderr)
                    continue
                j = json.loads(r.stdout)
                q, g = j["quality"], j["gaussian_curvature_measure"]
                route_rows.append({
                    "route": route, "eps": eps, "vertices": q["vertices"], "triangles": q["triangles"],
                    "min_angle": q["min_angle_deg"], "mean_min_angle": q["mean_min_angle_deg"],
                    "pct_under_30": 100 * q["fraction_below_30_deg"],
                    "min_angle_uniformized": j["quality_uniformized"]["min_angle_deg"] if route == "uniformized"
                    else float("nan"),
                    "max_circumradius": q["max_circumradius"], "mean_circumradius": q["mean_circumradius"],
                    "gauss_bonnet": q["gauss_bonnet_residual"], "inverted": j["inverted_triangles"],
                    "area": j["total_area"],
                    "area_error": abs(j["total_area"] - j["input_mesh"]["area"]) / j["input_mesh"]["area"],
                    "e_G": g["mean_abs_error"], "max_error": g["max_abs_error"], "within": g["fraction_within"],
                    "loop_edges": j["loop_edges"], "cpu_seconds": cpu})
            if not route_rows:
                continue
            cols = ["eps", "vertices", "min_angle", "mean_min_angle", "pct_under_30", "min_angle_uniformized",
                    "max_circumradius", "mean_circumradius", "gauss_bonnet", "inverted", "area_error", "e_G",
                    "loop_edges", "cpu_seconds"]
            if route == "input":
                cols.remove("min_angle_uniformized")
            print(f"\nrefine in: {route}" + (f" (smoothing {a.smoothing})" if route == "input" else ""))
            print("| " + " | ".join(cols) + " |")
            print("|" + "---|" * len(cols))
            for r in route_rows:
                print("| " + " | ".join(f"{r[c]:.4g}" if isinstance(r[c], float) else str(r[c]) for c in cols) + " |")
            R = [r["mean_circumradius"] for r in route_rows]
            print(f"slope log e_G / log mean circumradius: {slope(R, [r['e_G'] for r in route_rows]):.3f}")
            print(f"slope log mean circumradius / log vertices: {slope([r['vertices'] for r in route_rows], R):.3f}")
            rows += route_rows
        if a.where:
            for eps in a.where.split(","):
                where(exe, a.mesh, float(eps), tmp)
    if not rows:
        sys.exit("mesh_study.py: every run failed")
    print(f"\nload average {os.getloadavg()[0]:.2f} (1 min) at the end")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
