#!/usr/bin/env bash
# Writes the spans and the per-triangle cycles of every timed engine on the scenes of
# scripts/cycles_table.sh, in the configurations that table uses (default, N = 4, divide, fixed
# divider) and with a stalling sink, into OUTDIR: one file per scene x engine x configuration.
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
# label | options
configs=("default|" "n4|--endpoints 4" "divide|--boundary divide" "fixed|--divider fixed"
         "stall|--sink-stall random:7:30 --fifo-depth 2")
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" | tr ':=,' '___')
  "$bin" raster --scene "$scene" --engine golden --spans "$out/$name.golden.spans" >/dev/null
  for engine in improved-sc improved-rtl trad-sc trad-rtl; do
    for c in "${configs[@]}"; do
      label=${c%%|*}; opts=${c#*|}
      # The traditional unit reads none of --endpoints, --boundary, --divider (trirast refuses them).
      case "$engine:$label" in trad-*:n4|trad-*:divide|trad-*:fixed) continue ;; esac
      # shellcheck disable=SC2086
      "$bin" raster --scene "$scene" --engine "$engine" $opts \
        --spans "$out/$name.$engine.$label.spans" --cycles "$out/$name.$engine.$label.csv" \
        >/dev/null 2>"$out/.stderr" || { cat "$out/.stderr" >&2; exit 1; }
    done
  done
done
rm -f "$out/.stderr"
echo "behaviour_snapshot: $(ls "$out" | wc -l) files in $out"
