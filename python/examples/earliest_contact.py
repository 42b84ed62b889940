#!/usr/bin/env python3
"""Earliest contact of a simulation step, and how close the first colliding pair comes.

Loads two frames of a mesh (the same vertices and faces at t = 0 and t = 1), finds the earliest
contact with exactccd (exact: no false negative, a certified time of impact), and plots the
distance of the first colliding pair over the step with matplotlib, saving a PNG.

    PYTHONPATH=build/python MPLBACKEND=Agg python3 python/examples/earliest_contact.py \\
        data/scenes/cloth/T0.obj data/scenes/cloth/T1.obj --out earliest-contact.png
"""

import argparse
import sys

import numpy as np

import exactccd


def point_triangle_distance(p, a, b, c):
    """Euclidean distance from p to the closed triangle (a, b, c) (Ericson, Real-Time Collision
    Detection, 5.1.5), in floating point: for the plot only, the contact itself is exact."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = ab @ ap, ac @ ap
    if d1 <= 0 and d2 <= 0:
        return np.linalg.norm(p - a)
    bp = p - b
    d3, d4 = ab @ bp, ac @ bp
    if d3 >= 0 and d4 <= d3:
        return np.linalg.norm(p - b)
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return np.linalg.norm(p - (a + d1 / (d1 - d3) * ab))
    cp = p - c
    d5, d6 = ab @ cp, ac @ cp
    if d6 >= 0 and d5 <= d6:
        return np.linalg.norm(p - c)
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return np.linalg.norm(p - (a + d2 / (d2 - d6) * ac))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return np.linalg.norm(p - (b + w * (c - b)))
    denom = 1.0 / (va + vb + vc)
    return np.linalg.norm(p - (a + ab * vb * denom + ac * vc * denom))


def segment_distance(p1, q1, p2, q2):
    """Distance between the closed segments [p1, q1] and [p2, q2] (Ericson 5.1.9)."""
    d1, d2, r = q1 - p1, q2 - p2, p1 - p2
    a, e, f = d1 @ d1, d2 @ d2, d2 @ r
    if a == 0 and e == 0:
        return np.linalg.norm(r)
    if a == 0:
        s, t = 0.0, np.clip(f / e, 0, 1)
    else:
        c = d1 @ r
        if e == 0:
            s, t = np.clip(-c / a, 0, 1), 0.0
        else:
            b = d1 @ d2
            denom = a * e - b * b
            s = np.clip((b * f - c * e) / denom, 0, 1) if denom != 0 else 0.0
            t = (b * s + f) / e
            if t < 0:
                s, t = np.clip(-c / a, 0, 1), 0.0
            elif t > 1:
                s, t = np.clip((b - c) / a, 0, 1), 1.0
    return np.linalg.norm((p1 + d1 * s) - (p2 + d2 * t))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("t0", help="the mesh at t = 0 (any format read_mesh reads)")
    parser.add_argument("t1", help="the mesh at t = 1 (same vertices and faces)")
    parser.add_argument("--out", default="earliest-contact.png", help="the PNG to write")
    parser.add_argument("--min-distance", type=float, default=0.0)
    args = parser.parse_args(argv)

    V0, F = exactccd.read_mesh(args.t0)
    V1, F1 = exactccd.read_mesh(args.t1)
    if V0.shape != V1.shape or not np.array_equal(F, F1):
        sys.exit("the two frames must have the same vertices and faces")

    hits = exactccd.find_collisions(V0, V1, F, min_distance=args.min_distance)
    if len(hits["kind"]) == 0:
        print(f"no contact: the whole step is free ({len(V0)} vertices, {len(F)} triangles)")
        return 0
    first = int(np.lexsort((hits["toi"][:, 1], hits["toi"][:, 0]))[0])
    lo, hi = hits["toi"][first]
    assert (lo, hi) == exactccd.earliest_toi(V0, V1, F, min_distance=args.min_distance)
    kind = exactccd.KIND_NAMES[hits["kind"][first]]
    if hits["kind"][first] == exactccd.VERTEX_FACE:
        v, tri = int(hits["vertex"][first]), F[hits["triangle"][first]]
        label = f"vertex {v} / triangle {int(hits['triangle'][first])} {tri.tolist()}"

        def distance(X):
            return point_triangle_distance(X[v], *X[tri])
    else:
        ea, eb = hits["edge_a"][first], hits["edge_b"][first]
        label = f"edge {ea.tolist()} / edge {eb.tolist()}"

        def distance(X):
            return segment_distance(X[ea[0]], X[ea[1]], X[eb[0]], X[eb[1]])

    step = exactccd.max_collision_free_step(V0, V1, F, min_distance=args.min_distance)
    print(f"{len(hits['kind'])} colliding pairs; earliest contact {kind} {label}")
    print(f"time of impact in [{lo!r}, {hi!r}]; largest collision-free step {step!r}")

    import matplotlib
    import matplotlib.pyplot as plt

    ts = np.linspace(0.0, 1.0, 401)
    ds = [distance(V0 + t * (V1 - V0)) for t in ts]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(ts, ds, label="distance (floating point)")
    ax.axvline(lo, color="red", linestyle="--", label=f"exact TOI {lo:.6g}")
    if args.min_distance > 0:
        ax.axhline(args.min_distance, color="gray", linestyle=":", label="min_distance")
    ax.set_xlabel("t")
    ax.set_ylabel("distance")
    ax.set_title(f"first contact: {kind}, {label}", fontsize=9)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out} (matplotlib {matplotlib.__version__})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
