#!/usr/bin/env bash
# The scene step against mesh size and threads (issue 14, item 3): one run of the BM_Step*
# benchmarks of build/scene_bench (cloth over a sphere, 1.8k to 1.0M triangles, 1 and 2
# threads, wall time, median of 3 repetitions), and the peak resident memory of one 2-thread
# find_collisions step per size, each in a fresh process (getrusage ru_maxrss). Writes
# docs/figures/scene_step.json, scene_step_memory.json, scene_step.md and scene_step.png.
# Needs a Release build of scene_bench and candidates_bench in build/ and Debian's python3-matplotlib.
# Also a caller's candidates with disjoint boxes (candidates_bench, docs/figures/candidates_disjoint.txt)
# and the cloth-ball step (BM_Frames*, docs/figures/scene_frames.{json,txt}) when its frames are
# there (below).
# Usage: bash tools/plot/scene_step.sh   (about 30 minutes on an idle 2-core machine)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/figures
mkdir -p "$out"
load=$(uptime)
echo "== load before: $load"
build/scene_bench --benchmark_filter='BM_Step|BM_LineSearch' --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/scene_step.json" --benchmark_out_format=json
: > "$out/scene_step_memory.json.tmp"
for r in 16 64 220 708; do build/scene_bench --peak_memory="$r" >> "$out/scene_step_memory.json.tmp"; done
mv "$out/scene_step_memory.json.tmp" "$out/scene_step_memory.json"
# A caller's candidates whose boxes do not overlap (issue 23): find_collisions over them against
# a bare loop of the box test over the same rows, one thread, medians of 5 (CPU time).
build/candidates_bench --benchmark_filter=Disjoint --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  > "$out/candidates_disjoint.txt"
echo "== load after: $(uptime)"
/usr/bin/python3 tools/plot/scene_step.py "$out/scene_step.json" "$out/scene_step_memory.json" "$out/scene_step.png" \
  "load before: $load; after: $(uptime)" > "$out/scene_step.md"
cat "$out/scene_step.md"
# The cloth-ball step of the Scalable CCD dataset (when a checkout is beside the repository:
# ../ext/Sample-Scalable-CCD-Data or $SCALABLE_CCD_DATA): the BM_Frames* benchmarks (whole
# find_collisions and earliest_toi, streamed broad phase, narrow phase filtered and naive over
# the same candidates, 1 and 2 threads; medians of 3).
data=${SCALABLE_CCD_DATA:-../ext/Sample-Scalable-CCD-Data}
frames="$data/cloth-ball/frames"
if [ -f "$frames/cloth_ball92.ply" ]; then
  echo "== cloth-ball frames, load $(cut -d' ' -f1-3 /proc/loadavg)"
  build/scene_bench --frames="$frames/cloth_ball92.ply,$frames/cloth_ball93.ply" --benchmark_filter='BM_Frames' \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out/scene_frames.json" --benchmark_out_format=json > "$out/scene_frames.txt"
  echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$out/scene_frames.txt"
  cat "$out/scene_frames.txt"
else
  echo "SKIPPED: the cloth-ball frames ($frames) are absent"
fi
