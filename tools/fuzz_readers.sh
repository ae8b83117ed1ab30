#!/usr/bin/env bash
# Builds the libFuzzer targets of the readers with clang (+ ASan, UBSan) in build-fuzz/ and runs
# each for SECONDS seconds (default 60), two at a time, starting from the committed seed corpus
# (docs/design/sanitizers_and_fuzzing.md). A crash, leak, timeout or internal error is a finding:
# the reproducer is left in build-fuzz/findings/ and the script fails.
# Usage: tools/fuzz_readers.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DLINESURF_FUZZ=ON \
  -DLINESURF_BUILD_BENCHMARKS=OFF
cmake --build build-fuzz -j "$(nproc)" --target linesurf_fuzzers
mkdir -p build-fuzz/findings build-fuzz/logs
targets=$(ls tests/robustness/fuzz/corpus)
run_one() {
  local name=$1 seconds=$2
  mkdir -p "build-fuzz/corpus/$name"
  # The first directory collects new inputs; the committed corpus is only read.
  if build-fuzz/bin/linesurf_fuzz_"$name" "build-fuzz/corpus/$name" \
      "tests/robustness/fuzz/corpus/$name" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/findings/$name-" > "build-fuzz/logs/$name.log" 2>&1; then
    echo "fuzz $name: ${seconds} s, no finding ($(grep -o 'stat::number_of_executed_units: *[0-9]*' "build-fuzz/logs/$name.log" | grep -o '[0-9]*$') runs)"
  else
    echo "fuzz $name: FINDING, see build-fuzz/logs/$name.log and build-fuzz/findings/"
    tail -40 "build-fuzz/logs/$name.log"
    return 1
  fi
}
export -f run_one
export ASAN_OPTIONS=detect_leaks=1
echo "$targets" | xargs -P 2 -I{} bash -c "run_one {} $seconds"
