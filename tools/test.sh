#!/usr/bin/env bash
# Installs what is missing, builds exactccd and runs the whole test suite (CTest), then the
# same suite built with AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer.
# Usage: bash tools/test.sh     (build directories: build/, build-asan/)
# EXACTCCD_SKIP_SANITIZERS=1 skips the second pass (CI always runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

echo "== Release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_WERROR=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

if [ "${EXACTCCD_SKIP_SANITIZERS:-0}" != "1" ]; then
  echo "== ASan + UBSan + LSan build and tests"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEXACTCCD_SANITIZE=ON \
        -DEXACTCCD_BUILD_BENCHMARKS=OFF -DEXACTCCD_WERROR=ON
  cmake --build build-asan -j"$jobs"
  # The package test installs and builds a consumer without sanitizers: covered above.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs" -E '^package\.'
fi
