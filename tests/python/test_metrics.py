"""conformesh.metrics: families, sampled fields with the file readers' conventions, Python functions."""

import math

import numpy as np
import pytest

import conformesh
from conformesh import metrics


def test_every_family_builds_with_defaults():
    names = [f["name"] for f in metrics.families()]
    assert "kerr-newman" in names and "sphere" in names
    for name in names:
        m = metrics.family(name)
        assert m.description
        u0, u1, v0, v1 = m.chart
        assert u0 < u1 and v0 < v1


def test_family_errors():
    with pytest.raises(conformesh.InputError, match="no-such"):
        metrics.family("no-such")
    with pytest.raises(conformesh.InputError, match="zzz"):
        metrics.family("sphere", zzz=1)
    with pytest.raises(conformesh.InputError, match="not a number"):
        metrics.family("kerr-newman", a="x")


def test_round_sphere_closed_forms():
    m = metrics.family("sphere")
    u = np.linspace(0, 2 * math.pi, 7)
    v = np.linspace(0.1, 3.0, 7)
    guu, guv, gvv = m.g(u, v)
    np.testing.assert_allclose(guu, np.sin(v) ** 2, rtol=1e-14)
    np.testing.assert_allclose(guv, 0, atol=1e-15)
    np.testing.assert_allclose(gvv, 1, rtol=1e-14)
    np.testing.assert_allclose(m.gaussian_curvature(u, v), 1, rtol=1e-12)
    np.testing.assert_allclose(m.area_element(u, v), np.sin(v), rtol=1e-14)
    assert m.shape == "sphere" and m.poles == "both" and m.euler_characteristic == 2


def kerr_horizon(a, nu=64, nv=48, M=1.0):
    """The Kerr horizon 2-metric on a cell-centred theta-phi grid (u = phi, v = theta), in NumPy."""
    uu, vv = metrics.grid((0, 2 * math.pi, 0, math.pi), (nu, nv), poles="both")
    rp = M + math.sqrt(M * M - a * a)
    rho2 = rp * rp + a * a * np.cos(vv) ** 2
    g_uu = (rp * rp + a * a) ** 2 * np.sin(vv) ** 2 / rho2
    return g_uu, np.zeros_like(vv), rho2, rp


def test_sampled_equals_field_file(tmp_path):
    """metrics.sampled on arrays and read_field on the file write_field makes from the same grid agree."""
    family = metrics.family("ellipsoid")
    nu, nv = 32, 16
    uu, vv = metrics.grid(family.chart, (nu, nv), poles="both")
    g = family.g(uu, vv)
    s = metrics.sampled(*g, chart=family.chart, periodic_u=True, poles="both")
    for ext in (".txt", ".h5"):
        path = str(tmp_path / ("field" + ext))
        metrics.write_field(path, family, nu, nv)
        f = metrics.read_field(path)
        u = np.random.default_rng(0).uniform(0, 2 * math.pi, 50)
        v = np.random.default_rng(1).uniform(0.05, 3.0, 50)
        for a, b in zip(s.g(u, v), f.g(u, v)):
            np.testing.assert_allclose(a, b, rtol=1e-13, atol=1e-14)


def test_sampled_kerr_area_and_gauss_bonnet():
    a = 0.6
    g_uu, g_uv, g_vv, rp = kerr_horizon(a)
    m = metrics.sampled(g_uu, g_uv, g_vv, chart=(0, 2 * math.pi, 0, math.pi), periodic_u=True, poles="both")
    r = conformesh.remesh(m, 0.15, check=False)
    t = r.triangulation
    assert t.angle_deficits().sum() == pytest.approx(4 * math.pi, abs=1e-10)
    assert t.total_area == pytest.approx(8 * math.pi * rp, rel=5e-3)  # area of the Kerr horizon, 8 pi M r+


def test_sampled_validation():
    z = np.ones((8, 8))
    chart = (0, 1, 0, 1)
    bad = z.copy()
    bad[3, 5] = np.nan
    with pytest.raises(conformesh.InputError, match=r"g_uv\[3, 5\] is nan"):
        metrics.sampled(z, bad, z, chart=chart)
    with pytest.raises(conformesh.InputError, match="g_vv has shape"):
        metrics.sampled(z, 0 * z, np.ones((8, 7)), chart=chart)
    with pytest.raises(conformesh.InputError, match="2-D"):
        metrics.sampled(z, 0 * z, np.ones(8), chart=chart)
    with pytest.raises(conformesh.InputError):  # not positive definite
        metrics.sampled(z, 2 * z, z, chart=chart)
    with pytest.raises(conformesh.InputError, match="poles"):
        metrics.sampled(z, 0 * z, z, chart=chart, poles="north")
    with pytest.raises(conformesh.InputError):  # 'both' needs the sphere chart
        metrics.sampled(z, 0 * z, z, chart=chart, periodic_u=True, poles="both")


def test_from_function_flat_torus_is_batched():
    calls = []

    def fn(u, v):
        calls.append(u.size)
        return np.full_like(u, 4.0), np.zeros_like(u), np.ones_like(u)

    m = metrics.from_function(fn, chart=(0, 1, 0, 1), shape=(16, 16), periodic_u=True, periodic_v=True,
                              batch=100)
    assert max(calls) <= 100 and sum(calls) == 256
    np.testing.assert_allclose(m.area_element(0.3, 0.7), 2.0, rtol=1e-14)
    np.testing.assert_allclose(m.gaussian_curvature(0.3, 0.7), 0, atol=1e-10)
    assert m.genus == 1
