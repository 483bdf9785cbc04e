#!/usr/bin/env bash
# The front door: install what is missing, build, run the main job on a built-in scene and print
# the report and where every output file went.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
./scripts/deps.sh
# A new build/ Verilates only the RTL models a default run takes (the demo runs every engine at its
# defaults: cmake/trirast_rtl_builds.cmake, TRIRAST_RTL_DEFAULT_RUN_ONLY); scripts/build.sh adds
# the other models of the default widths, scripts/test.sh every width configuration too.
# An existing build/ is used as it is configured.
build_args=()
if [ ! -f build/CMakeCache.txt ]; then
  build_args=(--cmake-arg -DTRIRAST_RTL_EXTRA_WIDTHS=OFF --cmake-arg -DTRIRAST_RTL_DEFAULT_RUN_ONLY=ON)
  echo "== building trirast (first build: the RTL models a default run takes; progress below)"
elif grep -q '^TRIRAST_RTL_DEFAULT_RUN_ONLY:BOOL=ON$' build/CMakeCache.txt; then
  build_args=(--cmake-arg -DTRIRAST_RTL_DEFAULT_RUN_ONLY=ON)
fi
./scripts/build.sh ${build_args[@]+"${build_args[@]}"} trirast
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
echo "demo.sh: done in $((SECONDS - start)) s"
exit $status
