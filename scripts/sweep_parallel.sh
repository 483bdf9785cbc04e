#!/usr/bin/env bash
# The distributed sweep's task list through GNU parallel, on this workstation or ssh
# hosts; the same tasks, result files and merge as scripts/sweep_slurm.sh.
#   scripts/sweep_parallel.sh [--quick] [--jobs J] [--shards N] [--results DIR] [--out DIR]
#                             [--synth [--rounds R]] [--sshlogin LOGIN]... [--bin PATH]
#                             [-- SWEEP-OPTIONS...]
# 1. parallel runs `trirast sweep --shard K/N --out RESULTS` for K = 0..N-1, J at a time (default
#    J = the cores, N = 4 J); a rerun skips the tasks whose result files are complete (resumable).
# 2. With --synth, up to R rounds (default 3) of: `trirast sweep --merge RESULTS --synth-todo`,
#    then scripts/sweep_synth_task.sh for every listed configuration through parallel.
# 3. `trirast sweep --merge RESULTS --out OUT` (OUT default RESULTS/out).
# --sshlogin is passed to parallel (repeatable); the hosts need this tree and binary at the same
# paths and RESULTS on a shared file system. A failed shard or synthesis job is named (from
# parallel's --joblog) and the merge names the tasks without a result file; exit 1 then.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
die() { echo "sweep_parallel.sh: $*" >&2; exit 2; }
QUICK=0; JOBS="$(nproc)"; SHARDS=""; RES=""; OUT=""; SYNTH=0; ROUNDS=3; BIN=""; SSH=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    --jobs) JOBS="${2:?--jobs needs a number}"; shift ;;
    --shards) SHARDS="${2:?--shards needs a number}"; shift ;;
    --results) RES="${2:?--results needs a directory}"; shift ;;
    --out) OUT="${2:?--out needs a directory}"; shift ;;
    --synth) SYNTH=1 ;;
    --rounds) ROUNDS="${2:?--rounds needs a number}"; shift ;;
    --sshlogin) SSH+=(--sshlogin "${2:?--sshlogin needs a login}"); shift ;;
    --bin) BIN="${2:?--bin needs a path}"; shift ;;
    --) shift; break ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) die "unknown option '$1' (see --help)" ;;
  esac
  shift
done
[[ "$JOBS" =~ ^[1-9][0-9]*$ ]] || die "--jobs: '$JOBS' is not a number >= 1"
[ -n "$SHARDS" ] || SHARDS=$((4 * JOBS))
[[ "$SHARDS" =~ ^[1-9][0-9]*$ ]] || die "--shards: '$SHARDS' is not a number >= 1"
[[ "$ROUNDS" =~ ^[0-9]+$ ]] || die "--rounds: '$ROUNDS' is not a number >= 0"
command -v parallel >/dev/null || die "GNU parallel not found (Debian package parallel: scripts/deps.sh)"
RES="${RES:-$ROOT/build/sweep-parallel}"
mkdir -p "$RES/logs"
RES="$(cd "$RES" && pwd)"
OUT="${OUT:-$RES/out}"
# shellcheck source=scripts/sweep_tasks.sh
. "$ROOT/scripts/sweep_tasks.sh"
sweep_tasks_prepare "$@"
START=$(date +%s)

failed_jobs() {  # failed_jobs JOBLOG WHAT: names the jobs of parallel's joblog that failed
  awk -F'\t' -v what="$2" 'NR > 1 && $7 != 0 {printf "sweep_parallel.sh: %s %s failed (exit %s): %s\n", what, $1, $7, $9}' "$1" >&2
}

echo "sweep_parallel.sh: $TASKS tasks in $SHARDS shards, $JOBS at a time; results in $RES"
SIM_OK=1
parallel --jobs "$JOBS" "${SSH[@]}" --joblog "$RES/logs/parallel-sim.log" --halt never \
  "$(printf '%q ' "$BIN" sweep "${SEL[@]}") --shard {}/$SHARDS --out $(printf '%q' "$RES") > $(printf '%q' "$RES")/logs/sim-{}.out 2>&1" \
  ::: $(seq 0 $((SHARDS - 1))) || SIM_OK=0
if [ "$SIM_OK" = 0 ]; then
  failed_jobs "$RES/logs/parallel-sim.log" shard
  "$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$RES/check" >/dev/null || true
  exit 1
fi
if [ "$SYNTH" = 1 ]; then
  for ROUND in $(seq 0 $((ROUNDS - 1))); do
    TODO="$RES/synth-todo-$ROUND.txt"
    "$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$RES/round-$ROUND" --synth-todo "$TODO" \
      > "$RES/logs/plan-$ROUND.txt"
    n=$(grep -c . "$TODO" || true)
    [ "$n" -gt 0 ] || break
    echo "sweep_parallel.sh: round $ROUND: $n front configuration(s) to synthesize"
    parallel --jobs "$JOBS" "${SSH[@]}" --joblog "$RES/logs/parallel-synth-$ROUND.log" --halt never \
      "$(printf '%q ' "$ROOT/scripts/sweep_synth_task.sh" "$TODO") {} $(printf '%q' "$RES") > $(printf '%q' "$RES")/logs/synth-$ROUND-{}.out 2>&1" \
      ::: $(seq 0 $((n - 1))) || { failed_jobs "$RES/logs/parallel-synth-$ROUND.log" "synthesis of line"; exit 1; }
  done
fi
"$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$OUT"
echo "sweep_parallel.sh: done in $(($(date +%s) - START)) s: $OUT"
