#!/usr/bin/python3
"""The Python package's overheads (docs/python.md, "Measured"): the paper's 22k teapot remeshed through Python against
the CLI, run alternately; Triangulation.from_lengths on a 10^6-face array, time and the rise of peak resident memory.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py build/apps/conformesh [ROUNDS]

Each measurement is a fresh process (no warm caches inside Python); the machine is shared, so the script reports the
range over ROUNDS (default 5) alternating runs, not a mean.
"""

import os
import subprocess
import sys
import tempfile
import time

TEAPOT = ["teapot-patch", "--param", "patch=4", "--eps", "0.011853"]

PY_TEAPOT = r"""
import sys, time
t0 = time.perf_counter()
import conformesh
t1 = time.perf_counter()
r = conformesh.remesh(conformesh.metrics.family("teapot-patch", patch=4), 0.011853)
r.write(sys.argv[1])
t2 = time.perf_counter()
print(t1 - t0, t2 - t1, r.triangulation.num_vertices)
"""

PY_FROM_LENGTHS = r"""
import sys, time
import numpy as np
import conformesh
n = 708  # a 708 x 708 periodic grid: 2 n^2 = 1 002 528 faces
i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
a = (i * n + j).ravel()
b = (i * n + (j + 1) % n).ravel()
c = (((i + 1) % n) * n + (j + 1) % n).ravel()
d = (((i + 1) % n) * n + j).ravel()
F = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)]).astype(np.int32)
s = np.sqrt(2.0)
L = np.concatenate([np.tile([1.0, 1.0, s], (n * n, 1)), np.tile([s, 1.0, 1.0], (n * n, 1))])
def status(key):  # kB
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith(key + ":"))
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # resets VmHWM (peak RSS) to the current RSS: the peak below is the call's own
before = status("VmRSS")
t0 = time.perf_counter()
t = conformesh.Triangulation.from_lengths(F, L)
t1 = time.perf_counter()
peak, kept = status("VmHWM"), status("VmRSS")
assert t.num_faces == 2 * n * n and t.genus == 1
print(t1 - t0, (peak - before) / 1024, (kept - before) / 1024, (F.nbytes + L.nbytes) / 2**20)
"""


def run(cmd, env=None):
    t0 = time.perf_counter()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout
    return time.perf_counter() - t0, out


def main():
    cli = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    env = dict(os.environ)
    tmp = tempfile.mkdtemp()
    cli_s, py_s, py_call = [], [], []
    for _ in range(rounds):
        t, _ = run([cli, "remesh", *TEAPOT, "-o", os.path.join(tmp, "cli.ply")], env)
        cli_s.append(t)
        t, out = run([sys.executable, "-c", PY_TEAPOT, os.path.join(tmp, "py.ply")], env)
        py_s.append(t)
        py_call.append(float(out.split()[1]))
    with open(os.path.join(tmp, "cli.ply"), "rb") as x, open(os.path.join(tmp, "py.ply"), "rb") as y:
        same = x.read() == y.read()
    print(f"teapot, CLI whole process:    {min(cli_s):.3f}-{max(cli_s):.3f} s")
    print(f"teapot, Python whole process: {min(py_s):.3f}-{max(py_s):.3f} s")
    print(f"teapot, Python remesh+write:  {min(py_call):.3f}-{max(py_call):.3f} s")
    print(f"teapot, PLY files identical: {same}; vertices {out.split()[2]}")
    rows = [run([sys.executable, "-c", PY_FROM_LENGTHS], env)[1].split() for _ in range(rounds)]
    secs = [float(r[0]) for r in rows]
    rise = [float(r[1]) for r in rows]
    kept = [float(r[2]) for r in rows]
    print(f"from_lengths, 1 002 528 faces: {min(secs):.3f}-{max(secs):.3f} s; peak RSS during the call "
          f"{min(rise):.0f}-{max(rise):.0f} MiB above the RSS before it, {min(kept):.0f}-{max(kept):.0f} MiB kept "
          f"(the Triangulation); the arrays F and L are {float(rows[0][3]):.0f} MiB")


if __name__ == "__main__":
    main()
