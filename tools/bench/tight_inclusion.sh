#!/usr/bin/env bash
# The README's headline table: Tight Inclusion, exactccd's filtered method and the textbook
# cubic on the same vertex-face and edge-edge files, in one run (tools/bench/tight_inclusion_bench.cpp).
# Tight Inclusion is not a dependency of exactccd: build it yourself, outside this repository
# (docs/performance.md, "Tight Inclusion", has the commands), and pass its build directory.
# Usage: bash tools/bench/tight_inclusion.sh TIGHT_INCLUSION_BUILD_DIR [REPETITIONS]
#        (after building exactccd into build/; prints the table and the conditions; skips, with
#        exit 0, when the directory holds no Tight Inclusion build)
set -euo pipefail
cd "$(dirname "$0")/../.."
ti_build=${1:-}
repetitions=${2:-5}
library=$( [ -n "$ti_build" ] && find "$ti_build" -name libtight_inclusion.a 2>/dev/null | head -1 || true)
if [ -z "$library" ]; then
  echo "tight_inclusion.sh: SKIPPED: no Tight Inclusion build (libtight_inclusion.a) under '${ti_build}'"
  exit 0
fi
ti_source=$(sed -n 's/^TightInclusion_SOURCE_DIR:STATIC=//p' "$ti_build/CMakeCache.txt")
[ -f "$ti_source/src/tight_inclusion/config.hpp" ] || { echo "no configured Tight Inclusion source at '$ti_source'"; exit 1; }
[ -f build/libexactccd.a ] && [ -f build/libexactccd_tools.a ] || { echo "build exactccd into build/ first"; exit 1; }
c++ -std=c++17 -O3 -DNDEBUG -ffp-contract=off -Iinclude -Ilib -Itools/lib -Ibuild/include -I"$ti_source/src" -I/usr/include/eigen3 \
    tools/bench/tight_inclusion_bench.cpp build/libexactccd_tools.a build/libexactccd.a "$library" \
    -lmpfi -lmpfr -lgmpxx -lgmp -lspdlog -lfmt -pthread -o build/tight_inclusion_bench
files() { ls "$@" | paste -sd, -; }
sets=("simulation-like=$(files data/sim/*.csv)"
      "degenerate catalogue=$(files data/catalogue/*.csv)"
      "degenerate families=$(files data/families/*.csv)")
sample=../shared/data/sample-queries/unit-tests
if [ -d "$sample" ]; then sets=("shared unit-tests=$(files "$sample"/*/*.csv)" "${sets[@]}"); fi
echo "commit $(git rev-parse --short HEAD), $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "Tight Inclusion: $ti_source ($(git -C "$ti_source" rev-parse --short HEAD 2>/dev/null || echo '?')), $library"
echo "repetitions: $repetitions (Tight Inclusion's log lines, which its logger writes to stdout: build/tight_inclusion_bench.log)"
build/tight_inclusion_bench "$repetitions" "${sets[@]}" > build/tight_inclusion_bench.out
grep -v '^\[' build/tight_inclusion_bench.out
grep '^\[' build/tight_inclusion_bench.out > build/tight_inclusion_bench.log || true
echo "Tight Inclusion log lines: $(wc -l < build/tight_inclusion_bench.log); the most frequent:"
cut -d']' -f3- build/tight_inclusion_bench.log | sort | uniq -c | sort -rn | head -3
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg), $(date -u '+%H:%M UTC')"
