#!/usr/bin/env bash
# Installs what is missing, builds exactccd and runs the whole test suite (CTest).
# Usage: bash tools/test.sh            (build directory: build/)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_WERROR=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"
