"""The rigid motion model from Python: batch functions against the closed-form cases and the
C++ answers printed by the CLI, bad input, and the scene functions against the batch functions
over every pair."""

import os
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import exactccd


def _turning_vertex(direction):
    """A's vertex (5, 0, 0) turns a quarter turn about z, q(t) = (1, 0, 0, t); B's static triangle
    (0,0,-1), 2 direction, (0,0,1): reached at t = tan(phi / 2) (1/2 for (3, 4))."""
    return [0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1,
            0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
            5, 0, 0, 0, 0, -1, 2 * direction[0], 2 * direction[1], 0, 0, 0, 1]


def test_closed_form_times():
    q = np.array([_turning_vertex((3, 4)), _turning_vertex((4, 3)), _turning_vertex((-3, 4))], dtype=np.float64)
    hits = exactccd.rigid_vertex_face_ccd(q)
    assert hits.tolist() == [True, True, False]
    toi = exactccd.rigid_vertex_face_toi(q, threads=2)
    assert toi[0].tolist() == [0.5, 0.5]
    assert Fraction(toi[1][0]) < Fraction(1, 3) < Fraction(toi[1][1]) and np.nextafter(toi[1][0], 1) == toi[1][1]
    assert np.isnan(toi[2]).all()
    assert exactccd.rigid_vertex_face_ccd(q[:1], tmax=0.25).tolist() == [False]


def test_coordinates_are_taken_exactly_as_by_every_function():
    """float32, float16 and integer arrays (every value a double) are widened exactly, as for the
    linear batch functions (docs/python.md): the same answers as float64."""
    q = np.array([_turning_vertex((3, 4)), _turning_vertex((4, 3)), _turning_vertex((-3, 4))], dtype=np.float64)
    expected = exactccd.rigid_vertex_face_toi(q)
    for dtype in (np.float32, np.float16, np.int32, np.int64):
        np.testing.assert_array_equal(exactccd.rigid_vertex_face_toi(q.astype(dtype)), expected)


@pytest.mark.parametrize("threads", [-1, 1025, 2**40])
def test_threads_out_of_range_are_refused(threads):
    """The module's one range of threads, 0..1024: anything else is a ValueError, never capped."""
    q = np.array([_turning_vertex((3, 4))], dtype=np.float64)
    message = rf"threads must be in 0\.\.1024 \(0: every hardware thread\), not {threads}$"
    with pytest.raises(ValueError, match=message):
        exactccd.rigid_vertex_face_ccd(q, threads=threads)
    with pytest.raises(ValueError, match=message):
        exactccd.rigid_edge_edge_toi(np.zeros((0, 40)), threads=threads)
    with pytest.raises(ValueError, match=message):
        exactccd.rigid_max_collision_free_step([], threads=threads)


def test_bad_input_names_the_row():
    q = np.array([_turning_vertex((3, 4)), _turning_vertex((3, 4))], dtype=np.float64)
    q[1, 10] = -2.0  # qA1 (numbers 10..13) = (-2, 0, 0, 0) = -2 qA0: the path passes through zero
    q[1, 11:14] = 0.0
    with pytest.raises(ValueError, match=r"q\[1\].*passes through 0"):
        exactccd.rigid_vertex_face_toi(q)
    with pytest.raises(ValueError):
        exactccd.rigid_edge_edge_ccd(np.zeros((2, 39)))
    with pytest.raises(ValueError, match=r"q\[0, 5\] = 9007199254740993 is not exactly a double"):
        big = q[:1].astype(np.int64)
        big[0, 5] = 2**53 + 1
        exactccd.rigid_vertex_face_ccd(big)
    with pytest.raises(ValueError, match="must be an array of float64"):
        exactccd.rigid_vertex_face_ccd(q[:1].astype(np.complex128))
    with pytest.raises(ValueError):
        exactccd.rigid_vertex_face_ccd(q[:1], min_distance=-1.0)
    q[1] = q[0]
    q[1, 3] = np.nan
    with pytest.raises(ValueError, match=r"q\[1\]"):
        exactccd.rigid_vertex_face_ccd(q)


def _bundled(name):
    path = os.path.join(os.environ["EXACTCCD_DATA"], "rigid", name)
    rows = [line.split(",") for line in open(path, encoding="utf-8") if line.strip() and not line.startswith("#")]
    return path, np.array([[float.fromhex(x) for x in r[:40]] for r in rows], dtype=np.float64)


@pytest.mark.parametrize("name,function", [("rigid-sim-box-vertex-face.csv", exactccd.rigid_vertex_face_toi),
                                           ("rigid-sim-rings-edge-edge.csv", exactccd.rigid_edge_edge_toi)])
def test_batch_equals_the_cli(name, function):
    path, q = _bundled(name)
    toi = function(q, min_distance=2.0 ** -9, tmax=0.75)
    kind = "vf" if "vertex-face" in name else "ee"
    out = subprocess.run([os.environ["EXACTCCD_CLI"], "check", "--motion", "rigid", "--kind", kind, "--answers",
                          "--toi", "--min-distance", "0.001953125", "--tmax", "0.75", path],
                         check=True, capture_output=True, text=True).stdout.split("\n")
    for row, line in zip(toi, out):
        if line == "0":
            assert np.isnan(row).all()
        else:
            _, lo, hi = line.split()
            assert row.tolist() == [float(lo), float(hi)]


def test_scene_equals_the_pairs():
    box_v = np.array([[x, y, z] for z in (-0.3, 0.3) for y in (-0.3, 0.3) for x in (-0.3, 0.3)])
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    box_f = np.array([t for f in faces for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))])
    square_v = np.array([[-1.0, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]])
    square_f = np.array([[0, 1, 2], [0, 2, 3]])
    box = (box_v, box_f, np.array([0.1, 0.05, 0.5]), np.array([1.0, 0.2, 0.1, 0]),
           np.array([0.1, 0.0, 0.1]), np.array([1.0, 0.3, 0.3, 0.2]))
    ground = (square_v, square_f, np.zeros(3), np.array([1.0, 0, 0, 0]), np.zeros(3), np.array([1.0, 0, 0, 0]))
    hits = exactccd.rigid_find_collisions([box, ground], threads=2)
    assert len(hits["kind"]) > 0
    # Each reported vertex-face pair equals its batch query.
    for k in range(len(hits["kind"])):
        if hits["kind"][k] != exactccd.VERTEX_FACE:
            continue
        a, b = (box, ground) if hits["body_a"][k] == 0 else (ground, box)
        tri = b[1][hits["triangle"][k]]
        q = np.concatenate([a[2], a[3], a[4], a[5], b[2], b[3], b[4], b[5], a[0][hits["vertex"][k]],
                            b[0][tri[0]], b[0][tri[1]], b[0][tri[2]]])
        assert exactccd.rigid_vertex_face_toi(q[None, :])[0].tolist() == hits["toi"][k].tolist()
    earliest = exactccd.rigid_earliest_toi([box, ground])
    assert earliest == min((lo, hi) for lo, hi in hits["toi"].tolist())
    step = exactccd.rigid_max_collision_free_step([box, ground])
    assert step == (0.0 if earliest[0] == 0 else np.nextafter(earliest[0], 0))
    assert exactccd.rigid_earliest_toi([box]) is None
    with pytest.raises(ValueError):
        exactccd.rigid_find_collisions([(box_v, box_f, np.zeros(3), np.zeros(4), np.zeros(3), np.array([1.0, 0, 0, 0]))])
