#!/usr/bin/env bash
# The front door: install what is missing, build, run the main job on a built-in scene and print
# the report and where every output file went.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
./scripts/build.sh trirast
out=out/demo
mkdir -p "$out"
scene="builtin:mixed"
echo "== trirast raster: the SystemC model of the improved unit on $scene (spans, cycles, trace)"
./build/trirast raster --engine improved-sc --scene "$scene" \
  --spans "$out/improved-sc.spans" --image "$out/improved-sc.png" --report "$out/improved-sc.json" \
  --cycles "$out/improved-sc_cycles.csv" --trace "$out/improved-sc.vcd" --trace-tris 0:99
echo
echo "== trirast compare: every engine against the golden on $scene"
engines=$(./build/trirast engines | awk '{print $1}' | paste -sd, -)
status=0
./build/trirast compare --scene "$scene" --engines "$engines" \
  --diff-image "$out/diff.png" --report "$out/compare.json" || status=$?
echo
echo "outputs in $out/ (open the trace with: gtkwave $out/improved-sc.gtkw):"
ls -l "$out" | awk 'NR > 1 {print "  " $NF " (" $5 " bytes)"}'
exit $status
