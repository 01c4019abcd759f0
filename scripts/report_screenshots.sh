#!/usr/bin/env bash
# Screenshots of the reports for the user guide (docs/guide/img/*.png): an indent_line, a
# line_half and a cone70_pie45_short run report, a sweep report and the fit report of the
# bundled demo. On demand (about 2 minutes; needs Debian's chromium: apt-get install chromium).
# Usage: bash scripts/report_screenshots.sh [OUT]   (runs into OUT, default out/screenshots)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/screenshots}
img=docs/guide/img
spifit=build/cli/spifit
browser=$(command -v chromium || true)
if [ -z "$browser" ]; then echo "chromium not found (apt-get install chromium)" >&2; exit 2; fi
[ -x "$spifit" ] || bash scripts/build.sh
mkdir -p "$out" "$img"
for scene in indent_line line_half cone70_pie45_short; do
  "$spifit" -q run "experiments/aa3003o/scenes/$scene.toml" --out "$out/$scene" --force
done
"$spifit" -q sweep experiments/aa3003o/sweep_indent_penalty.toml --out "$out/sweep_indent_penalty" --force
"$spifit" -q fit experiments/aa3003o/fit_classic.toml --out "$out/fit_classic" --force
shot() {  # directory, image name, window height
  "$browser" --headless --disable-gpu --no-sandbox --hide-scrollbars --window-size=1100,"$3" \
    --screenshot="$PWD/$img/$2.png" "file://$(realpath "$1")/report.html" >/dev/null 2>&1
  [ -s "$img/$2.png" ] || { echo "no screenshot of $1/report.html" >&2; exit 1; }
  echo "wrote $img/$2.png"
}
shot "$out/indent_line" run_report_indent_line 2600
shot "$out/line_half" run_report_line_half 3400
shot "$out/cone70_pie45_short" run_report_cone70_short 3400
shot "$out/sweep_indent_penalty" sweep_report_indent_penalty 3000
shot "$out/fit_classic" fit_report_classic 3000
