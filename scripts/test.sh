#!/usr/bin/env bash
# README command 2: install missing packages, build, run the test suite (all but the
# "long" label; run those with: ctest --test-dir build -L long).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh spifit_tests   # spifit and the tests, not the benchmarks
ctest --test-dir build -LE long -j "$(nproc)" --output-on-failure --timeout 600
