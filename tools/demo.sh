#!/usr/bin/env bash
# The main job, in about a minute: installs what is missing, builds the exactccd program, then
# shows what the project is for: the exact oracle (exactccd check) on the bundled data and on
# the shared benchmark sample (when it is beside this checkout), the textbook method's mistakes
# on the kinds it answers (vertex-face, edge-edge), a minimum separation with times of impact,
# one scene step, and the benchmark of every method on the same queries.
# Usage: bash tools/demo.sh      (CI runs it after tools/test.sh, on the same build/)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs" --target exactccd_cli
exe=build/exactccd
# The files of the two kinds the textbook method answers (its cubic is for vertex-face and
# edge-edge only; data/kinds holds point-edge, point-point and the 2D kinds).
textbook_files=(data/catalogue/*.csv data/families/*.csv data/sim/*.csv)

# Linear-motion query files (data/rigid holds rigid-body queries, another format: below).
linear_files=(data/catalogue/*.csv data/families/*.csv data/sim/*.csv data/kinds/*.csv)

echo "== the oracle on the bundled data: exactccd check --stats data/{catalogue,families,sim,kinds}/*.csv"
"$exe" check --stats "${linear_files[@]}"
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then
  echo
  echo "== the oracle on the shared benchmark sample: exactccd check --stats $sample/*/*.csv"
  "$exe" check --stats "$sample"/*/*.csv
else
  echo
  echo "== (the shared benchmark sample $sample is absent: skipped)"
fi
echo
echo "== the textbook method (double-precision cubic, not robust: note its FP and FN) on the"
echo "   vertex-face and edge-edge files: exactccd check --method naive data/{catalogue,families,sim}/*.csv"
"$exe" check --method naive "${textbook_files[@]}"
echo
echo "== minimum separation: which simulation-like queries come within 1e-3 (every kind):"
echo "   exactccd check --min-distance 1e-3 data/sim/*.csv data/kinds/*.csv"
echo "   (the files' truth column is contact: truth_1 counts the queries that touch, yes_truth_0 those"
echo "   that come within 1e-3 without touching, right answers to this question, no_truth_1 must be 0)"
"$exe" check --min-distance 1e-3 data/sim/*.csv data/kinds/*.csv
echo
echo "== their times of impact, the tightest double interval [lo, hi] of the exact time (first 3):"
echo "   exactccd check --min-distance 1e-3 --toi --answers data/sim/sim-cloth-vertex-face.csv"
"$exe" check --min-distance 1e-3 --toi --answers data/sim/sim-cloth-vertex-face.csv > build/demo-toi.txt
grep -m 3 '^1 ' build/demo-toi.txt
echo
echo "== rigid bodies (rotation and translation over the step), exact too:"
echo "   exactccd check --motion rigid --kind vf --stats data/rigid/*-vertex-face.csv (and --kind ee)"
"$exe" check --motion rigid --kind vf --stats data/rigid/*-vertex-face.csv
"$exe" check --motion rigid --kind ee --stats data/rigid/*-edge-edge.csv
echo
echo "== one scene step: exactccd scene data/scenes/cloth/T0.obj data/scenes/cloth/T1.obj (first lines)"
"$exe" scene data/scenes/cloth/T0.obj data/scenes/cloth/T1.obj > build/demo-scene.txt
head -9 build/demo-scene.txt
echo
echo "== the benchmark, every method on the same queries (bundled datasets):"
echo "   exactccd bench --repetitions 3 --methods naive,naive-tolerance,mpfr256,filtered,exact"
"$exe" bench --repetitions 3 --methods naive,naive-tolerance,mpfr256,filtered,exact
echo
echo "demo: done"
