"""exactccd.SceneBroadPhase (the C++ SceneBroadPhase: built once, refitted per line-search
trial) against the free scene functions, on the bundled scenes and random trial steps, at
d = 0 and d > 0, with tmax < 1."""

import numpy as np
import pytest

import exactccd
from conftest import DATA

SCENES = sorted(p for p in (DATA / "scenes").iterdir() if (p / "T0.obj").exists())


def same_collisions(a, b):
    assert sorted(a) == sorted(b)
    for key in a:
        assert np.array_equal(a[key], b[key]), key


@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.name)
@pytest.mark.parametrize("d,tmax", [(0.0, 1.0), (1e-3, 1.0), (1e-2, 0.5)])
def test_line_search_equals_the_free_functions(scene, d, tmax):
    V0, F = exactccd.read_mesh(scene / "T0.obj")
    V1, _ = exactccd.read_mesh(scene / "T1.obj")
    bp = exactccd.SceneBroadPhase(V0, V1, F, min_distance=d, tmax=tmax)
    assert bp.min_distance == d and bp.tmax == tmax
    steps = 0
    for alpha in (1.0, 0.5, 0.25, 0.125):  # a backtracking line search: refit, never rebuild
        Va = V0 + alpha * (V1 - V0)  # at alpha = 1 not always V1 in doubles: refit to it too
        bp.update(Va)
        kw = dict(min_distance=d, tmax=tmax)
        same_collisions(bp.find_collisions(), exactccd.find_collisions(V0, Va, F, **kw))
        assert bp.earliest_toi() == exactccd.earliest_toi(V0, Va, F, **kw)
        assert bp.is_collision_free() == exactccd.is_collision_free(V0, Va, F, **kw)
        assert bp.max_collision_free_step() == exactccd.max_collision_free_step(V0, Va, F, **kw)
        c = bp.candidates
        assert set(c) == {"vertex_face", "edge_edge", "point_edge", "point_point"}
        for rows in c.values():
            assert rows.dtype == np.int64 and rows.ndim == 2 and rows.shape[1] == 2
            assert [tuple(r) for r in rows] == sorted({tuple(r) for r in rows})  # sorted, unique
        # A rebuilt broad phase has the same candidates (the hierarchy only changes speed).
        fresh = exactccd.SceneBroadPhase(V0, Va, F, min_distance=d, tmax=tmax).candidates
        for k in c:
            assert np.array_equal(c[k], fresh[k]), k
        steps += 1
    assert steps == 4
    assert bp.edges.shape[1] == 2 and len(bp.edges) > len(F)


def test_collisions_name_the_same_primitives_as_the_candidates():
    V0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, 1], [0.3, 0.2, 1]], dtype=float)
    V1 = V0.copy()
    V1[3:, 2] = -1
    F = np.array([[0, 1, 2]])
    E = np.array([[3, 4]])
    bp = exactccd.SceneBroadPhase(V0, V1, F, E)
    got = bp.find_collisions()
    want = exactccd.find_collisions(V0, V1, F, E)
    same_collisions(got, want)
    assert got["vertex"].tolist() == [3, 4] and got["toi"].tolist() == [[0.5, 0.5], [0.5, 0.5]]
    assert bp.max_collision_free_step() == np.nextafter(0.5, 0)


def test_bad_input():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2]])
    bp = exactccd.SceneBroadPhase(V, V, F)
    with pytest.raises(ValueError, match="positions_t1 has 2 vertices"):
        bp.update(V[:2])
    bad = V.copy()
    bad[1, 1] = np.nan
    with pytest.raises(ValueError):
        bp.update(bad)
    assert bp.is_collision_free()  # unchanged
    with pytest.raises(ValueError, match="3D scene"):
        exactccd.SceneBroadPhase(V[:, :2], V[:, :2], E=np.array([[0, 1]]))
    with pytest.raises(ValueError, match="tmax"):
        exactccd.SceneBroadPhase(V, V, F, tmax=0.0)
