#!/usr/bin/env bash
# The improved2 unit's two corner forms against each other over every input at reduced widths
# (docs/formal.md, "Not proven, and why", the improved2 corner unit's two forms): a Verilator C++
# build of tb/improved2/improved2_corner_forms_exhaustive_tb.sv (the serial form, radix 16 and
# radix 4, beside the products form) and its driver improved2_corner_forms_exhaustive.cpp, with
# the package of the configuration subpixel bits 0, coordinate bits 2, box bits 1
# (scripts/gen_params.py: P = 3, F = 1, PixBits 1, BoxBits 1; every triangle, corner, Xmax and
# edge mask, the unit's drive protocol).
#
#   tb/improved2/improved2_corner_forms_exhaustive.sh [WORKDIR]
#       (ctest improved2_corner_forms_exhaustive) exit 0 when both forms agree on every case
#   tb/improved2/improved2_corner_forms_exhaustive.sh --plant NAME [WORKDIR]
#       (ctest improved2_corner_forms_exhaustive_plant_NAME) the same on a copy of the RTL with
#       the planted bug NAME; exit 0 (CAUGHT) only when the comparison reports a difference
#   tb/improved2/improved2_corner_forms_exhaustive.sh --random-tiny N [--plant NAME] [WORKDIR]
#       (ctest improved2_corner_forms_random_tiny) not every case: N random cases (a fixed seed;
#       vertices uniform, extreme or small) at the tiny configuration (subpixel bits 0, coordinate
#       bits 8, box bits 6: P = 9), where radix 16 takes up to three digits and E can be far
#   tb/improved2/improved2_corner_forms_exhaustive.sh --list-plants
#
# WORKDIR (default build/improved2_corner_forms) gets the package, the build (obj, its log
# build.log), the planted copy (plant/) and the run's output (run.out).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
ME="improved2_corner_forms_exhaustive.sh"
PLANT=""
RANDOM_CASES=""

# The plants: NAME FILE (under rtl/) OLD NEW; OLD must occur exactly once in FILE.
plant_spec() {
  case "$1" in
    second_run_carry)   # the second run's dx = dxL + Xmax * 2^F + 1 (its adder's carry-in set)
      PLANT_FILE=common/trirast_corner_serial.sv
      PLANT_OLD='{second_i ? DW'"'"'(mx_q) : ~vxw, !second_i}'
      PLANT_NEW='{second_i ? DW'"'"'(mx_q) : ~vxw, 1'"'"'b1}' ;;
    *) return 1 ;;
  esac
}
PLANTS="second_run_carry"

while [ $# -gt 0 ]; do
  case "$1" in
    --plant)
      [ $# -ge 2 ] || { echo "$ME: --plant needs a name (--list-plants)" >&2; exit 2; }
      plant_spec "$2" || { echo "$ME: no plant $2 (plants: $PLANTS)" >&2; exit 2; }
      PLANT="$2"; shift 2 ;;
    --random-tiny)
      [ $# -ge 2 ] || { echo "$ME: --random-tiny needs a count of cases" >&2; exit 2; }
      RANDOM_CASES="$2"; shift 2 ;;
    --list-plants) echo "$PLANTS" | tr ' ' '\n'; exit 0 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "$ME: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
. "$ROOT/tb/improved2/improved2_checks_workdir.sh"
improved2_checks_workdir "$ROOT/build/improved2_corner_forms" "$@"

WIDTHS=(--subpixel-bits 0 --coord-bits 2 --box-bits 1)
[ -z "$RANDOM_CASES" ] || WIDTHS=(--subpixel-bits 0 --coord-bits 8 --box-bits 6)   # tiny
python3 "$ROOT/scripts/gen_params.py" "${WIDTHS[@]}" --sv "$WORK/trirast_pkg.sv" >/dev/null ||
  { echo "$ME: scripts/gen_params.py failed" >&2; exit 1; }

SERIAL="$ROOT/rtl/common/trirast_corner_serial.sv"
PRODUCTS="$ROOT/rtl/improved2/trirast_improved2_corner_products.sv"
rm -rf "${WORK:?}/plant"
if [ -n "$PLANT" ]; then
  mkdir -p "$WORK/plant"
  copy="$WORK/plant/$(basename "$PLANT_FILE")"
  PLANT_OLD="$PLANT_OLD" PLANT_NEW="$PLANT_NEW" python3 - "$ROOT/rtl/$PLANT_FILE" "$copy" <<'EOF' ||
import os, sys
text = open(sys.argv[1]).read()
old, new = os.environ["PLANT_OLD"], os.environ["PLANT_NEW"]
if text.count(old) != 1:
    sys.exit(f"the plant's text occurs {text.count(old)} times in {sys.argv[1]}, not once")
open(sys.argv[2], "w").write(text.replace(old, new))
EOF
    { echo "$ME: plant $PLANT does not apply to rtl/$PLANT_FILE" >&2; exit 1; }
  case "$PLANT_FILE" in
    */trirast_corner_serial.sv) SERIAL="$copy" ;;
    */trirast_improved2_corner_products.sv) PRODUCTS="$copy" ;;
  esac
fi

rm -rf "${WORK:?}/obj"
verilator --cc --exe --build -j 1 -O3 --x-assign fast --x-initial fast -Wno-fatal -Wno-lint \
  -Wno-style -CFLAGS -O2 -I"$ROOT/rtl/common" "$WORK/trirast_pkg.sv" "$SERIAL" "$PRODUCTS" \
  "$ROOT/tb/improved2/improved2_corner_forms_exhaustive_tb.sv" \
  "$ROOT/tb/improved2/improved2_corner_forms_exhaustive.cpp" \
  --top-module improved2_corner_forms_exhaustive_tb -Mdir "$WORK/obj" >"$WORK/build.log" 2>&1 ||
  { echo "$ME: Verilator build failed ($WORK/build.log)" >&2; exit 1; }

rc=0
"$WORK/obj/Vimproved2_corner_forms_exhaustive_tb" ${RANDOM_CASES:+--random "$RANDOM_CASES"} \
  >"$WORK/run.out" 2>&1 || rc=$?
grep '^improved2_corner_forms_exhaustive:' "$WORK/run.out" | head -n 4
if [ -z "$PLANT" ]; then
  [ "$rc" -eq 0 ] && exit 0
  echo "$ME: the corner forms differ, or the cases fell short ($WORK/run.out)" >&2
  exit 1
fi
# A plant is caught when the comparison names a difference (a crash or a build error is not).
if [ "$rc" -eq 1 ] &&
   grep -q '^improved2_corner_forms_exhaustive: radix .*edge' "$WORK/run.out"; then
  echo "$ME: plant $PLANT: CAUGHT"
  exit 0
fi
echo "$ME: plant $PLANT: NOT CAUGHT (exit $rc, $WORK/run.out)" >&2
exit 1
