#!/usr/bin/python3
"""Scene-level CCD cost against scene size: wall time of `exactccd scene` (OBJ parsing, broad
phase, exact narrow phase, earliest TOI, safe step, two static intersection checks) and its
peak resident memory, from a CSV with columns resolution,triangles,candidates,seconds,max_rss_kb
(seconds as [h:]m:ss.ss from /usr/bin/time -v). See docs/scene.md for the command.

usage: /usr/bin/python3 tools/plot/scene_scaling.py SCALING.csv OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def seconds(text):
    parts = [float(p) for p in text.split(":")]
    total = 0.0
    for p in parts:
        total = total * 60 + p
    return total


def main(path, out):
    rows = list(csv.DictReader(open(path, newline="")))
    tri = [int(r["triangles"]) for r in rows]
    sec = [seconds(r["seconds"]) for r in rows]
    mem = [int(r["max_rss_kb"]) / 1024 for r in rows]
    cand = [int(r["candidates"]) for r in rows]
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.loglog(tri, sec, "o-", label="exactccd scene (2 threads)")
    a.set_xlabel("triangles")
    a.set_ylabel("wall time per step (s)")
    a.grid(alpha=0.3, which="both")
    for t, s, c in zip(tri, sec, cand):
        a.annotate(f"{c:,} cand.", (t, s), fontsize=7, xytext=(4, -10), textcoords="offset points")
    b.loglog(tri, mem, "s-", color="tab:orange")
    b.set_xlabel("triangles")
    b.set_ylabel("peak resident memory (MiB)")
    b.grid(alpha=0.3, which="both")
    fig.suptitle("Scene-level CCD: cloth over a sphere, one step")
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
