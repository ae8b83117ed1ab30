#!/usr/bin/env bash
# Configures (Release) build/ with the CLI, tests and benchmarks switched on explicitly (so a cache
# written by another configuration cannot switch them off), builds everything and runs the whole
# CTest suite; no test found is an error. tools/run_example.sh builds in build-example/.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLINESURF_BUILD_CLI=ON -DLINESURF_BUILD_TESTS=ON \
  -DLINESURF_BUILD_BENCHMARKS=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"
