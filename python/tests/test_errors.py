"""Bad input raises ValueError with the library's message: shapes, dtypes, NaN, inf, bad
min_distance, tmax and threads, malformed scenes, unreadable meshes."""

import numpy as np
import pytest

import exactccd
from conftest import KINDS, TEST_DATA


def good(kind, n=2):
    _, _, rows, dim = KINDS[kind]
    return np.zeros((n, rows, dim))


@pytest.mark.parametrize("kind", list(KINDS))
@pytest.mark.parametrize("what", ["ccd", "toi"])
def test_bad_batches(kind, what):
    f = getattr(exactccd, f"{kind}_{what}")
    _, _, rows, dim = KINDS[kind]
    shape = rf"\(N, {rows}, {dim}\)"
    for bad in (np.zeros((2, rows, 5 - dim)), np.zeros((2, rows + 2, dim)), np.zeros((rows, dim)),
                np.zeros((1, 2, rows, dim)), np.zeros(3)):
        with pytest.raises(ValueError, match=shape):
            f(bad)
    for dtype in (np.complex128, object, bool):  # float32 and integers: test_inputs.py
        with pytest.raises(ValueError, match="float64"):
            f(good(kind).astype(dtype))
    with pytest.raises(ValueError, match="must be an array"):
        f(None)
    for value in (np.nan, np.inf, -np.inf):
        q = good(kind, 5)
        q[3, rows - 1, dim - 1] = value
        with pytest.raises(ValueError, match=rf"^q\[3\]: exactccd::{kind}_{what}: .*finite"):
            f(q)
    for d in (-1.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="min_distance"):
            f(good(kind), min_distance=d)
        with pytest.raises(ValueError, match="min_distance"):
            f(good(kind, 0), min_distance=d)  # also for an empty batch
    for t in (0.0, -0.5, 1.5, np.nan):
        with pytest.raises(ValueError, match="tmax"):
            f(good(kind), tmax=t)
    with pytest.raises(ValueError, match="threads"):
        f(good(kind), threads=-1)


V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
F = np.array([[0, 1, 2]])


def test_bad_scenes():
    for fn in (exactccd.find_collisions, exactccd.earliest_toi, exactccd.is_collision_free,
               exactccd.max_collision_free_step):
        fn(V, V, F)  # fine
        with pytest.raises(ValueError, match="same shape"):
            fn(V, V[:3], F)
        with pytest.raises(ValueError, match="float64"):
            fn(V.astype(np.complex128), V, F)
        with pytest.raises(ValueError, match=r"\(n, 3\) or \(n, 2\)"):
            fn(np.zeros((4, 4)), np.zeros((4, 4)), F)
        with pytest.raises(ValueError, match="integer"):
            fn(V, V, F.astype(np.float64))
        with pytest.raises(ValueError, match=r"F must have shape \(n, 3\)"):
            fn(V, V, np.array([[0, 1]]))
        with pytest.raises(ValueError, match="range"):
            fn(V, V, np.array([[0, 1, 7]]))
        with pytest.raises(ValueError, match="range"):
            fn(V, V, np.array([[0, 1, 2**40]]))
        with pytest.raises(ValueError):
            fn(V, V, np.array([[0, 1, 1]]))  # repeated index
        bad = V.copy()
        bad[2, 1] = np.nan
        with pytest.raises(ValueError):
            fn(V, bad, F)
        with pytest.raises(ValueError, match="min_distance"):
            fn(V, V, F, min_distance=-1.0)
        with pytest.raises(ValueError, match="tmax"):
            fn(V, V, F, tmax=2.0)
        with pytest.raises(ValueError, match="triangles"):
            fn(V[:, :2], V[:, :2], F)
    with pytest.raises(ValueError):
        exactccd.intersection_free(V, np.array([[0, 1, 9]]))
    with pytest.raises(ValueError):
        exactccd.intersection_free(np.full((4, 3), np.inf), F)


def test_read_mesh_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        exactccd.read_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(ValueError, match=r"bad\.obj:4: "):
        exactccd.read_mesh(bad)
    empty = tmp_path / "empty.obj"
    empty.write_text("v 0 0 0\n")
    with pytest.raises(ValueError, match="no faces"):
        exactccd.read_mesh(empty)
    unknown = tmp_path / "mesh.xyz"
    unknown.write_text("v 0 0 0\n")
    with pytest.raises(ValueError, match="mesh.xyz"):
        exactccd.read_mesh(unknown)
