#!/bin/bash
# docs/which-unit-wins.md and docs/img/which-unit-wins/*.png: which unit (improved, improved2 in
# both corner forms, traditional, half-space at stamp sizes 1, 2, 4) wins where, in time and per
# area, from the timed SystemC models (per-triangle cycles on the benchmark scenes and meshes, and a
# sweep of box sizes and aspect ratios) and the areas and routed clocks in docs/synth.csv
# (scripts/synth.sh).
# Usage: scripts/which_unit_wins.sh [OUTPUT.md]   (default docs/which-unit-wins.md; the plots go
#                                                 to docs/img/which-unit-wins/, or to the folder
#                                                 TRIRAST_WUW_IMG names)
# About a minute (the two high-poly scenes dominate); the run's CSVs stay in build/which-unit-wins/.
# The meshes of the Debian package assimp-testmodels (/usr/share/assimp/models) that it uses are
# skipped with a note when the package is not installed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
out="${1:-$root/docs/which-unit-wins.md}"
img="${TRIRAST_WUW_IMG:-$root/docs/img/which-unit-wins}"
data="$build/which-unit-wins"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j2 --target trirast_unit_compare >/dev/null
meshes=()
for m in OBJ/WusonOBJ.obj OBJ/spider.obj; do
  if [ -f "/usr/share/assimp/models/$m" ]; then meshes+=("/usr/share/assimp/models/$m")
  else echo "which_unit_wins: /usr/share/assimp/models/$m: not installed (assimp-testmodels), skipped" >&2; fi
done
rm -rf "$data"
mkdir -p "$data" "$img"
SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$build/trirast_unit_compare" "$data" "$root" "${meshes[@]}"
cmd="scripts/which_unit_wins.sh${1:+ $1}"
/usr/bin/python3 "$root/scripts/which_unit_wins.py" --data "$data" --synth "$root/docs/synth.csv" \
  --doc "$out" --img "$img" --command "$cmd"
