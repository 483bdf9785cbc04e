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
./build/trirast raster --engine model --scene "$scene" \
  --spans "$out/model.spans" --image "$out/model.png" --report "$out/model.json" \
  --cycles "$out/model_cycles.csv" --trace "$out/model.vcd" --trace-tris 0:99
echo
echo "== trirast compare: every engine against the golden on $scene"
engines=$(./build/trirast engines | awk '{print $1}' | paste -sd, -)
status=0
./build/trirast compare --scene "$scene" --engines "$engines" \
  --diff-image "$out/diff.png" --report "$out/compare.json" || status=$?
echo
echo "outputs in $out/ (open the trace with: gtkwave $out/model.gtkw):"
ls -l "$out" | awk 'NR > 1 {print "  " $NF " (" $5 " bytes)"}'
exit $status
