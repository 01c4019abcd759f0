#!/usr/bin/env bash
# Runs the short benchmarks (about 70 s on 2 cores: the indent scenes, the line test's half
# model, the short cone, the material-point and fit_classic timings) with JSON output under
# out/bench/ and regenerates the table between the bench_table markers of
# docs/results/benchmarks.md from it (scripts/bench_table.py): the one time per case that the
# other docs quote. Needs a build with benchmarks (bash scripts/build.sh). Run it on an idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p out/bench
run() {  # run NAME EXECUTABLE [FLAGS...]
  local name=$1 exe=$2
  shift 2
  "$exe" --benchmark_out="out/bench/$name.json" --benchmark_out_format=json "$@" >/dev/null
}
run forming build/bench/bench_forming --benchmark_filter='forming/(indent|indent_line|indent_brick|indent_solid_shell|line_half)/'
run cone build/bench/bench_cone --benchmark_filter='cone70_short'
run material_point build/bench/bench_material_point
run fit_classic build/bench/bench_fit
python3 scripts/bench_table.py --into docs/results/benchmarks.md out/bench/forming.json out/bench/cone.json out/bench/material_point.json \
  out/bench/fit_classic.json
echo "docs/results/benchmarks.md: table regenerated from out/bench/*.json"
