#!/usr/bin/env bash
# Installs what is missing, builds exactccd and runs the whole test suite (CTest), then the
# same suite built with AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer, then
# the libFuzzer targets built with clang and their smoke runs (docs/fuzzing.md).
# Usage: bash tools/test.sh     (build directories: build/, build-native/, build-asan/,
#                                build-fuzz-clang/)
# A Release build with -march=native runs the suite too. EXACTCCD_SKIP_NATIVE=1,
# EXACTCCD_SKIP_SANITIZERS=1 and EXACTCCD_SKIP_FUZZERS=1 skip those passes (CI runs them all).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

echo "== Release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_WERROR=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

if [ "${EXACTCCD_SKIP_NATIVE:-0}" != "1" ]; then
  # The filters' bounds must not depend on the instruction set: the same suite built with
  # -march=native (FMA, AVX where the machine has them; the library keeps -ffp-contract=off).
  # Only the suites of the floating-point code are built and run here (filters, TOIs, minimum
  # separation, the environment guard, wide exponents): the scene, I/O, CLI and Python suites
  # do not depend on the instruction set and run in the pass above (this keeps CI within 30
  # minutes on 2 cores).
  echo "== Release build with -march=native and the floating-point suites"
  cmake -S . -B build-native -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_NATIVE=ON \
        -DEXACTCCD_BUILD_BENCHMARKS=OFF -DEXACTCCD_BUILD_PYTHON=OFF -DEXACTCCD_WERROR=ON
  native_suites=(test_filtered test_volume_sign test_volume_exclusion test_catalogue test_families
                 test_toi test_wide_exponents test_regressions test_fuzz_regressions test_sample_queries
                 test_min_separation test_min_separation_catalogue test_distance_sign
                 test_fixed_integer_stage test_parallel_factor_strategy test_fp_environment)
  cmake --build build-native -j"$jobs" --target "${native_suites[@]}"
  # Suites not built here have a placeholder test "<suite>_NOT_BUILT" (gtest_discover_tests).
  ctest --test-dir build-native --output-on-failure -j"$jobs" -E '^(package|cli|docs|python|fuzz)\.|_NOT_BUILT$'
fi

if [ "${EXACTCCD_SKIP_SANITIZERS:-0}" != "1" ]; then
  echo "== ASan + UBSan + LSan build and tests"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEXACTCCD_SANITIZE=ON \
        -DEXACTCCD_BUILD_BENCHMARKS=OFF -DEXACTCCD_WERROR=ON
  cmake --build build-asan -j"$jobs"
  # The package test installs and builds a consumer without sanitizers: covered above. The two
  # longest CLI runs (fuzz-against with shrinking, generate/check on the wide families: over 3
  # minutes together under ASan) run in the Release pass only, to keep CI under 30 minutes;
  # fuzz-against's plug-in loading and shrinking are then not run under the sanitizers. Likewise
  # the two longest minimum-separation property runs (near queries checked with CGAL's
  # constructions, every bundled file at four distances: about 110 s under ASan); the separation
  # code runs under the sanitizers in test_min_separation, the catalogue and the other
  # MinSeparationCgal tests. Also left to the Release pass (about 2 minutes under ASan
  # together): regenerating data/sim (cli.sim_fresh), the largest filtered-equals-exact sweep
  # over every kind (the others run here), and the two largest broad-phase comparisons with
  # brute force (the broad phase runs here in the other scene and broad-phase tests).
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs" \
      -E '^(package\.|cli\.(fuzz_against|families_wide|merge|cluster_slurm|sim_fresh)$|MinSeparationCgal\.NearQueries$|MinSeparationData\.|MinSeparation\.FilteredEqualsExactForEveryKind$|SceneBroadPhase\.RefitGivesTheCandidatesOfARebuild$|BroadPhase\.RandomAndDegenerateScenesMatchSweepAndBruteForce$)'
fi

if [ "${EXACTCCD_SKIP_FUZZERS:-0}" != "1" ]; then
  echo "== clang libFuzzer build and fuzz smoke tests"
  cmake -S . -B build-fuzz-clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DEXACTCCD_BUILD_FUZZERS=ON -DEXACTCCD_BUILD_TESTS=OFF -DEXACTCCD_BUILD_BENCHMARKS=OFF \
        -DEXACTCCD_WERROR=ON
  cmake --build build-fuzz-clang -j"$jobs"
  ctest --test-dir build-fuzz-clang --output-on-failure -j"$jobs" -R '^fuzz\.'
fi
