"""Type stubs of the compiled module boolean_isosurfacing._core."""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
IndexArray = npt.NDArray[np.int64]
LabelArray = npt.NDArray[np.int32]
ArrayLike = npt.ArrayLike
Polygons = Union[Sequence[ArrayLike], ArrayLike]
Box = Tuple[float, float, float, float, float, float]

parallel: bool
taubin_default_lambda: float
taubin_default_mu: float
taubin_default_number_of_iterations: int

class InvalidInputError(ValueError): ...
class EmptyInputError(InvalidInputError): ...
class NonTriangleFaceError(InvalidInputError): ...
class OpenMeshError(InvalidInputError): ...
class NonFiniteValueError(InvalidInputError): ...
class InwardOrientedMeshError(InvalidInputError): ...
class SelfIntersectingMeshError(InvalidInputError): ...
class LatticeTooLargeError(InvalidInputError): ...
class ParseError(InvalidInputError): ...

def surveyor_volume(V: ArrayLike, F: ArrayLike, signed: bool = False) -> float:
    """Volume enclosed by the closed triangle mesh (V, F) (relative error < 4e-15)."""

def csg(
    meshes: Sequence[Tuple[ArrayLike, ArrayLike]],
    expr: str,
    cells: Optional[int] = None,
    spacing: Optional[float] = None,
    shift: bool = True,
    features: bool = True,
    feature_angle: float = 30.0,
    threads: int = 0,
    max_memory_bytes: Optional[int] = None,
) -> Tuple[FloatArray, IndexArray, Dict[str, Any]]:
    """Marching Cubes CSG of closed meshes: returns (V, F, info)."""

def contour(
    points: ArrayLike,
    normals: Optional[ArrayLike] = None,
    cell_size: Optional[float] = None,
    cells: Optional[float] = None,
    k: int = 15,
    rho: Optional[float] = None,
    delta: Optional[float] = None,
    max_jump: Optional[float] = None,
    min_component_size: Optional[float] = None,
    margin: Optional[float] = None,
    threads: int = 0,
) -> Tuple[FloatArray, IndexArray, Dict[str, Any]]:
    """Contours point samples (Hoppe et al. 1992): returns (V, F, info)."""

def boolean_isosurface(
    fields: ArrayLike,
    expr: str,
    grid: Optional[Tuple[int, int, int]] = None,
    box: Box = (-1.0, -1.0, -1.0, 1.0, 1.0, 1.0),
    mesh: Optional[Tuple[ArrayLike, ArrayLike]] = None,
    close: bool = False,
    smooth: int = 0,
    lambda_: float = 0.6307,
    mu: float = -0.6732,
    slab_layers: int = 0,
    threads: int = 0,
) -> Tuple[FloatArray, List[IndexArray], LabelArray, List[IndexArray], IndexArray, Dict[str, Any]]:
    """TBISO: returns (V, polygons, labels, creases, corners, info)."""

def grid_points(grid: Tuple[int, int, int], box: Box = (-1.0, -1.0, -1.0, 1.0, 1.0, 1.0)) -> FloatArray:
    """The vertex positions of a TBISO grid, x fastest."""

def crease_network(V: ArrayLike, polygons: Polygons, labels: ArrayLike) -> Tuple[List[IndexArray], IndexArray]:
    """The crease polylines and corners of a labelled polygon soup."""

def smooth_with_creases(
    V: ArrayLike,
    polygons: Polygons,
    labels: Optional[ArrayLike] = None,
    iterations: int = 10,
    lambda_: float = 0.6307,
    mu: float = -0.6732,
    keep_creases: bool = True,
) -> FloatArray:
    """Taubin lambda|mu smoothing keeping creases and corners: returns the new V."""

def icosphere(center: Tuple[float, float, float] = (0.0, 0.0, 0.0), radius: float = 1.0,
              subdivisions: int = 4) -> Tuple[FloatArray, IndexArray]:
    """A geodesic sphere (V, F), 20 * 4^subdivisions outward triangles."""

def torus(center: Tuple[float, float, float] = (0.0, 0.0, 0.0), major_radius: float = 0.8,
          minor_radius: float = 0.35, major_segments: int = 96, minor_segments: int = 48) -> Tuple[FloatArray, IndexArray]:
    """A torus (V, F) around the z axis through center, 2 * major * minor outward triangles."""

def read_mesh(path: str, closed: bool = True) -> Tuple[FloatArray, IndexArray]: ...
def write_mesh(path: str, V: ArrayLike, F: ArrayLike) -> None: ...
def read_points(path: str) -> Tuple[FloatArray, Optional[FloatArray]]: ...
def write_points(path: str, points: ArrayLike, normals: Optional[ArrayLike] = None) -> None: ...
def read_tris(path: str) -> Tuple[FloatArray, FloatArray]: ...
def write_tris(path: str, V: ArrayLike, F: ArrayLike) -> None: ...
def read_tetrahedral_mesh(path: str) -> Tuple[FloatArray, IndexArray]: ...
def write_tetrahedral_mesh(path: str, X: ArrayLike, T: ArrayLike) -> None: ...
def read_fields(path: str, number_of_vertices: int = 0, number_of_fields: int = 0) -> FloatArray: ...
def write_fields(path: str, fields: ArrayLike) -> None: ...
def read_isosurface_ply(path: str) -> Tuple[FloatArray, List[IndexArray], LabelArray]: ...
def write_isosurface_ply(path: str, V: ArrayLike, polygons: Polygons, labels: ArrayLike, binary: bool = False) -> None: ...
def write_creases(path: str, V: ArrayLike, creases: Sequence[ArrayLike]) -> None: ...
def write_corners(path: str, V: ArrayLike, corners: ArrayLike) -> None: ...
