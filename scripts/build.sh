#!/usr/bin/env bash
# Configures (Release) and builds spifit into build/: the targets given (spifit for the main job,
# spifit_tests for the test suite), or everything (tests and benchmarks) when none is given.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"
