#!/usr/bin/env bash
# Configures (Release) build/ with the CLI, tests and benchmarks switched on explicitly (so a cache
# written by another configuration cannot switch them off), builds everything and runs the whole
# CTest suite; no test found is an error. tools/run_example.sh builds in build-example/.
# Unity build: half the CPU time of one unit per file (docs/design/build_and_ci.md).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON -DLINESURF_BUILD_CLI=ON \
  -DLINESURF_BUILD_TESTS=ON -DLINESURF_BUILD_BENCHMARKS=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"
