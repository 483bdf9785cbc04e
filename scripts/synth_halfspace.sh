#!/usr/bin/env bash
# Area of the half-space unit (rtl/trirast_halfspace.f, top trirast_hs_top) in Yosys:
# synth_ice40 (LCs) and synth_xilinx -family xc7 (LUTs, FFs) at the build parameters given.
#   scripts/synth_halfspace.sh [WORKDIR] [STAMP TILE ZIGZAG]...
# e.g. scripts/synth_halfspace.sh /tmp/hs-synth 2 8 1 4 16 0
# Prints one line per configuration and target; the logs stay in WORKDIR. No place and route
# (see docs/synth.md, "The half-space unit").
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
WORK="${1:-/tmp/trirast-hs-synth}"
shift || true
[ $# -ge 3 ] || set -- 2 8 1
mkdir -p "$WORK"
SOURCES="$(sed 's#//.*##' "$ROOT/rtl/trirast_halfspace.f" | awk -v d="$ROOT/rtl" 'NF {print d "/" $1}' | tr '\n' ' ')"
while [ $# -ge 3 ]; do
  s=$1 t=$2 z=$3; shift 3
  name="s${s}t${t}z${z}"
  for target in ice40 xc7; do
    if [ $target = ice40 ]; then synth="synth_ice40 -top trirast_hs_top"
    else synth="synth_xilinx -family xc7 -top trirast_hs_top"; fi
    yosys -q -l "$WORK/$name.$target.log" -p "read_verilog -sv -I $ROOT/rtl $SOURCES; \
      chparam -set StampSize $s -set TileSize $t -set WalkZigzag $z trirast_hs_top; \
      $synth; tee -o $WORK/$name.$target.stat stat" >/dev/null
    if [ $target = ice40 ]; then
      lc=$(grep -o "SB_LUT4 *[0-9]*" "$WORK/$name.$target.stat" | awk '{print $2}' | tail -1)
      ff=$(grep -o "SB_DFF[A-Z]* *[0-9]*" "$WORK/$name.$target.stat" | awk '{s+=$2} END {print s}')
      echo "stamp $s tile $t zigzag $z ice40: SB_LUT4 $lc, flip-flops $ff"
    else
      lut=$(grep -o "LUT[1-6] *[0-9]*" "$WORK/$name.$target.stat" | awk '{s+=$2} END {print s}')
      ff=$(grep -o "FD[A-Z]* *[0-9]*" "$WORK/$name.$target.stat" | awk '{s+=$2} END {print s}')
      echo "stamp $s tile $t zigzag $z xc7: LUTs $lut, flip-flops $ff"
    fi
  done
done
