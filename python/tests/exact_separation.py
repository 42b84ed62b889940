"""An independent check of a triangle mesh's separation, in exact integer arithmetic, calling
nothing of exactccd: the soak test's witness (test_soak.py) that the simulation never lets two
primitives come within d of each other, nor any two triangles intersect.

`check(V, F, d)` brute-forces every pair of primitives that share no vertex index, as the
library's scene functions pair them (docs/scene.md): vertex-triangle, edge-edge, and for the
intersection check edge-triangle. A pair is dropped only when its two boxes are apart by more
than 2d on some axis, computed in floating point and proved sound below; every other pair is
decided exactly: the coordinates, scaled by one power of two, are Python integers, and every
distance is compared as a ratio of integers.
"""

import numpy as np

from fractions import Fraction


def _integers(V, d):
    """(X, D): the coordinates and d as Python integers, all scaled by one power of two 2^-e
    (every double is m 2^k with an integer m; e is the smallest k), so X[i][k] / 2^e = V[i, k]."""
    values = [float(x) for x in V.ravel()] + [float(d)]
    ratios = [Fraction(x) for x in values]
    scale = max(r.denominator for r in ratios)          # a power of two
    ints = [r.numerator * (scale // r.denominator) for r in ratios]
    X = [tuple(ints[3 * i:3 * i + 3]) for i in range(len(V))]
    return X, ints[-1], scale


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def point_segment2(p, a, b):
    """The squared distance from p to the closed segment ab, exactly (a Fraction)."""
    ab, ap = _sub(b, a), _sub(p, a)
    length2, t = _dot(ab, ab), _dot(ap, ab)
    if length2 == 0 or t <= 0:
        return Fraction(_dot(ap, ap))
    if t >= length2:
        bp = _sub(p, b)
        return Fraction(_dot(bp, bp))
    return Fraction(_dot(ap, ap) * length2 - t * t, length2)  # |ap|^2 - t^2 / |ab|^2


def point_triangle2(p, a, b, c):
    """The squared distance from p to the closed triangle abc: to its plane when p projects
    inside (the three edge orientations agree with the normal), else to the nearest edge; a
    degenerate triangle (zero normal) is its edges' hull."""
    n = _cross(_sub(b, a), _sub(c, a))
    n2 = _dot(n, n)
    if n2 != 0:
        inside = all(_dot(_cross(_sub(w, u), _sub(p, u)), n) >= 0 for u, w in ((a, b), (b, c), (c, a)))
        if inside:
            h = _dot(_sub(p, a), n)
            return Fraction(h * h, n2)
    return min(point_segment2(p, a, b), point_segment2(p, b, c), point_segment2(p, c, a))


def segment_segment2(p0, p1, q0, q1):
    """The squared distance between the closed segments p0p1 and q0q1: at the lines' closest
    points when both parameters lie in [0, 1] (lines not parallel), else on the boundary of the
    parameter square, i.e. from an endpoint to the other segment (the squared distance is a
    convex quadratic in the two parameters)."""
    d1, d2, r = _sub(p1, p0), _sub(q1, q0), _sub(p0, q0)
    a, e, b, c, f = _dot(d1, d1), _dot(d2, d2), _dot(d1, d2), _dot(d1, r), _dot(d2, r)
    den = a * e - b * b
    if den != 0:
        s, t = b * f - c * e, a * f - b * c         # times den
        if 0 <= s <= den and 0 <= t <= den:
            w = tuple(den * r[k] + s * d1[k] - t * d2[k] for k in range(3))
            return Fraction(_dot(w, w), den * den)
    return min(point_segment2(p0, q0, q1), point_segment2(p1, q0, q1),
               point_segment2(q0, p0, p1), point_segment2(q1, p0, p1))


def _orient(a, b, c, p):
    """The sign of det[b - a, c - a, p - a]: which side of the plane abc p lies on."""
    v = _dot(_cross(_sub(b, a), _sub(c, a)), _sub(p, a))
    return (v > 0) - (v < 0)


def segment_crosses_triangle(p, q, a, b, c):
    """Whether the segment pq crosses the triangle abc properly: p and q strictly on opposite
    sides of its plane and the line pq strictly inside its three edges. With every vertex-
    triangle and edge-edge distance positive (checked first), this is the only way they can
    meet: a touching or coplanar meeting would put an endpoint on the triangle or an edge on an
    edge."""
    if _orient(a, b, c, p) * _orient(a, b, c, q) >= 0:
        return False
    s = {_orient(p, q, a, b), _orient(p, q, b, c), _orient(p, q, c, a)}
    return s == {1} or s == {-1}


def near_pairs(V, A, B, reach, same=False):
    """Pairs (i, j) of rows of A and B (vertex indices: points, edges or triangles) that share no
    vertex index and whose boxes are not certainly apart by more than `reach`: i < j when A and
    B are the same list (same=True). Brute force over all pairs, in chunks.

    Soundness: a pair is dropped when fl(lo_b - hi_a) > 2 reach (or the other way round) on some
    axis. For doubles x, y, round to nearest gives fl(y - x) <= (y - x)(1 + 2^-53) when y > x
    (a difference that underflows is exact, one that overflows leaves y - x huge), so y - x >=
    2 reach / (1 + 2^-53) > reach: the boxes, hence the primitives, are farther apart than
    reach."""
    lo_a, hi_a = V[A].min(axis=1), V[A].max(axis=1)
    lo_b, hi_b = V[B].min(axis=1), V[B].max(axis=1)
    out = []
    chunk = max(1, 2_000_000 // max(1, len(B)))
    for start in range(0, len(A), chunk):
        sl = slice(start, start + chunk)
        keep = np.ones((len(A[sl]), len(B)), dtype=bool)
        for k in range(3):
            keep &= lo_b[None, :, k] - hi_a[sl, None, k] <= 2 * reach
            keep &= lo_a[sl, None, k] - hi_b[None, :, k] <= 2 * reach
        i, j = np.nonzero(keep)
        out.append(np.stack([i + start, j], axis=1))
    ij = np.concatenate(out)
    shared = (A[ij[:, 0]][:, :, None] == B[ij[:, 1]][:, None, :]).any(axis=(1, 2))
    ij = ij[~shared]
    return ij[ij[:, 0] < ij[:, 1]] if same else ij


def unique_edges(F):
    """The triangles' undirected edges, each once."""
    E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    return np.unique(E, axis=0)


def check(V, F, d):
    """(closest, pairs, crossing): the exact minimum squared distance over the near vertex-
    triangle and edge-edge pairs as a Fraction (None when there is no near pair; every other
    pair is farther apart than d), the number of pairs decided exactly, and whether some edge
    crosses a triangle it shares no vertex with (only looked for when every distance is
    positive, see segment_crosses_triangle)."""
    V = np.asarray(V, dtype=np.float64)
    F = np.asarray(F, dtype=np.int64)
    E = unique_edges(F)
    X, D, scale = _integers(V, d)
    points = np.unique(F).reshape(-1, 1)
    vf = near_pairs(V, points, F, d)
    ee = near_pairs(V, E, E, d, same=True)
    closest = None
    for i, j in vf:
        a, b, c = F[j]
        d2 = point_triangle2(X[points[i, 0]], X[a], X[b], X[c])
        closest = d2 if closest is None else min(closest, d2)
    for i, j in ee:
        d2 = segment_segment2(X[E[i, 0]], X[E[i, 1]], X[E[j, 0]], X[E[j, 1]])
        closest = d2 if closest is None else min(closest, d2)
    crossing = False
    if closest is None or closest > 0:
        for i, j in near_pairs(V, E, F, 0):
            a, b, c = F[j]
            if segment_crosses_triangle(X[E[i, 0]], X[E[i, 1]], X[a], X[b], X[c]):
                crossing = True
                break
    pairs = len(vf) + len(ee)
    return (None if closest is None else closest / (scale * scale)), pairs, crossing
