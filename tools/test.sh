#!/usr/bin/env bash
# Installs what is missing, builds exactccd and runs the whole test suite (CTest), then the
# same suite built with AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer and
# -march=native, then the libFuzzer targets built with clang and their smoke runs
# (docs/fuzzing.md).
# Usage: bash tools/test.sh     (build directories: build/, build-asan/, build-fuzz-clang/)
# Then the Python package installed with pip into a fresh virtual environment and its pytest
# suite run against it (tools/test_pip_install.sh).
# EXACTCCD_SKIP_SANITIZERS=1, EXACTCCD_SKIP_FUZZERS=1 and EXACTCCD_SKIP_PIP=1 skip those passes
# (CI runs them all).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
# Each ctest pass records the tests its build registers and those it runs; at the end
# tools/check_test_sets.py fails unless every registered test ran in some pass.
sets=build/ci-test-sets
record_pass() {  # record_pass NAME BUILD_DIR [the pass's ctest selection...]
  local name=$1 dir=$2; shift 2
  mkdir -p "$sets"
  ctest --test-dir "$dir" --show-only=json-v1 > "$sets/$name.registered.json"
  ctest --test-dir "$dir" --show-only=json-v1 "$@" > "$sets/$name.ran.json"
}

echo "== [${SECONDS} s] Release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXACTCCD_WERROR=ON
cmake --build build -j"$jobs"
# The pytest files (python.test_*) run once, against the pip-installed package, in the pip pass
# below (tools/test_pip_install.sh runs every one of them); here only without that pass.
release_skip=()
if [ "${EXACTCCD_SKIP_PIP:-0}" != "1" ]; then release_skip=(-E '^python\.test_'); fi
rm -rf "$sets"
record_pass release build "${release_skip[@]}"
ctest --test-dir build --output-on-failure -j"$jobs" "${release_skip[@]}"

if [ "${EXACTCCD_SKIP_SANITIZERS:-0}" != "1" ]; then
  # Also built with -march=native (FMA, AVX where the machine has them; the library keeps
  # -ffp-contract=off): the filters' bounds must not depend on the instruction set, and this
  # pass runs the floating-point suites on the other instruction set (one build instead of a
  # separate native Release pass, to keep CI within 30 minutes on 2 cores). -O1 with line
  # tables only (-g1), as AddressSanitizer's documentation suggests: the reports name functions,
  # files and lines, and its heaviest files compile about a third faster than at -O2 (measured on
  # three of them).
  echo "== [${SECONDS} s] ASan + UBSan + LSan build with -march=native, and the tests"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
        -DEXACTCCD_SANITIZE=ON -DEXACTCCD_NATIVE=ON -DEXACTCCD_BUILD_BENCHMARKS=OFF -DEXACTCCD_WERROR=ON
  cmake --build build-asan -j"$jobs"
  # The tests labelled sanitizer-skip (tests/CMakeLists.txt says which and why: long runs of
  # code the other tests run here too) are left to the Release pass, to keep CI under 30 minutes.
  record_pass sanitizers build-asan -LE sanitizer-skip
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE sanitizer-skip
fi

if [ "${EXACTCCD_SKIP_FUZZERS:-0}" != "1" ]; then
  echo "== [${SECONDS} s] clang libFuzzer build and fuzz smoke tests"
  cmake -S . -B build-fuzz-clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
        -DEXACTCCD_BUILD_FUZZERS=ON -DEXACTCCD_BUILD_TESTS=OFF -DEXACTCCD_BUILD_BENCHMARKS=OFF \
        -DEXACTCCD_WERROR=ON
  cmake --build build-fuzz-clang -j"$jobs" --target exactccd_fuzzers  # not the program: fuzz/fuzz.cmake
  record_pass fuzzers build-fuzz-clang -R '^fuzz\.'
  ctest --test-dir build-fuzz-clang --output-on-failure -j"$jobs" -R '^fuzz\.'
fi
if [ "${EXACTCCD_SKIP_PIP:-0}" != "1" ]; then
  # The Python package as users install it: pip install . (offline) into a fresh virtual
  # environment, the pytest suite against the installed package, pip wheel, --user, uninstall.
  echo "== [${SECONDS} s] pip install . and pytest of the installed package (tools/test_pip_install.sh)"
  bash tools/test_pip_install.sh build-pip-test
fi
echo "== [${SECONDS} s] every registered test ran in some pass (tools/check_test_sets.py)"
pip_pass=()
if [ "${EXACTCCD_SKIP_PIP:-0}" != "1" ]; then pip_pass=(--pip-pass python/tests); fi
python3 tools/check_test_sets.py "$sets" "${pip_pass[@]}"
echo "== [${SECONDS} s] all passes done"
