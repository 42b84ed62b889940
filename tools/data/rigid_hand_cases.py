#!/usr/bin/env python3
"""Hand-derived rigid-motion CCD cases (issue 24): writes tests/data/rigid/hand-*.csv and the
expected `exactccd check --motion rigid --answers --toi` output beside each (.expected).

Every case (CASES below) carries its inputs (exact doubles) and the time of impact derived by
hand in docs/rigid-hand-derived.md: a rational, a quadratic surd p + q*sqrt(r), or the unique
root of a stated polynomial in a stated rational interval, together with the condition
polynomial of the derivation. The script checks each case two further ways, both exact and
neither using exactccd:

 1. a generic exact solver (`earliest_contact`): the primitives' world positions as rational
    functions of t, the distance split into its features (face, edges, vertices; segment
    interiors, endpoints), each feature's set {t : distance <= d, closest point in the
    feature} written as polynomial sign conditions, and its earliest point found among t = 0
    and the real roots of those polynomials, every sign decided exactly (Sturm sequences,
    rational bisection, gcds);
 2. a dense exact sampling of the squared distance (computed by another method: clamped
    Gram-system closest points, in Fractions) at many rational t before the time of impact
    (or over all of [0, tmax] when there is none), which must all exceed d^2, and at a rational
    time of impact, where it must be <= d^2.

The hand value, the solver's value and the samples must agree or the script stops. The double
enclosure [lo, hi] of the time of impact is then found by exact comparisons of the algebraic
number with candidate doubles. No floating-point arithmetic decides anything.

usage: tools/data/rigid_hand_cases.py [--out DIR] [--check-only] [--samples N] [--only ID...]
       tools/data/rigid_hand_cases.py --self-test   (every check must reject a wrong hand TOI)
"""
import argparse
import functools
import math
import sys
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import sympy as sp

T = sp.Symbol("t")
ROOT = Path(__file__).resolve().parents[2]

# ------------------------------------------------------------------------------------------
# Exact doubles and their literals


def as_fraction(x):
    """An int, Fraction or literal string (decimal or C99 hex) as an exact Fraction."""
    if isinstance(x, str):
        value = Fraction(float.fromhex(x)) if "0x" in x.lower() else Fraction(x)
    else:
        value = Fraction(x)
    assert is_double(value), f"{x} is not exactly a double"
    return value


def is_double(value):
    """True iff the rational is exactly a finite double."""
    try:
        return Fraction(float(value)) == value
    except OverflowError:
        return False


def literal(value):
    """A short literal that strtod reads back as exactly this double."""
    assert is_double(value)
    if value.denominator == 1 and abs(value) < 2**53:
        return str(value.numerator)
    text = repr(float(value))
    if len(text) <= 12 and Fraction(text) == value:
        return text
    mantissa, exponent = float(value).hex().split("p")
    return mantissa.rstrip("0").rstrip(".") + "p" + exponent


def read_literal(text):
    """strtod's reading of a literal (round to nearest), exactly."""
    text = text.strip()
    return Fraction(float.fromhex(text)) if "0x" in text.lower() else Fraction(float(text))


def g17(x):
    return format(x, ".17g")


# ------------------------------------------------------------------------------------------
# Real algebraic numbers: a squarefree polynomial with exactly one root in [a, b]


def fpoly(p):
    """Coefficients (highest first) as Fractions, for fast exact evaluation."""
    return [Fraction(int(c.p), int(c.q)) for c in p.all_coeffs()]


def horner(coeffs, x):
    acc = Fraction(0)
    for c in coeffs:
        acc = acc * x + c
    return acc


def sgn(x):
    return (x > 0) - (x < 0)


def qq(x):
    return sp.Rational(x.numerator, x.denominator)


class Alg:
    """A real algebraic number: rational `value`, or the unique root of the squarefree
    polynomial `f` in the open interval (a, b), f(a) and f(b) nonzero of opposite signs."""

    def __init__(self, f=None, a=None, b=None, value=None):
        self.value = value
        if value is not None:
            return
        self.f, self.a, self.b = f, Fraction(a), Fraction(b)
        self.fc = fpoly(f)
        if f.degree() == 1:
            c1, c0 = self.fc
            self.value = -c0 / c1
            return
        if self.a == self.b:
            assert horner(self.fc, self.a) == 0
            self.value = self.a
            return
        assert sgn(horner(self.fc, self.a)) * sgn(horner(self.fc, self.b)) < 0
        assert f.count_roots(qq(self.a), qq(self.b)) == 1

    @staticmethod
    def rational(x):
        return Alg(value=Fraction(x))

    def is_rational(self):
        return self.value is not None

    def bisect(self):
        m = (self.a + self.b) / 2
        fm = horner(self.fc, m)
        if fm == 0:
            self.value = m
        elif sgn(fm) == sgn(horner(self.fc, self.a)):
            self.a = m
        else:
            self.b = m

    def cmp_rational(self, x):
        """sign(self - x), exactly."""
        x = Fraction(x)
        if not self.is_rational() and self.a < x < self.b and horner(self.fc, x) == 0:
            self.value = x  # the one root of f in (a, b) is x
        while not self.is_rational() and self.a <= x <= self.b:
            self.bisect()
        if self.is_rational():
            return sgn(self.value - x)
        return 1 if x < self.a else -1

    def sign_of(self, g):
        """sign(g(self)) for a Poly g, exactly."""
        if g.is_zero:
            return 0
        if self.is_rational():
            return sgn(horner(fpoly(g), self.value))
        common = sp.gcd(self.f, g)
        if common.degree() >= 1 and common.count_roots(qq(self.a), qq(self.b)) > 0:
            return 0  # the only root of f in (a, b) is a root of g
        while g.count_roots(qq(self.a), qq(self.b)) > 0:
            self.bisect()
            if self.is_rational():
                return sgn(horner(fpoly(g), self.value))
        return sgn(horner(fpoly(g), self.a))

    def __repr__(self):
        if self.is_rational():
            return f"Alg({self.value})"
        return f"Alg(root of {self.f.as_expr()} in ({self.a}, {self.b}))"


def alg_cmp(x, y):
    """sign(x - y) for two Alg, exactly."""
    if x.is_rational() and y.is_rational():
        return sgn(x.value - y.value)
    if x.is_rational():
        return -y.cmp_rational(x.value)
    if y.is_rational():
        return x.cmp_rational(y.value)
    common = sp.gcd(x.f, y.f)
    if common.degree() >= 1 and x.sign_of(common) == 0 and y.sign_of(common) == 0:
        # x is a root of y.f; y is the only root of y.f in (y.a, y.b): equal iff x lies there
        if not x.is_rational() and not y.is_rational():
            if x.cmp_rational(y.a) > 0 and x.cmp_rational(y.b) < 0:
                return 0
    while True:
        for z in (x, y):
            if z.is_rational():
                return alg_cmp(x, y)
        if x.b < y.a:
            return -1
        if y.b < x.a:
            return 1
        x.bisect()
        y.bisect()


def real_roots_in(p, lo, hi):
    """The real roots of the Poly p in [lo, hi] as Alg (p not identically zero)."""
    out = []
    for f, _ in p.factor_list()[1]:  # irreducible factors: no rational root of degree >= 2
        if f.degree() == 1:
            c1, c0 = fpoly(f)
            roots = [Alg.rational(-c0 / c1)]
        else:
            roots = [Alg(f, Fraction(int(a.p), int(a.q)), Fraction(int(b.p), int(b.q)))
                     for (a, b), _ in f.intervals(inf=qq(lo), sup=qq(hi))]
        out += [x for x in roots if x.cmp_rational(lo) >= 0 and x.cmp_rational(hi) <= 0]
    return out


def double_enclosure(x):
    """The tightest double interval [lo, hi] around the Alg x (lo == hi iff x is a double)."""
    if x.is_rational():
        approx = float(x.value)
    else:
        while x.b - x.a > abs(x.a) * Fraction(1, 2**80) + Fraction(1, 2**1100):
            x.bisect()
            if x.is_rational():
                break
        approx = float(x.value if x.is_rational() else (x.a + x.b) / 2)
    c = x.cmp_rational(Fraction(approx))
    if c == 0:
        return approx, approx
    lo, hi = (approx, math.nextafter(approx, math.inf)) if c > 0 else (
        math.nextafter(approx, -math.inf), approx)
    assert x.cmp_rational(Fraction(lo)) > 0 and x.cmp_rational(Fraction(hi)) < 0
    return lo, hi


# ------------------------------------------------------------------------------------------
# Hand-derived times of impact


@dataclass
class Surd:
    """p + q*sqrt(r), r > 0 not a square of a rational, q != 0."""
    p: Fraction
    q: Fraction
    r: Fraction
    text: str

    def alg(self):
        p, q, r = Fraction(self.p), Fraction(self.q), Fraction(self.r)
        f = sp.Poly(T**2 - 2 * qq(p) * T + qq(p * p - q * q * r), T, domain="QQ")
        assert len(sp.factor_list(f)[1]) == 1 and f.degree() == 2, "not irreducible"
        ends = sorted([p, p + q * (r + 1)])  # sqrt(r) < r + 1; the conjugate is on p's other side
        return Alg(f, ends[0], ends[1])


@dataclass
class RootIn:
    """The unique root of `poly` (a sympy expression in t) in [lo, hi], and its smallest
    root in [0, hi] (the derivations claim the earliest root)."""
    poly: object
    lo: Fraction
    hi: Fraction
    text: str

    def alg(self):
        f = sp.Poly(self.poly, T, domain="QQ").sqf_part()
        assert f.count_roots(qq(self.lo), qq(self.hi)) == 1
        assert f.count_roots(0, qq(self.lo)) == 0
        return Alg(f, self.lo, self.hi)


def hand_alg(toi):
    if toi is None:
        return None
    if isinstance(toi, (Surd, RootIn)):
        return toi.alg()
    return Alg.rational(Fraction(toi))


def toi_text(toi):
    if toi is None:
        return "none"
    if isinstance(toi, (Surd, RootIn)):
        return toi.text
    return str(Fraction(toi))


# ------------------------------------------------------------------------------------------
# Motion: positions as rational functions of t with denominator |qA|^i |qB|^j


class Sc:
    """A scalar num(t) / (DA(t)^e[0] * DB(t)^e[1]); DA, DB > 0 on [0, 1]."""

    def __init__(self, ctx, num, e):
        self.ctx, self.num, self.e = ctx, num, e

    def _lift(self, e):
        da, db = self.ctx
        return self.num * da ** (e[0] - self.e[0]) * db ** (e[1] - self.e[1])

    def __add__(self, o):
        e = (max(self.e[0], o.e[0]), max(self.e[1], o.e[1]))
        return Sc(self.ctx, self._lift(e) + o._lift(e), e)

    def __neg__(self):
        return Sc(self.ctx, -self.num, self.e)

    def __sub__(self, o):
        return self + (-o)

    def __mul__(self, o):
        if not isinstance(o, Sc):
            return Sc(self.ctx, self.num * qq(Fraction(o)), self.e)
        return Sc(self.ctx, self.num * o.num, (self.e[0] + o.e[0], self.e[1] + o.e[1]))


def vsub(u, v):
    return [a - b for a, b in zip(u, v)]


def vdot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def vcross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def quat_matrix(q):
    """M(q) of the issue (entries: any ring elements)."""
    w, x, y, z = q
    return [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]


def lerp_poly(v0, v1):
    return [sp.Poly((1 - T) * qq(a) + T * qq(b), T, domain="QQ") for a, b in zip(v0, v1)]


@dataclass
class Pose:
    c0: tuple
    q0: tuple
    c1: tuple
    q1: tuple

    def values(self):
        return list(self.c0) + list(self.q0) + list(self.c1) + list(self.q1)


def world_point(ctx, pose, which, p):
    """X(t) = c(t) + M(q(t)) p / |q(t)|^2 as three Sc (which = 0 for body A, 1 for B)."""
    c = lerp_poly(pose.c0, pose.c1)
    q = lerp_poly(pose.q0, pose.q1)
    m = quat_matrix(q)
    d = ctx[which]
    e = (1, 0) if which == 0 else (0, 1)
    return [Sc(ctx, c[i] * d + sum((m[i][j] * qq(p[j]) for j in range(3)),
                                   sp.Poly(0, T, domain="QQ")), e) for i in range(3)]


def quat_norm2(pose):
    q = lerp_poly(pose.q0, pose.q1)
    return sum((x * x for x in q), sp.Poly(0, T, domain="QQ"))


# ------------------------------------------------------------------------------------------
# The generic exact solver


@dataclass
class Feature:
    name: str
    nonneg: list  # Sc that must be >= 0
    nonzero: list = field(default_factory=list)  # Sc that must be != 0


def point_features(ctx, name, x, pts, dd):
    """Features of the distance from the point x to the hull of pts (1, 2 or 3 points of one
    body, given as body coordinates `pts[i][0]` and world curves `pts[i][1]`)."""
    feats = []
    for i, (_, v) in enumerate(pts):
        w = vsub(x, v)
        feats.append(Feature(f"{name}-v{i}", [Sc(ctx, dd(), (0, 0)) - vdot(w, w)]))
    for i in range(len(pts)):
        for j in range(i + 1, len(pts)):
            (bu, u), (bv, v) = pts[i], pts[j]
            if bu == bv:
                continue  # a zero-length edge is its vertex
            e, w = vsub(v, u), vsub(x, u)
            we, ee, wxe = vdot(w, e), vdot(e, e), vcross(w, e)
            feats.append(Feature(f"{name}-e{i}{j}", [
                we, ee - we, ee * dd_sc(ctx, dd) - vdot(wxe, wxe)]))
    if len(pts) == 3:
        (ba, a), (bb, b), (bc, c) = pts
        body_n = vcross(vsub(list(bb), list(ba)), vsub(list(bc), list(ba)))
        if any(k != 0 for k in body_n):
            n = vcross(vsub(b, a), vsub(c, a))
            w = vsub(x, a)
            wn = vdot(w, n)
            feats.append(Feature(f"{name}-face", [
                vdot(vcross(vsub(b, a), vsub(x, a)), n),
                vdot(vcross(vsub(c, b), vsub(x, b)), n),
                vdot(vcross(vsub(a, c), vsub(x, c)), n),
                vdot(n, n) * dd_sc(ctx, dd) - wn * wn]))
    return feats


def dd_sc(ctx, dd):
    return Sc(ctx, dd(), (0, 0))


def query_features(q):
    ctx = (quat_norm2(q.A), quat_norm2(q.B))
    d2 = qq(q.d * q.d)

    def dd():
        return sp.Poly(d2, T, domain="QQ")

    A = lambda p: (tuple(p), world_point(ctx, q.A, 0, p))
    B = lambda p: (tuple(p), world_point(ctx, q.B, 1, p))
    pts = q.points
    if q.kind == "vf":
        return point_features(ctx, "p", A(pts[0])[1], [B(pts[1]), B(pts[2]), B(pts[3])], dd)
    a0, a1, b0, b1 = A(pts[0]), A(pts[1]), B(pts[2]), B(pts[3])
    feats = []
    for k, x in enumerate((a0, a1)):
        feats += point_features(ctx, f"a{k}", x[1], [b0, b1], dd)
    for k, x in enumerate((b0, b1)):
        feats += point_features(ctx, f"b{k}", x[1], [a0, a1], dd)
    if a0[0] != a1[0] and b0[0] != b1[0]:
        ea, eb = vsub(a1[1], a0[1]), vsub(b1[1], b0[1])
        n = vcross(ea, eb)
        w = vsub(b0[1], a0[1])
        nn = vdot(n, n)
        s = vdot(vcross(w, eb), n)  # s * |n|^2: parameter on A of the closest points
        u = vdot(vcross(w, ea), n)  # u * |n|^2: parameter on B
        wn = vdot(w, n)
        feats.append(Feature("interiors", [s, nn - s, u, nn - u, nn * dd_sc(ctx, dd) - wn * wn],
                             [nn]))
    return feats


def feature_earliest(feat, tmax):
    polys = [c.num for c in feat.nonneg]
    zeros = [c.num for c in feat.nonzero]
    candidates = [Alg.rational(0)]
    for p in polys:
        if not p.is_zero:
            candidates += [r for r in real_roots_in(p, Fraction(0), tmax)]
    candidates.sort(key=functools.cmp_to_key(alg_cmp))
    for x in candidates:
        if all(x.sign_of(p) >= 0 for p in polys) and all(x.sign_of(z) != 0 for z in zeros):
            return x
    return None


def earliest_contact(q):
    """(TOI as Alg or None, name of the feature that attains it)."""
    for pose in (q.A, q.B):
        assert quat_norm2(pose).count_roots(0, 1) == 0, "q(t) vanishes in [0, 1]"
    best, best_name = None, None
    for feat in query_features(q):
        x = feature_earliest(feat, q.tmax)
        if x is not None and (best is None or alg_cmp(x, best) < 0):
            best, best_name = x, feat.name
    return best, best_name


# ------------------------------------------------------------------------------------------
# The independent exact distance at a rational time (sampling check)


def pose_at(pose, t):
    c = [(1 - t) * a + t * b for a, b in zip(pose.c0, pose.c1)]
    q = [(1 - t) * a + t * b for a, b in zip(pose.q0, pose.q1)]
    n2 = sum(x * x for x in q)
    m = quat_matrix(q)
    return lambda p: [c[i] + sum(m[i][j] * p[j] for j in range(3)) / n2 for i in range(3)]


def point_segment_d2(x, a, b):
    e, w = vsub(b, a), vsub(x, a)
    ee = vdot(e, e)
    s = Fraction(0) if ee == 0 else min(max(vdot(w, e) / ee, Fraction(0)), Fraction(1))
    r = [w[i] - s * e[i] for i in range(3)]
    return vdot(r, r)


def point_triangle_d2(x, a, b, c):
    e1, e2, w = vsub(b, a), vsub(c, a), vsub(x, a)
    g11, g12, g22 = vdot(e1, e1), vdot(e1, e2), vdot(e2, e2)
    det = g11 * g22 - g12 * g12
    best = min(point_segment_d2(x, a, b), point_segment_d2(x, b, c), point_segment_d2(x, c, a))
    if det != 0:
        r1, r2 = vdot(w, e1), vdot(w, e2)
        s = (r1 * g22 - r2 * g12) / det
        u = (g11 * r2 - g12 * r1) / det
        if s >= 0 and u >= 0 and s + u <= 1:
            res = [w[i] - s * e1[i] - u * e2[i] for i in range(3)]
            best = min(best, vdot(res, res))
    return best


def segment_segment_d2(p0, p1, q0, q1):
    best = min(point_segment_d2(p0, q0, q1), point_segment_d2(p1, q0, q1),
               point_segment_d2(q0, p0, p1), point_segment_d2(q1, p0, p1))
    u, v, w = vsub(p1, p0), vsub(q1, q0), vsub(q0, p0)
    uu, uv, vv, wu, wv = vdot(u, u), vdot(u, v), vdot(v, v), vdot(w, u), vdot(w, v)
    det = uv * uv - uu * vv  # of [[uu, -uv], [uv, -vv]]
    if det != 0:
        s = (wu * (-vv) - (-uv) * wv) / det
        r = (uu * wv - uv * wu) / det
        if 0 <= s <= 1 and 0 <= r <= 1:
            res = [p0[i] + s * u[i] - q0[i] - r * v[i] for i in range(3)]
            best = min(best, vdot(res, res))
    return best


def distance2_at(q, t):
    t = Fraction(t)
    xa, xb = pose_at(q.A, t), pose_at(q.B, t)
    p = q.points
    if q.kind == "vf":
        return point_triangle_d2(xa(p[0]), xb(p[1]), xb(p[2]), xb(p[3]))
    return segment_segment_d2(xa(p[0]), xa(p[1]), xb(p[2]), xb(p[3]))


def sample_times(upper, n, include_upper):
    ts = {upper * k / n for k in range(n + (1 if include_upper else 0))}
    if not include_upper:
        ts |= {upper - upper / 2**k for k in range(1, 60)}
    return sorted(ts)


# ------------------------------------------------------------------------------------------
# Cases


@dataclass
class Query:
    cid: str
    kind: str
    d: Fraction
    tmax: Fraction
    A: Pose
    B: Pose
    points: list
    toi: object  # None (no collision), a rational, Surd or RootIn
    cond: object  # the condition polynomial of the derivation (sympy expression), or None
    tests: str
    facts: list = field(default_factory=list)  # (rational function of t, lo, hi): lo < f(TOI) < hi

    def truth(self):
        return 0 if self.toi is None else 1


def vec(*xs):
    return tuple(as_fraction(x) for x in xs)


I = (1, 0, 0, 0)
O = (0, 0, 0)


def pose(c0=O, q0=I, c1=None, q1=None):
    c1 = c0 if c1 is None else c1
    q1 = q0 if q1 is None else q1
    return Pose(vec(*c0), vec(*q0), vec(*c1), vec(*q1))


STATIC = pose()
RZ = pose(q1=(1, 0, 0, 1))  # quarter turn about z through the origin: q(t) = (1, 0, 0, t)
PREV_HALF = "0x1.fffffffffffffp-2"  # the double just below 1/2
GAP = Fraction(1, 2**40)

CASES = []


def case(cid, kind, A, B, points, toi, cond, tests, d=0, tmax=1, facts=()):
    pts = [vec(*p) for p in points]
    assert len(pts) == 4
    CASES.append(Query(cid, kind, as_fraction(d), as_fraction(tmax), A, B, pts, toi,
                       None if cond is None else sp.sympify(cond), tests,
                       [(sp.sympify(f), Fraction(lo), Fraction(hi)) for f, lo, hi in facts]))


R2 = Surd(-1, 1, 2, "sqrt(2) - 1")
t = T

# ---- vertex-face, d = 0 -------------------------------------------------------------------
TRI_XZ = [(0, 0, 0), (2, 0, 0), (0, 0, 1)]  # in B's plane y = 0; a at the rotation axis
case("vf01", "vf", STATIC, RZ, [(1, 1, "0.25")] + TRI_XZ, R2, t**2 + 2 * t - 1,
     "triangle turns a quarter turn about the z axis through its vertex a; face meets p at "
     "angle pi/4 (irrational TOI)")
case("vf02", "vf", STATIC, RZ, [(1, "0.75", "0.25")] + TRI_XZ, Fraction(1, 3),
     3 * t**2 + 8 * t - 3, "as vf01, contact at t = 1/3 (rational, not a double)")
case("vf03", "vf", STATIC, RZ, [(0, 1, "0.25")] + TRI_XZ, 1, 1 - t**2,
     "as vf01, contact exactly at the end of the quarter turn, t = 1")
P_HALF = [("0.75", 1, "0.25")] + TRI_XZ
case("vf04", "vf", STATIC, RZ, P_HALF, Fraction(1, 2), 2 * t**2 + 3 * t - 2,
     "as vf01, contact at t = 1/2 = tmax", tmax="0.5")
case("vf05", "vf", STATIC, RZ, P_HALF, None, 2 * t**2 + 3 * t - 2,
     "as vf04 with tmax the double just below 1/2: no collision", tmax=PREV_HALF)
case("vf06", "vf", STATIC, pose(q0=(2, 0, 0, 0), q1=(2, 0, 0, 2)), P_HALF, Fraction(1, 2),
     2 * t**2 + 3 * t - 2, "vf04 with both quaternions scaled by 2: same path, same TOI 1/2")
case("vf07", "vf", STATIC, pose(q0=(2, 0, 0, 0), q1=(3, 0, 0, 3)), P_HALF, Fraction(2, 5),
     5 * t - 2, "vf04 with q0 = (2,0,0,0), q1 = (3,0,0,3): same end poses, same answer, "
     "time reparametrised: TOI 2/5")
case("vf08", "vf", pose(c0=(-1, 0, 0), q0=(1, 1, 1, 1), c1=(1, 0, 0)),
     pose(q0=(2, 2, 2, 2)), [(0, 0, "0.25"), (-1, -1, 0), (1, -1, 0), (0, 1, 0)],
     Fraction(3, 8), 8 * t - 3,
     "both bodies under the same constant rotation (120 deg about (1,1,1), B's quaternion "
     "scaled by 2), A translating: a linear query in B's frame")
case("vf09", "vf", STATIC, RZ, [("0.75", 1, 0)] + TRI_XZ, Fraction(1, 2), 2 * t**2 + 3 * t - 2,
     "triangle turning about an axis through its vertex a: its edge ab sweeps exactly "
     "through p (contact on the edge)")
TRI_X = lambda h: [(h, -1, -1), (h, 1, -1), (h, 0, 1)]  # in B's plane x = h
case("vf10", "vf", STATIC, RZ, [("0.75", 1, 0)] + TRI_X("1.25"), Fraction(1, 2),
     (2 * t - 1)**2, "face turning onto a vertex tangentially: double root, touch without "
     "crossing at t = 1/2")
case("vf11", "vf", STATIC, RZ, [("0.75", 1, 0)] + TRI_X(Fraction(5, 4) + GAP), None,
     None, "vf10 with the face moved out by 2^-40: just missing")
case("vf12", "vf", STATIC, RZ, [("0.75", 1, 0)] + TRI_X(Fraction(5, 4) + GAP), Fraction(1, 2),
     (2 * t - 1)**2, "vf11 with d = 2^-40: just touching (distance exactly d at t = 1/2 only)",
     d=GAP)
case("vf13", "vf", STATIC, RZ, [("0.75", 1, 0)] + TRI_X(Fraction(5, 4) + 2 * GAP), None, None,
     "vf10 with the face out by 2^-39 and d = 2^-40: just missing", d=GAP)
case("vf14", "vf", RZ, STATIC, [(1, 0, 0), (0, 0, -1), (2, 0, -1), (1, 0, 1)], 0, t,
     "contact exactly at t = 0: p on the face at the start, then turning away")
CUBIC_VF = 4 * t**3 + t**2 - 4 * t + 1
TRI_Z = lambda h: [(-1, -1, h), (1, -1, h), (0, 2, h)]  # in the plane z = h
case("vf15", "vf", pose(q1=(1, 1, 0, 0), c1=(0, 0, -1)), STATIC, [(0, 1, 0)] + TRI_Z("0.25"),
     RootIn(CUBIC_VF, Fraction(1, 4), Fraction(1, 2),
            "the root of 4t^3 + t^2 - 4t + 1 in (1/4, 1/2)"), CUBIC_VF,
     "rotation about x together with translation along -z: cubic TOI (three real roots)")
case("vf16", "vf", pose(q1=(1, 1, 0, 0), c1=(0, 0, -1)), STATIC, [(0, 1, 0)] + TRI_Z("0.25"),
     None, CUBIC_VF, "vf15 with tmax = 1/4: no collision", tmax="0.25")
case("vf17", "vf", RZ, pose(q1=(2, 0, 0, 1)),
     [(1, 0, 0), (0, 0, -1), (0, 0, 1), (3, "0.875", 0)], Fraction(1, 2),
     6 * t**2 - t - 1, "both bodies rotating about z at different rates (B: q0 = (1,0,0,0), "
     "q1 = (2,0,0,1)); relative half-angle tangent t^2/(1+t+t^2) reaches 1/7 at t = 1/2")
case("vf18", "vf", RZ, STATIC, [("0.75", -1, 0), (0, 0, 0), (2, 0, 0), ("0.5", 0, 0)],
     Fraction(1, 2), 2 * t**2 + 3 * t - 2,
     "degenerate triangle (collinear vertices, hull the segment [0, 2] of the x axis); the "
     "rotating vertex reaches it at t = 1/2")
TRI_DIAG = lambda lo, hi, mid: [(lo, lo, -1), (hi, hi, -1), (mid, mid, 1)]
case("vf19", "vf", RZ, STATIC, [(1, 0, 0)] + TRI_DIAG("0.625", "0.875", "0.75"), R2,
     t**2 + 2 * t - 1, "rotating path hits a small triangle on the arc (at angle pi/4) that "
     "the straight path between the end positions misses (vf20)")
case("vf20", "vf", pose(c1=(-1, 1, 0)), STATIC, [(1, 0, 0)] + TRI_DIAG("0.625", "0.875", "0.75"),
     None, 2 * t - 1, "vf19's end positions joined by a straight line (constant rotation): miss")
case("vf21", "vf", RZ, STATIC, [(1, 0, 0)] + TRI_DIAG("0.375", "0.625", "0.5"), None,
     t**2 + 2 * t - 1, "converse: a triangle on the chord; the rotating path misses it")
case("vf22", "vf", pose(c1=(-1, 1, 0)), STATIC, [(1, 0, 0)] + TRI_DIAG("0.375", "0.625", "0.5"),
     Fraction(1, 2), 2 * t - 1, "vf21's straight path hits at t = 1/2")

# ---- vertex-face, d > 0 -------------------------------------------------------------------
TRI_Y = lambda h: [(-1, h, -1), (2, h, -1), ("0.5", h, 1)]  # in the plane y = h
case("vf23", "vf", RZ, STATIC, [("1.25", 0, 0)] + TRI_Y("1.25"), Fraction(1, 2),
     2 * t**2 - 5 * t + 2, "vertex-plane distance reaches d = 1/4 at t = 1/2 (face interior)",
     d="0.25")
case("vf24", "vf", RZ, STATIC, [(1, 0, 0)] + TRI_Y("0.75"), Surd(2, -1, 3, "2 - sqrt(3)"),
     t**2 - 4 * t + 1, "vertex-plane distance reaches d = 1/4 at angle pi/6: TOI 2 - sqrt(3)",
     d="0.25")
case("vf25", "vf", RZ, STATIC, [("1.25", 0, 0), ("0.75", "1.25", 0), ("0.75", 2, -1),
                               ("0.75", 2, 1)], Fraction(1, 2), 2 * t**2 - 5 * t + 2,
     "d = 1/4 reached at a vertex of the triangle (vertex-vertex distance)", d="0.25")
case("vf26", "vf", RZ, STATIC, [("1.25", 0, 0), (0, 0, 0), (0, 2, 0), (-1, 1, 0)],
     Surd(0, Fraction(1, 3), 6, "sqrt(6)/3"), 3 * t**2 - 2,
     "coplanar from the start (plane distance 0 <= d all along) but the projection is outside: "
     "d = 1/4 reached at the edge x = 0 when 5/4 cos(theta) = 1/4", d="0.25")
case("vf27", "vf", pose(c0=(0, "1.125", 0), q1=(1, 0, 0, 1)), STATIC,
     [(1, 0, 0)] + TRI_Y("1.25"), 0, None,
     "vertex-plane distance 1/8 < d = 1/4 already at t = 0: TOI 0", d="0.25")
case("vf28", "vf", RZ, STATIC, [("1.25", 0, 0)] + TRI_Y("1.25"), Fraction(1, 2),
     2 * t**2 - 5 * t + 2, "vf23 with tmax = 1/2: contact at tmax", d="0.25", tmax="0.5")
case("vf29", "vf", RZ, STATIC, [("1.25", 0, 0)] + TRI_Y("1.25"), None,
     2 * t**2 - 5 * t + 2, "vf23 with tmax just below 1/2: no collision", d="0.25",
     tmax=PREV_HALF)

# ---- vertex-face, general motion: both bodies translating and rotating about other axes ----
GEN_VF_A = pose(q1=(1, "0.5", 0, 0), c1=("0.25", 0, 0))
GEN_VF_B = pose(c0=(0, 0, "0.75"), q1=(1, 0, "0.5", 0), c1=(0, 0, "0.25"))
GEN_VF_PTS = [("0.5", 1, 0), (-4, -4, 0), (8, -4, 0), (-4, 8, 0)]
GEN_VF_YX = -(t**5 + 10 * t**4 - 12 * t**3 + 96 * t**2 - 64 * t - 32) / (4 * (t**2 + 4)**2)
GEN_VF_YY = (4 - t**2) / (4 + t**2)
QUARTIC_VF = 2 * t**4 - 11 * t**3 + 30 * t**2 - 76 * t + 24
case("vf30", "vf", GEN_VF_A, GEN_VF_B, GEN_VF_PTS,
     RootIn(QUARTIC_VF, Fraction(1, 4), Fraction(3, 8),
            "the root of 2t^4 - 11t^3 + 30t^2 - 76t + 24 in (1/4, 3/8)"),
     (t + 2) * QUARTIC_VF, "both bodies translating and rotating (A about x, B about y): the "
     "coplanarity numerator has degree 5, (t + 2) times an irreducible quartic",
     facts=[(GEN_VF_YX, "0.5", "0.75"), (GEN_VF_YY, "0.75", 1)])
QUINTIC_VF = t**5 - 4 * t**4 + 4 * t**3 - 12 * t**2 - 64 * t + 16
case("vf31", "vf", GEN_VF_A, GEN_VF_B, GEN_VF_PTS,
     RootIn(QUINTIC_VF, Fraction(7, 32), Fraction(1, 4),
            "the root of t^5 - 4t^4 + 4t^3 - 12t^2 - 64t + 16 in (7/32, 1/4)"),
     QUINTIC_VF, "vf30 at d = 1/4: the plane distance reaches d at the root of a quintic",
     d="0.25", facts=[(GEN_VF_YX, "0.5", "0.75"), (GEN_VF_YY, "0.75", 1)])

# ---- edge-edge, d = 0 ---------------------------------------------------------------------
SPOKE = [(0, 0, 0), (2, 0, 0)]  # A's edge from the rotation axis along x
case("ee01", "ee", RZ, STATIC, SPOKE + [(1, 1, -1), (1, 1, 1)], R2, t**2 + 2 * t - 1,
     "quarter turn of an edge about the z axis through its endpoint; meets a vertical edge at "
     "angle pi/4")
case("ee02", "ee", RZ, STATIC, SPOKE + [(1, "0.75", -1), (1, "0.75", 1)], Fraction(1, 3),
     3 * t**2 + 8 * t - 3, "as ee01, TOI 1/3 (rational, not a double)")
case("ee03", "ee", RZ, STATIC, SPOKE + [("0.75", 1, 0), ("0.75", 1, 1)], Fraction(1, 2),
     2 * t**2 + 3 * t - 2, "edges crossing at an endpoint: A's interior meets B's endpoint b0")
case("ee04", "ee", RZ, STATIC, [(0, 0, 0), ("1.25", 0, 0), ("0.75", 1, 0), ("0.75", 1, 1)],
     Fraction(1, 2), 2 * t**2 + 3 * t - 2, "endpoint meets endpoint: a1 = b0 at t = 1/2")
case("ee05", "ee", STATIC, RZ, [("0.75", 1, 0), ("0.75", 1, 0)] + SPOKE, Fraction(1, 2),
     2 * t**2 + 3 * t - 2, "zero-length edge (a point) swept exactly by B's turning edge")
VERT = lambda r, z0, z1: [(r, 0, z0), (r, 0, z1)]  # vertical edge at (r, 0) in A's frame
case("ee06", "ee", RZ, STATIC, VERT("1.25", -1, 1) + [("0.75", 1, "0.5"), ("0.75", 1, 2)],
     Fraction(1, 2), (2 * t - 1)**2, "parallel edges for all t (both along z); at t = 1/2 "
     "collinear and overlapping")
case("ee07", "ee", RZ, STATIC, VERT("1.25", -1, 1) + [("0.75", 1, "1.25"), ("0.75", 1, 2)],
     None, (2 * t - 1)**2, "ee06 with B's edge lifted: collinear at t = 1/2 with a gap of 1/4 "
     "along the line: no collision at d = 0")
case("ee08", "ee", RZ, STATIC, [(1, 0, 0), (2, 0, 0), ("0.75", 1, 0), ("1.5", 2, 0)],
     Fraction(1, 2), 2 * t**2 + 3 * t - 2, "collinear under rotation: two radial edges in one "
     "plane, overlapping when A's edge turns onto B's line")
TANGENT = [("1.75", "0.25", 0), ("-0.25", "1.75", 0)]  # tangent to the circle r = 5/4 at angle a
case("ee09", "ee", RZ, STATIC, VERT("1.25", -1, 1) + TANGENT, Fraction(1, 2), (2 * t - 1)**2,
     "A's vertical edge circles at radius 5/4 and touches B's edge on the tangent line "
     "tangentially (double root)")
SHIFT = (3 * Fraction(1, 2**42), 4 * Fraction(1, 2**42))
case("ee10", "ee", RZ, STATIC, VERT("1.25", -1, 1) + [
    (Fraction(7, 4) + SHIFT[0], Fraction(1, 4) + SHIFT[1], 0),
    (Fraction(-1, 4) + SHIFT[0], Fraction(7, 4) + SHIFT[1], 0)], None, None,
    "ee09 with B's edge moved out by 5*2^-42 along the normal: just missing")
case("ee11", "ee", RZ, STATIC, SPOKE + [(1, 0, -1), (1, 0, 1)], 0, t,
     "contact exactly at t = 0, then turning away")
case("ee12", "ee", RZ, STATIC, SPOKE + [(0, "1.25", -1), (0, "1.25", 1)], 1, 1 - t**2,
     "contact exactly at t = 1 (end of the quarter turn)")
case("ee13", "ee", RZ, STATIC, SPOKE + [("0.75", 1, 0), ("0.75", 1, 1)], Fraction(1, 2),
     2 * t**2 + 3 * t - 2, "ee03 with tmax = 1/2: contact at tmax", tmax="0.5")
case("ee14", "ee", RZ, STATIC, SPOKE + [("0.75", 1, 0), ("0.75", 1, 1)], None,
     2 * t**2 + 3 * t - 2, "ee03 with tmax just below 1/2: no collision", tmax=PREV_HALF)
RX_EDGE = [(0, 0, 0), (0, 2, 0), (-1, "0.75", 1), (1, "0.75", 1)]
case("ee15", "ee", pose(q1=(1, 1, 0, 0)), STATIC, RX_EDGE, Fraction(1, 2), 2 * t**2 + 3 * t - 2,
     "edge turning about x (q from (1,0,0,0) to (1,1,0,0)) meets an edge parallel to x")
case("ee16", "ee", pose(q0=(2, 0, 0, 0), q1=(2, 2, 0, 0)), STATIC, RX_EDGE, Fraction(1, 2),
     2 * t**2 + 3 * t - 2, "ee15 with both quaternions scaled by 2: the same path, TOI 1/2")
case("ee17", "ee", pose(q0=(2, 0, 0, 0), q1=(3, 3, 0, 0)), STATIC, RX_EDGE, Fraction(2, 5),
     5 * t - 2, "ee15 with q0 = (2,0,0,0), q1 = (3,3,0,0): same end poses and answer, TOI 2/5")
case("ee18", "ee", pose(c0=(-1, 0, 0), q0=(1, 1, 1, 1), c1=(1, 0, 0)), pose(q0=(3, 3, 3, 3)),
     [(-1, 0, 0), (1, 0, 0), (0, -1, "0.25"), (0, 1, "0.25")], Fraction(5, 8), 8 * t - 5,
     "both bodies under the same constant rotation: the linear query in B's frame")
case("ee19", "ee", RZ, pose(q1=(1, 1, 0, 0)), VERT(1, -1, 1) + [(-1, "0.5", 0), (1, "0.5", 0)],
     Surd(-2, 1, 5, "sqrt(5) - 2"), t**2 + 4 * t - 1,
     "both bodies rotating, about different axes (A about z, B about x, the same angle)")
case("ee20", "ee", RZ, STATIC, VERT(1, -1, 1) + [("0.625", "0.625", 0), ("0.875", "0.875", 0)],
     R2, t**2 + 2 * t - 1, "rotating edge hits a short edge on the arc that the straight path "
     "misses (ee21)")
case("ee21", "ee", pose(c1=(-1, 1, 0)), STATIC,
     VERT(1, -1, 1) + [("0.625", "0.625", 0), ("0.875", "0.875", 0)], None, 2 * t - 1,
     "ee20's end positions joined by a straight line: miss")
case("ee22", "ee", RZ, STATIC, VERT(1, -1, 1) + [("0.375", "0.375", 0), ("0.625", "0.625", 0)],
     None, t**2 + 2 * t - 1, "converse: an edge on the chord; the rotating edge misses it")
case("ee23", "ee", pose(c1=(-1, 1, 0)), STATIC,
     VERT(1, -1, 1) + [("0.375", "0.375", 0), ("0.625", "0.625", 0)], Fraction(1, 2), 2 * t - 1,
     "ee22's straight path hits at t = 1/2")

# ---- edge-edge, d > 0 ---------------------------------------------------------------------
B_ALONG_X = [(-2, "1.25", 0), (2, "1.25", 0)]
case("ee24", "ee", RZ, STATIC, VERT("1.25", -1, 1) + B_ALONG_X, Fraction(1, 2),
     2 * t**2 - 5 * t + 2, "edge-edge (line-line) distance reaches d = 1/4 at t = 1/2 "
     "(interiors)", d="0.25")
CUBIC_EE = t**3 - 4 * t**2 + 11 * t - 4
case("ee25", "ee", pose(q1=(1, 0, 0, 1), c1=(0, "0.25", 0)), STATIC,
     VERT("1.25", -1, 1) + B_ALONG_X,
     RootIn(CUBIC_EE, Fraction(1, 4), Fraction(1, 2),
            "the real root of t^3 - 4t^2 + 11t - 4 (in (1/4, 1/2))"), CUBIC_EE,
     "rotation and translation together; edge-edge distance d = 1/4: cubic TOI", d="0.25")
case("ee26", "ee", pose(q1=(1, 0, 0, 1), c1=(0, "0.25", 0)), STATIC,
     VERT("1.25", -1, 1) + B_ALONG_X, None, CUBIC_EE, "ee25 with tmax = 1/4: no collision",
     d="0.25", tmax="0.25")
case("ee27", "ee", RZ, STATIC, [(0, 0, 0), ("1.25", 0, 0), ("0.75", "1.25", 0), ("0.75", 2, 0)],
     Fraction(1, 2), 2 * t**2 - 5 * t + 2, "endpoint-endpoint distance a1-b0 reaches d = 1/4",
     d="0.25")
case("ee28", "ee", RZ, STATIC, VERT("1.25", -1, 1) + [("0.75", 1, "1.25"), ("0.75", 1, 2)],
     Fraction(1, 2), (2 * t - 1)**2, "ee07 (parallel, collinear at t = 1/2 with a gap 1/4) at "
     "d = 1/4: touches exactly, endpoint-endpoint", d="0.25")
case("ee29", "ee", RZ, STATIC, VERT("1.25", "0.1875", 1) + B_ALONG_X, Fraction(1, 2),
     2 * t**2 - 5 * t + 2, "the lines come within d = 5/16 before the segments do (A's closest "
     "point clamped to its endpoint z = 3/16)", d="0.3125")
case("ee30", "ee", RZ, STATIC, [(0, 0, 0), ("1.25", 0, 0), ("0.75", "1.25", 0), ("0.75", 2, 0)],
     Fraction(1, 2), 2 * t**2 - 5 * t + 2, "ee27 with tmax = 1/2: contact at tmax", d="0.25",
     tmax="0.5")

# ---- edge-edge, general motion: both bodies translating and rotating about other axes ----
GEN_EE_A = pose(c1=(0, "0.25", 0), q1=(1, 0, 0, 1))
GEN_EE_B = pose(c0=(1, 1, 0), c1=(1, "0.25", "0.25"), q1=(1, "0.25", 0, 0))
GEN_EE_PTS = [(0, 0, 0), (2, 0, 0), (0, 0, -1), (0, 0, 1)]
GEN_EE_S = -(t**2 + 1) * (3 * t**6 + 2 * t**5 - 33 * t**4 + 736 * t**2 - 512 * t - 256) / (
    2 * (t**4 + t**2 + 16) * (t**4 + 33 * t**2 + 16))
GEN_EE_U = (t**9 - 28 * t**8 + 34 * t**7 - 248 * t**6 + 193 * t**5 + 2212 * t**4 - 1504 * t**3
            + 640 * t**2 + 256 * t + 1024) / (8 * (t**4 + t**2 + 16) * (t**4 + 33 * t**2 + 16))
QUINTIC_EE = t**5 + t**4 - 19 * t**3 + 15 * t**2 + 48 * t - 16
case("ee31", "ee", GEN_EE_A, GEN_EE_B, GEN_EE_PTS,
     RootIn(QUINTIC_EE, Fraction(5, 16), Fraction(21, 64),
            "the root of t^5 + t^4 - 19t^3 + 15t^2 + 48t - 16 in (5/16, 21/64)"), QUINTIC_EE,
     "both bodies translating and rotating (A about z, B about x): the coplanarity numerator "
     "(degree 9) is |qA|^2 |qB|^2 times an irreducible quintic",
     facts=[(GEN_EE_S, "0.5", "0.75"), (GEN_EE_U, "0.25", "0.5")])
DECIC_EE = (4 * QUINTIC_EE)**2 - Fraction(1, 16) * (
    16 * (t**2 + 1)**2 * (t**2 + 16)**2 - 4096 * t**4)
case("ee32", "ee", GEN_EE_A, GEN_EE_B, GEN_EE_PTS,
     RootIn(DECIC_EE, Fraction(7, 32), Fraction(15, 64),
            "the smallest root in [0, 1] of the degree-10 polynomial (4Q)^2 - (1/16)(16 (t^2+1)^2 "
            "(t^2+16)^2 - 4096 t^4), Q = t^5 + t^4 - 19t^3 + 15t^2 + 48t - 16, in (7/32, 15/64)"),
     DECIC_EE, "ee31 at d = 1/4: the line-line distance reaches d at a root of a degree-10 "
     "polynomial", d="0.25", facts=[(GEN_EE_S, "0.5", "0.75"), (GEN_EE_U, "0.25", "0.5")])

# ------------------------------------------------------------------------------------------
# Checking and writing


def check_case(q, samples, use_solver=True):
    hand = hand_alg(q.toi)
    if hand is not None:
        assert hand.cmp_rational(0) >= 0 and hand.cmp_rational(q.tmax) <= 0
        if q.cond is not None:
            cond = sp.Poly(q.cond, T, domain="QQ")
            assert hand.sign_of(cond) == 0, f"{q.cid}: hand TOI is not a root of its condition"
        for f, lo, hi in q.facts:
            num, den = (sp.Poly(x, T, domain="QQ") for x in sp.fraction(sp.together(f)))
            sd = hand.sign_of(den)
            assert sd != 0
            assert hand.sign_of(num - den * qq(lo)) == sd and hand.sign_of(den * qq(hi) - num) == sd, (
                f"{q.cid}: {f} not in ({lo}, {hi}) at the TOI")
    solved, feature = earliest_contact(q) if use_solver else (hand, "not run")
    if hand is None or solved is None:
        assert hand is None and solved is None, f"{q.cid}: hand {hand} vs solver {solved}"
    else:
        assert alg_cmp(hand, solved) == 0, f"{q.cid}: hand {hand} vs solver {solved}"
    d2 = q.d * q.d
    if hand is None:
        times = sample_times(q.tmax, samples, include_upper=True)
    else:
        lo, hi = double_enclosure(hand)
        upper = Fraction(lo)
        times = [] if upper == 0 and lo == hi else sample_times(upper, samples, lo != hi)
        if hand.is_rational():
            assert distance2_at(q, hand.value) <= d2, f"{q.cid}: no contact at the TOI"
    for s in times:
        assert distance2_at(q, s) > d2, f"{q.cid}: contact at sampled t = {s} before the TOI"
    return hand, feature, len(times)


def check_edge_edge_degree(q):
    """The issue's fact, on this query: det[X_b0 - X_a0, R_A e_A, R_B e_B] times
    |qA|^4 |qB|^4 is a polynomial of degree <= 9 divisible by |qA|^2 |qB|^2."""
    qa, qb = lerp_poly(q.A.q0, q.A.q1), lerp_poly(q.B.q0, q.B.q1)
    ca, cb = lerp_poly(q.A.c0, q.A.c1), lerp_poly(q.B.c0, q.B.c1)
    da, db = quat_norm2(q.A), quat_norm2(q.B)
    ma, mb = quat_matrix(qa), quat_matrix(qb)
    a0, a1, b0, b1 = q.points
    mul = lambda m, v: [sum((m[i][j] * qq(v[j]) for j in range(3)), sp.Poly(0, T, domain="QQ"))
                        for i in range(3)]
    w = [(cb[i] - ca[i]) * da * db + mul(mb, b0)[i] * da - mul(ma, a0)[i] * db for i in range(3)]
    ea, eb = mul(ma, vsub(a1, a0)), mul(mb, vsub(b1, b0))
    raw = vdot(w, vcross(ea, eb))
    assert raw.is_zero or raw.degree() <= 9
    quo, rem = raw.div(da * db)
    assert rem.is_zero and (quo.is_zero or quo.degree() <= 5), q.cid


def group_name(q):
    return f"hand-{q.kind}-d{literal(q.d)}-tmax{literal(q.tmax)}"


def csv_line(q):
    values = q.A.values() + q.B.values() + [x for p in q.points for x in p]
    assert len(values) == 40
    return ",".join(literal(v) for v in values) + f",{q.truth()}"


def expected_line(q, hand):
    if hand is None:
        return "0"
    lo, hi = double_enclosure(hand)
    return f"1 {g17(lo)} {g17(hi)}"


def reread(line, q):
    """The line read back as strtod would: every field must be exactly the intended value."""
    fields = line.split(",")
    assert len(fields) == 41
    values = [read_literal(f) for f in fields[:40]]
    assert values == q.A.values() + q.B.values() + [x for p in q.points for x in p]
    assert int(fields[40]) == q.truth()


def self_test(args):
    """Each case with a wrong hand answer or TOI must be rejected by the checks."""
    import copy
    for q in CASES:
        if args.only and q.cid not in args.only:
            continue
        wrong = copy.copy(q)
        if q.toi is None:
            wrong.toi = q.tmax / 2
        elif isinstance(q.toi, (Surd, RootIn)):
            wrong.toi = Fraction(double_enclosure(hand_alg(q.toi))[0])
        else:
            r = Fraction(q.toi)
            wrong.toi = (r + q.tmax) / 2 if r < q.tmax else r / 2
        wrong.cond = None
        try:
            check_case(wrong, args.samples)
        except AssertionError as e:
            print(f"{q.cid}: wrong TOI {toi_text(wrong.toi)} rejected ({e})", flush=True)
            continue
        raise SystemExit(f"{q.cid}: a wrong TOI {toi_text(wrong.toi)} passed the checks")
    # The sampling alone (solver not run) against a later wrong TOI: it can only see contacts
    # that last over an interval of t, so it is reported, not required, case by case.
    caught = []
    for q in CASES:
        if q.toi is None or (args.only and q.cid not in args.only):
            continue
        hi = Fraction(double_enclosure(hand_alg(q.toi))[1])
        if hi >= q.tmax:
            continue
        wrong = copy.copy(q)
        wrong.toi, wrong.cond, wrong.facts = (hi + q.tmax) / 2, None, []
        try:
            check_case(wrong, args.samples, use_solver=False)
        except AssertionError:
            caught.append(q.cid)
    print(f"the distance check alone (solver not run) rejects a later wrong TOI in "
          f"{len(caught)} cases: {' '.join(caught)}")
    print("self-test passed")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(ROOT / "tests" / "data" / "rigid"))
    ap.add_argument("--check-only", action="store_true")
    ap.add_argument("--samples", type=int, default=200)
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--self-test", action="store_true",
                    help="check that every case's checks fail on a wrong hand value")
    args = ap.parse_args()
    if args.self_test:
        return self_test(args)
    ids = [q.cid for q in CASES]
    assert len(ids) == len(set(ids))
    groups = {}
    for q in CASES:
        if args.only and q.cid not in args.only:
            continue
        hand, feature, n = check_case(q, args.samples)
        if q.kind == "ee":
            check_edge_edge_degree(q)
        line = csv_line(q)
        reread(line, q)
        exp = expected_line(q, hand)
        print(f"{q.cid} {q.kind} d={literal(q.d)} tmax={literal(q.tmax)} toi={toi_text(q.toi)} "
              f"-> {exp}  [solver feature {feature}; {n} samples]", flush=True)
        groups.setdefault(group_name(q), []).append((q, line, exp))
    if args.check_only or args.only:
        return  # files are written only from the whole case list
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name, rows in sorted(groups.items()):
        with open(out / f"{name}.csv", "w") as f:
            f.write(f"# {name}: hand-derived rigid {rows[0][0].kind} queries, "
                    f"d = {literal(rows[0][0].d)}, tmax = {literal(rows[0][0].tmax)}; written by "
                    "tools/data/rigid_hand_cases.py, derivations in docs/rigid-hand-derived.md\n")
            for q, line, _ in rows:
                f.write(f"# {q.cid}: {q.tests}\n{line}\n")
        with open(out / f"{name}.expected", "w") as f:
            for _, _, exp in rows:
                f.write(exp + "\n")
    print(f"{sum(len(r) for r in groups.values())} cases in {len(groups)} files under {out}")


if __name__ == "__main__":
    sys.exit(main())
