#!/usr/bin/env bash
# Regenerates every chart and table in docs/figures from real runs (one documented command):
#   bash tools/plot/make_charts.sh
# Needs a Release build in build/ (tools/demo.sh or tools/test.sh makes one) and Debian's
# python3-matplotlib. Writes docs/figures/{bench.json,bench-table.md,speed_accuracy.png,
# stability.csv,stability.png}, the simulation-like summaries {bench-sim.json,
# bench-separation.json,bench-summary.md} and, by tools/plot/scene_step.sh (build/scene_bench: the scene
# step per phase and thread count, 1.8k to 1.0M triangles), docs/figures/{scene_step.json,
# scene_step_memory.json,scene_step.md,scene_step.png} (and, when their inputs are there, the
# cloth-ball step: scene_frames.{json,txt}), and by tools/plot/scene_scaling.sh (the
# whole `exactccd scene` step up to 1M triangles) docs/figures/scene_scaling.{csv,png}.
set -euo pipefail
cd "$(dirname "$0")/../.."
echo "== make_charts.sh started $(date -u '+%Y-%m-%d %H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
exe=build/exactccd
out=docs/figures
mkdir -p "$out"
files=()
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then files+=("$sample"/vertex-face/*.csv "$sample"/edge-edge/*.csv); fi
files+=(data/sim/*.csv data/catalogue/*.csv data/families/*.csv)
echo "== $exe bench --methods all --repetitions 5 --json $out/bench.json ${files[*]}"
"$exe" bench --methods all --repetitions 5 --json "$out/bench.json" "${files[@]}" > "$out/bench-table.txt"
# The simulation-like sets alone, filtered against naive with many repetitions (the 1.5x target),
# and the filtered method at minimum separations (the <= 2x target; 21 repetitions, so that the
# first, after the exact reference has run on the file, weighs little on the means): README's
# summary tables.
echo "== $exe bench --methods filtered,naive --repetitions 41 --json $out/bench-sim.json data/sim/*.csv"
"$exe" bench --methods filtered,naive --repetitions 41 --json "$out/bench-sim.json" data/sim/*.csv > "$out/bench-sim.txt"
echo "== $exe bench --methods filtered --repetitions 21 --min-distances 0,1e-4,1e-3,1e-2 --relative --json $out/bench-separation.json data/sim/*.csv"
"$exe" bench --methods filtered --repetitions 21 --min-distances 0,1e-4,1e-3,1e-2 --relative \
  --json "$out/bench-separation.json" data/sim/*.csv > "$out/bench-separation.txt"
/usr/bin/python3 tools/plot/bench_summary.py "$out/bench-sim.json" "$out/bench-separation.json" > "$out/bench-summary.md"
echo "== $exe stability --threads 2 --out $out/stability.csv"
"$exe" stability --threads 2 --out "$out/stability.csv"
/usr/bin/python3 tools/plot/speed_accuracy.py "$out/bench.json" "$out/speed_accuracy.png" > "$out/bench-table.md"
/usr/bin/python3 tools/plot/stability.py "$out/stability.csv" "$out/stability.png"
echo "== bash tools/plot/scene_step.sh"
bash tools/plot/scene_step.sh > /dev/null
echo "written: $out/scene_step.json $out/scene_step_memory.json $out/scene_step.md $out/scene_step.png (scene_frames.* when the frames are there)"
echo "== bash tools/plot/scene_scaling.sh"
bash tools/plot/scene_scaling.sh > /dev/null
echo "written: $out/scene_scaling.csv $out/scene_scaling.png"
echo "== make_charts.sh finished $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "written: $out/bench.json $out/bench-table.txt $out/bench-table.md $out/speed_accuracy.png $out/stability.csv $out/stability.png"
echo "written: $out/bench-sim.json $out/bench-sim.txt $out/bench-separation.json $out/bench-separation.txt $out/bench-summary.md"
