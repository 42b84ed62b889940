#!/usr/bin/env python3
"""The summary tables (docs/performance.md) from `exactccd bench --json` files (tools/plot/make_charts.sh).

usage: /usr/bin/python3 tools/plot/bench_summary.py SIM.json SEPARATION.json

SIM.json: `bench --methods filtered,naive` on data/sim: per scene (the two files of each) and
over all files, the filtered and naive mean ns per query (per-file means weighted by their
query counts) and their ratio, and the queries decided by GMP or CGAL.
SEPARATION.json: `bench --methods filtered --min-distances 0,... --relative` on data/sim: per
distance the weighted mean, its ratio to the d = 0 mean of the same run, and the queries
decided by GMP or CGAL. Prints Markdown.
"""
import json
import sys
from collections import defaultdict


def scene_of(dataset):
    # sim-cloth-edge-edge -> cloth
    parts = dataset.split("-")
    return parts[1] if len(parts) > 1 and parts[0] == "sim" else dataset


def gmp_cgal(row):
    s = row.get("stages") or {}
    return s.get("integer", 0) + s.get("exact", 0), s.get("exact", 0)


def weighted(rows):
    n = sum(r["queries"] for r in rows)
    return sum(r["mean_ns"] * r["queries"] for r in rows) / n, n


def sim_table(path):
    rows = json.load(open(path))
    by = defaultdict(lambda: defaultdict(list))
    for r in rows:
        if r.get("min_distance", 0) != 0:
            continue
        by[scene_of(r["dataset"])][r["method"]].append(r)
        by["all"][r["method"]].append(r)
    print("| scenes | queries | naive ns | filtered ns | filtered / naive | GMP or CGAL (filtered) |")
    print("|---|---|---|---|---|---|")
    for scene in [s for s in by if s != "all"] + ["all"]:
        f, n = weighted(by[scene]["filtered"])
        nv, _ = weighted(by[scene]["naive"])
        g = sum(gmp_cgal(r)[0] for r in by[scene]["filtered"])
        label = "all (8 files)" if scene == "all" else scene
        print(f"| {label} | {n} | {nv:.0f} | {f:.0f} | {f / nv:.2f} | {g} |")


def separation_table(path):
    rows = [r for r in json.load(open(path)) if r["method"] == "filtered"]
    by = defaultdict(list)
    for r in rows:
        by[r["min_distance"]].append(r)
    base, _ = weighted(by[0])
    print("| d / box size | filtered mean ns | against d = 0 | GMP or CGAL | of which CGAL | FP / FN |")
    print("|---|---|---|---|---|---|")
    for d in sorted(by):
        m, n = weighted(by[d])
        g = sum(gmp_cgal(r)[0] for r in by[d])
        c = sum(gmp_cgal(r)[1] for r in by[d])
        fp = sum(r["fp"] for r in by[d])
        fn = sum(r["fn"] for r in by[d])
        print(f"| {d:g} | {m:.0f} | {m / base:.2f} | {g} ({100.0 * g / n:.2f}%) | {c} | {fp} / {fn} |")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sim_table(sys.argv[1])
    print()
    separation_table(sys.argv[2])


if __name__ == "__main__":
    main()
