#!/usr/bin/env bash
# The main job: installs what is missing, builds exactccd, runs the oracle (exactccd check) on
# the bundled data and on the shared benchmark sample (when it is beside this checkout), then
# the benchmark of every method on the same queries.
# Usage: bash tools/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs" --target exactccd_cli
exe=build/exactccd

echo "== the oracle on the bundled data: exactccd check --stats data/*/*.csv"
"$exe" check --stats data/*/*.csv
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then
  echo
  echo "== the oracle on the shared benchmark sample: exactccd check --stats $sample/*/*.csv"
  "$exe" check --stats "$sample"/*/*.csv
fi
echo
echo "== the textbook method on the same data (not robust: note its FP and FN)"
"$exe" check --method naive data/*/*.csv
for scene in data/scenes/*/; do
  echo
  echo "== scene-level CCD: exactccd scene ${scene}T0.obj ${scene}T1.obj (first lines)"
  "$exe" scene "${scene}T0.obj" "${scene}T1.obj" > build/scene-demo.txt
  head -9 build/scene-demo.txt
done
echo
echo "== exactccd bench --methods naive,naive-tolerance,mpfr256,filtered,exact (bundled datasets)"
"$exe" bench --repetitions 3 --methods naive,naive-tolerance,mpfr256,filtered,exact
