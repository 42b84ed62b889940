#!/usr/bin/python3
"""Speed against accuracy: each method's mean time per query against its error count, one panel
per dataset group, from `exactccd bench --methods all --json` output. Also prints the table
(markdown) that docs/performance.md shows.

usage: /usr/bin/python3 tools/plot/speed_accuracy.py BENCH.json OUT.png
"""
import json
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from stability import STYLE  # noqa: E402


def group_of(dataset):
    if dataset.startswith("unit-tests"):
        return "shared unit-tests"
    if dataset.startswith("sim-"):
        return "simulation-like (data/sim)"
    if dataset.startswith("catalogue"):
        return "degenerate catalogue"
    if dataset.startswith("families"):
        return "degenerate families"
    return dataset


def main(path, out):
    with open(path) as f:
        results = json.load(f)
    # group -> method -> [queries, total_ns(mean), total_ns(median), fp, fn]
    acc = defaultdict(lambda: defaultdict(lambda: [0, 0.0, 0.0, 0, 0]))
    for r in results:
        a = acc[group_of(r["dataset"])][r["method"]]
        a[0] += r["queries"]
        a[1] += r["mean_ns"] * r["queries"]
        a[2] += r["median_ns"] * r["queries"]
        a[3] += r["fp"]
        a[4] += r["fn"]
    groups = list(acc)
    fig, axes = plt.subplots(1, len(groups), figsize=(4.5 * len(groups), 4.2), squeeze=False)
    print("| dataset | method | queries | mean ns/query | median ns/query | FP | FN |")
    print("|---|---|---|---|---|---|---|")
    for ax, g in zip(axes[0], groups):
        for m, (n, mean_total, median_total, fp, fn) in acc[g].items():
            mean_ns = mean_total / n
            ax.scatter([mean_ns], [fp + fn], color=STYLE.get(m, "black"), s=50, label=m, zorder=3)
            ax.annotate(m, (mean_ns, fp + fn), fontsize=7, xytext=(3, 3), textcoords="offset points")
            print(f"| {g} | {m} | {n} | {mean_ns:.0f} | {median_total / n:.0f} | {fp} | {fn} |")
        ax.set_xscale("log")
        ax.set_xlabel("mean time per query (ns, log scale)")
        ax.set_ylabel("false positives + false negatives")
        ax.set_title(g, fontsize=10)
        ax.grid(alpha=0.3)
    fig.suptitle("Speed against accuracy (exact methods sit on the zero-error line)")
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
