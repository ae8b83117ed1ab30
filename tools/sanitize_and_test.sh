#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/
# (clang 14, everything -O1 with line tables only; UBSan findings abort; benchmarks are not
# built; the Python tests preload the shared ASan runtime into python) and runs it; no test
# found is an error (docs/design/sanitizers_and_fuzzing.md). A step of .ci/run.
# Usage: tools/sanitize_and_test.sh [extra ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DLINESURF_SANITIZE=address,undefined \
  -DLINESURF_BUILD_CLI=ON -DLINESURF_BUILD_TESTS=ON -DLINESURF_BUILD_BENCHMARKS=OFF \
  -DLINESURF_BUILD_PYTHON=ON
cmake --build build-asan -j "$jobs"
# Exported, so that the linesurf processes the CLI tests start are checked the same way: a
# finding there aborts (a signal exit the tests fail on).
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:abort_on_error=1
ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$jobs" "$@"
