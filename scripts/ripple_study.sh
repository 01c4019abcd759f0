#!/usr/bin/env bash
# Force ripple of the line-test travel for 2x2, 3x3 and 4x4 contact points per element on two
# meshes (experiments/aa3003o/studies/ripple_*.toml). Ripple = (max - min) / mean of Fz over the
# middle 60 % of the B -> C travel. Prints a table; results in ${OUT:-out/ripple}/.
set -euo pipefail
cd "$(dirname "$0")/.."
spifit=build/cli/spifit
out=${OUT:-out/ripple}
mkdir -p "$out"
printf '%-8s %-8s %10s %10s %10s %12s %8s\n' mesh points mean_Fz ripple_Fz mean_Fx increments wall_s
for f in experiments/aa3003o/studies/ripple_n*_p*.toml; do
  name=$(basename "$f" .toml)
  "$spifit" -q run "$f" --out "$out/$name" --force
  # B -> C: tool_x from -10 to 10; the middle 60 %: -6 .. 6.
  awk -F, -v name="$name" 'NR > 2 && $2 >= -6 && $2 <= 6 && $4 < 5.0 {
      n++; s += $7; sx += $5; if (n == 1 || $7 > mx) mx = $7; if (n == 1 || $7 < mn) mn = $7 }
    END { split(name, a, "_"); printf "%-8s %-8s %10.2f %9.2f%% %10.2f", substr(a[2], 2), substr(a[3], 2), s / n, 100 * (mx - mn) / (s / n), sx / n }' \
    "$out/$name/force.csv"
  python3 -c "import json,sys; d=json.load(open('$out/$name/summary.json')); print(' %12d %8.1f' % (d['increments'], d['wall_seconds']))"
done
