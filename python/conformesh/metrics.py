"""Smooth metrics g(u, v) on a chart: the CLI's families, sampled fields and Python functions.

Every metric is a :class:`Metric`; pass it to :func:`conformesh.remesh` or
:func:`conformesh.convergence`.
"""

import numpy as np

from ._conformesh.metrics import (
    Metric,
    families,
    family,
    read_field,
    sampled,
    write_field,
)

__all__ = [
    "Metric",
    "families",
    "family",
    "from_function",
    "grid",
    "read_field",
    "sampled",
    "write_field",
]


def grid(chart, shape, periodic_u=False, periodic_v=False, poles="none"):
    """The chart points of a sampled field's grid, as two arrays of shape (NV, NU).

    ``shape`` is (NU, NV). The node conventions are those of :func:`sampled`:
    a periodic axis has nodes x0 + i (x1 - x0) / N, another axis
    x0 + i (x1 - x0) / (N - 1); with poles="both" the v-nodes are
    cell-centred, (j + 1/2) pi / NV.
    """
    u0, u1, v0, v1 = (float(x) for x in chart)
    nu, nv = (int(n) for n in shape)
    if poles == "both":
        u = u0 + (u1 - u0) * np.arange(nu) / nu
        v = v0 + (v1 - v0) * (np.arange(nv) + 0.5) / nv
    else:
        u = u0 + (u1 - u0) * np.arange(nu) / (nu if periodic_u else nu - 1)
        v = v0 + (v1 - v0) * np.arange(nv) / (nv if periodic_v else nv - 1)
    vv, uu = np.meshgrid(v, u, indexing="ij")
    return uu, vv


def from_function(fn, chart, shape=(128, 128), periodic_u=False, periodic_v=False,
                  poles="none", batch=65536):
    """A metric from a Python callable ``fn(u, v) -> (g_uu, g_uv, g_vv)``.

    ``fn`` receives 1-D float64 arrays of chart points, at most ``batch`` at a
    time, and returns three arrays of the same length. It is evaluated on the
    grid of ``shape`` = (NU, NV) nodes (the conventions of :func:`sampled`)
    and the samples are interpolated by cubic B-splines: the metric equals
    ``fn`` at the nodes and is fourth-order accurate in g between them (second
    order in the curvature). Raises InputError when ``fn`` returns arrays of
    the wrong length or values that are not finite or not positive definite
    (naming the grid node).
    """
    if not callable(fn):
        raise InputError("metrics.from_function: fn must be callable")
    uu, vv = grid(chart, shape, periodic_u, periodic_v, poles)
    u, v = uu.ravel(), vv.ravel()
    out = [np.empty(u.size) for _ in range(3)]
    batch = max(1, int(batch))
    for start in range(0, u.size, batch):
        stop = min(u.size, start + batch)
        values = fn(u[start:stop], v[start:stop])
        if len(values) != 3:
            raise InputError("metrics.from_function: fn must return (g_uu, g_uv, g_vv)")
        for k, name in enumerate(("g_uu", "g_uv", "g_vv")):
            a = np.broadcast_to(np.asarray(values[k], dtype=np.float64), (stop - start,))
            out[k][start:stop] = a
    return sampled(*(a.reshape(uu.shape) for a in out), chart=chart,
                   periodic_u=periodic_u, periodic_v=periodic_v, poles=poles)


from ._conformesh import InputError  # noqa: E402  (after the names it documents)
