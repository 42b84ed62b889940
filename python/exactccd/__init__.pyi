"""Type stubs of exactccd (the compiled module exactccd._exactccd and its re-exports)."""

import os
from typing import Dict, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
VERTEX_FACE: int
EDGE_EDGE: int
POINT_EDGE: int
POINT_POINT: int
KIND_NAMES: Tuple[str, str, str, str]
KINDS: Dict[str, Tuple[int, int]]

_Coords = npt.ArrayLike
_Indices = Optional[npt.ArrayLike]

def vertex_face_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def vertex_face_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def edge_edge_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def edge_edge_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def point_edge_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def point_edge_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def point_point_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def point_point_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def edge_edge_2d_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def edge_edge_2d_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def point_edge_2d_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def point_edge_2d_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def point_point_2d_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def point_point_2d_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def find_collisions(
    V0: _Coords,
    V1: _Coords,
    F: _Indices = None,
    E: _Indices = None,
    P: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> Dict[str, np.ndarray]: ...
def earliest_toi(
    V0: _Coords,
    V1: _Coords,
    F: _Indices = None,
    E: _Indices = None,
    P: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> Optional[Tuple[float, float]]: ...
def is_collision_free(
    V0: _Coords,
    V1: _Coords,
    F: _Indices = None,
    E: _Indices = None,
    P: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> bool: ...
def max_collision_free_step(
    V0: _Coords,
    V1: _Coords,
    F: _Indices = None,
    E: _Indices = None,
    P: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> float: ...
def candidates_find_collisions(
    V0: _Coords,
    V1: _Coords,
    vertex_face: _Indices = None,
    edge_edge: _Indices = None,
    point_edge: _Indices = None,
    point_point: _Indices = None,
    F: _Indices = None,
    E: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> Dict[str, np.ndarray]: ...
def candidates_earliest_toi(
    V0: _Coords,
    V1: _Coords,
    vertex_face: _Indices = None,
    edge_edge: _Indices = None,
    point_edge: _Indices = None,
    point_point: _Indices = None,
    F: _Indices = None,
    E: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> Optional[Tuple[float, float]]: ...
def candidates_is_collision_free(
    V0: _Coords,
    V1: _Coords,
    vertex_face: _Indices = None,
    edge_edge: _Indices = None,
    point_edge: _Indices = None,
    point_point: _Indices = None,
    F: _Indices = None,
    E: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> bool: ...
def candidates_max_collision_free_step(
    V0: _Coords,
    V1: _Coords,
    vertex_face: _Indices = None,
    edge_edge: _Indices = None,
    point_edge: _Indices = None,
    point_point: _Indices = None,
    F: _Indices = None,
    E: _Indices = None,
    min_distance: float = 0.0,
    tmax: float = 1.0,
    threads: int = 0,
) -> float: ...
def intersection_free(V: _Coords, F: npt.ArrayLike) -> bool: ...
def read_mesh(path: Union[str, os.PathLike]) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...

class SceneBroadPhase:
    def __init__(
        self,
        V0: _Coords,
        V1: _Coords,
        F: _Indices = None,
        E: _Indices = None,
        P: _Indices = None,
        min_distance: float = 0.0,
        tmax: float = 1.0,
        threads: int = 0,
    ) -> None: ...
    def update(self, V1: _Coords) -> None: ...
    @property
    def candidates(self) -> Dict[str, npt.NDArray[np.int64]]: ...
    @property
    def edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def min_distance(self) -> float: ...
    @property
    def tmax(self) -> float: ...
    def find_collisions(self) -> Dict[str, npt.NDArray[np.generic]]: ...
    def earliest_toi(self) -> Optional[Tuple[float, float]]: ...
    def is_collision_free(self) -> bool: ...
    def max_collision_free_step(self) -> float: ...

_RigidBody = Tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike]

def rigid_vertex_face_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def rigid_vertex_face_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def rigid_edge_edge_ccd(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.bool_]: ...
def rigid_edge_edge_toi(q: _Coords, min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0) -> npt.NDArray[np.float64]: ...
def rigid_find_collisions(
    bodies: Sequence[_RigidBody], min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0
) -> Dict[str, npt.NDArray[np.generic]]: ...
def rigid_earliest_toi(
    bodies: Sequence[_RigidBody], min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0
) -> Optional[Tuple[float, float]]: ...
def rigid_max_collision_free_step(
    bodies: Sequence[_RigidBody], min_distance: float = 0.0, tmax: float = 1.0, threads: int = 0
) -> float: ...
