#!/usr/bin/env bash
# Regenerates every chart and table in docs/figures from real runs (one documented command):
#   bash tools/plot/make_charts.sh
# Needs a Release build in build/ (tools/demo.sh or tools/test.sh makes one) and Debian's
# python3-matplotlib. Writes docs/figures/{bench.json,bench-table.md,speed_accuracy.png,
# stability.csv,stability.png} and, by tools/plot/scene_step.sh (build/scene_bench: the scene
# step per phase and thread count, 1.8k to 1.0M triangles), docs/figures/{scene_step.json,
# scene_step_memory.json,scene_step.md,scene_step.png}.
set -euo pipefail
cd "$(dirname "$0")/../.."
exe=build/exactccd
out=docs/figures
mkdir -p "$out"
files=()
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then files+=("$sample"/vertex-face/*.csv "$sample"/edge-edge/*.csv); fi
files+=(data/sim/*.csv data/catalogue/*.csv data/families/*.csv)
echo "== $exe bench --methods all --repetitions 5 --json $out/bench.json ${files[*]}"
"$exe" bench --methods all --repetitions 5 --json "$out/bench.json" "${files[@]}" > "$out/bench-table.txt"
echo "== $exe stability --threads 2 --out $out/stability.csv"
"$exe" stability --threads 2 --out "$out/stability.csv"
/usr/bin/python3 tools/plot/speed_accuracy.py "$out/bench.json" "$out/speed_accuracy.png" > "$out/bench-table.md"
/usr/bin/python3 tools/plot/stability.py "$out/stability.csv" "$out/stability.png"
echo "== bash tools/plot/scene_step.sh"
bash tools/plot/scene_step.sh > /dev/null
echo "written: $out/scene_step.json $out/scene_step_memory.json $out/scene_step.md $out/scene_step.png"
echo "written: $out/bench.json $out/bench-table.txt $out/bench-table.md $out/speed_accuracy.png $out/stability.csv $out/stability.png"
