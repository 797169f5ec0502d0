#!/usr/bin/python3
"""Survey of CGAL's data set through the pipeline: info -> remesh by the default route (--refine-in input, with
its curvature-measure check), then uniformize -> remesh --refine-in uniformized; one process at a time, each under a
time limit; writes docs/robustness.md (the default route's verdict per file, a table of outcomes and times, the worst
times). A default-route output counts as ok only if it exits 0 with its smallest angle >= min(20.7 deg, the input's
smallest angle sum), no inverted triangle, Gauss-Bonnet and the input's area to 1e-9, and the written file, read back
by `conformesh info`, has the same smallest corner bound and area.

  /usr/bin/python3 scripts/survey_cgal.py BUILD/apps/conformesh [--data DIR] [--eps-rel 0.05] [--limit 60]
                                          [--no-check] [--only NAME ...] [-o docs/robustness.md]

Needs: Python 3.8+ (standard library only) and CGAL's data set, Debian's /usr/share/doc/libcgal-dev/data.tar.gz
(package libcgal-demo), extracted to a temporary directory unless --data names an extracted `data/meshes`.
Exit codes of conformesh (docs/cli.md): 0 verified output, 1 refused input or failed computation, 2 bad command line,
3 output failed verification; 'timeout' when the limit was hit.
"""
import argparse
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time

TARBALL = "/usr/share/doc/libcgal-dev/data.tar.gz"
MESH_EXTENSIONS = (".off", ".obj", ".ply")
DEFAULT_ROUTE = "input"  # what `conformesh remesh MESH` refines in without --refine-in (docs/cli.md)


def need(condition, what):
    if not condition:
        sys.exit("survey_cgal.py: missing " + what)


def mesh_dir(data):
    if data:
        return data
    need(os.path.exists(TARBALL), TARBALL + " (apt-get install libcgal-demo), or pass --data DIR")
    tmp = tempfile.mkdtemp(prefix="cgal-survey-")
    with tarfile.open(TARBALL) as t:
        t.extractall(tmp, members=[m for m in t.getmembers() if m.name.startswith("data/meshes/")])
    return os.path.join(tmp, "data", "meshes")


def run(cmd, limit):
    """(status, seconds, parsed JSON or None, last stderr line)."""
    t = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return "timeout", limit, None, "over %g s" % limit
    dt = time.monotonic() - t
    try:
        j = json.loads(p.stdout) if p.stdout.strip() else None
    except json.JSONDecodeError:
        j = None
    err = [line for line in p.stderr.splitlines() if line.strip()]
    return p.returncode, dt, j, (err[-1] if err else "")


RUPPERT_DEG = 20.7048110546  # arcsin(1/(2B)) at B = sqrt 2, the default --ratio (docs/cli.md)


def remesh_row(exe, path, out, eps_rel, limit, route, check):
    """(status, seconds, detail, figures): figures holds the JSON's quality of a run that wrote an output."""
    cmd = [exe, "-q", "remesh", path, "--eps-rel", str(eps_rel), "-o", out, "--json"]
    if route != DEFAULT_ROUTE:
        cmd += ["--refine-in", route]
    if not check:
        cmd.append("--no-check")
    status, dt, j, err = run(cmd, limit)
    detail, figures = err, {}
    if j and status in (0, 3):
        # A file of several components reports each under "components" (docs/cli.md): the worst of them counts.
        parts = j.get("components") or [j]
        qs = [c.get("quality", {}) for c in parts]
        figures = {"vertices": j.get("output_mesh", {}).get("vertices", sum(q.get("vertices", 0) for q in qs)),
                   "min_angle": min(q.get("min_angle_deg", 0) for q in qs),
                   "inverted": sum(c.get("inverted_triangles", 0) for c in parts),
                   "gauss_bonnet": max((q.get("gauss_bonnet_residual", 0) for q in qs), key=abs),
                   "area": j.get("total_area"), "input_area": j.get("input_mesh", {}).get("area")}
        detail = "%d vertices, min angle %.2f deg" % (figures["vertices"], figures["min_angle"])
        if status == 0 and route == DEFAULT_ROUTE:
            # The written file read back, by info: its corner angles in its own lengths, its area.
            s2, _, j2, err2 = run([exe, "-q", "info", out, "--json"], limit)
            figures["reread"] = (j2.get("min_corner_angle_deg"), j2.get("total_area")) if s2 == 0 and j2 else err2
        if status == 3:
            detail = "; ".join(j.get("verification", {}).get("failures", []))[:160]
    return status, dt, detail, figures


def wrong_output(row):
    """What looks wrong about an exit-0 output of the default route (empty if nothing): the angle bound
    min(20.7 deg, the input's smallest angle sum), inversions, Gauss-Bonnet, the kept area."""
    status, _, _, f = row[DEFAULT_ROUTE]
    if status != 0:
        return []
    bad = []
    bound = row.get("angle_bound")
    if bound is not None and f["min_angle"] < bound - 1e-9:
        bad.append("min angle %.3f deg < bound %.3f deg" % (f["min_angle"], bound))
    if f["inverted"]:
        bad.append("%d inverted" % f["inverted"])
    if abs(f["gauss_bonnet"]) > 1e-9:
        bad.append("Gauss-Bonnet residual %.2e" % f["gauss_bonnet"])
    if f["area"] is not None and f["input_area"] and abs(f["area"] / f["input_area"] - 1) > 1e-9:
        bad.append("area %.12g vs input %.12g" % (f["area"], f["input_area"]))
    reread = f.get("reread")
    if isinstance(reread, str):
        bad.append("the written file does not read back: " + reread)
    elif reread:
        corner, area = reread
        if bound is not None and corner < bound - 1e-9:
            bad.append("the written file's smallest corner %.3f deg < bound %.3f deg" % (corner, bound))
        if f["input_area"] and abs(area / f["input_area"] - 1) > 1e-9:
            bad.append("the written file's area %.12g vs input %.12g" % (area, f["input_area"]))
    return bad


def survey_one(exe, path, out_dir, eps_rel, limit, check):
    name = os.path.basename(path)
    row = {"mesh": name}
    status, dt, j, err = run([exe, "-q", "info", path, "--json"], limit)
    row["info"] = (status, dt, err)
    out = os.path.join(out_dir, "r.ply")
    # The default route runs on every file, refused ones too: it must refuse them as clearly as info does.
    row[DEFAULT_ROUTE] = remesh_row(exe, path, out, eps_rel, limit, DEFAULT_ROUTE, check)
    if status != 0:
        return row
    row["vertices"], row["faces"] = j.get("vertices"), j.get("faces")
    if "min_angle_sum_deg" in j:
        row["cone"] = j["min_angle_sum_deg"]
        row["angle_bound"] = min(RUPPERT_DEG, row["cone"])
    uni = os.path.join(out_dir, "u.ply")
    status, dt, j, err = run([exe, "-q", "uniformize", path, "-o", uni, "--json"], limit)
    row["uniformize"] = (status, dt, err)
    if j:
        row["target"] = j.get("target")
        row["flips_per_edge"] = j.get("flips", 0) / max(1, 3 * (row["faces"] or 1) / 2)
    row["uniformized"] = remesh_row(exe, path, out, eps_rel, limit, "uniformized", False)
    return row


def cell(r):
    if r is None:
        return "—"
    status, dt = r[0], r[1]
    return "%s (%.1f s)" % ("ok" if status == 0 else status, dt)


def default_outcome(r):
    """The default route's verdict on one file: ok (verified, nothing wrong), refused (exit 1 on input that info
    refuses too), or failed (anything else: exit 1 or 3 on valid input, a timeout, an exit 0 that looks wrong)."""
    status = r[DEFAULT_ROUTE][0]
    if status == 0:
        return "failed" if wrong_output(r) else "ok"
    if status == 1 and r["info"][0] == 1:
        return "refused"
    return "failed"


STAGES = ("info", DEFAULT_ROUTE, "uniformize", "uniformized")
LABELS = {"input": "remesh (default: --refine-in input)", "uniformized": "remesh --refine-in uniformized"}


def write_report(rows, args, path):
    lines = ["# Robustness on CGAL's data set", "",
             "Written by `/usr/bin/python3 scripts/survey_cgal.py BUILD/apps/conformesh` (%s); every run one process at "
             "a time with a %g s limit, remesh at `--eps-rel %g` (ε = %g·√area). The default route of `conformesh "
             "remesh MESH` (`--refine-in input`: the input refined in its own metric) runs on every file, %s; "
             "`--refine-in uniformized` runs with `--no-check` on files that info reads. Status: ok (exit 0, output "
             "verified), 1 (refused or failed, message), 3 (output failed verification, named), timeout. Angle bound: "
             "min(20.7°, the input's smallest angle sum), which the default route's smallest angle (in the output's "
             "own lengths, and again in the written file read back by `conformesh info`) must reach. Flips/edge: the flow's Ptolemy flips per input edge (the uniformized route "
             "refuses more than 50)."
             % (time.strftime("%Y-%m-%d"), args.limit, args.eps_rel, args.eps_rel,
                "with the curvature-measure check as a user runs it" if args.check else "with `--no-check`"), ""]
    verdicts = {}
    for r in rows:
        verdicts.setdefault(default_outcome(r), []).append(r["mesh"])
    lines += ["## Summary", "",
              "Default route (`conformesh remesh MESH`), %d files: **ok %d** (exit 0, verified, angle bound met), "
              "**refused %d** (exit 1 on input that info refuses too), **failed %d**%s." % (
                  len(rows), len(verdicts.get("ok", [])), len(verdicts.get("refused", [])),
                  len(verdicts.get("failed", [])),
                  (": " + ", ".join(verdicts["failed"])) if verdicts.get("failed") else ""), ""]
    counts = {}
    for r in rows:
        for k in STAGES:
            if k in r:
                s = "ok" if r[k][0] == 0 else str(r[k][0])
                counts.setdefault(k, {}).setdefault(s, 0)
                counts[k][s] += 1
    lines += ["| stage | outcomes |", "|---|---|"]
    for k in STAGES:
        lines.append("| %s | %s |" % (LABELS.get(k, k),
                                      ", ".join("%s: %d" % kv for kv in sorted(counts.get(k, {}).items()))))
    times = sorted(((r[k][1], r["mesh"], LABELS.get(k, k)) for r in rows for k in STAGES if k in r), reverse=True)
    lines += ["", "## Worst times", "", "Runs over the %g s limit: %d." % (
        args.limit, sum(1 for t in times if t[0] >= args.limit)), "", "| seconds | mesh | stage |", "|---|---|---|"]
    lines += ["| %.1f | %s | %s |" % t for t in times[:10]]
    lines += ["", "## Every file", "",
              "| mesh | V | F | info | smallest angle sum (deg) | remesh (default: input) | min angle (deg) | "
              "uniformize | target | flips/edge | remesh uniformized | note |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        notes = wrong_output(r)
        for k in STAGES:
            repeats = {DEFAULT_ROUTE: "info", "uniformized": "uniformize"}.get(k)  # the same message twice
            if k in r and r[k][0] != 0 and not (repeats in r and r[k][2] == r[repeats][2]):
                notes.append("%s: %s" % (LABELS.get(k, k), r[k][2].replace("|", "/")[:180]))
        fpe = r.get("flips_per_edge")
        f = r[DEFAULT_ROUTE][3]
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["mesh"], r.get("vertices", ""), r.get("faces", ""), cell(r.get("info")),
            "%.2f" % r["cone"] if "cone" in r else "", cell(r[DEFAULT_ROUTE]),
            "%.2f" % f["min_angle"] if f else "", cell(r.get("uniformize")), r.get("target", ""),
            "" if fpe is None else "%.1f" % fpe, cell(r.get("uniformized")), "; ".join(notes)))
    findings = ""  # the hand-written section (causes, what is left) survives a re-run
    if os.path.exists(path):
        with open(path) as f:
            old = f.read()
        if "\n## Findings" in old:
            findings = old[old.index("\n## Findings"):]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n" + findings)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("conformesh")
    ap.add_argument("--data")
    ap.add_argument("--eps-rel", type=float, default=0.05)
    ap.add_argument("--limit", type=float, default=60)
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--no-check", dest="check", action="store_false",
                    help="run the default route with --no-check too (faster; the check is part of the default)")
    ap.add_argument("-o", "--output", default=os.path.join(os.path.dirname(__file__), "..", "docs", "robustness.md"))
    args = ap.parse_args()
    need(os.access(args.conformesh, os.X_OK), "an executable conformesh at " + args.conformesh)
    meshes = mesh_dir(args.data)
    files = sorted(f for f in os.listdir(meshes) if f.lower().endswith(MESH_EXTENSIONS))
    if args.only:
        files = [f for f in files if f in args.only or os.path.splitext(f)[0] in args.only]
    out_dir = tempfile.mkdtemp(prefix="cgal-survey-out-")
    rows = []
    for i, f in enumerate(files):
        rows.append(survey_one(args.conformesh, os.path.join(meshes, f), out_dir, args.eps_rel, args.limit, args.check))
        print("[%d/%d] %s" % (i + 1, len(files), f), file=sys.stderr, flush=True)
        write_report(rows, args, args.output)


if __name__ == "__main__":
    main()
