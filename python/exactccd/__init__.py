"""Exact continuous collision detection: the C++ library exactccd from Python.

Batch functions per primitive kind, on NumPy float64 arrays of queries in file row order
(every point at t = 0, then every point at t = 1)::

    vertex_face_ccd(q, min_distance=0.0, tmax=1.0, threads=0)   # q: (N, 8, 3) -> (N,) bool
    vertex_face_toi(q, ...)                                      # -> (N, 2) [lo, hi], NaN rows
    edge_edge_ccd / edge_edge_toi                                # (N, 8, 3)
    point_edge_ccd / point_edge_toi                              # (N, 6, 3)
    point_point_ccd / point_point_toi                            # (N, 4, 3)
    edge_edge_2d_* (N, 8, 2), point_edge_2d_* (N, 6, 2), point_point_2d_* (N, 4, 2)

Scenes on arrays (V0, V1 of shape (n, 3), or (n, 2) for a 2D scene; F, E, P index arrays)::

    find_collisions(V0, V1, F, E=None, P=None, min_distance=0.0, tmax=1.0, threads=0) -> dict
    earliest_toi(...) -> (lo, hi) or None
    is_collision_free(...) -> bool
    max_collision_free_step(...) -> float
    intersection_free(V, F) -> bool
    read_mesh(path) -> (V, F)

The narrow phase over the caller's own candidate pairs (e.g. a simulator's broad phase; V0, V1
of shape (n, 3); candidate rows of vertex indices, or of face / edge indices with F / E)::

    candidates_find_collisions(V0, V1, vertex_face=None, edge_edge=None, point_edge=None,
                               point_point=None, F=None, E=None, min_distance=0.0, tmax=1.0,
                               threads=0) -> dict (kind, index, toi)
    candidates_earliest_toi(...) -> (lo, hi) or None
    candidates_is_collision_free(...) -> bool
    candidates_max_collision_free_step(...) -> float

A scene's broad phase kept across the calls of a line search (build once, refit per trial)::

    bp = SceneBroadPhase(V0, V1, F, E=None, P=None, min_distance=0.0, tmax=1.0, threads=0)
    bp.update(V1_trial); bp.max_collision_free_step()   # also find_collisions(), earliest_toi(),
                                                       # is_collision_free(), candidates, edges

Rigid bodies (each moving from pose (c0, q0) to (c1, q1); quaternions w x y z of any length)::

    rigid_vertex_face_ccd(q, min_distance=0.0, tmax=1.0, threads=0)  # q: (N, 40) -> (N,) bool
    rigid_vertex_face_toi(q, ...)                                     # -> (N, 2) [lo, hi]
    rigid_edge_edge_ccd / rigid_edge_edge_toi                         # (N, 40)
    rigid_find_collisions(bodies, min_distance=0.0, tmax=1.0, threads=0) -> dict
    rigid_earliest_toi(bodies, ...) -> (lo, hi) or None
    rigid_max_collision_free_step(bodies, ...) -> float
    # bodies: a sequence of (V, F, c0, q0, c1, q1)

Every answer is exact; a time of impact is the tightest double interval [lo, hi] holding the exact
time. Coordinates are float64 arrays, or float32/float16 (widened exactly), or integer arrays whose
every value is a double. threads is in 0..1024 (0: every hardware thread). Bad input (shape,
dtype, an integer that is not a double, NaN or infinite coordinates, bad min_distance, tmax or
threads) raises ValueError with the library's message. Long calls can be interrupted with Ctrl-C
(KeyboardInterrupt; the worker threads stop).
"""

from . import _exactccd
from ._exactccd import (  # noqa: F401
    EDGE_EDGE,
    SceneBroadPhase,
    __version__,
    KIND_NAMES,
    POINT_EDGE,
    POINT_POINT,
    VERTEX_FACE,
    candidates_earliest_toi,
    candidates_find_collisions,
    candidates_is_collision_free,
    candidates_max_collision_free_step,
    earliest_toi,
    find_collisions,
    intersection_free,
    is_collision_free,
    max_collision_free_step,
    read_mesh,
    rigid_earliest_toi,
    rigid_edge_edge_ccd,
    rigid_edge_edge_toi,
    rigid_find_collisions,
    rigid_max_collision_free_step,
    rigid_vertex_face_ccd,
    rigid_vertex_face_toi,
)

#: The batch functions' kinds (the library's one list of kinds): function stem -> (rows per
#: query: every point at t = 0, then at t = 1; coordinates per row). Each has <stem>_ccd and
#: <stem>_toi, imported here from the extension (their stubs: __init__.pyi).
KINDS = dict(_exactccd.KINDS)
globals().update({f"{k}_{f}": getattr(_exactccd, f"{k}_{f}") for k in KINDS for f in ("ccd", "toi")})

__all__ = [
    "EDGE_EDGE", "KIND_NAMES", "KINDS", "POINT_EDGE", "POINT_POINT", "SceneBroadPhase", "VERTEX_FACE",
    "candidates_earliest_toi", "candidates_find_collisions", "candidates_is_collision_free",
    "candidates_max_collision_free_step", "earliest_toi", "find_collisions", "intersection_free", "is_collision_free",
    "max_collision_free_step", "read_mesh", "rigid_earliest_toi", "rigid_edge_edge_ccd", "rigid_edge_edge_toi",
    "rigid_find_collisions", "rigid_max_collision_free_step", "rigid_vertex_face_ccd", "rigid_vertex_face_toi",
] + [f"{k}_{f}" for k in KINDS for f in ("ccd", "toi")]
