#!/usr/bin/env bash
# README command 1: install missing packages, build, and run the main job: the bundled
# AA3003-O identification (fit_classic: measured r-values + synthetic curves from card C.2),
# then the N-conflict fit, the bundled material-point scenes and the shell benchmarks.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh spifit   # only what the main job needs
spifit=build/cli/spifit
out=${SPIFIT_DEMO_OUT:-out}
mkdir -p "$out"
echo
echo "== AA3003-O identification: Hill 1948 + Swift (experiments/aa3003o/fit_classic.toml) =="
"$spifit" fit experiments/aa3003o/fit_classic.toml --out "$out/fit_classic" --force
echo "   -> $out/fit_classic/fit.json, card.toml, experiments/*.csv"
echo
echo "== Do the r45 and shear tests agree on N? (experiments/aa3003o/fit_n_conflict.toml) =="
echo "   They do not: the joint fit is NOT USABLE and exits 1, which is the answer this fit exists to give."
code=0
"$spifit" fit experiments/aa3003o/fit_n_conflict.toml --out "$out/fit_n_conflict" --force || code=$?
if [ "$code" -ne 1 ]; then
  echo "spifit: fit_n_conflict was expected to end NOT USABLE (exit 1), it exited $code" >&2
  exit 1
fi
echo
echo "== AA3003-O material-point scenes (results in $out/scenes/<scene>/) =="
for scene in experiments/aa3003o/scenes/*.toml; do
  case "$(basename "$scene")" in indent*|line*|cone*|vwall*) continue ;; esac   # FE scenes below (cones: on demand)
  name=$(basename "$scene" .toml)
  "$spifit" run "$scene" --out "$out/scenes/$name" --force
done
echo
echo "== Shell FE with the spherical tool: indent (thesis §7.1) and the line-test indent (point B) =="
for name in indent indent_line; do
  "$spifit" run "experiments/aa3003o/scenes/$name.toml" --out "$out/scenes/$name" --force
done
echo
echo "== Shell element obstacle course (experiments/benchmarks; results in $out/benchmarks/<name>/) =="
for scene in experiments/benchmarks/*.toml; do
  name=$(basename "$scene" .toml)
  "$spifit" run "$scene" --out "$out/benchmarks/$name" --force
done
