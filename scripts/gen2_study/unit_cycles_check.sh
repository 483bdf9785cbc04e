#!/usr/bin/env bash
# gen2 study: the SystemC model improved2-sc against the whole-unit prototype trirast_improved2_top, cycle for
# cycle (docs/gen2-design.md, "The C++ datapath and SystemC model").
#
#   scripts/gen2_study/unit_cycles_check.sh [WORKDIR]
#
# For each scene of SCENES (default builtin:mixed builtin:highpoly-far), each corner form of FORMS
# (default 0 1: DSP products, radix 16), each span FIFO depth of DEPTHS (default 8; powers of two
# up to 8, both units' FifoDepth) and each sink (always ready; ready two cycles of three, the
# testbench's +stall = --sink-stall periodic:2:1; and random:SEED:PERCENT for each SEED:PERCENT of
# RSINKS, default none, the testbench's +rseed=SEED +rpct=PERCENT): the scene's triangles go through
# scripts/gen2_study/g2_unit_tb.sv (Verilator; +cycles=FILE writes trirast_improved2_top's accept, first-span
# and done cycle per triangle) and through `trirast raster --engine improved2-sc --cycles`, and the
# two CSVs are compared row by row (the testbench's index is the triangle's position among the
# non-degenerate ones, which is the model's row order). Prints one line per run and exits 1 on
# any difference. TRIRAST (default build/trirast) must be built.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
ME="unit_cycles_check.sh"
WORK="${1:-$ROOT/build/gen2_unit_cycles}"
mkdir -p "$WORK"
WORK="$(cd "$WORK" && pwd)"
R="$ROOT/rtl"
S="$ROOT/scripts/gen2_study"
TRIRAST="${TRIRAST:-$ROOT/build/trirast}"
SCENES="${SCENES:-builtin:mixed builtin:highpoly-far}"
FORMS="${FORMS:-0 1}"
DEPTHS="${DEPTHS:-8}"
RSINKS="${RSINKS:-}"
PKG="$WORK/trirast_pkg.sv"
[ -x "$TRIRAST" ] || { echo "$ME: $TRIRAST not found (build it or set TRIRAST)" >&2; exit 1; }
command -v verilator >/dev/null || { echo "$ME: verilator not found in PATH" >&2; exit 1; }
python3 "$ROOT/scripts/gen_params.py" --subpixel-bits 8 --coord-bits 16 --box-bits 14 \
  --endpoints 1 --fifo-depth 8 --sv "$PKG" >/dev/null ||
  { echo "$ME: scripts/gen_params.py failed" >&2; exit 1; }
gen1_srcs=()
while read -r f; do
  case "$f" in trirast_pkg.sv) ;; trirast_*.sv) gen1_srcs+=("$R/$f") ;; esac
done < "$R/trirast_improved.f"
status=0
for form in $FORMS; do
 for depth in $DEPTHS; do
  dir="$WORK/unit${form}d$depth"
  rm -rf "$dir"
  verilator --binary -j 1 -Wno-fatal -Wno-lint -Wno-style --timing -I"$R" "$PKG" \
    -DG2_CORNER_FORM="$form" -DG2_FIFO_DEPTH="$depth" "${gen1_srcs[@]}" \
    "$R/trirast_corner_products.sv" "$R/trirast_corner_serial.sv" "$R/trirast_direct_test_2x2.sv" "$R/trirast_edge_lane2.sv" \
    "$R/trirast_edge_walker2.sv" "$R/trirast_span_generator2.sv" "$R/trirast_walk_stage2.sv" "$R/trirast_improved2_top.sv" \
    "$S/g2_unit_tb.sv" --top-module g2_unit_tb -Mdir "$dir" >"$dir.log" 2>&1 ||
    { echo "$ME: Verilator build failed ($dir.log)" >&2; exit 1; }
 done
done
for sc in $SCENES; do
  name="$(basename "${sc#builtin:}")"   # a mesh file by its file name
  tri="$WORK/$name.tri"; hex="$WORK/$name.hex"
  SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$TRIRAST" raster --engine golden --scene "$sc" \
    --export-tris "0:9999999:$tri" >/dev/null 2>"$WORK/export.log" ||
    { echo "$ME: --export-tris on $sc failed ($WORK/export.log)" >&2; exit 1; }
  args="$(python3 "$S/unit_tris.py" "$tri" "$hex")" ||
    { echo "$ME: unit_tris.py failed on $tri" >&2; exit 1; }
  w="$(echo "$args" | sed -n 's/.*+w=\([0-9]*\).*/\1/p')"
  h="$(echo "$args" | sed -n 's/.*+h=\([0-9]*\).*/\1/p')"
  for form in $FORMS; do
   cf=$([ "$form" = 0 ] && echo dsp || echo radix16)
   for depth in $DEPTHS; do
    # Sinks: always ready; two cycles of three; each SEED:PERCENT of RSINKS as random:SEED:PERCENT.
    sinks=("none" "periodic:2:1")
    for rs in $RSINKS; do sinks+=("random:$rs"); done
    for sink in "${sinks[@]}"; do
      case "$sink" in
        none) st="" ;;
        periodic:2:1) st="+stall" ;;
        random:*) rs="${sink#random:}"; st="+rseed=${rs%%:*} +rpct=${rs#*:}" ;;
      esac
      tag="$name.form$form.d$depth.${sink//:/_}"
      # shellcheck disable=SC2086
      "$WORK/unit${form}d$depth/Vg2_unit_tb" +tris="$hex" $args $st +cycles="$WORK/$tag.rtl.csv" \
        >"$WORK/$tag.rtl.log" 2>&1 || true
      grep -q '^g2_unit_tb: 0 errors' "$WORK/$tag.rtl.log" ||
        { echo "$ME: g2_unit_tb failed on $tag ($WORK/$tag.rtl.log)" >&2; exit 1; }
      SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$TRIRAST" raster --engine improved2-sc --scene "$sc" \
        --width "$w" --height "$h" --corner-form "$cf" --sink-stall "$sink" --fifo-depth "$depth" \
        --endpoints 1 --cycles "$WORK/$tag.model.csv" >/dev/null 2>"$WORK/$tag.model.log" ||
        { echo "$ME: trirast improved2-sc failed on $tag ($WORK/$tag.model.log)" >&2; exit 1; }
      python3 - "$WORK/$tag.rtl.csv" "$WORK/$tag.model.csv" "$sc, CornerForm $form ($cf), FIFO $depth, sink $sink" <<'PY' || status=1
import csv, sys
rtl = list(csv.DictReader(open(sys.argv[1])))
model = list(csv.DictReader(open(sys.argv[2])))
label = sys.argv[3]
diffs = 0
shown = 0
if len(rtl) != len(model):
    print(f"{label}: {len(rtl)} triangles in the RTL run, {len(model)} in the model's")
    diffs += 1
for i, (r, m) in enumerate(zip(rtl, model)):
    if int(r["index"]) != i:
        sys.exit(f"{sys.argv[1]}: row {i} has index {r['index']}")
    bad = [k for k in ("accept_cycle", "first_span_cycle", "done_cycle", "spans") if int(r[k]) != int(m[k])]
    if bad:
        diffs += 1
        if shown < 5:
            shown += 1
            print(f"  triangle {i} (scene index {m['tri']}): " +
                  ", ".join(f"{k} rtl {r[k]} model {m[k]}" for k in bad))
total_rtl = max(int(r["done_cycle"]) for r in rtl) + 1 if rtl else 0
total_model = max(int(m["done_cycle"]) for m in model) + 1 if model else 0
print(f"{label}: {min(len(rtl), len(model))} triangles compared, {diffs} differences "
      f"(last done + 1: rtl {total_rtl}, model {total_model})")
sys.exit(1 if diffs else 0)
PY
    done
   done
  done
done
exit $status
