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

Rigid bodies (each moving from pose (c0, q0) to (c1, q1); quaternions w x y z of any length)::

    rigid_vertex_face_ccd(q, min_distance=0.0, tmax=1.0, threads=0)  # q: (N, 40) -> (N,) bool
    rigid_vertex_face_toi(q, ...)                                     # -> (N, 2) [lo, hi]
    rigid_edge_edge_ccd / rigid_edge_edge_toi                         # (N, 40)
    rigid_find_collisions(bodies, min_distance=0.0, tmax=1.0, threads=0) -> dict
    rigid_earliest_toi(bodies, ...) -> (lo, hi) or None
    rigid_max_collision_free_step(bodies, ...) -> float
    # bodies: a sequence of (V, F, c0, q0, c1, q1)

Every answer is exact; a time of impact is the tightest double interval [lo, hi] holding the exact
time. Bad input (shape, dtype, NaN or infinite coordinates, bad min_distance or tmax) raises
ValueError with the library's message.
"""

from ._exactccd import (  # noqa: F401
    EDGE_EDGE,
    KIND_NAMES,
    POINT_EDGE,
    POINT_POINT,
    VERTEX_FACE,
    candidates_earliest_toi,
    candidates_find_collisions,
    candidates_is_collision_free,
    candidates_max_collision_free_step,
    earliest_toi,
    edge_edge_2d_ccd,
    edge_edge_2d_toi,
    edge_edge_ccd,
    edge_edge_toi,
    find_collisions,
    intersection_free,
    is_collision_free,
    max_collision_free_step,
    point_edge_2d_ccd,
    point_edge_2d_toi,
    point_edge_ccd,
    point_edge_toi,
    point_point_2d_ccd,
    point_point_2d_toi,
    point_point_ccd,
    point_point_toi,
    read_mesh,
    rigid_earliest_toi,
    rigid_edge_edge_ccd,
    rigid_edge_edge_toi,
    rigid_find_collisions,
    rigid_max_collision_free_step,
    rigid_vertex_face_ccd,
    rigid_vertex_face_toi,
    vertex_face_ccd,
    vertex_face_toi,
)

__version__ = "@PROJECT_VERSION@"

#: The batch functions' kinds: name -> (rows per query: every point at t = 0, then at t = 1; coordinates per row).
KINDS = {
    "vertex_face": (8, 3),
    "edge_edge": (8, 3),
    "point_edge": (6, 3),
    "point_point": (4, 3),
    "edge_edge_2d": (8, 2),
    "point_edge_2d": (6, 2),
    "point_point_2d": (4, 2),
}

__all__ = [
    "EDGE_EDGE", "KIND_NAMES", "KINDS", "POINT_EDGE", "POINT_POINT", "VERTEX_FACE",
    "candidates_earliest_toi", "candidates_find_collisions", "candidates_is_collision_free",
    "candidates_max_collision_free_step", "earliest_toi", "find_collisions", "intersection_free", "is_collision_free",
    "max_collision_free_step", "read_mesh",
] + [f"{k}_{f}" for k in KINDS for f in ("ccd", "toi")]
