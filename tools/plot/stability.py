#!/usr/bin/python3
"""Plots `exactccd stability` output: error rate against the perturbation exponent k, one panel
per degenerate family, one line per method (false negatives solid, false positives dashed).

usage: /usr/bin/python3 tools/plot/stability.py STABILITY.csv OUT.png
(Debian's python3 with python3-matplotlib.)
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "naive": "tab:red",
    "naive-tolerance": "tab:orange",
    "mpfr24": "tab:brown",
    "mpfr53": "tab:pink",
    "mpfr113": "tab:purple",
    "mpfr256": "tab:gray",
    "filtered": "tab:green",
    "exact": "tab:blue",
}


def main(path, out):
    rows = defaultdict(list)  # (family, method) -> [(k, fp_rate, fn_rate)]
    families = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            k = int(r["k"])
            if k < 0:
                continue  # the unperturbed configuration has no position on the k axis
            if r["family"] not in families:
                families.append(r["family"])
            rows[(r["family"], r["method"])].append((k, float(r["fp_rate"]), float(r["fn_rate"])))
    methods = [m for m in STYLE if any((fam, m) in rows for fam in families)]
    cols = 4
    nrows = (len(families) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(4 * cols, 2.6 * nrows), sharex=True, sharey=True)
    for ax, fam in zip(axes.flat, families):
        for m in methods:
            pts = sorted(rows.get((fam, m), []))
            if not pts:
                continue
            ks = [p[0] for p in pts]
            ax.plot(ks, [p[2] for p in pts], color=STYLE[m], lw=1.4, label=f"{m} FN")
            ax.plot(ks, [p[1] for p in pts], color=STYLE[m], lw=1.0, ls="--", label=f"{m} FP")
        ax.set_title(fam, fontsize=9)
        ax.set_ylim(-0.05, 1.05)
        ax.grid(alpha=0.3)
    for ax in axes.flat[len(families):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("k (perturbation 2^-k)")
    for ax in axes[:, 0]:
        ax.set_ylabel("error rate")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=8, fontsize=7)
    fig.suptitle("Error rate vs perturbation on the degenerate families "
                 "(solid: false negatives, dashed: false positives)")
    fig.tight_layout(rect=(0, 0.06, 1, 0.97))
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
