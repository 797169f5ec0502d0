#!/usr/bin/python3
"""Survey of CGAL's data set through the pipeline: info -> uniformize -> remesh (both --refine-in routes), one
process at a time, each under a time limit; writes docs/robustness.md (a table of outcomes and times, the worst times).

  /usr/bin/python3 scripts/survey_cgal.py BUILD/apps/conformesh [--data DIR] [--eps-rel 0.05] [--limit 60]
                                          [--only NAME ...] [-o docs/robustness.md]

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


def survey_one(exe, path, out_dir, eps_rel, limit):
    name = os.path.basename(path)
    row = {"mesh": name}
    status, dt, j, err = run([exe, "-q", "info", path, "--json"], limit)
    row["info"] = (status, dt, err)
    if status != 0:
        return row
    row["vertices"], row["faces"] = j.get("vertices"), j.get("faces")
    uni = os.path.join(out_dir, "u.ply")
    status, dt, j, err = run([exe, "-q", "uniformize", path, "-o", uni, "--json"], limit)
    row["uniformize"] = (status, dt, err)
    if j:
        row["target"] = j.get("target")
        row["flips_per_edge"] = j.get("flips", 0) / max(1, 3 * (row["faces"] or 1) / 2)
    for route in ("uniformized", "input"):
        out = os.path.join(out_dir, "r.ply")
        cmd = [exe, "-q", "remesh", path, "--eps-rel", str(eps_rel), "--refine-in", route, "--no-check", "-o", out,
               "--json"]
        status, dt, j, err = run(cmd, limit)
        detail = err
        if j and status in (0, 3):
            q = j.get("quality", {})
            detail = "%d vertices, min angle %.1f deg" % (q.get("vertices", 0), q.get("min_angle_deg", 0))
            if status == 3:
                detail = "; ".join(j.get("verification", {}).get("failures", []))[:160]
        row[route] = (status, dt, detail)
    return row


def cell(r):
    if r is None:
        return "—"
    status, dt, _ = r
    return "%s (%.1f s)" % ("ok" if status == 0 else status, dt)


def write_report(rows, args, path):
    lines = ["# Robustness on CGAL's data set", "",
             "Written by `/usr/bin/python3 scripts/survey_cgal.py BUILD/apps/conformesh` (%s); every run one process at "
             "a time with a %g s limit, remesh at `--eps-rel %g` (ε = %g·√area) with `--no-check`. Status: ok (exit 0, "
             "output verified), 1 (refused or failed, message), 3 (output failed verification, named), timeout. "
             "Flips/edge: the flow's Ptolemy flips per input edge (the uniformized route refuses more than 50)."
             % (time.strftime("%Y-%m-%d"), args.limit, args.eps_rel, args.eps_rel), ""]
    counts = {}
    for r in rows:
        for k in ("info", "uniformize", "uniformized", "input"):
            if k in r:
                s = r[k][0]
                counts.setdefault(k, {}).setdefault("ok" if s == 0 else str(s), 0)
                counts[k]["ok" if s == 0 else str(s)] += 1
    lines += ["## Summary", "", "| stage | outcomes |", "|---|---|"]
    for k in ("info", "uniformize", "uniformized", "input"):
        label = {"uniformized": "remesh --refine-in uniformized", "input": "remesh --refine-in input"}.get(k, k)
        lines.append("| %s | %s |" % (label, ", ".join("%s: %d" % kv for kv in sorted(counts.get(k, {}).items()))))
    times = sorted(((r[k][1], r["mesh"], k) for r in rows for k in ("info", "uniformize", "uniformized", "input")
                    if k in r), reverse=True)[:10]
    lines += ["", "## Worst times", "", "| seconds | mesh | stage |", "|---|---|---|"]
    lines += ["| %.1f | %s | %s |" % t for t in times]
    lines += ["", "## Every file", "",
              "| mesh | V | F | info | uniformize | target | flips/edge | remesh uniformized | remesh input | note |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        note = ""
        for k in ("info", "uniformize", "uniformized", "input"):
            if k in r and r[k][0] != 0:
                note = "%s: %s" % (k, r[k][2].replace("|", "/")[:180])
                break
        fpe = r.get("flips_per_edge")
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["mesh"], r.get("vertices", ""), r.get("faces", ""), cell(r.get("info")), cell(r.get("uniformize")),
            r.get("target", ""), "" if fpe is None else "%.1f" % fpe, cell(r.get("uniformized")),
            cell(r.get("input")), note))
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
        rows.append(survey_one(args.conformesh, os.path.join(meshes, f), out_dir, args.eps_rel, args.limit))
        print("[%d/%d] %s" % (i + 1, len(files), f), file=sys.stderr, flush=True)
        write_report(rows, args, args.output)


if __name__ == "__main__":
    main()
