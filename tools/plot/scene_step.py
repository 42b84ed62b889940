#!/usr/bin/python3
"""The scene step against mesh size, per phase and thread count, from one run of
tools/plot/scene_step.sh: Google Benchmark JSON of scene_bench's BM_Step* (medians of the
repetitions, wall time) and the --peak_memory lines (one JSON object per line). Prints a
Markdown table (ratios within the run) and writes the chart.

usage: /usr/bin/python3 tools/plot/scene_step.py STEP.json MEMORY.json OUT.png [NOTE]
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PHASES = [
    ("BM_StepBroadStream", "broad phase (streamed, as the scene functions run it)"),
    ("BM_StepBroad", "broad phase (tree, candidates listed)"),
    ("BM_StepRefit", "broad phase reused (SceneBroadPhase::update)"),
    ("BM_StepSweep", "broad phase (old sweep, 1 thread)"),
    ("BM_StepNarrow/filtered", "narrow, filtered (exact TOIs)"),
    ("BM_StepNarrow/naive", "narrow, naive"),
    ("BM_StepWhole", "whole step (find_collisions)"),
    ("BM_StepEarliest", "whole step (earliest_toi)"),
]


def load(path):
    """{(phase, resolution, threads): (milliseconds, triangles, candidates)} of the medians."""
    data = json.load(open(path))
    out = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        parts = b["run_name"].split("/")
        phase = "/".join(parts[:2]) if parts[0] == "BM_StepNarrow" else parts[0]
        rest = parts[2:] if parts[0] == "BM_StepNarrow" else parts[1:]
        res, threads = int(rest[0]), int(rest[1])
        assert b["time_unit"] == "ms"
        out[(phase, res, threads)] = (b["real_time"], int(b["triangles"]), int(b["candidates"]), b["cpu_time"])
    return data["context"], out


def main(step_path, memory_path, png, note=""):
    context, t = load(step_path)
    memory = {}
    for line in open(memory_path):
        if line.strip():
            m = json.loads(line)
            memory[m["resolution"]] = m
    sizes = sorted({r for (_, r, _) in t})
    print(f"Medians of {context.get('num_cpus', '?')}-CPU wall times, one run ({context.get('date', '')}). {note}\n")
    print("| triangles | candidates | threads | broad, streamed | broad, listed (tree) | broad reused (refit) | "
          "old sweep (1 thr.) | narrow filtered | narrow naive | find_collisions | earliest_toi | "
          "find_collisions / naive narrow | earliest_toi / naive narrow | same, 1-thread CPU times | "
          "1 thr. / 2 thr. (find_collisions, earliest_toi) | line search: first, next, fresh | "
          "peak RSS per triangle (2 thr.) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    nan = (float("nan"), 0, 0, float("nan"))
    for r in sizes:
        for th in (1, 2):
            g = lambda p: t.get((p, r, th), nan)[0]  # noqa: E731
            tri, cand = t[("BM_StepWhole", r, th)][1:3]
            whole, earliest, naive = g("BM_StepWhole"), g("BM_StepEarliest"), g("BM_StepNarrow/naive")
            cpu = ""
            if th == 1:
                c = lambda p: t.get((p, r, 1), nan)[3]  # noqa: E731
                cpu = f"{c('BM_StepWhole') / c('BM_StepNarrow/naive'):.2f}x, {c('BM_StepEarliest') / c('BM_StepNarrow/naive'):.2f}x"
            sweep = t.get(("BM_StepSweep", r, 1), nan)[0]
            speed = ""
            if th == 2:
                one = lambda p: t.get((p, r, 1), nan)[0]  # noqa: E731
                speed = f"{one('BM_StepWhole') / whole:.2f}x, {one('BM_StepEarliest') / earliest:.2f}x"
            mem = ""
            if th == 2 and r in memory:
                m = memory[r]
                mem = (f"{m['max_rss_kb_step'] * 1024 / m['triangles']:.0f} B "
                       f"({m['max_rss_kb_step'] / 1024:.0f} MiB; scene alone {m['max_rss_kb_scene'] / 1024:.0f} MiB)")
            line = f"{g('BM_LineSearchFirst'):.1f}, {g('BM_LineSearchNext'):.1f}, {g('BM_LineSearchFresh'):.1f} ms"
            print(f"| {tri:,} | {cand:,} | {th} | {g('BM_StepBroadStream'):.1f} ms | {g('BM_StepBroad'):.1f} ms | "
                  f"{g('BM_StepRefit'):.1f} ms | {sweep:.1f} ms | {g('BM_StepNarrow/filtered'):.1f} ms | {naive:.1f} ms | "
                  f"{whole:.1f} ms | {earliest:.1f} ms | {whole / naive:.2f}x | {earliest / naive:.2f}x | {cpu} | "
                  f"{speed} | {line} | {mem} |")
    fig, ax = plt.subplots(figsize=(8, 5))
    styles = {1: "-", 2: "--"}
    for i, (phase, label) in enumerate(PHASES):
        for th in (1, 2):
            pts = [(t[(phase, r, th)][1], t[(phase, r, th)][0] / 1000) for r in sizes if (phase, r, th) in t]
            if pts:
                ax.loglog(*zip(*pts), styles[th], marker="o", color=f"C{i}", label=f"{label}, {th} thr.")
    ax.set_xlabel("triangles (cloth over a sphere, one step)")
    ax.set_ylabel("wall time per step (s), median")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("Scene step per phase and thread count (shared 2-core machine: see docs/scene.md)", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    main(*sys.argv[1:])
