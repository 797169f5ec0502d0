"""uniformize, remesh, convergence, layout: mathematics, equality with the CLI, GIL and interruption."""

import json
import math
import os
import subprocess
import threading
import time
import _thread

import numpy as np
import pytest

import conformesh
from conformesh import metrics


def test_uniformize_sphere(sphere_t0):
    r = conformesh.uniformize(sphere_t0)
    assert r.geometry == "spherical" and r.report["target"] == "sphere"
    t = r.triangulation
    assert t.background == "spherical"
    # Closed surface of curvature +1: area 4 pi, interior angle sums 2 pi (the flow's residual).
    assert t.total_area == pytest.approx(4 * math.pi, rel=1e-8)
    assert r.report["max_interior_angle_sum_error"] < 1e-8
    assert r.conformal_factor.shape == (t.num_vertices,)
    np.testing.assert_allclose(np.linalg.norm(r.positions, axis=1), 1, rtol=1e-12)


def test_uniformize_torus_flat_area_one():
    r = conformesh.uniformize(metrics.family("torus").discretize(resolution=6))
    assert r.geometry == "euclidean"
    assert r.triangulation.total_area == pytest.approx(1, rel=1e-10)
    assert r.positions is None


def test_uniformize_genus_two_hyperbolic(data_dir):
    t = conformesh.read(os.path.join(data_dir, "eight.off"))
    r = conformesh.uniformize(t)
    assert r.geometry == "hyperbolic"
    # Gauss-Bonnet with K = -1: area = -2 pi chi = 4 pi (g - 1).
    assert r.triangulation.total_area == pytest.approx(4 * math.pi, rel=1e-7)


def test_several_components_refused_clearly(data_dir):
    # blobby_3cc.off has three connected components: the module takes one surface per call and says so.
    t = conformesh.read(os.path.join(data_dir, "blobby_3cc.off"))
    with pytest.raises(conformesh.InputError, match="3 connected components"):
        conformesh.uniformize(t)
    with pytest.raises(conformesh.InputError, match="3 connected components"):
        conformesh.remesh(t, eps=0.1)


def test_convergence_error(sphere_t0):
    with pytest.raises(conformesh.ConvergenceError):
        conformesh.uniformize(sphere_t0, tolerance=1e-14, max_steps=1)


def test_remesh_metric_matches_cli(tmp_path, cli):
    out = str(tmp_path / "cli.ply")
    text = subprocess.run([cli, "remesh", "ellipsoid", "--param", "f=0.3", "--eps", "0.2", "-o", out, "--json"],
                          check=True, capture_output=True, text=True).stdout
    expected = json.loads(text)
    r = conformesh.remesh(metrics.family("ellipsoid", f=0.3), 0.2)
    mine = str(tmp_path / "py.ply")
    r.write(mine)

    def strip(d):
        if isinstance(d, dict):
            return {k: strip(v) for k, v in d.items() if k not in ("seconds", "output", "written")}
        return d

    assert strip(r.report) == strip(expected)
    with open(out, "rb") as a, open(mine, "rb") as b:
        assert a.read() == b.read()
    back = conformesh.read(mine)
    np.testing.assert_array_equal(back.lengths, r.triangulation.lengths)
    np.testing.assert_array_equal(back.fields["u"], r.chart_coordinates[:, 0])


def test_remesh_metric_result():
    r = conformesh.remesh(metrics.family("sphere"), 0.25)
    t = r.triangulation
    n = t.num_vertices
    assert r.chart_coordinates.shape == (n, 2) and r.positions.shape == (n, 3)
    assert r.input_locations is None
    np.testing.assert_allclose(np.linalg.norm(r.positions, axis=1), 1, rtol=1e-12)
    assert t.angle_deficits().sum() == pytest.approx(4 * math.pi, abs=1e-10)
    assert t.total_area == pytest.approx(4 * math.pi, rel=2e-2)
    q = r.report["quality"]
    assert q["max_circumradius"] <= 0.25 * 1.05 and q["min_angle_deg"] > 20
    assert r.report["inverted_triangles"] == 0
    assert set(r.fields) >= {"u", "v", "lambda", "curvature", "error", "relative_error"}


def test_remesh_triangulation(data_dir):
    t = conformesh.read(os.path.join(data_dir, "knot1.off"))
    r = conformesh.remesh(t, eps=0.08 * math.sqrt(t.total_area), check=False)
    assert r.report["refine_in"] == "input"  # the default for a triangulation
    out = r.triangulation
    faces, bary = r.input_locations
    assert faces.shape == (out.num_vertices,) and bary.shape == (out.num_vertices, 3)
    np.testing.assert_allclose(bary.sum(axis=1), 1, atol=1e-12)
    assert out.genus == 1 and r.chart_coordinates is None
    assert out.total_area == pytest.approx(t.total_area, rel=1e-2)
    assert abs(out.angle_deficits().sum()) < 1e-9


def test_remesh_errors(sphere_t0):
    m = metrics.family("sphere")
    with pytest.raises(conformesh.InputError, match="eps"):
        conformesh.remesh(m, 0)
    with pytest.raises(conformesh.InputError, match="disk"):
        conformesh.remesh(m, 0.3, disk_target="square")
    with pytest.raises(conformesh.InputError, match="expected a conformesh"):
        conformesh.remesh("sphere", 0.3)
    with pytest.raises(conformesh.InputError, match="smoothing"):
        conformesh.remesh(sphere_t0, 0.3, refine_in="uniformized", smoothing=1)
    with pytest.raises(conformesh.InputError, match="applies to triangulations"):
        conformesh.remesh(m, 0.3, refine_in="input")
    with pytest.raises(conformesh.InputError, match="refine_in"):
        conformesh.remesh(sphere_t0, 0.3, refine_in=1)


def _smallest_angle_deg(t):
    """The smallest corner of `t` from its own lengths (law of cosines; independent of corner_angles)."""
    a, b, c = t.lengths[:, 0], t.lengths[:, 1], t.lengths[:, 2]
    worst = 180.0
    for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):  # the corner between sides x and y, opposite z
        cos = np.clip((x * x + y * y - z * z) / (2 * x * y), -1, 1)
        worst = min(worst, float(np.degrees(np.arccos(cos)).min()))
    return worst


def test_remesh_default_route_per_input(data_dir):
    """refine_in=None: a Triangulation is refined in its own metric (Ruppert's 20.7 deg at ratio sqrt 2 in the output's
    own lengths), a Metric uniformized; the paper's route stays reachable on a Triangulation."""
    t = conformesh.read(os.path.join(data_dir, "eight.off"))
    r = conformesh.remesh(t, 0.02, check=False)
    assert r.report["refine_in"] == "input"
    assert _smallest_angle_deg(r.triangulation) >= 20.7
    u = conformesh.remesh(t, 0.02, check=False, refine_in="uniformized")
    assert u.report["refine_in"] == "uniformized"
    assert u.report["quality_uniformized"]["min_angle_deg"] >= 20.7  # the bound holds where that route refines
    assert conformesh.remesh(metrics.family("sphere"), 0.3, check=False).report["eps"] == 0.3


def test_convergence_order_kerr():
    """Theorem 3.4 from Python: e_G = O(mean circumradius), Kerr horizon at a/M = 0.95."""
    s = conformesh.convergence(metrics.family("kerr-newman", a=0.95), vertices=[1500, 3000, 6000, 12000])
    assert len(s.rows) == 4
    x = np.log([row["mean_circumradius"] for row in s.rows])
    y = np.log([row["e_G"] for row in s.rows])
    slope = np.polyfit(x, y, 1)[0]
    assert slope >= 0.9
    assert slope == pytest.approx(s.orders["e_G_vs_mean_circumradius"], rel=1e-6)
    assert s.orders["mean_circumradius_vs_vertices"] == pytest.approx(-0.5, abs=0.1)


def test_layout_torus_and_disk():
    L = conformesh.layout(metrics.family("torus").discretize(resolution=6))
    tau = complex(*L.report["tau"])
    assert abs(tau.real) <= 0.5 + 1e-9 and abs(tau) >= 1 - 1e-9  # reduced into the modular fundamental domain
    assert L.corners.shape == (L.triangulation.num_faces, 3, 2)
    assert L.svg().startswith("<")
    d = conformesh.layout(metrics.family("hyperbolic-disk").discretize(resolution=4))
    assert d.target == "circle-domain"
    r = np.hypot(d.corners[..., 0], d.corners[..., 1])
    assert r.max() == pytest.approx(1, abs=1e-6)  # the unit disk


def test_progress_callback_receives_lines(sphere_t0):
    lines = []
    conformesh.uniformize(sphere_t0, progress=lines.append)
    assert lines and all(isinstance(s, str) for s in lines)


def test_progress_exception_propagates(sphere_t0):
    def boom(line):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        conformesh.remesh(metrics.family("sphere"), 0.2, progress=boom)


def test_gil_released_during_remesh():
    """A Python thread keeps running while remesh works (the GIL is released)."""
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    m = metrics.family("kerr-newman", a=0.95)
    thread = threading.Thread(target=count)
    thread.start()
    time.sleep(0.01)
    t0 = time.perf_counter()
    conformesh.remesh(m, 0.05, check=True)
    t1 = time.perf_counter()
    stop.set()
    thread.join()
    during = [t for t in ticks if t0 < t < t1]
    assert t1 - t0 > 0.1
    assert len(during) > 0.2 * (t1 - t0) / 0.001 * 0.1  # the thread ran throughout, not only after


def test_keyboard_interrupt_stops_remesh(tmp_path):
    """Ctrl-C (SIGINT to the main thread) during remesh raises KeyboardInterrupt at the next step."""
    m = metrics.family("kerr-newman", a=0.95)
    timer = threading.Timer(0.2, _thread.interrupt_main)
    t0 = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        conformesh.remesh(m, 0.01, check=True)
    timer.join()
    # The whole call takes about 8 s without the check (231k vertices, measured): stopping within 3 s means it
    # stopped between steps, not at the end.
    assert time.perf_counter() - t0 < 3


def test_remesh_triangulation_matches_cli(tmp_path, cli, data_dir):
    """The mesh route's report (refine/pipeline/remesh_json.h's meshRemeshJson) equals `remesh MESHFILE --json`."""
    path = os.path.join(data_dir, "knot1.off")
    out = str(tmp_path / "cli.ply")
    text = subprocess.run([cli, "remesh", path, "--eps", "0.5", "-o", out, "--json"], check=True,
                          capture_output=True, text=True).stdout
    expected = json.loads(text)
    r = conformesh.remesh(conformesh.read(path), 0.5)

    def strip(d):
        if isinstance(d, dict):
            return {k: strip(v) for k, v in d.items() if k not in ("seconds", "output", "written")}
        return d

    assert strip(r.report) == strip(expected)
    mine = str(tmp_path / "py.ply")
    r.write(mine)
    with open(out, "rb") as a, open(mine, "rb") as b:
        assert a.read() == b.read()
