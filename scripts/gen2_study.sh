#!/usr/bin/env bash
# Measurements for the second-generation improved unit (docs/improved2.md): small
# standalone prototypes of the candidate circuits (scripts/gen2_study/*.sv, not units) and the
# first generation's corresponding modules (rtl/), at the default configuration (S = 8, coordinate
# 16, box 14, N = 1, FIFO 8; package from scripts/gen_params.py).
#
#   scripts/gen2_study.sh [--only REGEX] [--timeout SECONDS] [--freq MHZ] [--no-pnr] [WORKDIR]
#   scripts/gen2_study.sh --report [WORKDIR]   (only print the table from WORKDIR's logs)
#   scripts/gen2_study.sh --check [WORKDIR]    (only the functional cross-check: Verilator --binary
#       of scripts/gen2_study/g2_check_tb.sv, random inputs: the corner-value prototypes (LSB-first
#       radix 2, 4, 16 with E_L and E_R; MSB-first radix 4, 16; narrow 13-bit; full-width `*`) against
#       the formula, trirast_improved2_edge_walker against rtl/improved/trirast_improved_edge_walker.sv row by row, trirast_improved2_span_generator
#       against rtl/improved/trirast_improved_span_generator.sv, trirast_improved2_direct_test_2x2 against the sign tests written out; then
#       scripts/gen2_study/g2_walk_check_tb.sv: g2_walk_slice as a whole against rtl/'s walk stage
#       and span port on the same random hand-offs and sink pattern (spans equal; one cycle later
#       each with an always-ready sink); then
#       scripts/gen2_study/g2_fifo_check_tb.sv: trirast_span_fifo_ram (block RAM) against
#       rtl/common/trirast_span_fifo.sv on random pushes and pops, depths 2 to 32; then
#       scripts/gen2_study/g2_lane_tb.sv: the redesigned lane trirast_improved2_edge_lane against gen1's normalizer + lane
#       on random and hard edges and on the edges of the scenes LANE_SCENES (default builtin:highpoly-far
#       builtin:mixed, exported by TRIRAST, default build/trirast; skipped when it is missing), with the
#       cycles per edge and per triangle of both, for trirast_improved2_edge_lane's PreIter = 0 and 1; then
#       scripts/gen2_study/g2_box_check_tb.sv: g2_box_stage (one cycle) and g2_box_stage3 (both
#       variants) against rtl/common/trirast_box_stage.sv's box and empty flag and the operands' formula,
#       random triangles of the box's hard cases under random offer and stall patterns; then
#       scripts/gen2_study/g2_unit_tb.sv: the whole-unit prototype trirast_improved2_top (both corner forms, and
#       the radix-16 form with the iCE40 fit's build choices) against rtl/improved/trirast_improved_top.sv on the scenes UNIT_SCENES (exported by TRIRAST; skipped when it
#       is missing), spans equal span for span, both units' cycles; then
#       scripts/gen2_study/g2_corner_check_tb.sv: the MSB-first corner units, pipelined
#       g2_corner_msb16p included, on full-width operands with the extremes, and its cycle count;
#       exit 1 on a difference)
#   scripts/gen2_study.sh --check-blocks [WORKDIR]   (the first two of --check only: g2_check_tb
#       and g2_walk_check_tb, about a minute; the suite runs it, test gen2_study_check_blocks)
#   scripts/gen2_study.sh --check-unit [WORKDIR]     (the whole-unit check of --check for CornerForm 1
#       with the build choices' other values, which the RtlImproved2 tests do not build, on
#       builtin:mixed; needs TRIRAST; the suite runs it, test gen2_study_check_unit)
#
# Per design, one tool at a time (the machine is shared):
#  - Yosys `synth_xilinx -family xc7 -top TOP` of the design alone: LUT (LUT1-6, as scripts/synth.sh
#    counts them: LUT RAM such as the span FIFO's RAM32M cells is not in it), FF, CARRY4, DSP48E1;
#  - Yosys `synth_ice40 -top TOP` of the design alone: SB_LUT4, SB_DFF*, SB_CARRY;
#  - nextpnr-ice40 --hx8k --package ct256 --seed 1 (request --freq, default 12 MHz as
#    scripts/synth.sh, --timing-allow-fail) of the design in a registered wrapper
#    (scripts/synth_wrap.py around rtl/common/trirast_synth_shell.sv: every path register -> design ->
#    register; its logic cells include the wrapper's flip-flops, InBits + 2 * OutBits, listed as
#    "wrapper FF"): logic cells, Fmax, critical path.
#    Each place and route is stopped after --timeout seconds (default 600).
# WORKDIR (default build/gen2_study) gets one directory per design with the logs; the table
# (Markdown) is printed and written to WORKDIR/table.md. --only REGEX runs the designs whose names
# match. Designs: see DESIGNS below (name, top, sources, parameters, description).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
ME="gen2_study.sh"
ONLY=""
TIMEOUT=600
FREQ=12
PNR=1
REPORT=0
CHECK=0
CHECK_BLOCKS=0
CHECK_UNIT=0
while [ $# -gt 0 ]; do
  case "$1" in
    --only) [ $# -ge 2 ] || { echo "$ME: --only needs REGEX" >&2; exit 2; }; ONLY="$2"; shift 2 ;;
    --timeout) [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+$ ]] || { echo "$ME: --timeout needs SECONDS (an integer)" >&2; exit 2; }
               TIMEOUT="$2"; shift 2 ;;
    --freq) [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "$ME: --freq needs MHZ (a number)" >&2; exit 2; }
            FREQ="$2"; shift 2 ;;
    --no-pnr) PNR=0; shift ;;
    --report) REPORT=1; shift ;;
    --check) CHECK=1; shift ;;
    --check-blocks) CHECK=1; CHECK_BLOCKS=1; shift ;;
    --check-unit) CHECK=1; CHECK_UNIT=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "$ME: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -le 1 ] || { echo "$ME: one WORKDIR at most (got: $*)" >&2; exit 2; }
WORK="${1:-$ROOT/build/gen2_study}"
if [ "$REPORT" = 0 ]; then
  for t in yosys nextpnr-ice40 python3 timeout; do
    command -v "$t" >/dev/null || { echo "$ME: $t not found in PATH" >&2; exit 1; }
  done
fi
mkdir -p "$WORK" || { echo "$ME: cannot create WORKDIR $WORK" >&2; exit 1; }
WORK="$(cd "$WORK" && pwd)"
R="$ROOT/rtl"
S="$ROOT/scripts/gen2_study"
# The whole gen2 unit's sources: its file list, rtl/improved2/trirast_improved2.f, without the package
# (each run writes its own, PKG).
I2_SRCS="$("$ROOT/scripts/rtl_filelist.sh" improved2 --no-pkg | tr '\n' ' ')"
I2_SRCS="${I2_SRCS% }"
TRIRAST="${TRIRAST:-$ROOT/build/trirast}"
LANE_SCENES="${LANE_SCENES:-builtin:highpoly-far builtin:mixed}"
PKG="$WORK/trirast_pkg.sv"

# name|top|sources (after the package)|chparam NAME=VALUE,...|description[|bram]
# (a sixth field "bram": the wrapper's synth_ice40 may map memories to block RAM, without -nobram)
DESIGNS=(
"g1.interface|trirast_box_stage|$R/common/trirast_box_stage.sv||gen1 interface: box + 9 corner products (E_L, E_R per edge), 1 cycle"
"g2.box_stage|g2_box_stage|$S/g2_box_stage.sv|Split=0|gen2 box stage B in one cycle: triangle register (no C), box, operands abs(dxL), abs(dy) into the corner stage's register"
"g2.box_stage2|g2_box_stage|$S/g2_box_stage.sv|Split=1|gen2 box stage B in two pipelined cycles (min/max; clip, empty, operands): triangle register (no C), box, operands abs(dxL), abs(dy) into the corner stage's register"
"g2.box_stage3|g2_box_stage3|$S/g2_box_stage3.sv|PortMinMax=0|gen2 box stage B in three pipelined steps with valid/ready (per-vertex first/last pixel and min/max; clip and empty beside each other; operands): triangle register, two more copies, empty registered"
"g2.box_stage3p|g2_box_stage3|$S/g2_box_stage3.sv|PortMinMax=1|the same with step 1 on the port's data before the triangle register: two copies of the triangle, the latency of g2.box_stage2"
"g2.corner_mul|trirast_improved2_corner_products|$R/improved2/trirast_improved2_corner_products.sv||vertex-relative E_L, six full-width 25x26 products written as *, 1 cycle"
"g2.corner_narrow13|g2_corner_narrow|$S/g2_corner_narrow.sv|NarrowBits=13|vertex-relative E_L, E_R, 13x13 multipliers (extent < 16 px), 1 cycle"
"g2.corner_narrow11|g2_corner_narrow|$S/g2_corner_narrow.sv|NarrowBits=11|vertex-relative E_L, E_R, 11x11 multipliers (extent < 4 px), 1 cycle"
"g2.corner_r2_lr|g2_corner_digit|$S/g2_corner_digit.sv|DigitBits=1,WithER=1|shift-add radix 2, E_L and E_R, ceil(bits/1) cycles"
"g2.corner_r4_lr|g2_corner_digit|$S/g2_corner_digit.sv|DigitBits=2,WithER=1|shift-add radix 4, E_L and E_R, ceil(bits/2) cycles"
"g2.corner_r4_l|g2_corner_digit|$S/g2_corner_digit.sv|DigitBits=2,WithER=0|shift-add radix 4, E_L only, ceil(bits/2) cycles"
"g2.corner_r16_l|g2_corner_digit|$S/g2_corner_digit.sv|DigitBits=4,WithER=0|digit-serial 25x4 (radix 16), E_L only, ceil(bits/4) cycles"
"g2.corner_msb4|g2_corner_signmag|$S/g2_corner_signmag.sv|DigitBits=2|MSB-first radix 4, E_L only, 1 + ceil(bits/2) cycles, no shifted multiplicands"
"g2.corner_msb16|g2_corner_signmag|$S/g2_corner_signmag.sv|DigitBits=4|MSB-first radix 16, E_L only, 1 + ceil(bits/4) cycles, no shifted multiplicands"
"g2.corner_msb16p|g2_corner_msb16p|$S/g2_corner_msb16p.sv|RegDigit=0|MSB-first radix 16 pipelined: +-A, 3A, -+B, 3B registered at the start, s = A*digit + B*digit registered, E_L only, 1 + ceil(bits/4) + 1 cycles"
"g2.corner_msb16p2|g2_corner_msb16p|$S/g2_corner_msb16p.sv|RegDigit=1|the same with the digit select registered too, 1 + ceil(bits/4) + 2 cycles"
"g2.corner_msb16ps|g2_corner_msb16p|$S/g2_corner_msb16p.sv|RegStart=1|g2.corner_msb16p with the operand magnitudes, signs, A, B registered first (B2's registers in the unit), 1 + 1 + ceil(bits/4) + 1 cycles"
"g1.edge_lane|trirast_improved_edge_lane|$R/improved/trirast_improved_adder_divider.sv $R/improved/trirast_improved_edge_lane.sv||gen1 edge lane: FSM + adder divider (50-bit numerator), one per edge"
"g1.lanes|g1_lanes|$R/improved/trirast_improved_adder_divider.sv $R/improved/trirast_improved_edge_lane.sv $R/improved/trirast_improved_edge_normalizer.sv $S/g1_lanes.sv||gen1 3 normalizers + 3 lanes as in the setup stage (fed by the interface's outputs)"
"g1.lanes_step|g1_lanes|$R/improved/trirast_improved_adder_divider.sv $R/improved/trirast_improved_edge_lane.sv $R/improved/trirast_improved_edge_normalizer.sv $S/g1_lanes.sv|TieMode=1|the same, boundary mode tied to step and the divider to adaptive (build parameters instead of runtime inputs)"
"g1.adder_divider|trirast_improved_adder_divider|$R/improved/trirast_improved_adder_divider.sv||gen1 adder divider alone (restoring, 1 quotient bit per cycle, 50-bit numerator)"
"g1.normalizer|trirast_improved_edge_normalizer|$R/improved/trirast_improved_edge_normalizer.sv||gen1 edge normalizer (combinational), one per edge"
"g2.lane|trirast_improved2_edge_lane|$R/improved2/trirast_improved2_edge_lane.sv||redesigned lane with its normalizer (step mode; registered operation, set-up cycle, 25-bit remainder arithmetic), one per edge"
"g2.lanes|g2_lanes|$R/improved2/trirast_improved2_edge_lane.sv $S/g2_lanes.sv|Adaptive=1|3 redesigned lanes with normalizers as in the setup stage (step mode, adaptive divider)"
"g2.lanes_fixed|g2_lanes|$R/improved2/trirast_improved2_edge_lane.sv $S/g2_lanes.sv|Adaptive=0|the same with the fixed divider (m = Q: no numerator shifter)"
"g2.lanes_pre|g2_lanes|$R/improved2/trirast_improved2_edge_lane.sv $S/g2_lanes.sv|Adaptive=1,PreIter=1|3 lanes, adaptive, with the pre-iteration (saturation through the trial subtractor, dir - e without an output adder; one more cycle per division)"
"g1.span_fifo|trirast_span_fifo|$R/common/trirast_span_fifo.sv|EntryBits=78|gen1 span FIFO, 8 entries of {tag, y, x_begin, x_end} (flip-flops)"
"g1.walker|trirast_improved_edge_walker|$R/improved/trirast_improved_edge_walker.sv|NumEndpoints=1|gen1 edge walker, N = 1 (serial add-compare-subtract)"
"g2.walker_cs|trirast_improved2_edge_walker|$R/improved2/trirast_improved2_edge_walker.sv||carry-select edge walker, parallel leave test, bound register"
"g1.span_gen|trirast_improved_span_generator|$R/improved/trirast_improved_span_generator.sv||gen1 span generator (serial compare-selects), combinational"
"g2.span_gen_par|trirast_improved2_span_generator|$R/improved2/trirast_improved2_span_generator.sv||span generator, 6 parallel compares, combinational"
"g1.walk_fifo|g1_walk_fifo|$R/improved/trirast_improved_edge_walker.sv $R/improved/trirast_improved_span_generator.sv $R/improved/trirast_improved_walk_stage.sv $R/common/trirast_span_fifo.sv $S/g1_walk_fifo.sv||gen1 walk stage + span FIFO (combinational push)"
"g2.walk_fifo|g2_walk_slice|$R/improved2/trirast_improved2_edge_walker.sv $R/improved2/trirast_improved2_span_generator.sv $R/common/trirast_span_fifo.sv $S/g2_walk_slice.sv||retimed walk stage + span FIFO (registered push, credit)"
"g2.box2x2_w50|trirast_improved2_direct_test_2x2|$R/improved2/trirast_improved2_direct_test_2x2.sv|W=50|direct 2x2 box test, 50-bit corner values (any triangle), 1 cycle"
"g2.box2x2_w26|trirast_improved2_direct_test_2x2|$R/improved2/trirast_improved2_direct_test_2x2.sv|W=26|direct 2x2 box test, 26-bit corner values (narrow path), 1 cycle"
"g2.unit|trirast_improved2_top|$I2_SRCS|CornerForm=0,FifoRam=0,WalkerCs=1,TestHi=0|whole gen2 unit prototype (N = 1, FIFO 8): box, E_L and E_R by DSP products, 2x2 test, 3 redesigned lanes, retimed walk + FIFO"
"g2.unit_msb16|g2_unit_msb16|$I2_SRCS $S/g2_unit_msb16.sv||the same with the MSB-first radix-16 corner unit (E_L, then E_R for lane boxes), the iCE40 form"
"g2.unit_xc7|trirast_improved2_top|$I2_SRCS|CornerForm=0,FifoRam=0,TestHi=1,WalkerCs=0|g2.unit (DSP corner) with the two iCE40 fit choices that apply to it: the 2x2 test on E_L >> F and the walkers' carry-in step (same spans and cycles)"
"g2.unit_ice40|g2_unit_ice40|$I2_SRCS $S/g2_unit_ice40.sv||g2.unit_msb16 with the iCE40 fit's build choices (same spans and cycles): span FIFO in block RAM (5 SB_RAM40_4K), walkers' carry-in step, corner signs on the multiplicands, 2x2 test on E_L >> F; no tri_c_i port|bram"
"g2.unit_ice40_pre|g2_unit_ice40|$I2_SRCS $S/g2_unit_ice40.sv|LanePreIter=1|g2.unit_ice40 with the lanes' pre-iteration (trirast_improved2_edge_lane PreIter 1: one more cycle per division; highpoly-far 3.11 cycles per triangle, mixed 12.20)|bram"
"g2.unit_ice40_ff|g2_unit_ice40|$I2_SRCS $S/g2_unit_ice40.sv|FifoRam=0|g2.unit_ice40 without FifoRam: the span FIFO in flip-flops (the wrapper's synthesis with -nobram)"
"g2.unit_ice40_cs|g2_unit_ice40|$I2_SRCS $S/g2_unit_ice40.sv|WalkerCs=1|g2.unit_ice40 without WalkerCs 0: carry-select walkers with the entry copies|bram"
"g2.unit_ice40_notest|g2_unit_ice40|$I2_SRCS $S/g2_unit_ice40.sv|TestHi=0|g2.unit_ice40 without TestHi: the 2x2 test on the 50-bit E_L|bram"
"g2.walk_ice40|trirast_improved2_walk_stage|$R/improved2/trirast_improved2_edge_walker.sv $R/improved2/trirast_improved2_span_generator.sv $R/common/trirast_span_fifo.sv $R/common/trirast_span_fifo_ram.sv $R/improved2/trirast_improved2_walk_stage.sv|FifoRam=1,WalkerCs=0|the whole unit's walk stage (trirast_improved2_walk_stage: retimed walk, tiny jobs, registered push) with the fit's span FIFO in block RAM and the walkers' carry-in step|bram"
"g2.walker_ci|trirast_improved2_edge_walker|$R/improved2/trirast_improved2_edge_walker.sv|CarrySelect=0|g2.walker_cs with the carry-in step (one X' and one bound adder, after the e sum's sign)"
"g2.corner_msb16f|g2_corner_signmag|$S/g2_corner_signmag.sv|DigitBits=4,SignFold=1|g2.corner_msb16 with the signs on the 25-bit multiplicands and the bias in the last digit's sum (1 + ceil(bits/4) cycles)"
"g2.corner_sd16|trirast_improved2_corner_serial|$R/improved2/trirast_improved2_corner_serial.sv|DigitBits=4|rtl/'s corner unit: MSB-first radix 16 on signed-digit pairs (four terms of P or M a digit, one accumulator add; E from the accumulator by one subtraction), 1 + ceil(signed bits/4) cycles"
"g2.span_fifo_ram|trirast_span_fifo_ram|$R/common/trirast_span_fifo_ram.sv|EntryBits=78|span FIFO, 8 entries, storage in block RAM (registered read, bypass register): the same cycles as g1.span_fifo|bram"
)

count() {  # count CELL-REGEX STATFILE: sum of the cells matching in Yosys's last stat
  [ -f "$2" ] || { echo "-"; return; }
  awk -v re="$1" '/Number of cells/ {sum = 0} $1 ~ re && $2 ~ /^[0-9]+$/ {sum += $2} END {print sum + 0}' "$2"
}
chparams() {  # chparams "A=1,B=2" TOP: Yosys chparam commands
  local p="$1" top="$2" out="" kv
  [ -z "$p" ] && return 0
  IFS=, read -ra kv <<< "$p"
  for x in "${kv[@]}"; do out="$out chparam -set ${x%%=*} ${x#*=} $top;"; done
  echo "$out"
}
wrap_params() {  # wrap_params "A=1,B=2": synth_wrap.py --param options
  local p="$1" kv
  [ -z "$p" ] && return 0
  IFS=, read -ra kv <<< "$p"
  for x in "${kv[@]}"; do printf -- '--param %s ' "$x"; done
}

run_design() {  # run_design NAME TOP SOURCES PARAMS [bram]
  local name="$1" top="$2" srcs="$3" params="$4" nobram="-nobram" d="$WORK/$1" ch t0
  [ "${5:-}" = bram ] && nobram=
  mkdir -p "$d"
  ch="$(chparams "$params" "$top")"
  t0=$(date +%s)
  echo "$ME: $name: yosys xc7" >&2
  rm -f "$d/xc7.stat" "$d/ice40.stat" "$d/pnr.stat" "$d/nextpnr.log" "$d/design.json"
  yosys -q -l "$d/xc7.log" -p "read_verilog -sv -I $R/common $PKG $srcs; $ch
    synth_xilinx -family xc7 -top $top; tee -q -o $d/xc7.stat stat" >/dev/null ||
    echo "$ME: $name: xc7 synthesis failed ($d/xc7.log)" >&2
  echo "$ME: $name: yosys ice40" >&2
  yosys -q -l "$d/ice40.log" -p "read_verilog -sv -I $R/common $PKG $srcs; $ch
    synth_ice40 -top $top; tee -q -o $d/ice40.stat stat" >/dev/null ||
    echo "$ME: $name: ice40 synthesis failed ($d/ice40.log)" >&2
  if [ "$PNR" = 1 ]; then
    echo "$ME: $name: wrapper + nextpnr (timeout ${TIMEOUT} s)" >&2
    # The port list at TOP's defaults (synth_wrap.py: it must not depend on PARAMS, which go on
    # the wrapper's instance; a chparam'd top with submodules gets a derived name).
    if yosys -q -l "$d/ports.log" -p "read_verilog -sv -I $R/common $PKG $srcs; hierarchy -top $top; proc;
         write_json $d/ports.json" >/dev/null 2>&1 &&
       # shellcheck disable=SC2046
       python3 "$ROOT/scripts/synth_wrap.py" --json "$d/ports.json" --top "$top" --name g2_wrap \
         --out "$d/wrap.sv" $(wrap_params "$params") &&
       # A combinational design has no clock port: drop the wrapper's clock connection.
       { grep -q '"clk_i"' "$d/ports.json" || sed -i '/^    \.clk_i (clk_i),$/d' "$d/wrap.sv"; } &&
       yosys -q -l "$d/pnr_yosys.log" -p "read_verilog -sv -I $R/common $PKG $srcs $R/common/trirast_synth_shell.sv $d/wrap.sv;
         synth_ice40 $nobram -top g2_wrap -json $d/design.json; tee -q -o $d/pnr.stat stat" >/dev/null; then
      timeout "$TIMEOUT" nextpnr-ice40 --hx8k --package ct256 --json "$d/design.json" \
        --pcf-allow-unconstrained --freq "$FREQ" --seed 1 --timing-allow-fail \
        --log "$d/nextpnr.log" >/dev/null 2>&1 || echo "$ME: $name: nextpnr stopped or failed ($d/nextpnr.log)" >&2
    else
      echo "$ME: $name: wrapper synthesis failed (logs in $d)" >&2
    fi
  fi
  echo "$(($(date +%s) - t0))" > "$d/seconds"
}

pnr_lc() {
  local lc
  lc=$(grep -o "ICESTORM_LC: *[0-9]*/ *[0-9]*" "$1/nextpnr.log" 2>/dev/null | tail -1 | sed 's/ICESTORM_LC: *//; s/ //g')
  echo "${lc:--}"
}
wrap_ffs() {  # the shell's flip-flops: InBits + 2 * OutBits (input, output and read-back registers)
  local w="$1/wrap.sv" i o
  [ -f "$w" ] || { echo "-"; return; }
  i=$(grep -o 'InBits ([0-9]*)' "$w" | grep -o '[0-9]*')
  o=$(grep -o 'OutBits ([0-9]*)' "$w" | grep -o '[0-9]*')
  echo $((i + 2 * o))
}
pnr_fmax() {  # achieved Fmax after routing, or why there is none
  local log="$1/nextpnr.log"
  [ -f "$log" ] || { echo "-"; return; }
  if ! grep -q "Program finished normally" "$log"; then
    if grep -q "Unable to place cell\|Failed to expand region" "$log"; then echo "does not fit"; else echo "failed"; fi
    return
  fi
  grep -o "Max frequency for clock '[^']*': [0-9.]* MHz" "$log" | tail -1 | sed "s/.*: \([0-9.]*\) MHz/\1/"
}
pnr_path() {  # first source -> last sink of the critical path, and its logic/routing split
  local log="$1/nextpnr.log"
  [ -f "$log" ] || { echo "-"; return; }
  awk '/Critical path report for clock/ {f = 1; src = ""; next}
       f && /Critical path report for/ {exit}
       f && $4 == "Source" && src == "" {src = $5}
       f && $4 == "Setup" {snk = $5}
       f && /ns logic,/ {sub(/^Info: /, ""); lr = $0}
       END {if (src != "") printf "%s -> %s (%s)", src, snk, lr}' "$log"
}

report() {
  echo "| design | what | xc7 LUT | xc7 FF | xc7 CARRY4 | xc7 DSP | iCE40 LUT4 | iCE40 FF | iCE40 CARRY | wrapped LC / 7680 | wrapper FF | Fmax MHz | critical path (nextpnr) |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  local row name top srcs params desc opts d
  for row in "${DESIGNS[@]}"; do
    IFS='|' read -r name top srcs params desc opts <<< "$row"
    d="$WORK/$name"
    [ -d "$d" ] || continue
    echo "| $name | $desc | $(count '^LUT[1-6]$' "$d/xc7.stat") | $(count '^FD[RSCPE]*$' "$d/xc7.stat") | $(count '^CARRY4$' "$d/xc7.stat") | $(count '^DSP48' "$d/xc7.stat") | $(count '^SB_LUT4$' "$d/ice40.stat") | $(count '^SB_DFF' "$d/ice40.stat") | $(count '^SB_CARRY$' "$d/ice40.stat") | $(pnr_lc "$d") | $(wrap_ffs "$d") | $(pnr_fmax "$d") | $(pnr_path "$d" | sed -e "s|$ROOT/||g" -e 's/|/\\|/g') |"
  done
  echo
  echo "Default configuration (S = 8, coordinate 16, box 14), $(yosys -V 2>/dev/null | cut -d' ' -f1-2),"
  echo "nextpnr-ice40 --hx8k --package ct256 --seed 1 --freq $FREQ; wrapped LC include the wrapper's registers."
}

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
# tb_run TOP DIR LABEL SKIP [PLUSARGS ...]: runs the testbench built in WORKDIR/DIR, prints its
# "TOP:" lines as "LABEL:" (but those matching the regex SKIP, when not empty) and exits 1 unless
# it printed "TOP: 0 errors".
tb_run() {
  local top="$1" dir="$2" label="$3" skip="$4" out
  shift 4
  out="$("$WORK/$dir/V$top" "$@" 2>&1)" || true
  echo "$out" | grep "^$top:" | { if [ -n "$skip" ]; then grep -v -- "$skip"; else cat; fi; } |
    sed "s/^$top:/$label:/" || true
  grep -q "^$top: 0 errors" <<< "$out" || { echo "$ME: $label found differences" >&2; exit 1; }
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

# check_unit CFGS SCENES NEED: the whole-unit prototype trirast_improved2_top against gen1's
# trirast_improved_top (scripts/gen2_study/g2_unit_tb.sv) for each configuration of CFGS (0: CornerForm 0;
# 1: CornerForm 1 with the build choices' other values; 1fit: CornerForm 1 with the iCE40 fit's,
# the unit's defaults) on the SCENES exported by TRIRAST: spans equal span for span (sinks always
# ready, then both ready in two cycles of three), and both units' cycles. Without TRIRAST it is
# skipped, or (NEED non-empty) an error.
check_unit() {
  local cfgs="$1" scenes="$2" need="$3" cfg form fit lab sc hex st tri f
  local -a gen1_srcs
  if [ -x "$TRIRAST" ]; then
    gen1_srcs=()
    mapfile -t gen1_srcs < <("$ROOT/scripts/rtl_filelist.sh" improved --no-pkg)
    for sc in $scenes; do
      tri="$(scene_tris "$sc")"; hex="$WORK/unit_${sc#builtin:}.hex"
      python3 "$S/unit_tris.py" "$tri" "$hex" > "$hex.args" ||
        { echo "$ME: scripts/gen2_study/unit_tris.py failed on $tri" >&2; exit 1; }
    done
    # CornerForm 0 and 1, and CornerForm 1 with the iCE40 fit's build choices (G2_FIT:
    # g2_unit_ice40.sv's; the same cycles as CornerForm 1).
    for cfg in $cfgs; do
      form="${cfg:0:1}"; fit=0; lab=""
      [ "$cfg" = 1fit ] && { fit=1; lab=", iCE40 fit"; }
      # shellcheck disable=SC2086
      tb_build g2_unit_tb "check_unit$cfg" -DG2_CORNER_FORM=$form -DG2_FIT=$fit \
        "${gen1_srcs[@]}" $I2_SRCS "$S/g2_unit_tb.sv"
      for sc in $scenes; do
        hex="$WORK/unit_${sc#builtin:}.hex"
        for st in "" +stall; do   # sinks always ready; both ready in two cycles of three
          # shellcheck disable=SC2046,SC2086
          tb_run g2_unit_tb "check_unit$cfg" \
            "g2_unit_tb (CornerForm $form$lab, $sc${st:+, $st})" "" \
            +tris="$hex" $(cat "$hex.args") $st
        done
      done
    done
  elif [ -n "$need" ]; then
    echo "$ME: $TRIRAST not found: the whole-unit check needs it (set TRIRAST)" >&2; exit 1
  else
    echo "$ME: $TRIRAST not found: the whole-unit check is skipped (set TRIRAST)" >&2
  fi
}

if [ "$CHECK" = 1 ]; then
  command -v verilator >/dev/null || { echo "$ME: verilator not found in PATH" >&2; exit 1; }
  python3 "$ROOT/scripts/gen_params.py" --subpixel-bits 8 --coord-bits 16 --box-bits 14 \
    --endpoints 1 --fifo-depth 8 --sv "$PKG" >/dev/null ||
    { echo "$ME: scripts/gen_params.py failed" >&2; exit 1; }
  rm -f "$WORK"/scene_*.tri
  if [ "$CHECK_UNIT" = 1 ]; then
    # The build choices the suite's RtlImproved2 tests (the unit's defaults) do not run.
    check_unit 1 builtin:mixed need
    exit 0
  fi
  tb_build g2_check_tb check \
    "$R/improved/trirast_improved_edge_walker.sv" "$R/improved/trirast_improved_span_generator.sv" "$S/g2_corner_narrow.sv" \
    "$S/g2_corner_digit.sv" "$R/improved2/trirast_improved2_corner_serial.sv" "$R/improved2/trirast_improved2_corner_products.sv" "$R/improved2/trirast_improved2_edge_walker.sv" \
    "$R/improved2/trirast_improved2_span_generator.sv" "$R/improved2/trirast_improved2_direct_test_2x2.sv" "$S/g2_check_tb.sv"
  tb_run g2_check_tb check g2_check_tb ""
  # The retimed walk stage as a whole against gen1's walk stage and span port.
  tb_build g2_walk_check_tb check_walk \
    "$R/improved/trirast_improved_edge_walker.sv" "$R/improved/trirast_improved_span_generator.sv" "$R/common/trirast_span_fifo.sv" \
    "$R/common/trirast_span_port.sv" "$R/improved/trirast_improved_walk_stage.sv" "$R/improved2/trirast_improved2_edge_walker.sv" \
    "$R/improved2/trirast_improved2_span_generator.sv" "$S/g2_walk_slice.sv" "$S/g2_walk_check_tb.sv"
  tb_run g2_walk_check_tb check_walk g2_walk_check_tb ""
  [ "$CHECK_BLOCKS" = 0 ] || exit 0
  # The span FIFO in block RAM (the iCE40 fit's) against gen1's, depths 2 to 32.
  tb_build g2_fifo_check_tb check_fifo \
    "$R/common/trirast_span_fifo.sv" "$R/common/trirast_span_fifo_ram.sv" "$S/g2_fifo_check_tb.sv"
  tb_run g2_fifo_check_tb check_fifo g2_fifo_check_tb ""
  # The redesigned lane against gen1's normalizer + lane: random and hard edges, then the edges of
  # the scenes in LANE_SCENES exported by TRIRAST (when it runs).
  # Two builds: trirast_improved2_edge_lane as measured (PreIter = 0) and with its pre-iteration (PreIter = 1).
  for pre in 0 1; do
    tb_build g2_lane_tb "check_lane$pre" -GPreIter=$pre \
      "$R/improved/trirast_improved_adder_divider.sv" "$R/improved/trirast_improved_edge_lane.sv" "$R/improved/trirast_improved_edge_normalizer.sv" \
      "$R/improved/trirast_improved_edge_walker.sv" "$R/improved2/trirast_improved2_edge_lane.sv" "$S/g2_lane_tb.sv"
  done
  runs=("")
  if [ -x "$TRIRAST" ]; then
    for sc in $LANE_SCENES; do
      tri="$(scene_tris "$sc")"; edges="$WORK/lane_${sc#builtin:}.edges"
      python3 "$S/lane_edges.py" "$tri" "$edges" 2>/dev/null ||
        { echo "$ME: scripts/gen2_study/lane_edges.py failed on $tri" >&2; exit 1; }
      runs+=("+edges=$edges")
    done
  else
    echo "$ME: $TRIRAST not found: the lane check runs on random edges only (set TRIRAST)" >&2
  fi
  for pre in 0 1; do
    for r in "${runs[@]}"; do
      # A scene's run repeats the random and hard edges' line: printed once, by the first run.
      # shellcheck disable=SC2086
      tb_run g2_lane_tb "check_lane$pre" "g2_lane_tb (PreIter=$pre)" "${r:+random and hard}" $r
    done
  done
  tb_build g2_box_check_tb check_box \
    "$R/common/trirast_box_stage.sv" "$S/g2_box_stage.sv" "$S/g2_box_stage3.sv" "$S/g2_box_check_tb.sv"
  tb_run g2_box_check_tb check_box g2_box_check_tb ""
  check_unit "0 1 1fit" "${UNIT_SCENES:-builtin:mixed builtin:highpoly-far}" ""
  # The MSB-first corner units on full-width vertices with the extremes, and
  # g2_corner_msb16p's cycle count (scripts/gen2_study/g2_corner_check_tb.sv).
  tb_build g2_corner_check_tb check_corner \
    "$R/improved2/trirast_improved2_corner_serial.sv" "$S/g2_corner_signmag.sv" "$S/g2_corner_msb16p.sv" \
    "$S/g2_corner_check_tb.sv"
  tb_run g2_corner_check_tb check_corner g2_corner_check_tb ""
  exit 0
fi

if [ "$REPORT" = 0 ]; then
  python3 "$ROOT/scripts/gen_params.py" --subpixel-bits 8 --coord-bits 16 --box-bits 14 \
    --endpoints 1 --fifo-depth 8 --sv "$PKG" >/dev/null ||
    { echo "$ME: scripts/gen_params.py failed" >&2; exit 1; }
  ran=0
  for row in "${DESIGNS[@]}"; do
    IFS='|' read -r name top srcs params desc opts <<< "$row"
    if [ -n "$ONLY" ] && ! [[ "$name" =~ $ONLY ]]; then continue; fi
    run_design "$name" "$top" "$srcs" "$params" "$opts"
    ran=$((ran + 1))
  done
  [ "$ran" -gt 0 ] || { echo "$ME: --only '$ONLY' matches no design" >&2; exit 2; }
fi
report | tee "$WORK/table.md"
