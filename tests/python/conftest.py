"""Shared fixtures of the conformesh pytest suite (run by CTest: tests/CMakeLists.txt)."""

import os
import shutil

import numpy as np
import pytest

import conformesh


@pytest.fixture
def tetrahedron():
    """The regular tetrahedron of edge sqrt(2) (vertices of a cube), outward-oriented faces."""
    V = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=np.float64)
    F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]], dtype=np.int64)
    return V, F


@pytest.fixture
def cli():
    """The conformesh executable CTest passes in CONFORMESH_CLI (skips when run outside CTest without it)."""
    path = os.environ.get("CONFORMESH_CLI") or shutil.which("conformesh")
    if not path:
        pytest.skip("CONFORMESH_CLI not set")
    return path


@pytest.fixture
def data_dir():
    """CGAL's meshes extracted by tests/CMakeLists.txt."""
    path = os.environ.get("CONFORMESH_TEST_DATA_DIR")
    if not path or not os.path.isdir(path):
        pytest.skip("CONFORMESH_TEST_DATA_DIR not set")
    return path


def corner_lengths(V, F):
    """L[f, k] = |V[F[f, (k + 1) % 3]] - V[F[f, k]]|, computed independently of conformesh."""
    return np.linalg.norm(V[np.roll(F, -1, axis=1)] - V[F], axis=2)


@pytest.fixture
def sphere_t0():
    """T0 of the unit sphere (an icosahedral triangulation with geodesic lengths)."""
    return conformesh.metrics.family("sphere").discretize(resolution=4)
