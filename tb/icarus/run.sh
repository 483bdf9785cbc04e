#!/usr/bin/env bash
# Runs the Icarus testbench tb/icarus/tb_trirast.sv on small scenes (ctest rtl_icarus).
#   tb/icarus/run.sh PATH/TO/trirast_rtl_vectors WORKDIR [halfspace[:STAMP:TILE:WALK] | improved2[:FORM]]
# (halfspace: the half-space unit, rtl/halfspace/trirast_halfspace.f, at StampSize STAMP, TileSize TILE
# (0: none), walk row | zigzag (default 2:8:zigzag, trirast_halfspace_top's defaults), against the
# halfspace-rtl engine's vectors of the same build parameters; improved2: the second-generation
# unit, rtl/improved2/trirast_improved2.f, in CornerForm FORM (1 radix 16, the default; 0 products), against
# the improved2-rtl engine's vectors)
# For each scene, trirast_rtl_vectors writes the set-up triangles and the Verilated model's spans
# and cycles; Icarus runs the RTL at its default parameters (NumEndpoints = 1, FifoDepth = 8)
# and must agree span for span and cycle for cycle. Exit status 0 only if every scene passes.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
VECTORS="$1"
WORK="$2"
UNIT="${3:-}"
mkdir -p "$WORK"
LIST=improved
DEFINES=""
case "$UNIT" in
  "") ;;
  halfspace|halfspace:*)
    IFS=: read -r _ stamp tile walk _rest <<< "$UNIT:::"
    stamp=${stamp:-2}; tile=${tile:-8}; walk=${walk:-zigzag}
    case "$walk" in zigzag) zig=1 ;; row) zig=0 ;; *) echo "run.sh: walk '$walk' is not row or zigzag" >&2; exit 2 ;; esac
    UNIT="halfspace:$stamp:$tile:$walk"
    LIST=halfspace
    DEFINES="-DTRIRAST_TB_HALFSPACE -Ptb_trirast.HalfspaceStamp=$stamp -Ptb_trirast.HalfspaceTile=$tile -Ptb_trirast.HalfspaceZigzag=$zig"
    ;;
  improved2|improved2:*)
    IFS=: read -r _ form _rest <<< "$UNIT::"
    form=${form:-1}
    case "$form" in 0|1) ;; *) echo "run.sh: corner form '$form' is not 0 or 1" >&2; exit 2 ;; esac
    UNIT="improved2:$form"
    LIST=improved2
    DEFINES="-DTRIRAST_TB_IMPROVED2 -Ptb_trirast.I2CornerForm=$form"
    ;;
  *) echo "run.sh: unit '$UNIT' is not halfspace[:STAMP:TILE:WALK] or improved2[:FORM]" >&2; exit 2 ;;
esac
# The unit's file list (rtl/UNIT/trirast_UNIT.f).
SOURCES="$("$ROOT/scripts/rtl_filelist.sh" "$LIST")
  $ROOT/tb/icarus/tb_trirast.sv"
# Icarus prints "sorry: constant selects in always_* processes" for loops over arrays in
# always_comb (a sensitivity-list simplification, harmless), and "sorry: Case unique/unique0
# qualities are ignored" (Verilator checks them); keep the rest.
iverilog -g2012 $DEFINES -I "$ROOT/rtl/common" -o "$WORK/tb_trirast.vvp" $SOURCES \
  2> >(grep -v "constant selects\|qualities are ignored" >&2)
status=0
# scene  ready  stall
for case in "builtin:fan:n=12 1 0" "builtin:random:count=120,size=small,seed=3 3 2" \
            "builtin:hard-tiny:count=40 2 5"; do
  read -r scene ready stall <<< "$case"
  dir="$WORK/$(echo "$scene" | tr ':=,' '___')"
  mkdir -p "$dir"
  "$VECTORS" "$scene" "$dir" "$ready" "$stall" $UNIT
  out=$(vvp -n "$WORK/tb_trirast.vvp" +dir="$dir" $(cat "$dir/plusargs.txt"))
  echo "$scene (periodic:$ready:$stall): $(echo "$out" | tail -1)"
  if ! echo "$out" | grep -q "^PASS"; then
    echo "$out" | head -20
    status=1
  fi
done
exit $status
