#!/usr/bin/env bash
# Installs every build and test dependency of linesurf from Debian 12 packages.
# Run as root on Debian 12 (bookworm). Idempotent.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
  build-essential cmake pkg-config git \
  libcgal-dev libeigen3-dev libtbb-dev libopenvdb-dev libboost-iostreams-dev \
  libsuitesparse-dev coinor-libclp-dev coinor-libcbc-dev nlohmann-json3-dev libcli11-dev \
  libgmp-dev libmpfr-dev libgtest-dev libbenchmark-dev \
  libpng-dev libmaxflow-dev \
  clang-14 libfuzzer-14-dev libclang-rt-14-dev \
  python3-dev python3-numpy pybind11-dev python3-jsonschema \
  python3-distributed python3-mpi4py openmpi-bin
