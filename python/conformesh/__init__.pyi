"""Type stubs of the conformesh package."""

from . import metrics as metrics
from ._conformesh import (
    ConvergenceError as ConvergenceError,
    ConvergenceResult as ConvergenceResult,
    EmbedResult as EmbedResult,
    InputError as InputError,
    LayoutResult as LayoutResult,
    RefineResult as RefineResult,
    RemeshResult as RemeshResult,
    Triangulation as Triangulation,
    VerificationError as VerificationError,
    UniformizeResult as UniformizeResult,
    convergence as convergence,
    embed as embed,
    layout as layout,
    read as read,
    refine as refine,
    remesh as remesh,
    uniformize as uniformize,
    write as write,
)

__version__: str
