"""conformesh: intrinsic surface meshing with curvature convergence on NumPy arrays.

Li, Zeng, Morvan, Chen and Gu (2013): uniformize a surface by discrete Ricci flow, Delaunay-refine it in the
uniformized metric and pull the result back, with every output edge measured in the original metric. The
surface is a smooth metric g(u, v) on a chart (:mod:`conformesh.metrics`) or a triangulation
(:class:`Triangulation`).

Example::

    import conformesh
    m = conformesh.metrics.family("kerr-newman", a=0.95)
    r = conformesh.remesh(m, eps=0.1)
    print(r.report["gaussian_curvature_measure"]["mean_abs_error"])

docs/python.md is the reference.
"""

from . import _conformesh
from ._conformesh import (
    ConvergenceError,
    ConvergenceResult,
    EmbedResult,
    LayoutResult,
    RefineResult,
    embed,
    refine,
    convergence,
    layout,
    InputError,
    RemeshResult,
    Triangulation,
    UniformizeResult,
    read,
    remesh,
    uniformize,
    VerificationError,
    write,
)
from . import metrics

__version__ = _conformesh.__version__

__all__ = [
    "ConvergenceError",
    "ConvergenceResult",
    "EmbedResult",
    "LayoutResult",
    "RefineResult",
    "embed",
    "refine",
    "convergence",
    "layout",
    "InputError",
    "RemeshResult",
    "VerificationError",
    "Triangulation",
    "UniformizeResult",
    "__version__",
    "metrics",
    "read",
    "remesh",
    "uniformize",
    "write",
]
