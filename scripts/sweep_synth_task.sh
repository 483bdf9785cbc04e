#!/usr/bin/env bash
# One synthesis task of the distributed sweep (scripts/sweep_slurm.sh, scripts/sweep_parallel.sh):
#   scripts/sweep_synth_task.sh TODO INDEX RESULTS
# TODO is the list `trirast sweep --merge RESULTS --synth-todo TODO` wrote (one UNIT:S:COORD:BOX:N
# per line, index 0 first); the task synthesizes line INDEX with scripts/synth.sh --one into
# RESULTS/synth/UNIT-SS-cC-bB-NN.synth (JSON, written whole, then renamed). A complete result
# file made from the same sources is not redone (a rerun resumes): beside it, FILE.src holds a
# hash of the RTL and the synthesis scripts it was made from, and a result of other sources is
# made again.
# Traditional units are also placed and routed (iCE40 Fmax): they fit.
#   scripts/sweep_synth_task.sh --prune RESULTS
# removes the result files of RESULTS/synth made from other sources (or of unknown ones), so that
# the sweep's merge lists them for synthesis again (the drivers run it before their first merge).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
sources_hash() {
  cat "$ROOT"/rtl/*/*.sv "$ROOT"/rtl/*/*.svh "$ROOT"/rtl/*/*.f "$ROOT/scripts/synth.sh" \
    "$ROOT/scripts/synth_wrap.py" "$ROOT/scripts/gen_params.py" | sha1sum | cut -d' ' -f1
}
# complete_result FILE: whether FILE is a whole synthesis result of the sweep's result format
# (the version scripts/synth.sh --one writes), not one cut short.
complete_result() {
  python3 - "$1" 2>/dev/null <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
ok = (d.get("format") == "trirast-sweep-result" and d.get("version") == 2
      and d.get("kind") == "synthesis")
sys.exit(0 if ok else 1)
PY
}
if [ "${1:-}" = --prune ]; then
  [ $# -eq 2 ] || { echo "usage: sweep_synth_task.sh --prune RESULTS" >&2; exit 2; }
  SRC=$(sources_hash)
  n=0
  for f in "$2"/synth/*.synth; do
    [ -e "$f" ] || continue
    if [ "$(cat "$f.src" 2>/dev/null)" != "$SRC" ]; then rm -f "$f" "$f.src"; n=$((n + 1)); fi
  done
  [ "$n" -eq 0 ] || echo "sweep_synth_task.sh: $n synthesis result(s) of other sources removed from $2/synth"
  exit 0
fi
[ $# -eq 3 ] || { echo "usage: sweep_synth_task.sh TODO INDEX RESULTS" >&2; exit 2; }
TODO="$1"; INDEX="$2"; RES="$3"
[ -f "$TODO" ] || { echo "sweep_synth_task.sh: $TODO: no such file" >&2; exit 2; }
LINE=$(sed -n "$((INDEX + 1))p" "$TODO")
[ -n "$LINE" ] || { echo "sweep_synth_task.sh: $TODO: no task $INDEX" >&2; exit 2; }
IFS=: read -r unit s c b n <<< "$LINE"
OUT="$RES/synth/$unit-S$s-c$c-b$b-N$n.synth"
mkdir -p "$RES/synth"
SRC=$(sources_hash)
if [ -f "$OUT" ] && complete_result "$OUT" && [ "$(cat "$OUT.src" 2>/dev/null)" = "$SRC" ]; then
  echo "sweep_synth_task.sh: $LINE: done already ($OUT)"
  exit 0
fi
rm -f "$OUT" "$OUT.src"   # a result of other sources, or none
PNR=""
[ "$unit" = trad ] && PNR=--one-pnr
"$ROOT/scripts/synth.sh" --one "$LINE" --one-out "$OUT" $PNR "$RES/synth-work"
echo "$SRC" > "$OUT.src"
