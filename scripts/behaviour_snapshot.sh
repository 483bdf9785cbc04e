#!/usr/bin/env bash
# Writes the spans and the per-triangle cycles of every timed engine (each unit's SystemC model
# and RTL) on the scenes of scripts/cycles_table.sh, in the configurations each unit offers
# (default, N = 4, the improved unit's divide and fixed divider, the second generation's products
# corner form, the half-space unit's stamp sizes) and with a stalling sink, into OUTDIR: one file
# per scene x engine x configuration.
# Two snapshots of two trees compare with `diff -r A B`: a refactoring that changes no behaviour
# leaves every file byte-identical.
#   scripts/behaviour_snapshot.sh OUTDIR [TRIRAST_BINARY]     (default build/trirast)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?usage: scripts/behaviour_snapshot.sh OUTDIR [TRIRAST_BINARY]}"
bin="${2:-$root/build/trirast}"
[ -x "$bin" ] || { echo "behaviour_snapshot: $bin: not an executable (build first)" >&2; exit 2; }
mkdir -p "$out"
scenes=(builtin:lowpoly-far builtin:lowpoly-near builtin:highpoly-far builtin:highpoly-near
        builtin:mixed builtin:sphere builtin:torus builtin:surface "$root/tests/data/cube.obj")
# unit | label | options: only the options that apply to the unit
configs=("improved|default|" "improved|n4|--endpoints 4" "improved|divide|--boundary divide"
         "improved|fixed|--divider fixed" "improved|stall|--sink-stall random:7:30 --fifo-depth 2"
         "improved2|default|" "improved2|n4|--endpoints 4" "improved2|dsp|--corner-form dsp"
         "improved2|stall|--sink-stall random:7:30 --fifo-depth 2"
         "trad|default|" "trad|stall|--sink-stall random:7:30 --fifo-depth 2"
         "halfspace|default|" "halfspace|s4|--stamp 4 --tile 16 --hs-walk row"
         "halfspace|s1|--stamp 1 --tile none"
         "halfspace|stall|--sink-stall random:7:30 --fifo-depth 2")
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" | tr ':=,' '___')
  "$bin" raster --scene "$scene" --engine golden --spans "$out/$name.golden.spans" >/dev/null
  for c in "${configs[@]}"; do
    IFS='|' read -r unit label opts <<< "$c"
    for engine in "$unit-sc" "$unit-rtl"; do
      # shellcheck disable=SC2086
      "$bin" raster --scene "$scene" --engine "$engine" $opts \
        --spans "$out/$name.$engine.$label.spans" --cycles "$out/$name.$engine.$label.csv" \
        >/dev/null 2>"$out/.stderr" || { cat "$out/.stderr" >&2; exit 1; }
    done
  done
done
rm -f "$out/.stderr"
echo "behaviour_snapshot: $(ls "$out" | wc -l) files in $out"
