"""The narrow phase over the caller's own candidates (candidates_*): on small random and
degenerate scenes it gives exactly the pairs, TOIs, earliest TOI and safe step of the scene
functions (every non-adjacent pair given as a candidate, the scene deciding all pairs), and
exactly the per-pair answers of the batch functions per kind (an independent path through the
module), at 1, 2, 3 and 8 threads, d = 0 and d > 0, tmax = 1 and < 1; the face / edge index form
equals the vertex index form; bad input raises ValueError naming the element."""

import itertools

import numpy as np
import pytest

import exactccd

THREADS = [1, 2, 3, 8]
QUESTIONS = [(0.0, 1.0), (0.0, 0.6), (0.05, 1.0), (0.25, 0.5)]


def random_scene(rng, n=10, m=5, degenerate=False):
    if degenerate:  # a grid of step 1/4: exact coplanarities, touching at grid distances
        V0 = rng.integers(-2, 3, size=(n, 3)) / 4.0
        V1 = rng.integers(-2, 3, size=(n, 3)) / 4.0
        V1[::3] = V0[::3]  # static vertices
    else:
        V0 = rng.uniform(-1, 1, size=(n, 3))
        V1 = rng.uniform(-1, 1, size=(n, 3))
    F = np.array([rng.choice(n, size=3, replace=False) for _ in range(m)], dtype=np.int64)
    return V0, V1, F


def unique_edges(F):
    return sorted({tuple(sorted((int(t[i]), int(t[(i + 1) % 3])))) for t in F for i in range(3)})


def all_pairs(V0, F):
    """Every vertex-triangle and edge-edge pair sharing no vertex, in the scene's order."""
    used = sorted({int(v) for t in F for v in t})
    vf = [(v, f) for v in used for f in range(len(F)) if v not in F[f]]
    E = unique_edges(F)
    ee = [(i, j) for i, j in itertools.combinations(range(len(E)), 2) if not set(E[i]) & set(E[j])]
    return np.array(vf, dtype=np.int64).reshape(-1, 2), np.array(E, dtype=np.int64).reshape(-1, 2), \
        np.array(ee, dtype=np.int64).reshape(-1, 2)


@pytest.mark.parametrize("degenerate", [False, True])
def test_equals_scene_functions(degenerate):
    rng = np.random.default_rng(20261202 + degenerate)
    colliding = 0
    for _ in range(6):
        V0, V1, F = random_scene(rng, degenerate=degenerate)
        vf, E, ee = all_pairs(V0, F)
        vf4 = np.column_stack([vf[:, 0], F[vf[:, 1]]])
        ee4 = np.column_stack([E[ee[:, 0]], E[ee[:, 1]]])
        for d, tmax in QUESTIONS:
            want = exactccd.find_collisions(V0, V1, F, min_distance=d, tmax=tmax, threads=1)
            want_pairs = [(0, int(v), int(t), *toi) if k == exactccd.VERTEX_FACE else (1, *map(int, a), *map(int, b), *toi)
                          for k, v, t, a, b, toi in zip(want["kind"], want["vertex"], want["triangle"], want["edge_a"],
                                                        want["edge_b"], want["toi"].tolist())]
            colliding += len(want_pairs)
            for threads in THREADS:
                kw = dict(min_distance=d, tmax=tmax, threads=threads)
                got = exactccd.candidates_find_collisions(V0, V1, vertex_face=vf4, edge_edge=ee4, **kw)
                assert set(got) == {"kind", "index", "toi"}
                assert got["kind"].dtype == np.int8 and got["index"].dtype == np.int64
                pairs = [(0, int(vf[i, 0]), int(vf[i, 1]), *toi) if k == exactccd.VERTEX_FACE
                         else (1, *map(int, E[ee[i, 0]]), *map(int, E[ee[i, 1]]), *toi)
                         for k, i, toi in zip(got["kind"], got["index"], got["toi"].tolist())]
                assert pairs == want_pairs
                assert exactccd.candidates_earliest_toi(V0, V1, vf4, ee4, **kw) == \
                    exactccd.earliest_toi(V0, V1, F, min_distance=d, tmax=tmax)
                assert exactccd.candidates_max_collision_free_step(V0, V1, vf4, ee4, **kw) == \
                    exactccd.max_collision_free_step(V0, V1, F, min_distance=d, tmax=tmax)
                assert exactccd.candidates_is_collision_free(V0, V1, vf4, ee4, **kw) == (len(want_pairs) == 0)
                # The face / edge index form is the same question.
                by_index = exactccd.candidates_find_collisions(V0, V1, vertex_face=vf, edge_edge=ee, F=F, E=E, **kw)
                for key in got:
                    assert np.array_equal(by_index[key], got[key])
    assert colliding >= 10


def gather(V0, V1, rows):
    """Queries of candidate rows in file row order: every point at t0, then at t1."""
    return np.concatenate([V0[rows], V1[rows]], axis=1)


def test_equals_primitive_batches():
    rng = np.random.default_rng(7)
    kinds = [0, 0, 0, 0]
    for s in range(6):
        V0, V1, F = random_scene(rng, n=9, degenerate=s % 2 == 1)
        n = len(V0)
        vf4 = np.array([(v, *t) for v in range(n) for t in F if v not in t], dtype=np.int64)
        E = unique_edges(F)
        ee4 = np.array([(*a, *b) for a in E for b in E if not set(a) & set(b)], dtype=np.int64)
        pe3 = np.array([(v, *e) for v in range(n) for e in E if v not in e], dtype=np.int64)
        pp2 = np.array([(p, q) for p in range(n) for q in range(n) if p != q], dtype=np.int64)
        for lst in (vf4, ee4, pe3, pp2):
            rng.shuffle(lst)
        lists = [vf4, ee4, pe3, pp2]
        names = ["vertex_face", "edge_edge", "point_edge", "point_point"]
        for d, tmax in QUESTIONS:
            want_kind, want_index, want_toi = [], [], []
            for k, (rows, name) in enumerate(zip(lists, names)):
                toi = getattr(exactccd, name + "_toi")(gather(V0, V1, rows), min_distance=d, tmax=tmax)
                hit = np.flatnonzero(~np.isnan(toi[:, 0]))
                kinds[k] += len(hit)
                want_kind += [k] * len(hit)
                want_index += hit.tolist()
                want_toi += toi[hit].tolist()
            for threads in THREADS:
                kw = dict(min_distance=d, tmax=tmax, threads=threads)
                got = exactccd.candidates_find_collisions(V0, V1, *lists, **kw)
                assert got["kind"].tolist() == want_kind
                assert got["index"].tolist() == want_index
                assert got["toi"].tolist() == want_toi
                earliest = min(map(tuple, want_toi)) if want_toi else None
                assert exactccd.candidates_earliest_toi(V0, V1, *lists, **kw) == earliest
    assert min(kinds) >= 10, kinds


def test_vertex_through_triangle():
    V0 = np.array([[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64)
    V1 = V0.copy()
    V1[0, 2] = -1.0
    vf = np.array([[0, 1, 2, 3]])
    got = exactccd.candidates_find_collisions(V0, V1, vf)
    assert got["kind"].tolist() == [0] and got["index"].tolist() == [0] and got["toi"].tolist() == [[0.5, 0.5]]
    assert exactccd.candidates_earliest_toi(V0, V1, vf) == (0.5, 0.5)
    assert exactccd.candidates_earliest_toi(V0, V1, vf, min_distance=0.25) == (0.375, 0.375)
    assert exactccd.candidates_max_collision_free_step(V0, V1, vf) == np.nextafter(0.5, 0.0)
    assert exactccd.candidates_max_collision_free_step(V0, V1, vf, tmax=0.4) == 0.4
    assert not exactccd.candidates_is_collision_free(V0, V1, vf)
    assert exactccd.candidates_earliest_toi(V0, V1) is None  # no candidates
    assert "GIL" in exactccd.candidates_find_collisions.__doc__


@pytest.mark.parametrize("kwargs, message", [
    (dict(vertex_face=[[0, 1, 2, 4]]), "vertex_face candidate 0 has vertex index 4, out of range [0, 4)"),
    (dict(vertex_face=[[1, 1, 2, 3]]), "vertex_face candidate 0: its two sides share vertex index 1"),
    (dict(edge_edge=[[0, 1, 2, 3], [0, 1, -1, 3]]), "edge_edge candidate 1 has vertex index -1"),
    (dict(point_edge=[[0, 0, 1]]), "point_edge candidate 0: its two sides share vertex index 0"),
    (dict(point_point=[[2, 2]]), "point_point candidate 0: its two sides share vertex index 2"),
    (dict(vertex_face=[[0, 5]], F=[[1, 2, 3]]), "vertex_face candidate 0 has face index 5, out of range [0, 1)"),
    (dict(edge_edge=[[0, 3]], E=[[0, 1], [2, 3]]), "edge_edge candidate 0 has edge index 3"),
    (dict(vertex_face=[[0, 1, 2]]), "vertex_face must have shape (n, 4)"),
    (dict(vertex_face=[[0.0, 1, 2, 3]]), "vertex_face must be an integer array"),
    (dict(vertex_face=[[0, 1, 2, 3]], min_distance=-1.0), "min_distance"),
    (dict(vertex_face=[[0, 1, 2, 3]], tmax=0.0), "tmax"),
])
def test_bad_input_raises_value_error(kwargs, message):
    V0 = np.array([[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64)
    for f in (exactccd.candidates_find_collisions, exactccd.candidates_earliest_toi,
              exactccd.candidates_is_collision_free, exactccd.candidates_max_collision_free_step):
        with pytest.raises(ValueError) as e:
            f(V0, V0, **kwargs)
        assert message in str(e.value)


def test_non_finite_positions_raise():
    V0 = np.zeros((4, 3))
    V1 = V0.copy()
    V1[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"positions_t1\[2\] has a non-finite coordinate"):
        exactccd.candidates_earliest_toi(V0, V1, [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match="V0 and V1 must have the same shape"):
        exactccd.candidates_earliest_toi(V0, V1[:3], [[0, 1, 2, 3]])
