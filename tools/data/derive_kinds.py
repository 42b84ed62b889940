#!/usr/bin/env python3
"""Derives query sets of the other kinds (point-edge, point-point, and the 2D kinds) from the
bundled simulation sets (data/sim), for `exactccd check`/`bench` on every kind (data/kinds).

From each vertex-face query (p, a, b, c at t0 and t1): point-edge (p; a, b), point-point (p, a),
and the same in the plane (x and y only); from each edge-edge query: edge-edge in the plane.
The rows keep the exact rationals of the source. The truth column is the exact answer at
d = 0, tmax = 1 of `exactccd check --method exact` (the CGAL path of the separation terms, not
the filtered method the benchmark measures), filled in by this script.

usage: tools/data/derive_kinds.py EXACTCCD_BINARY OUT_DIR [--max-queries N]
"""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCENES = ["cloth", "fold"]


def queries(path, rows_per_query):
    rows = [line.strip().split(",") for line in open(path) if line.strip()]
    return [rows[i:i + rows_per_query] for i in range(0, len(rows), rows_per_query)]


def derive(query, picks, dimension):
    out = []
    for at in (0, 4):  # the picked points at t0, then at t1
        for k in picks:
            fields = query[at + k]
            out.append(fields[:2 * dimension])
    return out


def main():
    exe, out_dir = sys.argv[1], Path(sys.argv[2])
    max_queries = int(sys.argv[4]) if len(sys.argv) > 4 and sys.argv[3] == "--max-queries" else 200
    out_dir.mkdir(parents=True, exist_ok=True)
    for scene in SCENES:
        vf = queries(ROOT / f"data/sim/sim-{scene}-vertex-face.csv", 8)[:max_queries]
        ee = queries(ROOT / f"data/sim/sim-{scene}-edge-edge.csv", 8)[:max_queries]
        sets = {
            "point-edge": (vf, [0, 1, 2], 3, "pe"),
            "point-point": (vf, [0, 1], 3, "pp"),
            "edge-edge-2d": (ee, [0, 1, 2, 3], 2, "ee2"),
            "point-edge-2d": (vf, [0, 1, 2], 2, "pe2"),
            "point-point-2d": (vf, [0, 1], 2, "pp2"),
        }
        for name, (source, picks, dimension, short) in sets.items():
            derived = [derive(q, picks, dimension) for q in source]
            path = out_dir / f"kinds-{scene}-{name}.csv"
            tmp = path.with_suffix(".tmp.csv")
            with open(tmp, "w") as f:
                for q in derived:
                    for row in q:
                        f.write(",".join(row + ["0"]) + "\n")
            answers = subprocess.run([exe, "check", "--kind", short, "--method", "exact", "--answers",
                                      "--threads", "2", str(tmp)], check=True, capture_output=True,
                                     text=True).stdout.split()
            assert len(answers) == len(derived), (path, len(answers), len(derived))
            with open(path, "w") as f:
                for q, truth in zip(derived, answers):
                    for row in q:
                        f.write(",".join(row + [truth]) + "\n")
            tmp.unlink()
            print(f"{path.name}: {len(derived)} queries, {answers.count('1')} positives")


if __name__ == "__main__":
    main()
