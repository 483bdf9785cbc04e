#!/usr/bin/env bash
# The kit's ctests (tb/CMakeLists.txt, kit_*): for each case, `trirast raster --vectors` writes a
# scene's vectors with ENGINE and the raster OPTIONS, and tb/kit/run.sh runs the unit's top in SIM
# on them; every case must pass.
#   tb/kit/test_kit.sh [--fault] TRIRAST SIM WORK ENGINE "OPTIONS" SCENE@SINK ...
# SINK is a --sink-stall pattern. --fault: the run uses a copy of rtl/ in WORK with a planted
# one-pixel fault (trirast_span_port.sv: x_end + 1 on the spans of odd rows; the improved,
# traditional and half-space units' span port), and every case must FAIL with the scoreboard
# naming the first wrong span (the test shows that the kit sees a one-pixel difference).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
FAULT=0
if [ "${1:-}" = --fault ]; then FAULT=1; shift; fi
[ $# -ge 6 ] || { echo "usage: tb/kit/test_kit.sh [--fault] TRIRAST SIM WORK ENGINE OPTIONS SCENE@SINK ..." >&2; exit 2; }
TRIRAST="$1" SIM="$2" WORK="$3" ENGINE="$4" OPTIONS="$5"
shift 5
mkdir -p "$WORK"
RTL_ARGS=()
if [ $FAULT = 1 ]; then
  rm -rf "$WORK/rtl"
  cp -r "$ROOT/rtl" "$WORK/rtl"
  port="$WORK/rtl/common/trirast_span_port.sv"
  line='assign {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o} = head;'
  grep -qF "$line" "$port" || { echo "test_kit.sh: $port: the line to plant the fault in is gone" >&2; exit 2; }
  # head is {tag, y, x_begin, x_end}: bit 2*PixBits+1 is y's lowest bit; + 1 adds to x_end.
  sed -i "s|$line|assign {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o} = head + (head[2 * trirast_pkg::PixBits + 1] ? 1 : 0);  // PLANTED FAULT|" "$port"
  grep -q "PLANTED FAULT" "$port" || { echo "test_kit.sh: planting the fault failed" >&2; exit 2; }
  RTL_ARGS=(--rtl "$WORK/rtl")
fi
status=0
i=0
for case in "$@"; do
  scene="${case%@*}" sink="${case##*@}"
  i=$((i + 1))
  vec="$WORK/vectors-$i"
  rm -rf "$vec"
  # shellcheck disable=SC2086
  "$TRIRAST" raster --scene "$scene" --engine "$ENGINE" $OPTIONS --sink-stall "$sink" \
    --vectors "$vec" > "$WORK/raster-$i.log" || { cat "$WORK/raster-$i.log"; exit 1; }
  set +e
  out="$("$ROOT/tb/kit/run.sh" --sim "$SIM" "${RTL_ARGS[@]}" "$vec" "$WORK/build" 2>&1)"
  rc=$?
  set -e
  echo "$out"
  echo "case $i: $scene --engine $ENGINE $OPTIONS --sink-stall $sink: run.sh exit status $rc"
  if [ $FAULT = 0 ]; then
    [ $rc = 0 ] || status=1
  else
    # The planted fault must be reported as a span difference and fail the run.
    if [ $rc = 0 ] || ! grep -q "kit scoreboard: cycle [0-9]*: triangle [0-9]*: span [0-9]* is y [0-9]* \[[0-9]*, [0-9]*), expected" <<< "$out" ||
       ! grep -q "^FAIL\|FAIL: [0-9]* differences" <<< "$out"; then
      echo "test_kit.sh: the planted fault was not reported"
      status=1
    fi
  fi
done
exit $status
