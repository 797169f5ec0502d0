"""refine and embed: the refinement's bounds in the output's own lengths, an icosphere's realization recovered from its
edge lengths, an unrealizable tetrahedron, equality with the CLI, errors and interruption."""

import json
import math
import subprocess

import numpy as np
import pytest

import conformesh
from conformesh import metrics

from conftest import corner_lengths

# Round-off allowance on the bounds: the refinement compares circumradii computed from the same lengths by its own
# formulas (conformesh/refine/delaunay); ours (below) differ in the last bits, 1e-9 relative covers that with room.
ROUND_OFF = 1e-9


def euclidean_circumradii(L):
    """R = abc / (4 A) per face, A by Heron; L (m, 3)."""
    a, b, c = L.T
    s = (a + b + c) / 2
    area = np.sqrt(s * (s - a) * (s - b) * (s - c))
    return a * b * c / (4 * area)


def spherical_circumradii(L):
    """On the unit sphere: the circumcircle of three points is the circle through them in the plane of their chords
    2 sin(l/2); its spherical radius R satisfies sin R = r (r the chord triangle's circumradius, R < pi/2)."""
    return np.arcsin(euclidean_circumradii(2 * np.sin(L / 2)))


def check_bounds(t, eps, ratio):
    """Every circumradius <= eps and circumradius / shortest edge <= ratio, from t.lengths alone."""
    L = t.lengths
    R = spherical_circumradii(L) if t.background == "spherical" else euclidean_circumradii(L)
    assert R.max() <= eps * (1 + ROUND_OFF)
    assert (R / L.min(axis=1)).max() <= ratio * (1 + ROUND_OFF)
    return R


@pytest.fixture(scope="module")
def ellipsoid_t0star():
    """T0* of the ellipsoid f = 0.3: spherical background, a non-constant conformal factor lambda."""
    return conformesh.uniformize(metrics.family("ellipsoid", f=0.3).discretize(resolution=4)).triangulation


def test_refine_uniform_bounds_sphere(ellipsoid_t0star):
    r = conformesh.refine(ellipsoid_t0star, 0.12, uniform=True)
    t = r.triangulation
    assert t.background == "spherical" and r.conformal_factor is None
    R = check_bounds(t, 0.12, math.sqrt(2))
    # The report's figures are those of the same triangles (our formula against the library's, round-off apart).
    assert r.report["quality"]["max_circumradius"] == pytest.approx(R.max(), rel=ROUND_OFF)
    assert r.report["graded"] is False
    # Curvature +1 everywhere: Gauss-Bonnet, area 4 pi (the uniformization's tolerance, 1e-10 on angle sums).
    assert t.total_area == pytest.approx(4 * math.pi, rel=1e-8)
    assert t.num_vertices > ellipsoid_t0star.num_vertices
    np.testing.assert_array_equal(r.input_faces[: ellipsoid_t0star.num_vertices] >= 0, True)
    np.testing.assert_allclose(r.input_barycentric.sum(axis=1), 1, atol=1e-12)


def test_refine_ratio_bound_torus():
    """The flat torus of area 1 (Euclidean background) at B = 1.2 (smallest angle >= 24.6 deg)."""
    flat = conformesh.uniformize(metrics.family("torus").discretize(resolution=6)).triangulation
    r = conformesh.refine(flat, 0.05, ratio=1.2, uniform=True)
    check_bounds(r.triangulation, 0.05, 1.2)
    assert r.triangulation.total_area == pytest.approx(1, rel=1e-10)
    assert np.degrees(r.triangulation.corner_angles().min()) >= math.degrees(math.asin(1 / 2.4)) - 1e-7


def test_refine_constant_conformal_factor_is_exact_bound(ellipsoid_t0star):
    """lambda = c everywhere: the bound is eps e^(-c) exactly."""
    c = 0.5
    n = ellipsoid_t0star.num_vertices
    r = conformesh.refine(ellipsoid_t0star, 0.3, conformal_factor=np.full(n, c))
    check_bounds(r.triangulation, 0.3 * math.exp(-c), math.sqrt(2))
    np.testing.assert_allclose(r.conformal_factor, c, rtol=1e-14)
    assert r.report["graded"] is True


def test_refine_graded_by_field(ellipsoid_t0star):
    """lambda from the field: interpolated at circumcentres, so between its extremes; every circumradius is at most
    eps e^(-min lambda) and the interpolated lambda at the output vertices stays in [min, max]."""
    lam = ellipsoid_t0star.fields["lambda"]
    assert lam.max() - lam.min() > 0.1
    r = conformesh.refine(ellipsoid_t0star, 0.12)
    check_bounds(r.triangulation, 0.12 * math.exp(-lam.min()), math.sqrt(2))
    assert r.conformal_factor.min() >= lam.min() - 1e-12 and r.conformal_factor.max() <= lam.max() + 1e-12
    np.testing.assert_array_equal(r.conformal_factor[: len(lam)], lam)


def test_refine_flat_square_positions_reproduce_lengths():
    """A planar square (z = 0) with boundary: the output positions are points of the input's flat faces, so every
    output length equals the distance of its ends' positions (to round-off) and z stays 0."""
    n = 4
    x, y = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1))
    V = np.c_[x.ravel(), y.ravel(), np.zeros(x.size)]
    F = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            F += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    t = conformesh.Triangulation.from_positions(V, np.array(F))
    r = conformesh.refine(t, 0.08)
    out = r.triangulation
    check_bounds(out, 0.08, math.sqrt(2))
    assert out.total_area == pytest.approx(1, rel=1e-12)
    P = r.positions
    np.testing.assert_array_equal(P[:, 2], 0)
    np.testing.assert_allclose(corner_lengths(P, out.faces), out.lengths, rtol=1e-12)


def test_refine_matches_cli(tmp_path, cli, ellipsoid_t0star):
    src = str(tmp_path / "t0star.ply")
    conformesh.write(src, ellipsoid_t0star)
    out = str(tmp_path / "cli.ply")
    text = subprocess.run([cli, "refine", src, "--eps", "0.1", "--ratio", "1.3", "-o", out, "--json"], check=True,
                          capture_output=True, text=True).stdout
    expected = json.loads(text)
    r = conformesh.refine(conformesh.read(src), 0.1, ratio=1.3)
    for d in (expected, r.report):
        d.pop("seconds")
        d.pop("output", None)
    assert expected["verification"].pop("written") == out  # the file the CLI wrote; Python wrote none yet
    assert r.report == expected
    mine = str(tmp_path / "py.ply")
    r.write(mine)
    with open(out, "rb") as a, open(mine, "rb") as b:
        assert a.read() == b.read()


def test_refine_errors(ellipsoid_t0star):
    with pytest.raises(conformesh.InputError, match="boundary"):
        conformesh.refine(ellipsoid_t0star, 0.1, boundary="arc")
    with pytest.raises(conformesh.InputError, match="conformal_factor"):
        conformesh.refine(ellipsoid_t0star, 0.1, conformal_factor=np.zeros(3))
    with pytest.raises(conformesh.InputError):
        conformesh.refine(ellipsoid_t0star, -1)
    with pytest.raises(conformesh.InputError):
        conformesh.refine(ellipsoid_t0star, 0.1, ratio=0.5)
    with pytest.raises(conformesh.ConvergenceError):
        conformesh.refine(ellipsoid_t0star, 0.01, max_insertions=10)


def test_refine_progress_exception_stops(ellipsoid_t0star):
    """A raising progress stops the refinement at its next report (every 2000 insertions)."""
    calls = []

    def boom(line):
        calls.append(line)
        raise KeyError("stop")

    with pytest.raises(KeyError):
        conformesh.refine(ellipsoid_t0star, 0.03, uniform=True, progress=boom)
    assert len(calls) == 1 and "insertions" in calls[0]


# ---- embed ---------------------------------------------------------------------------------------------------------


def icosphere(levels):
    """The icosahedron subdivided `levels` times, vertices projected to the unit sphere (built here, not by conformesh)."""
    p = (1 + math.sqrt(5)) / 2
    V = [[-1, p, 0], [1, p, 0], [-1, -p, 0], [1, -p, 0], [0, -1, p], [0, 1, p], [0, -1, -p], [0, 1, -p],
         [p, 0, -1], [p, 0, 1], [-p, 0, -1], [-p, 0, 1]]
    F = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    V = [np.array(v, float) / np.linalg.norm(v) for v in V]
    for _ in range(levels):
        mid, G = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                x = V[a] + V[b]
                V.append(x / np.linalg.norm(x))
                mid[key] = len(V) - 1
            return mid[key]

        for a, b, c in F:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            G += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        F = G
    return np.array(V), np.array(F)


def procrustes(X, Y):
    """Rigid motion (rotation or reflection, translation) taking X closest to Y in least squares; returns the moved X."""
    cx, cy = X.mean(axis=0), Y.mean(axis=0)
    U, _, Wt = np.linalg.svd((X - cx).T @ (Y - cy))
    return (X - cx) @ U @ Wt + cy


@pytest.fixture(scope="module")
def icosphere_lengths():
    V, F = icosphere(2)  # 162 vertices, 320 faces
    return V, conformesh.Triangulation.from_lengths(F, corner_lengths(V, F))


def test_embed_icosphere_recovers_sphere(icosphere_lengths):
    """Lengths alone (no positions): the fit reproduces every edge to the fit's tolerance and, the convex polyhedron
    being rigid (Cauchy), is the icosphere up to a rigid motion; after Procrustes, the radius 1 and the vertices.
    The 1e-9 on positions: the fit's edge residuals are round-off (measured 4e-16), and the positions
    after Procrustes were measured 4.4e-16 from V; 1e-9 allows for the rigidity's conditioning on other builds and
    still tells a different polyhedron with the same lengths (one vertex popped inward moves by ~0.03)."""
    V, t = icosphere_lengths
    assert t.positions is None
    e = conformesh.embed(t)
    assert e.isometric and e.report["isometric"]
    tol = e.report["tolerance"]
    assert np.abs(e.edge_residuals).max() <= tol
    assert e.report["max_relative_residual"] == pytest.approx(np.abs(e.edge_residuals).max(), abs=1e-300)
    X = e.positions
    # Edge residuals recomputed here from the positions and the input lengths.
    ends = t.edges
    mine = np.linalg.norm(X[ends[:, 0]] - X[ends[:, 1]], axis=1) / t.edge_lengths - 1
    assert np.abs(mine).max() <= tol
    Y = procrustes(X, V)
    np.testing.assert_allclose(np.linalg.norm(Y, axis=1), 1, atol=1e-9)
    np.testing.assert_allclose(Y, V, atol=1e-9)
    np.testing.assert_array_equal(e.triangulation.positions, X)
    np.testing.assert_array_equal(e.triangulation.lengths, t.lengths)


def test_embed_init_is_used(icosphere_lengths):
    V, t = icosphere_lengths
    e = conformesh.embed(t, init=V * 1.001, regularizer=0)
    assert e.report["start"] == "initial positions" and e.isometric
    np.testing.assert_allclose(e.positions, V, atol=1e-9)  # started next to V: converges to V itself, no motion


def unrealizable_tetrahedron():
    """Base: equilateral of side 1; apex edges 0.55 < 1/sqrt(3) (the base's circumradius): every face satisfies the
    triangle inequality (0.55 + 0.55 > 1), but no point of R^3 is at 0.55 from all three base vertices."""
    F = np.array([[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]])
    d = {frozenset(e): (1.0 if 3 not in e else 0.55) for e in [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]}
    L = np.array([[d[frozenset((f[k], f[(k + 1) % 3]))] for k in range(3)] for f in F])
    return conformesh.Triangulation.from_lengths(F, L)


def test_embed_unrealizable_tetrahedron():
    t = unrealizable_tetrahedron()
    e = conformesh.embed(t)
    assert not e.isometric and e.verdict.startswith("not isometric")
    # The apex cannot reach all three base vertices: some relative residual stays of order
    # (1/sqrt(3) - 0.55) / 0.55 ~ 5e-2 shared over the edges (measured 2.5e-2); 1e-3 is far above the 1e-8 tolerance.
    assert np.abs(e.edge_residuals).max() > 1e-3
    with pytest.raises(conformesh.ConvergenceError, match="not isometric"):
        conformesh.embed(t, strict=True)


def test_embed_matches_cli(tmp_path, cli, icosphere_lengths):
    _, t = icosphere_lengths
    src = str(tmp_path / "lengths.ply")
    conformesh.write(src, t)
    out = str(tmp_path / "fit.ply")
    text = subprocess.run([cli, "embed", src, "-o", out, "--json"], check=True, capture_output=True, text=True).stdout
    expected = json.loads(text)
    e = conformesh.embed(conformesh.read(src))
    for d in (expected, e.report):
        for k in ("start_seconds", "fit_seconds", "output"):
            d.pop(k, None)
    assert e.report == expected
    np.testing.assert_array_equal(conformesh.read(out).positions, e.positions)


def test_embed_errors(icosphere_lengths, ellipsoid_t0star):
    _, t = icosphere_lengths
    with pytest.raises(conformesh.InputError, match="Euclidean|euclidean"):
        conformesh.embed(ellipsoid_t0star)
    with pytest.raises(conformesh.InputError, match="init"):
        conformesh.embed(t, init=np.zeros((3, 3)))
    with pytest.raises(conformesh.InputError, match="init"):
        conformesh.embed(t, init=np.full((t.num_vertices, 3), np.nan))
    with pytest.raises(conformesh.InputError, match="landmarks"):
        conformesh.embed(t, landmarks=2)
    with pytest.raises(conformesh.InputError, match="tolerance"):
        conformesh.embed(t, tolerance=0)


def test_embed_progress_exception_raised_after_fit(icosphere_lengths):
    """The fit cannot be stopped inside Ceres: an exception in progress is held and raised when the fit returns,
    and progress is not called again after it."""
    _, t = icosphere_lengths
    calls = []

    def boom(line):
        calls.append(line)
        raise KeyError("stop")

    with pytest.raises(KeyError):
        conformesh.embed(t, progress=boom)
    assert len(calls) == 1
