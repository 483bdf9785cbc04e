#!/usr/bin/env bash
# Speed against error: regenerates docs/speed-vs-error.md and its plots from nothing.
#   scripts/sweep.sh [--quick] [--jobs N] [--out DIR] [--synth] [--merge RESULTS] [--command TEXT]
#                    [-- SWEEP-OPTIONS...]
# - builds build/trirast if needed (TRIRAST_BIN=PATH uses that binary and builds nothing);
# - --synth first runs scripts/synth.sh (Yosys; minutes), so that docs/synth.csv is from this run;
#   without it an existing docs/synth.csv is read, and the report says so;
# - runs `trirast sweep` (engines x configurations x scenes) and `trirast fit` on three scenes
#   (and one with an error budget), and the second-generation unit's fit in both corner forms;
# - plots with Debian's /usr/bin/python3 (matplotlib) and writes the report.
# Outputs: default: data in build/sweep/, docs/speed-vs-error.md, plots in docs/img/speed-vs-error/.
#          --out DIR: everything in DIR (DIR/speed-vs-error.md, DIR/img/speed-vs-error/, data).
# --quick: three small scenes and ~20 configurations (the test suite runs it; a few seconds).
# --merge RESULTS: the sweep's data from a distributed run's result files (`trirast sweep --merge`,
#          scripts/sweep_slurm.sh and scripts/sweep_parallel.sh) instead of running it here;
#          --command: the command the report names (theirs). SWEEP-OPTIONS go to trirast sweep.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
START=$(date +%s.%N)
QUICK=0
JOBS=2
OUT=""
SYNTH=0
MERGE=""
CMD_OVERRIDE=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    --jobs) JOBS="${2:?--jobs needs a number}"; shift ;;
    --out) OUT="${2:?--out needs a directory}"; shift ;;
    --synth) SYNTH=1 ;;
    --merge) MERGE="${2:?--merge needs a directory}"; shift ;;
    --command) CMD_OVERRIDE="${2:?--command needs a text}"; shift ;;
    --) shift; break ;;
    -h|--help) sed -n "2,15p" "$0"; exit 0 ;;
    *) echo "sweep.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
PY=/usr/bin/python3
[ -x "$PY" ] || { echo "sweep.sh: $PY (Debian's, with matplotlib) is missing: apt-get install python3-matplotlib" >&2; exit 2; }

if [ -n "$OUT" ]; then
  mkdir -p "$OUT"
  OUT="$(cd "$OUT" && pwd)"
  DATA="$OUT/data"
  DOC="$OUT/speed-vs-error.md"
  IMG="$OUT/img/speed-vs-error"
else
  DATA="$ROOT/build/sweep"
  DOC="$ROOT/docs/speed-vs-error.md"
  IMG="$ROOT/docs/img/speed-vs-error"
fi

BIN="${TRIRAST_BIN:-}"
if [ -z "$BIN" ]; then
  echo "sweep.sh: building trirast" >&2
  cmake -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$ROOT/build" -j2 --target trirast >/dev/null
  BIN="$ROOT/build/trirast"
fi

if [ "$SYNTH" = 1 ]; then
  echo "sweep.sh: synthesis (scripts/synth.sh)" >&2
  "$ROOT/scripts/synth.sh"
fi

# From nothing: the previous run's data, plots and report go first.
rm -rf "$DATA" "$IMG"
rm -f "$DOC"
mkdir -p "$DATA" "$IMG"

QUICK_ARG=()
[ "$QUICK" = 1 ] && QUICK_ARG=(--quick)
if [ -n "$MERGE" ]; then
  "$BIN" sweep "${QUICK_ARG[@]}" --merge "$MERGE" --out "$DATA" \
    --synth-csv "$ROOT/docs/synth.csv" --synth-script "$ROOT/scripts/synth.sh" "$@"
else
  "$BIN" sweep "${QUICK_ARG[@]}" --jobs "$JOBS" --out "$DATA" \
    --synth-csv "$ROOT/docs/synth.csv" --synth-script "$ROOT/scripts/synth.sh" "$@"
fi

fit() {  # fit N SCENE [options...]
  local n="$1"; shift
  "$BIN" fit --synth-csv "$ROOT/docs/synth.csv" --synth-script "$ROOT/scripts/synth.sh" \
    --report "$DATA/fit_$n.json" "$@"
}
if [ "$QUICK" = 1 ]; then
  fit 1 --scene builtin:sphere:tess=12 --cull back
  fit 2 --scene builtin:lowpoly-near
  fit 3 --scene builtin:hard-tiny
  fit 4 --scene builtin:mixed:objects=2,tess=8 --error-budget 1000
  fit 5 --unit improved2 --scene builtin:sphere:tess=12 --cull back
  fit 6 --unit improved2 --corner-form dsp --scene builtin:sphere:tess=12 --cull back
else
  fit 1 --scene builtin:sphere --cull back
  fit 2 --scene builtin:highpoly-far
  fit 3 --scene builtin:hard-all
  fit 4 --scene builtin:mixed --error-budget 1000
  fit 5 --unit improved2 --scene builtin:sphere --cull back
  fit 6 --unit improved2 --corner-form dsp --scene builtin:sphere --cull back
fi

CMD="scripts/sweep.sh"
[ "$QUICK" = 1 ] && CMD="$CMD --quick"
[ "$JOBS" != 2 ] && CMD="$CMD --jobs $JOBS"
[ -n "$OUT" ] && CMD="$CMD --out DIR"
[ "$SYNTH" = 1 ] && CMD="$CMD --synth"
[ -n "$CMD_OVERRIDE" ] && CMD="$CMD_OVERRIDE"
"$PY" "$ROOT/scripts/plot_sweep.py" --data "$DATA" --doc "$DOC" --img "$IMG" --start "$START" \
  --command "$CMD"
echo "sweep.sh: wrote $DOC, plots in $IMG, data in $DATA ($(awk -v a="$START" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }') s)" >&2
