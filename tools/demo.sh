#!/usr/bin/env bash
# Installs what is missing, builds exactccd and runs the oracle on the bundled data (and on the
# shared benchmark sample, when it is beside this checkout).
# Usage: bash tools/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs" --target exactccd_cli
exe=build/exactccd

shopt -s nullglob
bundled=(data/*/*.csv)
if [ ${#bundled[@]} -gt 0 ]; then
  echo "== exactccd check --stats on the bundled data (data/)"
  "$exe" check --stats "${bundled[@]}"
fi
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then
  echo
  echo "== exactccd check --stats on the shared benchmark sample ($sample)"
  "$exe" check --stats "$sample"/*/*.csv
  echo
  echo "== the same with the naive textbook method (not robust: note its errors)"
  "$exe" check --method naive "$sample"/*/*.csv
fi
