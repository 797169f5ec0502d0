"""Type stubs of conformesh's compiled core (re-exported by the package)."""

from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import metrics as metrics

__version__: str
ArrayLike = npt.ArrayLike
Progress = Optional[Callable[[str], None]]

class InputError(ValueError): ...
class ConvergenceError(RuntimeError): ...
class VerificationError(RuntimeError): ...

class Triangulation:
    @staticmethod
    def from_positions(V: ArrayLike, F: ArrayLike) -> "Triangulation": ...
    @staticmethod
    def from_lengths(F: ArrayLike, L: ArrayLike, tolerance: float = ..., background: str = ...) -> "Triangulation": ...
    @property
    def faces(self) -> npt.NDArray[np.int32]: ...
    @property
    def lengths(self) -> npt.NDArray[np.float64]: ...
    @property
    def edges(self) -> npt.NDArray[np.int32]: ...
    @property
    def edge_lengths(self) -> npt.NDArray[np.float64]: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def num_components(self) -> int: ...
    @property
    def euler_characteristic(self) -> int: ...
    @property
    def genus(self) -> int: ...
    @property
    def boundary_loops(self) -> int: ...
    @property
    def total_area(self) -> float: ...
    @property
    def background(self) -> str: ...
    @property
    def positions(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def fields(self) -> Dict[str, npt.NDArray[np.float64]]: ...
    @property
    def source(self) -> str: ...
    def corner_angles(self) -> npt.NDArray[np.float64]: ...
    def angle_deficits(self) -> npt.NDArray[np.float64]: ...
    def boundary_loop_vertices(self) -> List[npt.NDArray[np.int32]]: ...
    def summary(self) -> Dict[str, Any]: ...
    def delaunay(self) -> Tuple["Triangulation", int]: ...
    def with_fields(self, fields: Dict[str, ArrayLike]) -> "Triangulation": ...

def read(path: str) -> Triangulation: ...
def write(path: str, tri: Triangulation, fields: Optional[Dict[str, ArrayLike]] = ...,
          positions: Optional[ArrayLike] = ..., ascii: bool = ...) -> None: ...

class UniformizeResult:
    triangulation: Triangulation
    conformal_factor: npt.NDArray[np.float64]
    geometry: str
    positions: Optional[npt.NDArray[np.float64]]
    report: Dict[str, Any]

def uniformize(tri: Triangulation, *, tolerance: float = ..., max_steps: int = ..., method: str = ...,
               keep_failed: bool = ..., progress: Progress = ...) -> UniformizeResult: ...

class RemeshResult:
    triangulation: Triangulation
    chart_coordinates: Optional[npt.NDArray[np.float64]]
    input_faces: Optional[npt.NDArray[np.int32]]
    input_barycentric: Optional[npt.NDArray[np.float64]]
    @property
    def input_locations(self) -> Optional[Tuple[npt.NDArray[np.int32], npt.NDArray[np.float64]]]: ...
    positions: Optional[npt.NDArray[np.float64]]
    fields: Dict[str, npt.NDArray[np.float64]]
    report: Dict[str, Any]
    def write(self, path: str, vtk: Optional[str] = ..., ascii: bool = ...) -> None: ...

def remesh(source: Union["metrics.Metric", Triangulation], eps: float, check: bool = ..., *, ratio: float = ...,
           uniform: bool = ..., t0_resolution: int = ..., disk_target: str = ..., smoothing: Optional[int] = ...,
           smoothing_rule: str = ..., segment_rule: str = ..., refine_in: Optional[str] = ..., region: str = ...,
           keep_failed: bool = ..., progress: Progress = ...) -> RemeshResult: ...

class ConvergenceResult:
    rows: List[Dict[str, Any]]
    orders: Dict[str, float]
    report: Dict[str, Any]

def convergence(metric: "metrics.Metric", *, vertices: Sequence[int] = ..., ratio: float = ...,
                t0_resolution: int = ..., disk_target: str = ..., smoothing: Optional[int] = ...,
                smoothing_rule: str = ..., extrinsic: bool = ..., progress: Progress = ...) -> ConvergenceResult: ...

class LayoutResult:
    triangulation: Triangulation
    corners: npt.NDArray[np.float64]
    target: str
    report: Dict[str, Any]
    def svg(self, pixels: int = ...) -> str: ...
    def write(self, path: str, pixels: int = ...) -> None: ...

def layout(tri: Triangulation, *, tolerance: float = ..., tiles: int = ..., centre_vertex: int = ...,
           direction_vertex: int = ..., progress: Progress = ...) -> LayoutResult: ...

class RefineResult:
    triangulation: Triangulation
    input_faces: npt.NDArray[np.int32]
    input_barycentric: npt.NDArray[np.float64]
    @property
    def input_locations(self) -> Tuple[npt.NDArray[np.int32], npt.NDArray[np.float64]]: ...
    conformal_factor: Optional[npt.NDArray[np.float64]]
    positions: Optional[npt.NDArray[np.float64]]
    report: Dict[str, Any]
    def write(self, path: str, ascii: bool = ...) -> None: ...

def refine(tri: Triangulation, eps: float, *, ratio: float = ..., uniform: bool = ...,
           conformal_factor: Optional[ArrayLike] = ..., boundary: str = ..., segment_rule: str = ...,
           off_centers: bool = ..., frontal: bool = ..., smoothing: int = ..., smoothing_rule: str = ...,
           max_insertions: int = ..., keep_failed: bool = ..., progress: Progress = ...) -> RefineResult: ...

class EmbedResult:
    triangulation: Triangulation
    positions: npt.NDArray[np.float64]
    edge_residuals: npt.NDArray[np.float64]
    isometric: bool
    verdict: str
    report: Dict[str, Any]

def embed(tri: Triangulation, *, init: Optional[ArrayLike] = ..., tolerance: float = ..., regularizer: float = ...,
          landmarks: int = ..., max_iterations: int = ..., strict: bool = ..., progress: Progress = ...) -> EmbedResult: ...
