#!/usr/bin/env bash
# The cloth-ball step side by side with the Scalable CCD CPU pipeline (issue 23): in one run,
# alternating, `exactccd scene --stats --json` (everything it prints: every colliding pair with
# its exact TOI, the earliest TOI, the safe step, both intersection-free checks) and the anchor
# (tools/bench/anchor/scalable_ccd_step: Scalable CCD's sort and sweep on oneTBB, then Tight
# Inclusion's CPU narrow phase pruned by the earliest TOI so far; build it with
# tools/bench/anchor/build.sh, outside this repository), on 1 and 2 threads, ROUNDS rounds;
# wall time and peak memory of each process from /usr/bin/time, medians per program and threads.
#
#   bash tools/plot/anchor_step.sh ANCHOR_BUILD_DIR [T0 T1] [ROUNDS]
#
# T0 T1 default to the cloth-ball frames of a Sample-Scalable-CCD-Data checkout beside the
# repository (../ext/Sample-Scalable-CCD-Data or $SCALABLE_CCD_DATA). Skips (exit 0, "SKIPPED")
# when the anchor build or the frames are absent. Needs a Release build of exactccd in build/.
set -euo pipefail
cd "$(dirname "$0")/../.."
anchor_dir=${1:-}
anchor="$anchor_dir/scalable_ccd_step"
data=${SCALABLE_CCD_DATA:-../ext/Sample-Scalable-CCD-Data}
t0=${2:-$data/cloth-ball/frames/cloth_ball92.ply}
t1=${3:-$data/cloth-ball/frames/cloth_ball93.ply}
rounds=${4:-3}
if [ -z "$anchor_dir" ] || [ ! -x "$anchor" ]; then
  echo "SKIPPED: no anchor build at '$anchor' (bash tools/bench/anchor/build.sh SRC BUILD_DIR)"; exit 0
fi
if [ ! -f "$t0" ] || [ ! -f "$t1" ]; then echo "SKIPPED: frames $t0 $t1 not found"; exit 0; fi
out=$(mktemp -d)
echo "== anchor_step.sh $(date -u '+%Y-%m-%d %H:%M:%S UTC'), commit $(git rev-parse --short HEAD), load average $(cut -d' ' -f1-3 /proc/loadavg)"
for round in $(seq "$rounds"); do
  for threads in 1 2; do
    /usr/bin/time -f '{"wall_s": %e, "max_rss_kb": %M}' -o "$out/anchor-$threads-$round.time" \
      "$anchor" "$t0" "$t1" --threads "$threads" > "$out/anchor-$threads-$round.json"
    /usr/bin/time -f '{"wall_s": %e, "max_rss_kb": %M}' -o "$out/exactccd-$threads-$round.time" \
      build/exactccd scene "$t0" "$t1" --threads "$threads" --stats --json > "$out/exactccd-$threads-$round.json"
    echo "   round $round, $threads thread(s) done, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  done
done
echo "== finished $(date -u '+%Y-%m-%d %H:%M:%S UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/python3 - "$out" "$rounds" <<'PY'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
def load(prog, th, r):
    t = json.load(open(f"{out}/{prog}-{th}-{r}.time"))
    j = json.load(open(f"{out}/{prog}-{th}-{r}.json"))
    return t, j
print("| program | threads | wall time (median of %d) | peak memory | candidates | earliest TOI | colliding pairs listed |" % rounds)
print("|---|---|---|---|---|---|---|")
med = {}
for prog in ("anchor", "exactccd"):
    for th in (1, 2):
        runs = [load(prog, th, r) for r in range(1, rounds + 1)]
        wall = statistics.median(t["wall_s"] for t, _ in runs)
        rss = statistics.median(t["max_rss_kb"] for t, _ in runs) / 1024
        j = runs[0][1]
        med[(prog, th)] = wall
        if prog == "anchor":
            cand = j["vf_candidates"] + j["ee_candidates"]
            toi, pairs = f"{j['earliest_toi']:.6g}", "no"
        else:
            cand = j["candidates"]
            toi = f"[{j['earliest_toi'][0]:.17g}, {j['earliest_toi'][1]:.17g}]" if j["earliest_toi"] else "none"
            pairs = f"{len(j['vf_pairs']) + len(j['ee_pairs']):,}"
        name = "Scalable CCD CPU (sort and sweep + Tight Inclusion)" if prog == "anchor" else "exactccd scene"
        print(f"| {name} | {th} | {wall:.2f} s | {rss:.0f} MiB | {cand:,} | {toi} | {pairs} |")
for th in (1, 2):
    print(f"\nthreads {th}: anchor / exactccd = {med[('anchor', th)] / med[('exactccd', th)]:.2f}x")
print(f"exactccd 1 thr. / 2 thr. = {med[('exactccd', 1)] / med[('exactccd', 2)]:.2f}x; "
      f"anchor 1 thr. / 2 thr. = {med[('anchor', 1)] / med[('anchor', 2)]:.2f}x")
s = json.load(open(f"{out}/exactccd-2-1.json"))["stats"]
print("\nexactccd --stats, 2 threads, round 1: " + json.dumps(s))
PY
rm -rf "$out"
