#!/usr/bin/env bash
# The scene step against mesh size and threads (issue 14, item 3): one run of the BM_Step*
# benchmarks of build/scene_bench (cloth over a sphere, 1.8k to 1.0M triangles, 1 and 2
# threads, wall time, median of 3 repetitions), and the peak resident memory of one 2-thread
# find_collisions step per size, each in a fresh process (getrusage ru_maxrss). Writes
# docs/figures/scene_step.json, scene_step_memory.json, scene_step.md and scene_step.png.
# Needs a Release build of scene_bench in build/ and Debian's python3-matplotlib.
# Also the cloth-ball step (BM_Frames*, docs/figures/scene_frames.{json,txt}) and the side-by-side
# run against the Scalable CCD CPU pipeline (docs/figures/scene_anchor.md) when their inputs are
# there (below).
# Usage: [EXACTCCD_ANCHOR_BUILD=DIR] bash tools/plot/scene_step.sh   (about 30 minutes on an idle 2-core machine)
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
echo "== load after: $(uptime)"
/usr/bin/python3 tools/plot/scene_step.py "$out/scene_step.json" "$out/scene_step_memory.json" "$out/scene_step.png" \
  "load before: $load; after: $(uptime)" > "$out/scene_step.md"
cat "$out/scene_step.md"
# The cloth-ball step of the Scalable CCD dataset (when a checkout is beside the repository:
# ../ext/Sample-Scalable-CCD-Data or $SCALABLE_CCD_DATA): the BM_Frames* benchmarks (whole
# find_collisions and earliest_toi, streamed broad phase, narrow phase filtered and naive over
# the same candidates, 1 and 2 threads; medians of 3), then, when $EXACTCCD_ANCHOR_BUILD names
# the anchor's build (tools/bench/anchor/build.sh), exactccd scene against it (anchor_step.sh).
data=${SCALABLE_CCD_DATA:-../ext/Sample-Scalable-CCD-Data}
frames="$data/cloth-ball/frames"
if [ -f "$frames/cloth_ball92.ply" ]; then
  echo "== cloth-ball frames, load $(cut -d' ' -f1-3 /proc/loadavg)"
  build/scene_bench --frames="$frames/cloth_ball92.ply,$frames/cloth_ball93.ply" --benchmark_filter='BM_Frames' \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out/scene_frames.json" --benchmark_out_format=json > "$out/scene_frames.txt"
  echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$out/scene_frames.txt"
  cat "$out/scene_frames.txt"
  bash tools/plot/anchor_step.sh "${EXACTCCD_ANCHOR_BUILD:-}" "$frames/cloth_ball92.ply" "$frames/cloth_ball93.ply" 3 \
    | tee "$out/scene_anchor.md"
else
  echo "SKIPPED: the cloth-ball frames ($frames) are absent"
fi
