#!/usr/bin/env bash
# spifit against CalculiX on the centre indent of the line-test sheet (bench/calculix/README.md).
# Writes the spifit scene and the CalculiX deck of the same problem, runs both (one after the
# other, each timed with the wall clock), and prints the tool force Fz of both at the same
# depths, their relative difference, both wall times, the time ratio and the element counts.
# Needs python3 (standard library) and ccx (Debian package calculix-ccx, CalculiX 2.20).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"

usage() {
  cat <<EOF
Usage: bench/calculix/compare.sh [options]
  --smoke                 coarse meshes and 2 mm of travel (about 20 s): spifit 60 (half model,
                          1 800 shells), CalculiX 24 x 24 graded (576 S4), depths 0.5, 1, 1.5, 2
  --spifit-elements N     spifit [sheet] elements across the full side (default 100)
  --spifit-full           full spifit model (default: half model, y >= 0: N x N/2 shells;
                          the default 100 gives 5 000 shells)
  --spifit-grading G      spifit [sheet] grading, edge / centre element size (default 1)
  --spifit-element E      spifit [sheet] element: shell (default), brick or solid_shell
  --spifit-layers N       spifit [sheet] layers of bricks (default 3)
  --ccx-elements N        CalculiX S4 elements across the side, full model (default 40: 1 600)
  --ccx-element E          CalculiX sheet elements: S4 (default; ccx expands each into one C3D8I
                          through the thickness) or C3D8I (bricks, --ccx-layers through it)
  --ccx-layers N          C3D8I layers through the thickness (default 1)
  --ccx-grading G         CalculiX mesh grading, edge / centre element size (default 8:
                          1.33 mm at the centre, 10.6 mm at the edge for 40 elements)
  --contact TYPE          CalculiX contact: surface (SURFACE TO SURFACE, default) or node
                          (NODE TO SURFACE: a penalty spring at each slave node)
  --ccx-slave S           CalculiX slave surface: faces (the sheet's SPOS faces, default; contact on
                          the top face, tool sphere R) or nodes (mid-surface nodes, sphere R + t/2;
                          needs --contact node)
  --depth D               tool travel from first touch [mm] (default 5)
  --depths LIST           depths of the table, comma-separated (default 0.5,1,2,3,4,5)
  --penalty K             contact penalty [N/mm^3], both codes (default 1000)
  --threads T             spifit --threads and OMP_NUM_THREADS of ccx (default 2)
  --out DIR               run directory (default out/ccx_compare in the repository); emptied first
                          when it is one this script wrote (it holds ccx/job.inp), else refused
  --spifit PATH           spifit executable (default \$SPIFIT or $root/build/cli/spifit)
  --ccx PATH              ccx executable (default \$CCX or ccx)
EOF
}

spifit="${SPIFIT:-$root/build/cli/spifit}"
ccx="${CCX:-ccx}"
sp_elements=100
sp_half=true
sp_grading=1
sp_element=shell
sp_layers=3
cx_element=S4
cx_layers=1
cx_elements=40
cx_grading=8
contact=surface
slave=faces
depth=5
depths=""
penalty=1000
threads=2
out="$root/out/ccx_compare"
smoke=0
while [ $# -gt 0 ]; do
  case "$1" in
    --smoke) smoke=1 ;;
    --spifit-elements) sp_elements="$2"; shift ;;
    --spifit-full) sp_half=false ;;
    --spifit-grading) sp_grading="$2"; shift ;;
    --spifit-element) sp_element="$2"; shift ;;
    --spifit-layers) sp_layers="$2"; shift ;;
    --ccx-element) cx_element="$2"; shift ;;
    --ccx-layers) cx_layers="$2"; shift ;;
    --ccx-elements) cx_elements="$2"; shift ;;
    --ccx-grading) cx_grading="$2"; shift ;;
    --contact) contact="$2"; shift ;;
    --ccx-slave) slave="$2"; shift ;;
    --depth) depth="$2"; shift ;;
    --depths) depths="$2"; shift ;;
    --penalty) penalty="$2"; shift ;;
    --threads) threads="$2"; shift ;;
    --out) out="$2"; shift ;;
    --spifit) spifit="$2"; shift ;;
    --ccx) ccx="$2"; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare.sh: unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
  shift
done
if [ "$smoke" = 1 ]; then
  sp_elements=60
  cx_elements=24
  depth=2
  [ -n "$depths" ] || depths="0.5,1,1.5,2"
fi
[ -n "$depths" ] || depths="0.5,1,2,3,4,5"
case "$contact" in
  surface) contact_type="SURFACE TO SURFACE" ;;
  node) contact_type="NODE TO SURFACE" ;;
  *) echo "compare.sh: --contact surface|node" >&2; exit 2 ;;
esac
command -v python3 >/dev/null || { echo "compare.sh: needs python3" >&2; exit 1; }
command -v "$ccx" >/dev/null || { echo "compare.sh: no ccx ($ccx): apt-get install calculix-ccx" >&2; exit 1; }
[ -x "$spifit" ] || { echo "compare.sh: no spifit executable at $spifit (build it, or --spifit PATH)" >&2; exit 1; }

if [ -d "$out" ] && [ -n "$(ls -A "$out")" ] && [ ! -f "$out/ccx/job.inp" ]; then
  echo "compare.sh: $out is not empty and not a directory of this script: give another --out" >&2
  exit 2
fi
rm -rf "$out"
mkdir -p "$out/ccx"

# --- spifit scene: bench/calculix/indent_centre.toml with the mesh, depth and penalty replaced
awk -v el="$sp_elements" -v half="$sp_half" -v gr="$sp_grading" -v d="$depth" -v k="$penalty" \
    -v family="$sp_element" -v layers="$sp_layers" \
    -v card="$here/aa3003o_c4_mises.toml" '
  /^material = / { print "material = \"" card "\""; next }
  /^elements = / { print "elements = " el; next }
  /^half = / { print "half = " half; if (gr != 1) print "grading = " gr
                if (family != "shell") print "element = \"" family "\""
                if (family == "brick") print "layers = " layers
                next }
  /^name = "B"/ { inB = 1 }
  inB && /^z = / { print "z = -" d; inB = 0; next }
  /^penalty = / { print "penalty = " k; next }
  { print }' "$here/indent_centre.toml" > "$out/indent_centre.toml"

# --- CalculiX deck
python3 "$here/make_deck.py" --elements "$cx_elements" --grading "$cx_grading" --depth "$depth" \
  --element "$cx_element" --layers "$cx_layers" \
  --penalty "$penalty" --contact-type "$contact_type" --slave "$slave" -o "$out/ccx/job.inp" 2> "$out/ccx/make_deck.log"
cat "$out/ccx/make_deck.log"

now() { date +%s.%N; }

echo "spifit: $spifit --threads $threads run $out/indent_centre.toml --out $out/spifit"
t0=$(now)
"$spifit" --threads "$threads" run "$out/indent_centre.toml" --out "$out/spifit" --force > "$out/spifit.log" 2>&1 \
  || { cat "$out/spifit.log"; echo "compare.sh: spifit failed" >&2; exit 1; }
t1=$(now)
echo "ccx: (cd $out/ccx && OMP_NUM_THREADS=$threads $ccx -i job)"
t2=$(now)
cx_rc=0
(cd "$out/ccx" && OMP_NUM_THREADS="$threads" "$ccx" -i job > ccx.log 2>&1) || cx_rc=$?
t3=$(now)
if [ "$cx_rc" != 0 ] || grep -q '\*ERROR' "$out/ccx/ccx.log"; then
  grep -A2 '\*ERROR' "$out/ccx/ccx.log" | head -6 || tail -20 "$out/ccx/ccx.log"
  echo "compare.sh: ccx stopped (exit $cx_rc): the table shows the depths it reached" >&2
fi
[ -s "$out/ccx/job.dat" ] || { echo "compare.sh: no $out/ccx/job.dat" >&2; exit 1; }

cx_wall=$(python3 -c "print($t3 - $t2)")
sp_wall=$(python3 -c "print($t1 - $t0)")
sp_count=$(python3 -c "import json; print(json.load(open('$out/spifit/summary.json'))['model']['elements'])")
sp_desc="$sp_elements x $sp_elements"
sp_kind="shells"
[ "$sp_element" = brick ] && sp_kind="bricks, $sp_layers layers"
[ "$sp_element" = solid_shell ] && sp_kind="solid-shells"
cx_kind="$cx_element"
[ "$cx_element" = C3D8I ] && cx_kind="C3D8I, $cx_layers layer(s)"
[ "$sp_half" = true ] && sp_desc="$sp_elements x $((sp_elements / 2)), half model"
[ "$sp_grading" != 1 ] && sp_desc="$sp_desc, grading $sp_grading"
cx_desc="$cx_elements x $cx_elements, full model, $contact_type, slave $slave"
[ "$cx_grading" != 1 ] && cx_desc="$cx_desc, grading $cx_grading"

echo
echo "Centre indent, 182 x 182 x 1.2 mm, clamped, R 5 tool, $depth mm, penalty $penalty N/mm^3, von Mises + Swift (C.4)"
rc=0
python3 "$here/compare_table.py" --spifit "$out/spifit" --ccx "$out/ccx/job.dat" --depths "$depths" \
  --json "$out/table.json" > "$out/table.md" || rc=$?
cat "$out/table.md"
cx_count=$((cx_elements * cx_elements))
[ "$cx_element" = C3D8I ] && cx_count=$((cx_count * cx_layers))
python3 - "$sp_count" "$sp_desc" "$sp_wall" "$cx_count" "$cx_desc" "$cx_wall" "$threads" "$sp_kind" "$cx_kind" <<'EOF' | tee -a "$out/table.md"
import sys
spn, spd, spw, cxn, cxd, cxw, th, spk, cxk = sys.argv[1:]
spw, cxw = float(spw), float(cxw)
print()
print("| code | elements | wall time [s] |")
print("|---|---|---:|")
print("| spifit | %s %s (%s) | %.1f |" % (spn, spk, spd, spw))
print("| CalculiX | %s %s (%s) | %.1f |" % (cxn, cxk, cxd, cxw))
print()
print("time ratio CalculiX / spifit: %.1f (threads: %s each)" % (cxw / spw, th))
EOF
echo "files: $out (indent_centre.toml, spifit/, ccx/job.inp, ccx/job.dat, table.md, table.json)"
exit "$rc"
