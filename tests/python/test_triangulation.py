"""Triangulation: construction from arrays, validation, attributes, files."""

import json
import math
import os
import subprocess

import numpy as np
import pytest

import conformesh
from conftest import corner_lengths


def test_version_and_errors_are_exported():
    assert conformesh.__version__.count(".") == 2
    assert issubclass(conformesh.InputError, ValueError)
    assert issubclass(conformesh.ConvergenceError, RuntimeError)


def test_regular_tetrahedron_closed_forms(tetrahedron):
    V, F = tetrahedron
    t = conformesh.Triangulation.from_positions(V, F)
    a = math.sqrt(8.0)  # edge length
    assert (t.num_vertices, t.num_edges, t.num_faces) == (4, 6, 4)
    assert t.euler_characteristic == 2 and t.genus == 0 and t.boundary_loops == 0
    assert t.total_area == pytest.approx(4 * math.sqrt(3) / 4 * a * a, rel=1e-14)
    np.testing.assert_allclose(t.corner_angles(), math.pi / 3, rtol=1e-14)
    np.testing.assert_allclose(t.angle_deficits(), math.pi, rtol=1e-14)
    np.testing.assert_allclose(t.lengths, a, rtol=1e-15)
    np.testing.assert_array_equal(t.faces, F)
    assert t.faces.dtype == np.int32 and t.lengths.shape == (4, 3)
    np.testing.assert_array_equal(t.positions, V)


def test_from_lengths_matches_positions(tetrahedron):
    V, F = tetrahedron
    t = conformesh.Triangulation.from_lengths(F, corner_lengths(V, F))
    s = conformesh.Triangulation.from_positions(V, F)
    np.testing.assert_allclose(t.lengths, s.lengths, rtol=1e-15)
    assert t.positions is None
    assert t.summary()["gauss_bonnet_residual"] == pytest.approx(0, abs=1e-13)


@pytest.mark.parametrize("fdtype", [np.int32, np.int64, np.uint32, np.int16])
@pytest.mark.parametrize("vdtype", [np.float64, np.float32, np.int64])
def test_dtypes_accepted(tetrahedron, fdtype, vdtype):
    V, F = tetrahedron
    t = conformesh.Triangulation.from_positions(V.astype(vdtype), F.astype(fdtype))
    assert t.total_area == pytest.approx(4 * math.sqrt(3) / 4 * 8, rel=1e-6)


def test_non_contiguous_arrays(tetrahedron):
    V, F = tetrahedron
    big = np.zeros((8, 6))
    big[::2, ::2] = V
    Fbig = np.zeros((4, 6), dtype=np.int32)
    Fbig[:, ::2] = F
    Vs, Fs = big[::2, ::2], Fbig[:, ::2]
    assert not Vs.flags.c_contiguous and not Fs.flags.c_contiguous
    t = conformesh.Triangulation.from_positions(Vs, Fs)
    np.testing.assert_array_equal(t.faces, F)
    L = np.asfortranarray(corner_lengths(V, F))
    assert conformesh.Triangulation.from_lengths(Fs, L).total_area == pytest.approx(t.total_area, rel=1e-15)


def test_float_faces_rejected(tetrahedron):
    V, F = tetrahedron
    with pytest.raises(conformesh.InputError, match="integer array"):
        conformesh.Triangulation.from_positions(V, F.astype(float))


@pytest.mark.parametrize("shape", [(4, 2), (4,), (4, 3, 1)])
def test_bad_shapes(tetrahedron, shape):
    V, F = tetrahedron
    with pytest.raises(conformesh.InputError, match="expected shape"):
        conformesh.Triangulation.from_positions(np.zeros(shape), F)
    with pytest.raises(conformesh.InputError, match="expected shape"):
        conformesh.Triangulation.from_lengths(F, np.ones(shape))


def test_lengths_rows_must_match_faces(tetrahedron):
    _, F = tetrahedron
    with pytest.raises(conformesh.InputError, match="L has 3 rows but F has 4 faces"):
        conformesh.Triangulation.from_lengths(F, np.ones((3, 3)))


def test_nan_position_named(tetrahedron):
    V, F = tetrahedron
    V = V.copy()
    V[2, 1] = np.nan
    with pytest.raises(conformesh.InputError, match="row 2, column 1 is nan"):
        conformesh.Triangulation.from_positions(V, F)


def test_nan_length_named(tetrahedron):
    _, F = tetrahedron
    L = np.ones((4, 3))
    L[3, 2] = np.nan
    with pytest.raises(conformesh.InputError, match="face 3, column 2 is nan"):
        conformesh.Triangulation.from_lengths(F, L)


def test_disagreeing_lengths_name_both_faces(tetrahedron):
    _, F = tetrahedron
    L = np.ones((4, 3))
    L[2, 0] = 1.5  # edge (0, 3) of face 2; face 1 gives it 1
    with pytest.raises(conformesh.InputError, match=r"face 2 gives edge \(0, 3\) length 1.5 but face 1 gives 1"):
        conformesh.Triangulation.from_lengths(F, L)


def test_triangle_inequality_names_face():
    F = np.array([[0, 1, 2], [0, 2, 3]])
    L = np.array([[1.0, 1.0, 1.0], [1.0, 3.0, 1.0]])
    with pytest.raises(conformesh.InputError, match="face 1"):
        conformesh.Triangulation.from_lengths(F, L)


def test_non_positive_length_named(tetrahedron):
    _, F = tetrahedron
    L = np.ones((4, 3))
    L[1, 1] = -1
    with pytest.raises(conformesh.InputError, match=r"face 1: L\[1, 1\] = -1"):
        conformesh.Triangulation.from_lengths(F, L)


def test_index_out_of_range_and_unused_vertex(tetrahedron):
    V, F = tetrahedron
    bad = F.copy()
    bad[1, 2] = 9
    with pytest.raises(conformesh.InputError, match="face 1 has vertex index 9"):
        conformesh.Triangulation.from_positions(V, bad)
    with pytest.raises(conformesh.InputError, match="vertex 4 is used by no face"):
        conformesh.Triangulation.from_positions(np.vstack([V, [0, 0, 0]]), F)
    with pytest.raises(conformesh.InputError, match="vertex index -1"):
        conformesh.Triangulation.from_positions(V, F - 1)


def test_non_manifold_edge_named():
    V = np.random.default_rng(1).normal(size=(5, 3))
    F = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    with pytest.raises(conformesh.InputError, match="non-manifold edge"):
        conformesh.Triangulation.from_positions(V, F)


def test_gauss_bonnet_and_corner_sums(sphere_t0):
    t = sphere_t0
    assert t.genus == 0 and t.euler_characteristic == 2
    assert t.angle_deficits().sum() == pytest.approx(4 * math.pi, abs=1e-12)
    np.testing.assert_allclose(t.corner_angles().sum(axis=1), math.pi, atol=1e-13)
    u, v = t.fields["u"], t.fields["v"]
    assert u.shape == (t.num_vertices,) and v.min() >= 0 and v.max() <= math.pi


def test_disk_boundary_turning():
    t = conformesh.metrics.family("hyperbolic-disk").discretize(resolution=4)
    assert t.boundary_loops == 1 and t.euler_characteristic == 1
    assert len(t.boundary_loop_vertices()) == 1
    assert t.angle_deficits().sum() == pytest.approx(2 * math.pi, abs=1e-11)


def test_torus_topology():
    t = conformesh.metrics.family("torus").discretize(resolution=6)
    assert t.genus == 1 and t.euler_characteristic == 0
    assert abs(t.angle_deficits().sum()) < 1e-11


@pytest.mark.parametrize("ext", [".ply", ".obj", ".off"])
def test_file_round_trip(tmp_path, sphere_t0, ext):
    t = conformesh.Triangulation.from_positions(sphere_t0.positions, sphere_t0.faces)
    path = str(tmp_path / ("m" + ext))
    conformesh.write(path, t, fields={"w": np.arange(t.num_vertices) * 0.5} if ext == ".ply" else None)
    r = conformesh.read(path)
    np.testing.assert_array_equal(r.faces, t.faces)
    np.testing.assert_array_equal(r.positions, t.positions)  # written exactly
    if ext == ".ply":
        np.testing.assert_array_equal(r.lengths, t.lengths)
        np.testing.assert_array_equal(r.fields["w"], np.arange(t.num_vertices) * 0.5)


def test_metric_only_ply_round_trip(tmp_path, sphere_t0):
    path = str(tmp_path / "t0.ply")
    conformesh.write(path, sphere_t0, ascii=True)
    r = conformesh.read(path)
    np.testing.assert_array_equal(r.lengths, sphere_t0.lengths)
    with pytest.raises(conformesh.InputError):
        conformesh.write(str(tmp_path / "t0.obj"), conformesh.Triangulation.from_lengths(r.faces, r.lengths))


def test_read_errors_name_file(tmp_path):
    p = tmp_path / "bad.off"
    p.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n")
    with pytest.raises(conformesh.InputError, match="bad.off"):
        conformesh.read(str(p))
    with pytest.raises(conformesh.InputError):
        conformesh.read(str(tmp_path / "missing.ply"))
    with pytest.raises(conformesh.InputError):
        conformesh.read(str(tmp_path / "x.stl"))


def test_write_field_size_checked(tmp_path, tetrahedron):
    t = conformesh.Triangulation.from_positions(*tetrahedron)
    with pytest.raises(conformesh.InputError, match="field 'w'"):
        conformesh.write(str(tmp_path / "t.ply"), t, fields={"w": np.zeros(3)})


def test_summary_equals_cli_info(tmp_path, cli, data_dir):
    path = os.path.join(data_dir, "eight.off")
    out = subprocess.run([cli, "info", path, "--json"], check=True, capture_output=True, text=True).stdout
    expected = json.loads(out)
    got = conformesh.read(path).summary()
    assert got["genus"] == 2
    for key, value in expected.items():
        assert got[key] == value, key
