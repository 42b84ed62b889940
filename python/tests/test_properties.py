"""Property tests (hypothesis): permuting a triangle's vertices or an edge's ends never changes an
answer; d = 0 is the boolean CCD; a larger d never gives fewer collisions; the time limit cuts
the TOI; the 2D kinds are the 3D kinds with z = 0; bad shapes raise ValueError. Coordinates come
from a coarse grid so that degenerate queries (coplanar, collinear, touching) are frequent."""

import os

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from hypothesis.extra import numpy as hnp  # noqa: E402

import exactccd  # noqa: E402
from conftest import KINDS  # noqa: E402

# Examples per property (about 10 s for the file at 100), more with
# EXACTCCD_HYPOTHESIS_EXAMPLES=N.
EXAMPLES = int(os.environ.get("EXACTCCD_HYPOTHESIS_EXAMPLES", "100"))
SETTINGS = settings(max_examples=EXAMPLES, deadline=None, database=None)
COORDS = [i / 4.0 for i in range(-4, 5)] + [0.1, 1 / 3, -0.7, 1.0 + 2.0**-52, 2.0**-20, 3e-9]
coord = st.sampled_from(COORDS)
distance = st.sampled_from([0.0, 2.0**-10, 0.1, 0.25, 0.5, 1.0])


def queries(kind, n=4):
    _, _, rows, dim = KINDS[kind]
    return hnp.arrays(np.float64, (n, rows, dim), elements=coord)


def toi(kind, q, **kw):
    return getattr(exactccd, f"{kind}_toi")(q, **kw)


def ccd(kind, q, **kw):
    return getattr(exactccd, f"{kind}_ccd")(q, **kw)


def permuted(q, perm):
    """The query with its points (at t0 and at t1 alike) permuted."""
    half = q.shape[1] // 2
    order = list(perm) + [half + i for i in perm]
    return q[:, order]


# The permutations keeping each kind's question: a triangle's vertices, an edge's ends, the two
# edges (edge-edge) or the two points (point-point).
SYMMETRIES = {
    "vertex_face": [(0, 2, 3, 1), (0, 3, 2, 1), (0, 1, 3, 2)],
    "edge_edge": [(1, 0, 2, 3), (0, 1, 3, 2), (2, 3, 0, 1)],
    "point_edge": [(0, 2, 1)],
    "point_point": [(1, 0)],
}
SYMMETRIES.update({k + "_2d": v for k, v in SYMMETRIES.items() if k != "vertex_face"})


@pytest.mark.parametrize("kind", list(KINDS))
@SETTINGS
@given(data=st.data(), d=distance)
def test_symmetries_never_change_an_answer(kind, data, d):
    q = data.draw(queries(kind))
    want_ccd, want_toi = ccd(kind, q, min_distance=d), toi(kind, q, min_distance=d)
    for perm in SYMMETRIES[kind]:
        p = permuted(q, perm)
        assert np.array_equal(ccd(kind, p, min_distance=d), want_ccd)
        assert np.array_equal(toi(kind, p, min_distance=d), want_toi, equal_nan=True)


@pytest.mark.parametrize("kind", list(KINDS))
@SETTINGS
@given(data=st.data())
def test_zero_distance_is_the_boolean_ccd(kind, data):
    q = data.draw(queries(kind))
    answers = ccd(kind, q)
    assert np.array_equal(ccd(kind, q, min_distance=0.0, tmax=1.0), answers)
    t = toi(kind, q, min_distance=0.0)
    assert np.array_equal(~np.isnan(t[:, 0]), answers)
    hit = answers
    assert (t[hit, 0] <= t[hit, 1]).all() and (t[hit, 0] >= 0).all() and (t[hit, 1] <= 1).all()
    if kind in ("vertex_face", "edge_edge"):
        # the classic functions (C++: no CcdParams) are the same answers; the batch default is d = 0
        assert np.array_equal(toi(kind, q), t, equal_nan=True)


@pytest.mark.parametrize("kind", list(KINDS))
@SETTINGS
@given(data=st.data(), d1=distance, d2=distance)
def test_larger_distance_never_fewer_collisions(kind, data, d1, d2):
    q = data.draw(queries(kind))
    lo_d, hi_d = min(d1, d2), max(d1, d2)
    a, b = ccd(kind, q, min_distance=lo_d), ccd(kind, q, min_distance=hi_d)
    assert not (a & ~b).any()
    ta, tb = toi(kind, q, min_distance=lo_d), toi(kind, q, min_distance=hi_d)
    assert (tb[a, 0] <= ta[a, 0]).all()  # and never a later TOI


@pytest.mark.parametrize("kind", list(KINDS))
@SETTINGS
@given(data=st.data(), tmax=st.sampled_from([0.125, 0.3, 0.5, 0.999, 1.0]), d=distance)
def test_time_limit(kind, data, tmax, d):
    q = data.draw(queries(kind))
    full = toi(kind, q, min_distance=d)
    limited = ccd(kind, q, min_distance=d, tmax=tmax)
    hit = ~np.isnan(full[:, 0])
    assert not (limited & ~hit).any()
    assert limited[hit & (full[:, 1] <= tmax)].all()
    assert not limited[hit & (full[:, 0] > tmax)].any()
    limited_toi = toi(kind, q, min_distance=d, tmax=tmax)
    assert np.array_equal(limited_toi[limited], full[limited])


@pytest.mark.parametrize("kind", ["edge_edge", "point_edge", "point_point"])
@SETTINGS
@given(data=st.data(), d=distance)
def test_2d_kinds_are_3d_kinds_in_the_plane(kind, data, d):
    q = data.draw(queries(kind + "_2d"))
    flat = np.concatenate([q, np.zeros(q.shape[:2] + (1,))], axis=2)
    assert np.array_equal(toi(kind + "_2d", q, min_distance=d), toi(kind, flat, min_distance=d),
                          equal_nan=True)


@pytest.mark.parametrize("kind", list(KINDS))
@settings(max_examples=2 * EXAMPLES, deadline=None, database=None)
@given(shape=st.lists(st.integers(0, 9), min_size=0, max_size=4))
def test_bad_shapes_raise(kind, shape):
    _, _, rows, dim = KINDS[kind]
    q = np.zeros(shape)
    if len(shape) == 3 and shape[1:] == [rows, dim]:
        assert ccd(kind, q).shape == (shape[0],)
    else:
        with pytest.raises(ValueError):
            ccd(kind, q)
