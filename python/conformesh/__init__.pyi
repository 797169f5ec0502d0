"""Type stubs of the conformesh package."""

from . import metrics as metrics
from ._conformesh import (
    ConvergenceError as ConvergenceError,
    ConvergenceResult as ConvergenceResult,
    InputError as InputError,
    LayoutResult as LayoutResult,
    RemeshResult as RemeshResult,
    Triangulation as Triangulation,
    VerificationError as VerificationError,
    UniformizeResult as UniformizeResult,
    convergence as convergence,
    layout as layout,
    read as read,
    remesh as remesh,
    uniformize as uniformize,
    write as write,
)

__version__: str
