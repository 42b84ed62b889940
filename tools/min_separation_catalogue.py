#!/usr/bin/env python3
"""The hand-derived minimum-separation catalogue (tests/separation/test_min_separation_catalogue.cpp).

Every case's answer and TOI is derived by hand (the `why` line); this script only
  1. checks each derivation with exact rational arithmetic (fractions) and an independent
     closed-primitive distance: dist^2(TOI) = d^2, dist^2 > d^2 on a dense sample of [0, TOI)
     (for a miss: of [0, tmax]), and for an irrational TOI dist^2(lo) > d^2 >= dist^2(hi);
  2. turns each exact TOI into the tightest double interval: a double t gives [t, t], otherwise
     lo < t < hi = nextafter(lo, +inf), checked by exact comparisons (squaring for sqrt's);
  3. writes the C++ case tables (--cpp FILE: between its BEGIN/END CASE TABLES markers) and
     the markdown table (--md FILE).
It never calls the library.  Usage: python3 tools/min_separation_catalogue.py [--cpp F] [--md F]
"""
import argparse
import math
import sys
from decimal import Decimal, getcontext
from fractions import Fraction as F

getcontext().prec = 80

SUB = F(1, 2**1074)           # the smallest subnormal, 2^-1074
BELOW_QUARTER = F(math.nextafter(0.25, 0))
BELOW_5_16 = F(math.nextafter(0.3125, 0))
BELOW_3_8 = F(math.nextafter(0.375, 0))
BELOW_HALF = F(math.nextafter(0.5, 0))
BIG = F(1e300)                # the double nearest 10^300 (exactly)


# ---- exact closed-primitive distances (squared) --------------------------------------------
def sub(u, v): return tuple(a - b for a, b in zip(u, v))
def add(u, v): return tuple(a + b for a, b in zip(u, v))
def mul(s, u): return tuple(s * a for a in u)
def dot(u, v): return sum(a * b for a, b in zip(u, v))
def cross(u, v): return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def pt_seg2(p, a, b):
    ab = sub(b, a)
    L = dot(ab, ab)
    if L == 0:
        return dot(sub(p, a), sub(p, a))
    s = min(F(1), max(F(0), dot(sub(p, a), ab) / L))
    r = sub(p, add(a, mul(s, ab)))
    return dot(r, r)


def pt_tri2(p, a, b, c):
    n = cross(sub(b, a), sub(c, a))
    nn = dot(n, n)
    if nn != 0:
        h = dot(sub(p, a), n)
        q = sub(p, mul(h / nn, n))  # projection onto the plane
        s1 = dot(cross(sub(b, a), sub(q, a)), n)
        s2 = dot(cross(sub(c, b), sub(q, b)), n)
        s3 = dot(cross(sub(a, c), sub(q, c)), n)
        if s1 >= 0 and s2 >= 0 and s3 >= 0:
            return h * h / nn
    # outside the face, or a degenerate triangle (its hull is covered by its three edges)
    return min(pt_seg2(p, a, b), pt_seg2(p, b, c), pt_seg2(p, c, a))


def seg_seg2(a0, a1, b0, b1):
    best = min(pt_seg2(a0, b0, b1), pt_seg2(a1, b0, b1), pt_seg2(b0, a0, a1), pt_seg2(b1, a0, a1))
    u, v, w = sub(a1, a0), sub(b1, b0), sub(a0, b0)
    uu, uv, vv, uw, vw = dot(u, u), dot(u, v), dot(v, v), dot(u, w), dot(v, w)
    den = uu * vv - uv * uv
    if den != 0:  # interior critical point of |a0 + s u - b0 - r v|^2
        s = (uv * vw - vv * uw) / den
        r = (uu * vw - uv * uw) / den
        if 0 <= s <= 1 and 0 <= r <= 1:
            x = sub(add(a0, mul(s, u)), add(b0, mul(r, v)))
            best = min(best, dot(x, x))
    return best


KINDS = {  # kind: (C++ query type, points per time, dimension, distance^2 of the points at t)
    'vf': ('VertexFaceQuery', 4, 3, lambda P: pt_tri2(*P)),
    'ee': ('EdgeEdgeQuery', 4, 3, lambda P: seg_seg2(*P)),
    'pe': ('PointEdgeQuery', 3, 3, lambda P: pt_seg2(*P)),
    'pp': ('PointPointQuery', 2, 3, lambda P: dot(sub(P[0], P[1]), sub(P[0], P[1]))),
    'ee2': ('EdgeEdge2dQuery', 4, 2, lambda P: seg_seg2(*P)),
    'pe2': ('PointEdge2dQuery', 3, 2, lambda P: pt_seg2(*P)),
    'pp2': ('PointPoint2dQuery', 2, 2, lambda P: dot(sub(P[0], P[1]), sub(P[0], P[1]))),
}


# ---- the cases -------------------------------------------------------------------------------
def P(*xs):
    return tuple(F(x) for x in xs)


class Case:
    def __init__(self, kind, name, t0, t1, d, tmax=1, toi=None, irr=None, why='', dname=None,
                 tname=None):
        """toi: exact Fraction TOI (None and irr None: a miss); irr: (Decimal value, exact
        predicate 'x < TOI' on a Fraction x) for an irrational TOI."""
        self.kind, self.name, self.t0, self.t1 = kind, name, t0, t1
        self.d, self.tmax, self.toi, self.irr, self.why = F(d), F(tmax), toi, irr, why
        self.dname, self.tname = dname, tname

    def points(self, t):
        return [add(a, mul(t, sub(b, a))) for a, b in zip(self.t0, self.t1)]

    def f(self, t):  # dist^2 - d^2 at time t
        pts = self.points(t)
        if KINDS[self.kind][2] == 2:
            pts = [p + (F(0),) for p in pts]
        return KINDS[self.kind][3](pts) - self.d * self.d


def irr_one_minus(c, k):
    """TOI = 1 - c/sqrt(k) (c, k > 0 rational): x < TOI iff (1 - x)^2 k > c^2 (1 - x > 0)."""
    val = 1 - Decimal(c.numerator) / Decimal(c.denominator) / Decimal(k).sqrt()
    return (val, lambda x: (1 - x) > 0 and (1 - x) ** 2 * k > c * c)


cases = []


def case(*a, **k):
    cases.append(Case(*a, **k))


Q = F(1, 4)
# ---------------------------------------------------------------- vertex-face
T = [P(0, 0, 0), P(4, 0, 0), P(0, 4, 0)]  # static triangle in z = 0, face over x, y >= 0, x + y <= 4
case('vf', 'vf_face_descent', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, Q, toi=F(3, 8),
     why='height 1-2t over the interior point (1,1); 1-2t = 1/4 at t = 3/8')
case('vf', 'vf_face_descent_d0', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, 0, toi=F(1, 2),
     why='height 1-2t reaches 0 at t = 1/2')
case('vf', 'vf_face_descent_third_d0', [P(1, 1, 1)] + T, [P(1, 1, -2)] + T, 0, toi=F(1, 3),
     why='height 1-3t = 0 at t = 1/3, not a double')
case('vf', 'vf_face_parallel_pass_exact_d', [P(-2, 1, Q)] + T, [P(2, 1, Q)] + T, Q, toi=F(1, 2),
     why='x = -2+4t at height 1/4: dist = sqrt(x^2+1/16) for x < 0, 1/4 once x >= 0 (t = 1/2)')
case('vf', 'vf_face_parallel_pass_below_d', [P(-2, 1, Q)] + T, [P(2, 1, Q)] + T, BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('vf', 'vf_edge_interior', [P(2, F(-3, 4), 1)] + T, [P(2, 0, 0)] + T, F(5, 16), toi=F(3, 4),
     why='p - (2,0,0) = (1-t)(0,-3/4,1) outside the face: dist 5(1-t)/4 = 5/16 at t = 3/4')
case('vf', 'vf_edge_tangent', [P(2, -Q, 1)] + T, [P(2, -Q, -1)] + T, Q, toi=F(1, 2),
     why='nearest point (2,0,0) on edge: dist sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2 (double root)')
case('vf', 'vf_edge_tangent_below_d', [P(2, -Q, 1)] + T, [P(2, -Q, -1)] + T, BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('vf', 'vf_edge_irrational', [P(2, -1, 1)] + T, [P(2, 0, 0)] + T, F(1, 2),
     irr=irr_one_minus(F(1, 2), 2), why='dist to edge sqrt(2)(1-t) = 1/2 at t = 1 - sqrt(2)/4')
case('vf', 'vf_vertex_tangent', [P(F(-3, 16), -Q, 1)] + T, [P(F(-3, 16), -Q, -1)] + T, F(5, 16),
     toi=F(1, 2), why='nearest point the vertex (0,0,0): dist sqrt(25/256+(1-2t)^2), minimum 5/16 at t = 1/2')
case('vf', 'vf_vertex_tangent_below_d', [P(F(-3, 16), -Q, 1)] + T, [P(F(-3, 16), -Q, -1)] + T,
     BELOW_5_16, dname='nextafter(0.3125, 0)', why='minimum distance 5/16 > d')
case('vf', 'vf_vertex_13_16', [P(F(-3, 16), -Q, 1)] + T, [P(F(-3, 16), -Q, -1)] + T, F(13, 16),
     toi=F(1, 8), why='25/256 + (1-2t)^2 = 169/256: 1-2t = 3/4, t = 1/8')
case('vf', 'vf_vertex_irrational', [P(-1, -1, 0)] + T, [P(0, 0, 0)] + T, 1,
     irr=irr_one_minus(F(1), 2), why='dist to vertex sqrt(2)(1-t) = 1 at t = 1 - 1/sqrt(2)')
T1 = [P(0, 0, 1), P(4, 0, 1), P(0, 4, 1)]
case('vf', 'vf_rising_triangle', [P(1, 1, 1)] + T, [P(1, 1, 1)] + T1, Q, toi=F(3, 4),
     why='static point at height 1, face rises to z = t: gap 1-t = 1/4 at t = 3/4')
case('vf', 'vf_both_moving', [P(1, 1, 2)] + T, [P(1, 1, 0)] + T1, F(1, 2), toi=F(1, 2),
     why='point z = 2-2t, face z = t: gap 2-3t = 1/2 at t = 1/2')
case('vf', 'vf_tilting_triangle_d0', [P(1, 1, F(1, 2)), P(0, 0, 0), P(4, 0, 0), P(0, 4, 4)],
     [P(1, 1, F(1, 2)), P(0, 0, 0), P(4, 0, 0), P(0, 4, -4)], 0, toi=F(1, 4),
     why='c_z = 4-8t, plane z = c_z y/4 is 1-2t over (1,1) (inside), = 1/2 at t = 1/4')
TC = [P(0, 0, 0), P(2, 0, 0), P(4, 0, 0)]  # collinear: hull is the segment [0,4] x {0} x {0}
case('vf', 'vf_collinear_triangle', [P(2, F(3, 4), 1)] + TC, [P(2, F(-3, 4), -1)] + TC, F(5, 16),
     toi=F(3, 8), why='collinear triangle = segment; p - (2,0,0) = (1-2t)(0,3/4,1): 5|1-2t|/4 = 5/16 at 3/8')
case('vf', 'vf_collinear_triangle_tangent_below_d', [P(2, Q, 1)] + TC, [P(2, Q, -1)] + TC,
     BELOW_QUARTER, dname='nextafter(0.25, 0)',
     why='dist to the segment sqrt(1/16+(1-2t)^2) >= 1/4 > d (crosses the plane, never the hull)')
TP = [P(1, 1, 1)] * 3  # all three vertices coincident
case('vf', 'vf_point_triangle', [P(4, 5, 1)] + TP, [P(1, 1, 1)] + TP, F(5, 4), toi=F(3, 4),
     why='triangle = point (1,1,1); p - it = (1-t)(3,4,0): 5(1-t) = 5/4 at t = 3/4')
case('vf', 'vf_point_triangle_pass_miss', [P(0, F(5, 4), F(19, 16))] + TP, [P(2, F(5, 4), F(19, 16))] + TP,
     Q, why='dist sqrt((2t-1)^2 + 1/16 + 9/256) >= 5/16 > 1/4')
case('vf', 'vf_initially_within', [P(1, 1, Q)] + T, [P(1, 1, 2)] + T, F(1, 2), toi=F(0),
     why='initial height 1/4 <= 1/2')
case('vf', 'vf_initially_exactly_d', [P(1, 1, Q)] + T, [P(1, 1, 2)] + T, Q, toi=F(0),
     why='initial height 1/4 = d')
case('vf', 'vf_after_tmax', [P(2, F(-3, 4), 1)] + T, [P(2, 0, 0)] + T, F(5, 16), tmax=F(1, 2),
     why='vf_edge_interior reaches d at 3/4 > tmax')
case('vf', 'vf_at_tmax_edge', [P(2, F(-3, 4), 1)] + T, [P(2, 0, 0)] + T, F(5, 16), tmax=F(3, 4),
     toi=F(3, 4), why='vf_edge_interior reaches d exactly at tmax = 3/4')
case('vf', 'vf_at_tmax_face', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, Q, tmax=F(3, 8), toi=F(3, 8),
     why='vf_face_descent reaches d exactly at tmax = 3/8')
case('vf', 'vf_just_before_tmax', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, Q, tmax=BELOW_3_8,
     tname='nextafter(0.375, 0)', why='vf_face_descent reaches d at 3/8 > tmax')
case('vf', 'vf_huge_d', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, BIG, toi=F(0),
     dname='1e300', why='initial distance 1 <= d')
case('vf', 'vf_subnormal_descent', [P(1, 1, 2 * SUB)] + T, [P(1, 1, -2 * SUB)] + T, SUB, toi=F(1, 4),
     dname='2^-1074', why='height 2^-1073 (1-2t) = 2^-1074 at t = 1/4')
case('vf', 'vf_subnormal_parallel_pass', [P(-2, 1, SUB)] + T, [P(2, 1, SUB)] + T, SUB, toi=F(1, 2),
     dname='2^-1074', why='height 2^-1074, enters over the face (x = -2+4t = 0) at t = 1/2')
case('vf', 'vf_subnormal_parallel_pass_d0', [P(-2, 1, SUB)] + T, [P(2, 1, SUB)] + T, 0,
     why='minimum distance 2^-1074 > 0')
case('vf', 'vf_subnormal_d_ordinary_descent', [P(1, 1, 1)] + T, [P(1, 1, -1)] + T, SUB,
     toi=F(1, 2) - SUB / 2, dname='2^-1074',
     why='1-2t = 2^-1074 at t = 1/2 - 2^-1075: in (pred(1/2), 1/2)')

# ---------------------------------------------------------------- edge-edge
A = [P(-1, 0, 0), P(1, 0, 0)]  # edge a on the x axis, static
case('ee', 'ee_interior_descent', A + [P(0, -1, 1), P(0, 1, 1)], A + [P(0, -1, -1), P(0, 1, -1)], Q,
     toi=F(3, 8), why='crossed edges, b at height 1-2t, closest points interior: 1-2t = 1/4')
case('ee', 'ee_interior_descent_d0', A + [P(0, -1, 1), P(0, 1, 1)], A + [P(0, -1, -1), P(0, 1, -1)], 0,
     toi=F(1, 2), why='1-2t = 0')
case('ee', 'ee_crossed_slide_exact_d', A + [P(-3, -1, Q), P(-3, 1, Q)], A + [P(3, -1, Q), P(3, 1, Q)], Q,
     toi=F(1, 3), why='b at height 1/4, x = -3+6t: dist sqrt((x+1)^2+1/16) for x < -1; = 1/4 at x = -1, t = 1/3')
case('ee', 'ee_crossed_slide_below_d', A + [P(-3, -1, Q), P(-3, 1, Q)], A + [P(3, -1, Q), P(3, 1, Q)],
     BELOW_QUARTER, dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('ee', 'ee_endpoint_tangent', A + [P(F(5, 4), -1, 1), P(F(5, 4), 1, 1)],
     A + [P(F(5, 4), -1, -1), P(F(5, 4), 1, -1)], Q, toi=F(1, 2),
     why='a1 = (1,0,0) to b: sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2 (double root)')
case('ee', 'ee_endpoint_tangent_below_d', A + [P(F(5, 4), -1, 1), P(F(5, 4), 1, 1)],
     A + [P(F(5, 4), -1, -1), P(F(5, 4), 1, -1)], BELOW_QUARTER, dname='nextafter(0.25, 0)',
     why='minimum distance 1/4 > d')
case('ee', 'ee_endpoint_5_16', A + [P(F(5, 4), -1, 1), P(F(5, 4), 1, 1)],
     A + [P(F(5, 4), -1, -1), P(F(5, 4), 1, -1)], F(5, 16), toi=F(13, 32),
     why='1/16 + (1-2t)^2 = 25/256: 1-2t = 3/16, t = 13/32')
A2 = [P(0, 0, 0), P(2, 0, 0)]
case('ee', 'ee_parallel_slide_exact_d', A2 + [P(4, 0, Q), P(6, 0, Q)], A2 + [P(0, 0, Q), P(2, 0, Q)], Q,
     toi=F(1, 2), why='parallel at height 1/4, b0 x = 4-4t: overlap (and dist 1/4) from x = 2, t = 1/2')
case('ee', 'ee_parallel_slide_below_d', A2 + [P(4, 0, Q), P(6, 0, Q)], A2 + [P(0, 0, Q), P(2, 0, Q)],
     BELOW_QUARTER, dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('ee', 'ee_parallel_static_exact_d', A2 + [P(1, Q, 0), P(3, Q, 0)], A2 + [P(1, Q, 0), P(3, Q, 0)], Q,
     toi=F(0), why='static overlapping parallel edges 1/4 apart')
case('ee', 'ee_parallel_static_below_d', A2 + [P(1, Q, 0), P(3, Q, 0)], A2 + [P(1, Q, 0), P(3, Q, 0)],
     BELOW_QUARTER, dname='nextafter(0.25, 0)', why='constant distance 1/4 > d')
case('ee', 'ee_collinear_approach_d0', A2 + [P(4, 0, 0), P(6, 0, 0)], A2 + [P(1, 0, 0), P(3, 0, 0)], 0,
     toi=F(2, 3), why='collinear, b0 x = 4-3t meets a1 x = 2 at t = 2/3')
case('ee', 'ee_irrational_endpoint', A + [P(0, 1, 1), P(0, 3, 1)], A + [P(0, 0, 0), P(0, 2, 0)], F(1, 2),
     irr=irr_one_minus(F(1, 2), 2), why='b = (0, u..u+2, u), u = 1-t: dist sqrt(2) u = 1/2 at t = 1 - sqrt(2)/4')
Z = [P(0, 0, 0), P(0, 0, 0)]
case('ee', 'ee_zero_length_a', Z + [P(-1, F(3, 4), 1), P(1, F(3, 4), 1)],
     Z + [P(-1, F(-3, 4), -1), P(1, F(-3, 4), -1)], F(5, 16), toi=F(3, 8),
     why='a = origin; b through (0, 3(1-2t)/4, 1-2t): 5|1-2t|/4 = 5/16 at 3/8')
case('ee', 'ee_both_zero_length', Z + [P(3, 4, 0), P(3, 4, 0)], Z + [P(0, 0, 0), P(0, 0, 0)], F(5, 4),
     toi=F(3, 4), why='two points: 5(1-t) = 5/4 at 3/4')
case('ee', 'ee_initially_within', A + [P(0, -1, Q), P(0, 1, Q)], A + [P(0, -1, 2), P(0, 1, 2)], Q,
     toi=F(0), why='initial distance 1/4 = d')
case('ee', 'ee_after_tmax', A + [P(0, -1, 1), P(0, 1, 1)], A + [P(0, -1, -1), P(0, 1, -1)], Q,
     tmax=Q, why='ee_interior_descent reaches d at 3/8 > 1/4')
case('ee', 'ee_at_tmax', A + [P(0, -1, 1), P(0, 1, 1)], A + [P(0, -1, -1), P(0, 1, -1)], Q,
     tmax=F(3, 8), toi=F(3, 8), why='ee_interior_descent reaches d exactly at tmax')
case('ee', 'ee_huge_d', A + [P(0, -1, 1), P(0, 1, 1)], A + [P(0, -1, -1), P(0, 1, -1)], BIG,
     toi=F(0), dname='1e300', why='initial distance 1 <= d')
case('ee', 'ee_both_moving', [P(-1, 0, -1), P(1, 0, -1), P(0, -1, 1), P(0, 1, 1)],
     [P(-1, 0, 1), P(1, 0, 1), P(0, -1, -1), P(0, 1, -1)], F(1, 2), toi=F(3, 8),
     why='a at z = -1+2t, b at z = 1-2t, crossed: gap |2-4t| = 1/2 at 3/8')

# ---------------------------------------------------------------- point-edge (3D)
E = [P(-1, 0, 0), P(1, 0, 0)]
case('pe', 'pe_interior', [P(0, F(3, 4), 1)] + E, [P(0, F(-3, 4), -1)] + E, F(5, 16), toi=F(3, 8),
     why='p = (1-2t)(0,3/4,1) over the interior: 5|1-2t|/4 = 5/16 at 3/8')
case('pe', 'pe_interior_d0', [P(0, F(3, 4), 1)] + E, [P(0, F(-3, 4), -1)] + E, 0, toi=F(1, 2),
     why='passes through (0,0,0) at t = 1/2')
case('pe', 'pe_interior_third_d0', [P(0, 1, 0)] + E, [P(0, -2, 0)] + E, 0, toi=F(1, 3),
     why='y = 1-3t = 0 at t = 1/3, not a double')
case('pe', 'pe_interior_tangent', [P(0, Q, 1)] + E, [P(0, Q, -1)] + E, Q, toi=F(1, 2),
     why='sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2')
case('pe', 'pe_interior_tangent_below_d', [P(0, Q, 1)] + E, [P(0, Q, -1)] + E, BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('pe', 'pe_vertex_irrational', [P(2, 1, 0)] + E, [P(1, 0, 0)] + E, 1, irr=irr_one_minus(F(1), 2),
     why='nearest is the end (1,0,0): sqrt(2)(1-t) = 1 at t = 1 - 1/sqrt(2)')
case('pe', 'pe_vertex_tangent', [P(F(19, 16), Q, 1)] + E, [P(F(19, 16), Q, -1)] + E, F(5, 16), toi=F(1, 2),
     why='nearest is the end (1,0,0): sqrt(9/256+1/16+(1-2t)^2), minimum 5/16 at 1/2')
case('pe', 'pe_vertex_tangent_below_d', [P(F(19, 16), Q, 1)] + E, [P(F(19, 16), Q, -1)] + E, BELOW_5_16,
     dname='nextafter(0.3125, 0)', why='minimum distance 5/16 > d')
case('pe', 'pe_slide_along_line_d0', [P(3, 0, 0)] + E, [P(-1, 0, 0)] + E, 0, toi=F(1, 2),
     why='on the line, x = 3-4t reaches the end x = 1 at 1/2')
case('pe', 'pe_zero_length_edge', [P(4, 5, 1), P(1, 1, 1), P(1, 1, 1)], [P(1, 1, 1), P(1, 1, 1), P(1, 1, 1)],
     F(5, 4), toi=F(3, 4), why='edge = point (1,1,1): 5(1-t) = 5/4 at 3/4')
case('pe', 'pe_rotating_edge_d0', [P(0, 0, 1), P(-1, 0, 0), P(1, 0, 3)], [P(0, 0, 1), P(-1, 0, 0), P(1, 0, -1)],
     0, toi=F(1, 4), why='b_z = 3-4t, the edge crosses x = 0 at z = b_z/2 = 1 (the point) at t = 1/4')
case('pe', 'pe_same_motion_exact_d', [P(0, Q, 0)] + E, [P(1, F(9, 4), 3), P(0, 2, 3), P(2, 2, 3)], Q,
     toi=F(0), why='all translate by (1,2,3): constant distance 1/4 = d')
case('pe', 'pe_same_motion_below_d', [P(0, Q, 0)] + E, [P(1, F(9, 4), 3), P(0, 2, 3), P(2, 2, 3)],
     BELOW_QUARTER, dname='nextafter(0.25, 0)', why='constant distance 1/4 > d')
case('pe', 'pe_after_tmax', [P(0, F(3, 4), 1)] + E, [P(0, F(-3, 4), -1)] + E, F(5, 16), tmax=Q,
     why='pe_interior reaches d at 3/8 > 1/4')
case('pe', 'pe_at_tmax', [P(0, F(3, 4), 1)] + E, [P(0, F(-3, 4), -1)] + E, F(5, 16), tmax=F(3, 8),
     toi=F(3, 8), why='pe_interior reaches d exactly at tmax')
case('pe', 'pe_huge_d', [P(0, F(3, 4), 1)] + E, [P(0, F(-3, 4), -1)] + E, BIG, toi=F(0), dname='1e300',
     why='initial distance 5/4 <= d')

# ---------------------------------------------------------------- point-point (3D)
O = P(0, 0, 0)
case('pp', 'pp_approach', [P(3, 4, 0), O], [O, O], F(5, 4), toi=F(3, 4), why='5(1-t) = 5/4 at 3/4')
case('pp', 'pp_approach_d0', [P(3, 4, 0), O], [O, O], 0, toi=F(1), why='meet at t = 1')
case('pp', 'pp_approach_d0_tmax', [P(3, 4, 0), O], [O, O], 0, tmax=F(1, 2), why='meet at 1 > tmax')
case('pp', 'pp_pass_tangent', [P(-1, F(3, 16), Q), O], [P(1, F(3, 16), Q), O], F(5, 16), toi=F(1, 2),
     why='sqrt((2t-1)^2+25/256), minimum 5/16 at 1/2')
case('pp', 'pp_pass_tangent_below_d', [P(-1, F(3, 16), Q), O], [P(1, F(3, 16), Q), O], BELOW_5_16,
     dname='nextafter(0.3125, 0)', why='minimum distance 5/16 > d')
case('pp', 'pp_pass_13_16', [P(-1, F(3, 16), Q), O], [P(1, F(3, 16), Q), O], F(13, 16), toi=F(1, 8),
     why='(2t-1)^2 + 25/256 = 169/256: 2t-1 = -3/4, t = 1/8')
case('pp', 'pp_irrational', [P(1, 1, 1), O], [O, O], 1, irr=irr_one_minus(F(1), 3),
     why='sqrt(3)(1-t) = 1 at t = 1 - 1/sqrt(3)')
case('pp', 'pp_both_moving', [O, P(2, 0, 0)], [P(2, 0, 0), O], F(1, 2), toi=F(3, 8),
     why='x_p = 2t, x_q = 2-2t: |2-4t| = 1/2 at 3/8')
case('pp', 'pp_both_moving_d0', [O, P(2, 0, 0)], [P(2, 0, 0), O], 0, toi=F(1, 2), why='meet at 1/2')
case('pp', 'pp_same_motion_exact_d', [O, P(0, 0, Q)], [P(1, 1, 1), P(1, 1, F(5, 4))], Q, toi=F(0),
     why='zero relative motion, constant distance 1/4 = d')
case('pp', 'pp_same_motion_below_d', [O, P(0, 0, Q)], [P(1, 1, 1), P(1, 1, F(5, 4))], BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='constant distance 1/4 > d')
case('pp', 'pp_coincident_d0', [P(1, 2, 3), P(1, 2, 3)], [P(1, 2, 3), P(1, 2, 3)], 0, toi=F(0),
     why='coincident at t = 0')
case('pp', 'pp_subnormal', [P(4 * SUB, 0, 0), O], [P(-4 * SUB, 0, 0), O], SUB, toi=F(3, 8), dname='2^-1074',
     why='x = 2^-1072 (1-2t): |1-2t| = 1/4 at 3/8')
case('pp', 'pp_huge_coordinates', [P(BIG, 0, 0), P(-BIG, 0, 0)], [P(BIG, 0, 0), O], BIG, toi=F(1),
     dname='1e300', why='D = 1e300 (a double): dist D + D(1-t) = D(2-t) = D at t = 1 (squares overflow doubles)')
case('pp', 'pp_huge_coordinates_tmax', [P(BIG, 0, 0), P(-BIG, 0, 0)], [P(BIG, 0, 0), O], BIG, tmax=F(1, 2),
     dname='1e300', why='as above, D(2-t) > D on [0, 1/2]')
case('pp', 'pp_max_d', [P(BIG, 0, 0), P(-BIG, 0, 0)], [P(BIG, 0, 0), O], F(sys.float_info.max), toi=F(0),
     dname='DBL_MAX', why='initial distance 2e300 <= DBL_MAX')
case('pp', 'pp_tiny_tmax', [P(3, 4, 0), O], [O, O], F(5, 4), tmax=SUB, tname='2^-1074',
     why='pp_approach reaches d at 3/4 > tmax = 2^-1074')
case('pp', 'pp_tiny_tmax_initial', [P(1, 2, 3), P(1, 2, 3)], [P(4, 2, 3), P(1, 2, 3)], 0, tmax=SUB, toi=F(0),
     tname='2^-1074', why='coincident at t = 0 <= tmax = 2^-1074')

# ---------------------------------------------------------------- point-point (2D)
O2 = P(0, 0)
case('pp2', 'pp2_cross', [P(-1, 0), O2], [P(1, 0), O2], Q, toi=F(3, 8), why='|2t-1| = 1/4 at 3/8')
case('pp2', 'pp2_cross_d0', [P(-1, 0), O2], [P(1, 0), O2], 0, toi=F(1, 2), why='meet at 1/2')
case('pp2', 'pp2_pass_tangent', [P(-1, Q), O2], [P(1, Q), O2], Q, toi=F(1, 2),
     why='sqrt((2t-1)^2+1/16), minimum 1/4 at 1/2')
case('pp2', 'pp2_pass_tangent_below_d', [P(-1, Q), O2], [P(1, Q), O2], BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('pp2', 'pp2_pass_d0', [P(-1, Q), O2], [P(1, Q), O2], 0, why='minimum distance 1/4 > 0')
case('pp2', 'pp2_irrational', [P(1, 1), O2], [O2, O2], 1, irr=irr_one_minus(F(1), 2),
     why='sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)')
case('pp2', 'pp2_same_motion_exact_d', [O2, P(0, Q)], [P(3, 3), P(3, F(13, 4))], Q, toi=F(0),
     why='zero relative motion, distance 1/4 = d')
case('pp2', 'pp2_same_motion_below_d', [O2, P(0, Q)], [P(3, 3), P(3, F(13, 4))], F(1, 8),
     why='constant distance 1/4 > 1/8')
case('pp2', 'pp2_at_tmax', [P(-1, 0), O2], [P(1, 0), O2], Q, tmax=F(3, 8), toi=F(3, 8),
     why='pp2_cross reaches d exactly at tmax')
case('pp2', 'pp2_huge_d', [P(-1, 0), O2], [P(1, 0), O2], BIG, toi=F(0), dname='1e300',
     why='initial distance 1 <= d')

# ---------------------------------------------------------------- point-edge (2D)
E2 = [P(-1, 0), P(1, 0)]
case('pe2', 'pe2_interior', [P(0, 1)] + E2, [P(0, -1)] + E2, Q, toi=F(3, 8), why='|1-2t| = 1/4 at 3/8')
case('pe2', 'pe2_interior_d0', [P(0, 1)] + E2, [P(0, -1)] + E2, 0, toi=F(1, 2), why='crosses at 1/2')
case('pe2', 'pe2_vertex_irrational', [P(2, 1)] + E2, [P(1, 0)] + E2, 1, irr=irr_one_minus(F(1), 2),
     why='nearest is the end (1,0): sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)')
case('pe2', 'pe2_pass_beside_exact_d', [P(-3, Q)] + E2, [P(3, Q)] + E2, Q, toi=F(1, 3),
     why='at y = 1/4, x = -3+6t: sqrt((x+1)^2+1/16) for x < -1, 1/4 from x = -1 (t = 1/3)')
case('pe2', 'pe2_pass_beside_below_d', [P(-3, Q)] + E2, [P(3, Q)] + E2, BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('pe2', 'pe2_zero_length_edge', [P(3, 4), O2, O2], [O2, O2, O2], F(5, 4), toi=F(3, 4),
     why='edge = origin: 5(1-t) = 5/4 at 3/4')
case('pe2', 'pe2_slide_along_line_d0', [P(3, 0)] + E2, [P(-1, 0)] + E2, 0, toi=F(1, 2),
     why='x = 3-4t reaches the end x = 1 at 1/2')
case('pe2', 'pe2_rotating_edge_d0', [P(0, 1), P(-1, 0), P(1, 3)], [P(0, 1), P(-1, 0), P(1, -1)], 0,
     toi=F(1, 4), why='b_y = 3-4t: the edge crosses x = 0 at y = b_y/2 = 1 at t = 1/4')
case('pe2', 'pe2_after_tmax', [P(0, 1)] + E2, [P(0, -1)] + E2, Q, tmax=Q, why='reaches d at 3/8 > 1/4')
case('pe2', 'pe2_initially_within', [P(0, F(1, 2))] + E2, [P(0, 3)] + E2, F(1, 2), toi=F(0),
     why='initial distance 1/2 = d')
case('pe2', 'pe2_huge_d', [P(0, 1)] + E2, [P(0, -1)] + E2, BIG, toi=F(0), dname='1e300',
     why='initial distance 1 <= d')

# ---------------------------------------------------------------- edge-edge (2D)
A2D = [P(-1, 0), P(1, 0)]
case('ee2', 'ee2_crossing_at_t0', A2D + [P(0, -1), P(0, 1)], A2D + [P(0, -1), P(0, 1)], F(1, 2), toi=F(0),
     why='static crossing segments: distance 0 <= d')
case('ee2', 'ee2_crossing_at_t0_d0', A2D + [P(0, -1), P(0, 1)], A2D + [P(5, -1), P(5, 1)], 0, toi=F(0),
     why='crossing at t = 0')
case('ee2', 'ee2_endpoint_sweep_d0', A2D + [P(0, 1), P(0, 3)], A2D + [P(0, -1), P(0, 1)], 0, toi=F(1, 2),
     why='b0 = (0, 1-2t) reaches a at 1/2')
case('ee2', 'ee2_endpoint_sweep', A2D + [P(0, 1), P(0, 3)], A2D + [P(0, -1), P(0, 1)], Q, toi=F(3, 8),
     why='b0 = (0, 1-2t): 1-2t = 1/4 at 3/8')
case('ee2', 'ee2_endpoint_sweep_at_tmax', A2D + [P(0, 1), P(0, 3)], A2D + [P(0, -1), P(0, 1)], 0,
     tmax=F(1, 2), toi=F(1, 2), why='contact exactly at tmax = 1/2')
case('ee2', 'ee2_endpoint_sweep_before_tmax', A2D + [P(0, 1), P(0, 3)], A2D + [P(0, -1), P(0, 1)], 0,
     tmax=BELOW_HALF, tname='nextafter(0.5, 0)', why='contact at 1/2 > tmax')
A2B = [P(0, 0), P(2, 0)]
case('ee2', 'ee2_parallel_slide_exact_d', A2B + [P(4, Q), P(6, Q)], A2B + [P(0, Q), P(2, Q)], Q, toi=F(1, 2),
     why='parallel 1/4 apart, b0 x = 4-4t: overlap from x = 2, t = 1/2')
case('ee2', 'ee2_parallel_slide_below_d', A2B + [P(4, Q), P(6, Q)], A2B + [P(0, Q), P(2, Q)], BELOW_QUARTER,
     dname='nextafter(0.25, 0)', why='minimum distance 1/4 > d')
case('ee2', 'ee2_corner_irrational', [P(-1, 0), P(0, 0), P(1, 1), P(2, 1)],
     [P(-1, 0), P(0, 0), P(0, 0), P(1, 0)], 1, irr=irr_one_minus(F(1), 2),
     why='a1 = origin to b0 = (1-t, 1-t): sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)')
case('ee2', 'ee2_collinear_approach_d0', A2B + [P(4, 0), P(6, 0)], A2B + [P(1, 0), P(3, 0)], 0, toi=F(2, 3),
     why='b0 x = 4-3t meets a1 x = 2 at 2/3')
case('ee2', 'ee2_pass_by_d0', A2D + [P(2, 1), P(2, 3)], A2D + [P(2, -3), P(2, -1)], 0,
     why='b stays on x = 2, a ends at x = 1: distance >= 1')
case('ee2', 'ee2_pass_by_exact_d', A2D + [P(2, 1), P(2, 3)], A2D + [P(2, -3), P(2, -1)], 1, toi=F(1, 4),
     why='b0 y = 1-4t: dist sqrt(1+(1-4t)^2) until b spans y = 0 (t = 1/4), then 1')
case('ee2', 'ee2_zero_length_b_d0', A2D + [P(0, 1), P(0, 1)], A2D + [P(0, -1), P(0, -1)], 0, toi=F(1, 2),
     why='b = point (0, 1-2t) crosses a at 1/2')
case('ee2', 'ee2_huge_d', A2D + [P(0, 1), P(0, 3)], A2D + [P(0, -1), P(0, 1)], BIG, toi=F(0), dname='1e300',
     why='initial distance 1 <= d')


# ---- checks ----------------------------------------------------------------------------------
def is_double(x):
    return F(float(x)) == x


def tight(t):
    """The tightest double interval around the exact rational t."""
    x = float(t)  # correctly rounded
    if F(x) == t:
        return x, x
    lo = x if F(x) < t else math.nextafter(x, -math.inf)
    hi = math.nextafter(lo, math.inf)
    assert F(lo) < t < F(hi)
    return lo, hi


def check(c):
    for p in c.t0 + c.t1:
        for x in p:
            assert is_double(x), (c.name, x)
    assert is_double(c.d) and is_double(c.tmax) and 0 < c.tmax <= 1 and c.d >= 0, c.name
    samples = [F(i, 997) for i in range(998)] + [F(i, 2**10) for i in range(2**10 + 1)]
    if c.irr is not None:
        val, below = c.irr
        # bisection over doubles on the exact predicate x < TOI
        lo, hi = 0.0, 1.0
        assert below(F(lo)) and not below(F(hi))
        while math.nextafter(lo, math.inf) != hi:
            mid = (lo + hi) / 2
            if mid in (lo, hi):
                mid = math.nextafter(lo, math.inf)
            if below(F(mid)):
                lo = mid
            else:
                hi = mid
        assert F(str(val)) > F(lo) and F(str(val)) < F(hi), c.name  # the 80-digit value agrees
        assert c.f(F(lo)) > 0 and c.f(F(hi)) < 0, c.name             # a sign change of dist^2 - d^2
        end = F(lo)
        assert F(hi) <= c.tmax
        result = (True, lo, hi)
    elif c.toi is not None:
        t = c.toi
        assert 0 <= t <= c.tmax, c.name
        assert c.f(t) <= 0, c.name
        if t > 0:
            assert c.f(t) == 0, c.name
        end = t
        lo, hi = tight(t)
        result = (True, lo, hi)
    else:
        end = c.tmax
        result = (False, None, None)
        assert c.f(c.tmax) > 0
    # before the TOI (for a miss: on all of [0, tmax]) the distance exceeds d
    probes = [s * end for s in samples]
    if end > 0:
        probes += [end - end / 2**k for k in range(1, 80)]
    for s in probes:
        if s < end or (result[0] is False and s <= end):
            assert c.f(s) > 0, (c.name, s)
    return result


def lit(x, name=None):
    x = float(x)
    if x == 0:
        return '0.0'
    r = repr(x)
    if len(r) <= 10 and 'e' not in r:
        return r
    if abs(x) == 1e300:
        return '-1e300' if x < 0 else '1e300'
    return x.hex()


def dlit(c):
    if c.dname == 'nextafter(0.25, 0)':
        return 'kBelowQuarter'
    if c.dname == 'nextafter(0.3125, 0)':
        return 'kBelow5_16'
    if c.dname == '2^-1074':
        return 'kSub'
    if c.dname == 'DBL_MAX':
        return 'kMax'
    return lit(c.d, c.dname)


def tlit(c):
    if c.tname == 'nextafter(0.375, 0)':
        return 'kBelow3_8'
    if c.tname == 'nextafter(0.5, 0)':
        return 'kBelowHalf'
    if c.tname == '2^-1074':
        return 'kSub'
    return lit(c.tmax)


def fmt_frac(x, name=None):
    if name:
        return name
    x = F(x)
    if x.denominator == 1:
        return str(x.numerator)
    return f'{x.numerator}/{x.denominator}'


def cpp(results):
    def pts(ps):
        return ', '.join('{' + ', '.join(lit(x) for x in p) + '}' for p in ps)

    out = []
    for kind, (qtype, n, dim, _) in KINDS.items():
        out.append(f'std::vector<Case<{qtype}>> {kind}_cases() {{')
        out.append('  return {')
        for c, (hit, lo, hi) in results:
            if c.kind != kind:
                continue
            out.append(f'      // {c.why}')
            toi = f'{lit(lo)}, {lit(hi)}' if hit else 'kNone, kNone'
            out.append(f'      {{"{c.name}",')
            out.append(f'       {{{pts(c.t0)},')
            out.append(f'        {pts(c.t1)}}},')
            out.append(f'       {dlit(c)}, {tlit(c)}, {"true" if hit else "false"}, {toi}}},')
        out.append('  };')
        out.append('}')
        out.append('')
    return '\n'.join(out)


def md(results):
    out = ['| case | kind | d | tmax | expected | derivation |', '|---|---|---|---|---|---|']
    for c, (hit, lo, hi) in results:
        if not hit:
            exp = 'miss'
        elif c.irr is not None:
            exp = f'hit, t = {str(c.irr[0])[:20]}... in [{lo.hex()}, {hi.hex()}]'
        elif lo == hi:
            exp = f'hit, [{fmt_frac(c.toi)}, {fmt_frac(c.toi)}]'
        else:
            exp = f'hit, t = {fmt_frac(c.toi) if c.toi.denominator < 2**20 else "1/2 - 2^-1075"} in [{lo.hex()}, {hi.hex()}]'
        out.append(f'| {c.name} | {c.kind} | {fmt_frac(c.d, c.dname)} | {fmt_frac(c.tmax, c.tname)} | {exp} | {c.why} |')
    return '\n'.join(out) + '\n'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cpp')
    ap.add_argument('--md')
    args = ap.parse_args()
    names = [c.name for c in cases]
    assert len(names) == len(set(names)), 'duplicate names'
    results = [(c, check(c)) for c in cases]
    counts = {k: sum(c.kind == k for c in cases) for k in KINDS}
    print(f'{len(cases)} cases checked: {counts}', file=sys.stderr)
    if args.cpp:  # replaces the tables between the markers
        text = open(args.cpp).read()
        begin, end = '// BEGIN CASE TABLES (tools/min_separation_catalogue.py)\n', '// END CASE TABLES\n'
        i, j = text.index(begin) + len(begin), text.index(end)
        open(args.cpp, 'w').write(text[:i] + cpp(results) + text[j:])
    if args.md:
        open(args.md, 'w').write(md(results))


if __name__ == '__main__':
    main()
