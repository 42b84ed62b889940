#!/usr/bin/env python3
"""Benchmark CSV queries whose coordinates are rationals at the input size limit.

The worst case of `exactccd check` under the limit on numerators and denominators
(exactccd::io::kMaxFieldBits, README "Input files"): every coordinate is c + e with c a small
coordinate of a hand-made configuration (vertex-face: a vertex falling through a triangle, one
passing beside it, one sliding in its plane; edge-edge: crossing edges, coplanar edges) and e a
random rational with an odd denominator of nearly BITS bits and magnitude about 2^-SHIFT, so that
numerator and denominator both have up to BITS bits; then one query of independent random
rationals of that size. A large SHIFT leaves the configuration nearly degenerate, which is the
slowest for the exact path (roots a tiny distance apart). Deterministic (seeded).

  python3 tools/bench/limit_queries.py --kind vf --bits 4096 --shift 4000 > limit-vertex-face.csv
  build/exactccd check --method exact limit-vertex-face.csv
"""
import argparse
import random
from fractions import Fraction

CONFIGURATIONS = {
    "vf": [
        [(0.25, 0.25, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0), (0.25, 0.25, -1), (0, 0, 0), (1, 0, 0), (0, 1, 0)],
        [(2, 2, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0), (2, 2, -1), (0, 0, 0), (1, 0, 0), (0, 1, 0)],
        [(0.25, 0.25, 0), (0, 0, 0), (1, 0, 0), (0, 1, 0), (2, 2, 0), (0, 0, 0), (1, 0, 0), (0, 1, 0)],
    ],
    "ee": [
        [(-1, 0, 0), (1, 0, 0), (0, -1, 1), (0, 1, 1), (-1, 0, 0), (1, 0, 0), (0, -1, -1), (0, 1, -1)],
        [(-1, 0, 0), (1, 0, 0), (0, -1, 0), (0, 1, 0), (-1, 0, 0), (1, 0, 0), (0, -1, 0), (0, 1, 0)],
    ],
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kind", choices=["vf", "ee"], required=True)
    parser.add_argument("--bits", type=int, default=4096, help="largest numerator/denominator size")
    parser.add_argument("--shift", type=int, default=4000, help="perturbation about 2^-SHIFT (at most BITS - 42 keeps a random part)")
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    bits = args.bits

    def near(c):
        b = rng.getrandbits(bits - 8) | (1 << (bits - 9)) | 1
        a = rng.getrandbits(max(1, bits - 8 - args.shift)) * rng.choice([-1, 1])
        x = Fraction(c)
        num, den = x.numerator * b + a * x.denominator, b * x.denominator
        assert num.bit_length() <= bits and den.bit_length() <= bits
        return "%d,%d" % (num, den)

    def random_rational():
        b = rng.getrandbits(bits - 1) | (1 << (bits - 2)) | 1
        return "%d,%d" % (rng.getrandbits(bits - 2) * rng.choice([-1, 1]), b)

    rows = []
    for query in CONFIGURATIONS[args.kind]:
        rows += [",".join(near(c) for c in point) for point in query]
    rows += [",".join(random_rational() for _ in range(3)) for _ in range(8)]
    # The truth column is not known here: 0 (check then counts the collisions as FN).
    print("\n".join(row + ",0" for row in rows))


if __name__ == "__main__":
    main()
