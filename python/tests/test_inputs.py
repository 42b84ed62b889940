"""Input conversion and messages: float32 and float16 arrays widened to float64 (exactly),
integer arrays taken when every value is a double and refused (naming the element) otherwise,
error messages whose numbers read back (repr), and the one range of threads (0..1024)."""

import numpy as np
import pytest

import exactccd

# A vertex falling through a triangle: contact at t = 1/2.
VF = np.array([[[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0],
                [0.25, 0.25, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]])
V0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, 1]], dtype=np.float64)
V1 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, -1]], dtype=np.float64)
F = np.array([[0, 1, 2]])
P = np.array([3])  # the falling vertex (a vertex on no triangle takes part only as a point)


def test_float32_and_float16_are_widened_exactly():
    rng = np.random.default_rng(1)
    q = rng.standard_normal((200, 8, 3)).astype(np.float32)
    q[:, :, 2] *= np.float32(1e-30)  # small values, exactly float32
    want = exactccd.edge_edge_toi(q.astype(np.float64), min_distance=0.5)
    got = exactccd.edge_edge_toi(q, min_distance=0.5)
    assert np.array_equal(got, want, equal_nan=True)
    assert exactccd.vertex_face_toi(VF.astype(np.float32)).tolist() == [[0.5, 0.5]]
    assert exactccd.vertex_face_toi(VF.astype(np.float16)).tolist() == [[0.5, 0.5]]
    # A float32 value that is not a short decimal: widened, not re-rounded through text.
    x = np.float32(0.1)
    pp = np.array([[[0, 0, 0], [x, 0, 0], [0, 0, 0], [x, 0, 0]]], dtype=np.float32)
    assert exactccd.point_point_ccd(pp, min_distance=float(x)).tolist() == [True]
    assert exactccd.point_point_ccd(pp, min_distance=float(np.nextafter(x, np.float32(0)))).tolist() == [False]
    assert exactccd.earliest_toi(V0.astype(np.float32), V1.astype(np.float32), F, P=P) == (0.5, 0.5)


def test_integer_arrays_of_exact_doubles_are_taken():
    q = (VF * 4).astype(np.int64)  # every value an integer
    assert exactccd.vertex_face_toi(q).tolist() == [[0.5, 0.5]]
    for dtype in (np.int8, np.int16, np.int32, np.uint8, np.uint32, np.uint64):
        assert exactccd.vertex_face_ccd(np.abs(q).astype(dtype)).dtype == bool
    big = np.array([[[0, 0, 0], [2**53, 0, 0], [0, 0, 0], [2**60, 0, 0]]], dtype=np.int64)  # doubles
    assert exactccd.point_point_ccd(big, min_distance=2.0**53).tolist() == [True]
    assert exactccd.point_point_ccd(np.array([[[-2**63, 0, 0], [0] * 3, [-2**63, 0, 0], [0] * 3]], dtype=np.int64)).tolist() == [False]
    assert exactccd.earliest_toi((V0 * 4).astype(np.int64), (V1 * 4).astype(np.int64), F, P=P) == (0.5, 0.5)


def test_integers_that_are_not_doubles_are_refused_naming_the_element():
    q = np.zeros((3, 4, 3), dtype=np.int64)
    q[2, 1, 0] = 2**53 + 1
    with pytest.raises(ValueError, match=r"^q\[2, 1, 0\] = 9007199254740993 is not exactly a double"):
        exactccd.point_point_ccd(q)
    q[2, 1, 0] = 2**63 - 1
    with pytest.raises(ValueError, match=r"q\[2, 1, 0\] = 9223372036854775807 is not exactly a double"):
        exactccd.point_point_toi(q)
    u = np.zeros((1, 4, 3), dtype=np.uint64)
    u[0, 3, 2] = 2**64 - 1
    with pytest.raises(ValueError, match=r"q\[0, 3, 2\] = 18446744073709551615 is not exactly a double"):
        exactccd.point_point_ccd(u)
    v = (V0 * 4).astype(np.int64)
    v[1, 2] = 2**62 + 1
    with pytest.raises(ValueError, match=r"V0\[1, 2\] = 4611686018427387905 is not exactly a double"):
        exactccd.find_collisions(v, v, F)
    for dtype in (bool, np.complex128, object, np.longdouble):
        with pytest.raises(ValueError, match="float64"):
            exactccd.vertex_face_ccd(VF.astype(dtype))


def test_messages_print_numbers_that_read_back():
    cases = [("tmax", 1 + 2**-52, "tmax must be in (0, 1], not 1.0000000000000002"),
             ("tmax", -0.0, "tmax must be in (0, 1], not -0"),
             ("min_distance", -1e-300, "min_distance must be finite and >= 0, not -1e-300"),
             ("min_distance", -5e-324, "not -5e-324")]
    for name, value, text in cases:
        for call in (lambda **kw: exactccd.vertex_face_toi(VF, **kw),
                     lambda **kw: exactccd.find_collisions(V0, V1, F, **kw),
                     lambda **kw: exactccd.candidates_earliest_toi(V0, V1, vertex_face=[[3, 0, 1, 2]], **kw)):
            with pytest.raises(ValueError) as e:
                call(**{name: value})
            assert text in str(e.value), str(e.value)
            assert float(str(e.value).rsplit(" ", 1)[1]) == value


@pytest.mark.parametrize("threads", [-1, 1025, 100000, 2**40])
def test_threads_out_of_range_are_refused(threads):
    message = rf"threads must be in 0\.\.1024 \(0: every hardware thread\), not {threads}$"
    with pytest.raises(ValueError, match=message):
        exactccd.vertex_face_ccd(VF, threads=threads)
    with pytest.raises(ValueError, match=message):
        exactccd.find_collisions(V0, V1, F, threads=threads)
    with pytest.raises(ValueError, match=message):
        exactccd.candidates_is_collision_free(V0, V1, vertex_face=[[3, 0, 1, 2]], threads=threads)
    with pytest.raises(ValueError, match=message):
        exactccd.SceneBroadPhase(V0, V1, F, threads=threads)


@pytest.mark.parametrize("threads", [0, 1, 2, 1024])
def test_threads_in_range_give_the_same_answers(threads):
    assert exactccd.vertex_face_toi(VF, threads=threads).tolist() == [[0.5, 0.5]]
    assert exactccd.earliest_toi(V0, V1, F, P=P, threads=threads) == (0.5, 0.5)
