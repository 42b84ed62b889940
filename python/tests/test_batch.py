"""Batch functions: hand-known answers, and the CLI's answers and TOIs on every bundled file
(bit-identical TOIs), at d = 0 and with a minimum separation and a time limit."""

import numpy as np
import pytest

import exactccd
from conftest import SAMPLE_QUERIES, KINDS, bundled_files, cli_answers, kind_of_file, read_queries, shared_files

NAN2 = [np.nan, np.nan]


def fn(kind, what):
    return getattr(exactccd, f"{kind}_{what}")


def test_every_kind_is_bound():
    for kind in KINDS:
        assert callable(fn(kind, "ccd")) and callable(fn(kind, "toi"))
        assert fn(kind, "ccd").__doc__ and "min_distance" in fn(kind, "toi").__doc__
    assert exactccd.KINDS == {k: (rows, dim) for k, (_, _, rows, dim) in KINDS.items()}


def vf(p0, p1, tri0, tri1=None):
    tri1 = tri0 if tri1 is None else tri1
    return np.array([[p0, *tri0, p1, *tri1]], dtype=np.float64)


TRI = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


def test_vertex_face_hand_cases():
    q = np.concatenate([
        vf((0.25, 0.25, 1.0), (0.25, 0.25, -1.0), TRI),  # through the face at t = 1/2
        vf((2.0, 2.0, 1.0), (2.0, 2.0, -1.0), TRI),      # beside it
        vf((0.25, 0.25, 1.0), (0.25, 0.25, -2.0), TRI),  # at t = 1/3: not a double
        vf((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), TRI),       # on a vertex all the time
    ])
    assert exactccd.vertex_face_ccd(q).tolist() == [True, False, True, True]
    toi = exactccd.vertex_face_toi(q)
    assert toi.shape == (4, 2) and toi.dtype == np.float64
    assert toi[0].tolist() == [0.5, 0.5]
    assert np.isnan(toi[1]).all()
    lo, hi = toi[2]
    assert lo < 1 / 3 <= hi or lo <= 1 / 3 < hi
    assert hi == np.nextafter(lo, 2.0)
    assert toi[3].tolist() == [0.0, 0.0]
    # the time limit and the minimum separation
    assert exactccd.vertex_face_ccd(q, tmax=0.25).tolist() == [False, False, False, True]
    assert exactccd.vertex_face_ccd(q[1:2], min_distance=2.2).tolist() == [True]
    assert exactccd.vertex_face_ccd(q[1:2], min_distance=2.0).tolist() == [False]


def test_edge_edge_and_point_kinds_hand_cases():
    ee = np.array([[(0, 0, 1), (1, 0, 1), (0.5, -1, 0), (0.5, 1, 0),
                    (0, 0, -1), (1, 0, -1), (0.5, -1, 0), (0.5, 1, 0)]], dtype=np.float64)
    assert exactccd.edge_edge_ccd(ee).tolist() == [True]
    assert exactccd.edge_edge_toi(ee)[0].tolist() == [0.5, 0.5]
    pe = np.array([[(0.5, 1, 0), (0, 0, 0), (1, 0, 0), (0.5, -1, 0), (0, 0, 0), (1, 0, 0)]], dtype=np.float64)
    assert exactccd.point_edge_toi(pe)[0].tolist() == [0.5, 0.5]
    pp = np.array([[(0, 0, 0), (3, 0, 0), (0, 0, 0), (3, 0, 0)]], dtype=np.float64)
    assert exactccd.point_point_ccd(pp).tolist() == [False]
    assert exactccd.point_point_ccd(pp, min_distance=3.0).tolist() == [True]
    assert exactccd.point_point_toi(pp, min_distance=3.0)[0].tolist() == [0.0, 0.0]
    assert exactccd.point_point_ccd(pp, min_distance=2.5).tolist() == [False]
    # the 2D kinds: the 3D answers with z dropped
    for kind, q in (("edge_edge", ee), ("point_edge", pe), ("point_point", pp)):
        flat = q.copy()
        flat[..., 2] = 0
        for d in (0.0, 0.5, 3.0):
            assert np.array_equal(fn(kind + "_2d", "toi")(flat[..., :2], min_distance=d),
                                  fn(kind, "toi")(flat, min_distance=d), equal_nan=True)


@pytest.mark.parametrize("kind", list(KINDS))
def test_empty_batch(kind):
    _, _, rows, dim = KINDS[kind]
    q = np.zeros((0, rows, dim))
    assert fn(kind, "ccd")(q).shape == (0,) and fn(kind, "ccd")(q).dtype == np.bool_
    assert fn(kind, "toi")(q).shape == (0, 2)


@pytest.mark.parametrize("path", bundled_files(), ids=lambda p: p.name)
def test_bundled_file_equals_cli_and_truth(path):
    kind = kind_of_file(path)
    q, truth = read_queries(path, kind)
    answers, tois = fn(kind, "ccd")(q), fn(kind, "toi")(q)
    assert np.array_equal(answers, truth)
    want_answers, want_tois = cli_answers(path, kind)
    assert np.array_equal(answers, want_answers)
    assert np.array_equal(tois, want_tois, equal_nan=True)  # bit-identical doubles
    assert np.array_equal(~np.isnan(tois[:, 0]), answers)


SEPARATION_FILES = [p for p in bundled_files() if p.parent.name == "kinds" or "fold" in p.name]


@pytest.mark.parametrize("path", SEPARATION_FILES, ids=lambda p: p.name)
def test_bundled_file_with_separation_equals_cli(path):
    kind = kind_of_file(path)
    q, _ = read_queries(path, kind)
    q = q[:100]  # the CLI answers the whole file; compare the rows bound here
    d, tmax = 1e-3, 0.75
    want_answers, want_tois = cli_answers(path, kind, min_distance=d, tmax=tmax)
    assert np.array_equal(fn(kind, "ccd")(q, min_distance=d, tmax=tmax), want_answers[:100])
    assert np.array_equal(fn(kind, "toi")(q, min_distance=d, tmax=tmax), want_tois[:100], equal_nan=True)


def test_threads_do_not_change_answers():
    path = bundled_files()[0]
    kind = kind_of_file(path)
    q, _ = read_queries(path, kind)
    base = fn(kind, "toi")(q, threads=1)
    for threads in (0, 2, 7, 1024):
        assert np.array_equal(fn(kind, "toi")(q, threads=threads), base, equal_nan=True)


def test_non_contiguous_and_list_input():
    path = bundled_files()[0]
    kind = kind_of_file(path)
    q, _ = read_queries(path, kind)
    want = fn(kind, "toi")(q)
    assert np.array_equal(fn(kind, "toi")(q[::-1][::-1]), want, equal_nan=True)
    assert np.array_equal(fn(kind, "toi")(np.asfortranarray(q)), want, equal_nan=True)
    assert np.array_equal(fn(kind, "toi")(q[::2]), want[::2], equal_nan=True)
    assert np.array_equal(fn(kind, "toi")(q[:3].tolist()), want[:3], equal_nan=True)


def test_gil_is_released():
    import threading
    import time

    path = bundled_files()[0]
    kind = kind_of_file(path)
    q, _ = read_queries(path, kind)
    big = np.tile(q, (400, 1, 1))
    start = time.perf_counter()
    fn(kind, "toi")(big, min_distance=0.01, threads=1)
    alone = time.perf_counter() - start
    if alone < 0.1:
        pytest.skip(f"the batch takes {alone:.3f} s: too short to tell")
    worker = threading.Thread(target=lambda: fn(kind, "toi")(big, min_distance=0.01, threads=1))
    ticks = 0
    worker.start()
    while worker.is_alive():
        ticks += 1  # runs only while the batch does not hold the GIL
        time.sleep(0.001)
    worker.join()
    assert ticks >= 20, (ticks, alone)  # holding the GIL would allow about one


@pytest.mark.skipif(not shared_files(), reason=f"the shared benchmark sample is absent ({SAMPLE_QUERIES})")
@pytest.mark.parametrize("path,kind", shared_files(), ids=lambda v: getattr(v, "name", v))
def test_shared_sample_equals_cli(path, kind):
    q, _ = read_queries(path, kind)
    want_answers, want_tois = cli_answers(path, kind)
    assert np.array_equal(fn(kind, "ccd")(q), want_answers)
    assert np.array_equal(fn(kind, "toi")(q), want_tois, equal_nan=True)
