#!/usr/bin/env bash
# The improved2 unit's block and whole-unit checks: Verilator --binary builds of the testbenches in
# tb/improved2/ (and tb/common/span_fifo_ram_tb.sv), each holding production RTL (rtl/improved2/,
# rtl/common/) against the improved unit's blocks or the formulas they compute, on random and
# extreme operands and on scenes' triangles. The package is the default configuration's (S = 8,
# coordinate 16, box 14, N = 1, FIFO 8; scripts/gen_params.py).
#
#   tb/improved2/run_checks.sh --check-blocks [WORKDIR]   (ctest improved2_block_checks)
#       improved2_blocks_tb: the corner units (products; signed-digit serial, radix 4 and 16)
#       against the formula, the edge walkers (carry-select and carry-in step) and the span
#       generator against the improved unit's row by row, the direct 2x2 test (50-bit and the
#       unit's split form) against the sign tests written out; then improved2_walk_stage_tb: the
#       walk stage against the improved unit's walk stage and span port on random hand-offs
#       (spans equal; each one cycle later with an always-ready sink).
#   tb/improved2/run_checks.sh --check-unit [WORKDIR]     (ctest improved2_unit_vs_improved)
#       improved2_unit_vs_improved_tb: the whole unit in CornerForm 1 with the build choices its
#       defaults do not take (FifoRam 0, WalkerCs 1, TestHi 0, JobRing 0) against the improved
#       unit on builtin:mixed, sinks always ready and then ready two cycles of three: spans equal
#       span for span, both units' cycles. Needs TRIRAST.
#   tb/improved2/run_checks.sh --check-all [WORKDIR]
#       --check-blocks, then: the walk stage with the iCE40 fit's choices (FifoRam 1, WalkerCs 0);
#       span_fifo_ram_tb (the block-RAM span FIFO against the flip-flop one, depths 2 to 32);
#       improved2_edge_lane_tb (the edge lane, PreIter 0 and 1, against the improved unit's
#       normalizer + lane on random and hard edges and on the edges of LANE_SCENES, with both
#       lanes' cycles); the whole unit in CornerForm 0, 1 and 1 with the iCE40 fit's choices on
#       UNIT_SCENES; improved2_corner_unit_tb (the signed-digit corner unit on full-width operands
#       with the extremes, its cycle count and far-from-0 flags). Without TRIRAST the scene runs
#       are skipped (said on stderr).
#
# Environment: TRIRAST, the trirast binary that exports the scenes' triangles (default
# build/trirast); LANE_SCENES (default "builtin:highpoly-far builtin:mixed"); UNIT_SCENES (default
# "builtin:mixed builtin:highpoly-far"). WORKDIR (default build/improved2_checks) gets the package,
# one Verilator build per testbench (DIR, its log DIR.log) and each run's whole output (DIR*.out).
# Prints each testbench's summary lines; exit 0 when every one printed "0 errors", 1 on a
# difference or a failed build or export, 2 on a usage error.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
ME="run_checks.sh"
MODE=""
while [ $# -gt 0 ]; do
  case "$1" in
    --check-blocks|--check-unit|--check-all)
      [ -z "$MODE" ] || { echo "$ME: one mode at most (got $MODE and $1)" >&2; exit 2; }
      MODE="${1#--check-}"; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "$ME: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ -n "$MODE" ] || { echo "$ME: needs --check-blocks, --check-unit or --check-all (see --help)" >&2; exit 2; }
. "$ROOT/tb/improved2/improved2_checks_workdir.sh"
improved2_checks_workdir "$ROOT/build/improved2_checks" "$@"
R="$ROOT/rtl"
T="$ROOT/tb/improved2"
TRIRAST="${TRIRAST:-$ROOT/build/trirast}"
PKG="$WORK/trirast_pkg.sv"

# tb_build TOP DIR [VERILATOR ARGS/SOURCES ...]: Verilator --binary of testbench TOP (the package
# first) into WORKDIR/DIR, its log in WORKDIR/DIR.log.
tb_build() {
  local top="$1" dir="$2"
  shift 2
  rm -rf "${WORK:?}/$dir"
  verilator --binary -j 1 -Wno-fatal -Wno-lint -Wno-style --timing -I"$R/common" "$PKG" "$@" \
    --top-module "$top" -Mdir "$WORK/$dir" >"$WORK/$dir.log" 2>&1 ||
    { echo "$ME: Verilator build of $top failed ($WORK/$dir.log)" >&2; exit 1; }
}
# tb_run TOP DIR LABEL SKIP [PLUSARGS ...]: runs the testbench built in WORKDIR/DIR (its whole
# output in WORKDIR/DIR-N.out), prints its "TOP:" lines as "LABEL:" (but those matching the regex
# SKIP, when not empty) and exits 1 unless it printed "TOP: 0 errors".
RUNS=0
tb_run() {
  local top="$1" dir="$2" label="$3" skip="$4" out
  shift 4
  RUNS=$((RUNS + 1))
  out="$WORK/$dir-$RUNS.out"
  # (a testbench stopped by $fatal aborts; the shell's note of that is dropped: OUT says why)
  { "$WORK/$dir/V$top" "$@" >"$out" 2>&1; } 2>/dev/null || true
  grep "^$top:" "$out" | { if [ -n "$skip" ]; then grep -v -- "$skip"; else cat; fi; } |
    sed "s/^$top:/$label:/" || true
  grep -q "^$top: 0 errors" "$out" || { echo "$ME: $label found differences ($out)" >&2; exit 1; }
}
# scene_tris SCENE: WORKDIR/scene_NAME.tri, the scene's triangles exported by TRIRAST (once).
scene_tris() {
  local tri="$WORK/scene_${1#builtin:}.tri"
  if [ ! -s "$tri" ]; then
    SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$TRIRAST" raster --engine golden --scene "$1" \
      --export-tris "0:9999999:$tri" >/dev/null 2>"$WORK/scene_export.log" ||
      { echo "$ME: $TRIRAST --export-tris on $1 failed ($WORK/scene_export.log)" >&2; exit 1; }
  fi
  echo "$tri"
}

check_blocks() {
  tb_build improved2_blocks_tb blocks \
    "$R/improved/trirast_improved_edge_walker.sv" "$R/improved/trirast_improved_span_generator.sv" \
    "$R/common/trirast_corner_serial.sv" "$R/improved2/trirast_improved2_corner_products.sv" \
    "$R/improved2/trirast_improved2_edge_walker.sv" "$R/improved2/trirast_improved2_span_generator.sv" \
    "$R/improved2/trirast_improved2_direct_test_2x2.sv" "$T/improved2_blocks_tb.sv"
  tb_run improved2_blocks_tb blocks improved2_blocks_tb ""
}

# check_walk_stage [FIT]: the walk stage against the improved unit's walk stage and span port;
# FIT non-empty: with the iCE40 fit's build choices.
check_walk_stage() {
  local dir=walk_stage label=improved2_walk_stage_tb
  local -a params=()
  if [ -n "${1:-}" ]; then
    dir=walk_stage_fit; label="improved2_walk_stage_tb (FifoRam 1, WalkerCs 0)"
    params=(-GFifoRam=1 -GWalkerCs=0)
  fi
  tb_build improved2_walk_stage_tb "$dir" "${params[@]}" \
    "$R/improved/trirast_improved_edge_walker.sv" "$R/improved/trirast_improved_span_generator.sv" \
    "$R/common/trirast_span_fifo.sv" "$R/common/trirast_span_fifo_ram.sv" "$R/common/trirast_span_port.sv" \
    "$R/improved/trirast_improved_walk_stage.sv" "$R/improved2/trirast_improved2_edge_walker.sv" \
    "$R/improved2/trirast_improved2_span_generator.sv" "$R/improved2/trirast_improved2_walk_stage.sv" \
    "$T/improved2_walk_stage_tb.sv"
  tb_run improved2_walk_stage_tb "$dir" "$label" ""
}

# check_unit CFGS SCENES NEED: the whole improved2 unit against the improved unit
# (improved2_unit_vs_improved_tb.sv) for each configuration of CFGS (0: CornerForm 0; 1:
# CornerForm 1 with the build choices' other values; 1fit: CornerForm 1 with the iCE40 fit's, the
# unit's defaults) on the SCENES exported by TRIRAST: spans equal span for span (sinks always
# ready, then both ready in two cycles of three), and both units' cycles. Without TRIRAST it is
# skipped, or (NEED non-empty) an error.
check_unit() {
  local cfgs="$1" scenes="$2" need="$3" cfg form fit lab sc hex st tri
  local -a improved_srcs improved2_srcs
  if [ ! -x "$TRIRAST" ]; then
    if [ -n "$need" ]; then
      echo "$ME: $TRIRAST not found: the whole-unit check needs it (set TRIRAST)" >&2; exit 1
    fi
    echo "$ME: $TRIRAST not found: the whole-unit check is skipped (set TRIRAST)" >&2
    return 0
  fi
  mapfile -t improved_srcs < <("$ROOT/scripts/rtl_filelist.sh" improved --no-pkg)
  mapfile -t improved2_srcs < <("$ROOT/scripts/rtl_filelist.sh" improved2 --no-pkg)
  for sc in $scenes; do
    tri="$(scene_tris "$sc")"; hex="$WORK/unit_${sc#builtin:}.hex"
    python3 "$T/unit_tris.py" "$tri" "$hex" > "$hex.args" ||
      { echo "$ME: tb/improved2/unit_tris.py failed on $tri" >&2; exit 1; }
  done
  for cfg in $cfgs; do
    form="${cfg:0:1}"; fit=0; lab=""
    [ "$cfg" = 1fit ] && { fit=1; lab=", iCE40 fit"; }
    tb_build improved2_unit_vs_improved_tb "unit$cfg" -DIMPROVED2_CORNER_FORM="$form" \
      -DIMPROVED2_FIT="$fit" "${improved_srcs[@]}" "${improved2_srcs[@]}" \
      "$T/improved2_unit_vs_improved_tb.sv"
    for sc in $scenes; do
      hex="$WORK/unit_${sc#builtin:}.hex"
      for st in "" +stall; do   # sinks always ready; both ready in two cycles of three
        # shellcheck disable=SC2046,SC2086
        tb_run improved2_unit_vs_improved_tb "unit$cfg" \
          "improved2_unit_vs_improved_tb (CornerForm $form$lab, $sc${st:+, $st})" "" \
          +tris="$hex" $(cat "$hex.args") $st
      done
    done
  done
}

# check_edge_lane: the edge lane against the improved unit's normalizer + lane, for PreIter 0 (the
# unit's) and 1, on random and hard edges, then on the edges of LANE_SCENES (when TRIRAST runs).
check_edge_lane() {
  local pre sc tri edges r
  local -a runs=("")
  for pre in 0 1; do
    tb_build improved2_edge_lane_tb "edge_lane$pre" -GPreIter=$pre \
      "$R/improved/trirast_improved_adder_divider.sv" "$R/improved/trirast_improved_edge_lane.sv" \
      "$R/improved/trirast_improved_edge_normalizer.sv" "$R/improved/trirast_improved_edge_walker.sv" \
      "$R/improved2/trirast_improved2_edge_lane.sv" "$T/improved2_edge_lane_tb.sv"
  done
  if [ -x "$TRIRAST" ]; then
    for sc in ${LANE_SCENES:-builtin:highpoly-far builtin:mixed}; do
      tri="$(scene_tris "$sc")"; edges="$WORK/lane_${sc#builtin:}.edges"
      python3 "$T/lane_edges.py" "$tri" "$edges" 2>/dev/null ||
        { echo "$ME: tb/improved2/lane_edges.py failed on $tri" >&2; exit 1; }
      runs+=("+edges=$edges")
    done
  else
    echo "$ME: $TRIRAST not found: the edge lane check runs on random edges only (set TRIRAST)" >&2
  fi
  for pre in 0 1; do
    for r in "${runs[@]}"; do
      # A scene's run repeats the random and hard edges' line: printed once, by the first run.
      # shellcheck disable=SC2086
      tb_run improved2_edge_lane_tb "edge_lane$pre" "improved2_edge_lane_tb (PreIter=$pre)" \
        "${r:+random and hard}" $r
    done
  done
}

python3 "$ROOT/scripts/gen_params.py" --subpixel-bits 8 --coord-bits 16 --box-bits 14 \
  --endpoints 1 --fifo-depth 8 --sv "$PKG" >/dev/null ||
  { echo "$ME: scripts/gen_params.py failed" >&2; exit 1; }
rm -f "$WORK"/scene_*.tri "$WORK"/*.out
case "$MODE" in
  blocks)
    check_blocks
    check_walk_stage ;;
  unit)
    check_unit 1 builtin:mixed need ;;
  all)
    check_blocks
    check_walk_stage
    check_walk_stage fit
    tb_build span_fifo_ram_tb span_fifo_ram \
      "$R/common/trirast_span_fifo.sv" "$R/common/trirast_span_fifo_ram.sv" "$ROOT/tb/common/span_fifo_ram_tb.sv"
    tb_run span_fifo_ram_tb span_fifo_ram span_fifo_ram_tb ""
    check_edge_lane
    check_unit "0 1 1fit" "${UNIT_SCENES:-builtin:mixed builtin:highpoly-far}" ""
    tb_build improved2_corner_unit_tb corner_unit \
      "$R/common/trirast_corner_serial.sv" "$T/improved2_corner_unit_tb.sv"
    tb_run improved2_corner_unit_tb corner_unit improved2_corner_unit_tb "" ;;
esac
