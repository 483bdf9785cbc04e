#!/usr/bin/env bash
# The sweep on a Slurm cluster: simulation shards and synthesis jobs as job arrays,
# a dependent merge job.
#   scripts/sweep_slurm.sh [--quick] [--shards N] [--results DIR] [--out DIR] [--synth [--rounds R]]
#                          [--doc [--doc-out DIR]] [--no-wait] [--bin PATH] [-- SWEEP-OPTIONS...]
# 1. `sbatch --array=0-(N-1)`: task shards `trirast sweep --shard K/N --out RESULTS` (one result
#    file per configuration x scene; a rerun skips complete ones).
# 2. A merge job (`--dependency=afterok` on the array): with --synth, `trirast sweep --merge
#    RESULTS --synth-todo` lists the configurations on a Pareto front whose area is still an
#    estimate; they are submitted as a synthesis array (scripts/sweep_synth_task.sh: Yosys
#    Xilinx 7, and iCE40 place and route for the traditional unit) with a further merge job
#    afterok on it; up to R rounds (default 3: synthesized areas move points on and off the area
#    front). The list holds every buildable configuration on a hardware front (and both default
#    units) whose area is not from this run's synthesis: docs/synth.csv rows of an older RTL are
#    redone. Model-only configurations (quotient truncation K) are never synthesized (no RTL). Then the final merge: `trirast sweep --merge RESULTS --out OUT`, or with --doc
#    scripts/sweep.sh --merge RESULTS (docs/speed-vs-error.md and its plots; --doc-out DIR: there).
# 3. Waits for RESULTS/done (or RESULTS/failed) unless --no-wait; a failed shard or synthesis job
#    is named, and the merge names the tasks without a result file.
# Defaults: N = 16 shards (4 with --quick), RESULTS = build/sweep-slurm, OUT = RESULTS/out.
# SLURM_CONF must point at the cluster's configuration (scripts/slurm_local.sh env, locally).
# SWEEP-OPTIONS (--engines, --scenes, --width, --height, --synth-csv, --synth-script) are passed
# to every trirast sweep of the run, so that every task and the merge see the same task list.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
SELF="$ROOT/scripts/sweep_slurm.sh"
die() { echo "sweep_slurm.sh: $*" >&2; exit 2; }

# ---- stage jobs (run by Slurm): --stage merge ROUND RESULTS ----
if [ "${1:-}" = --stage ]; then
  ROUND="$3"; RES="$4"
  # shellcheck disable=SC1091
  . "$RES/run.env"
  fail() { echo "sweep_slurm.sh: $*" >&2; echo "$*" > "$RES/failed"; exit 1; }
  echo "$(date -u +%s) $(cut -d' ' -f1-3 /proc/loadavg) merge-$ROUND" >> "$RES/load.txt"
  if [ "$SYNTH" = 1 ] && [ "$ROUND" -lt "$ROUNDS" ]; then
    TODO="$RES/synth-todo-$ROUND.txt"
    "$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$RES/round-$ROUND" --synth-todo "$TODO" \
      > "$RES/logs/plan-$ROUND.txt" || fail "merge of round $ROUND failed: $RES/logs/merge-$ROUND.out"
    n=$(grep -c . "$TODO" || true)
    if [ "$n" -gt 0 ]; then
      echo "sweep_slurm.sh: round $ROUND: $n front configuration(s) to synthesize: $(tr '\n' ' ' < "$TODO")"
      s=$(sbatch --parsable --array=0-$((n - 1)) -J "$JOBNAME" -o "$RES/logs/synth-$ROUND-%a.out" \
            --wrap "'$ROOT/scripts/sweep_synth_task.sh' '$TODO' \$SLURM_ARRAY_TASK_ID '$RES' && touch '$RES/status/synth-$ROUND-'\$SLURM_ARRAY_TASK_ID.ok || { touch '$RES/status/synth-$ROUND-'\$SLURM_ARRAY_TASK_ID.failed; exit 1; }") ||
        fail "sbatch of the synthesis array failed"
      sbatch --parsable --dependency=afterok:"$s" --kill-on-invalid-dep=yes -J "$JOBNAME" \
        -o "$RES/logs/merge-$((ROUND + 1)).out" --wrap "'$SELF' --stage merge $((ROUND + 1)) '$RES'" >/dev/null ||
        fail "sbatch of the merge job failed"
      exit 0
    fi
  fi
  if [ "$DOC" = 1 ]; then
    TRIRAST_BIN="$BIN" "$ROOT/scripts/sweep.sh" "${QUICK_ARG[@]}" --merge "$RES" \
      ${DOC_OUT:+--out "$DOC_OUT"} --command "$CMDLINE" -- "${SEL_EXTRA[@]}" || fail "final merge (scripts/sweep.sh --merge) failed"
  else
    "$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$OUT" || fail "final merge failed"
  fi
  echo "round $ROUND" > "$RES/done"
  exit 0
fi

QUICK=0; SHARDS=""; RES=""; OUT=""; SYNTH=0; ROUNDS=3; DOC=0; DOC_OUT=""; WAIT=1; BIN=""
CMDLINE="scripts/sweep_slurm.sh $*"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    --shards) SHARDS="${2:?--shards needs a number}"; shift ;;
    --results) RES="${2:?--results needs a directory}"; shift ;;
    --out) OUT="${2:?--out needs a directory}"; shift ;;
    --synth) SYNTH=1 ;;
    --rounds) ROUNDS="${2:?--rounds needs a number}"; shift ;;
    --doc) DOC=1 ;;
    --doc-out) DOC_OUT="${2:?--doc-out needs a directory}"; shift ;;
    --no-wait) WAIT=0 ;;
    --bin) BIN="${2:?--bin needs a path}"; shift ;;
    --) shift; break ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) die "unknown option '$1' (see --help)" ;;
  esac
  shift
done
SEL_EXTRA=("$@")
[ -n "$SHARDS" ] || { SHARDS=16; [ "$QUICK" = 1 ] && SHARDS=4; }
[[ "$SHARDS" =~ ^[1-9][0-9]*$ ]] || die "--shards: '$SHARDS' is not a number >= 1"
[[ "$ROUNDS" =~ ^[0-9]+$ ]] || die "--rounds: '$ROUNDS' is not a number >= 0"
command -v sbatch >/dev/null || die "sbatch not found (Debian package slurm-wlm; scripts/slurm_local.sh starts a local one)"
RES="${RES:-$ROOT/build/sweep-slurm}"
mkdir -p "$RES/logs" "$RES/status"
RES="$(cd "$RES" && pwd)"
OUT="${OUT:-$RES/out}"
mkdir -p "$OUT"; OUT="$(cd "$OUT" && pwd)"
if [ -n "$DOC_OUT" ]; then mkdir -p "$DOC_OUT"; DOC_OUT="$(cd "$DOC_OUT" && pwd)"; fi
# shellcheck source=scripts/sweep_tasks.sh
. "$ROOT/scripts/sweep_tasks.sh"
sweep_tasks_prepare "${SEL_EXTRA[@]}"
JOBNAME="trirast-sweep-$(basename "$RES")-$$"
rm -f "$RES/done" "$RES/failed" "$RES"/status/* "$RES/load.txt"
# The load during the run (the report names it): "EPOCH LOAD1 LOAD5 LOAD15 WHAT" lines, one at
# submission, one per merge job, and every 30 s while this script waits.
echo "$(nproc)" > "$RES/cpus.txt"
echo "$(date -u +%s) $(cut -d' ' -f1-3 /proc/loadavg) submit" >> "$RES/load.txt"
{
  echo "BIN='$BIN'"
  echo "OUT='$OUT'"
  echo "DOC=$DOC"
  echo "DOC_OUT='$DOC_OUT'"
  echo "SYNTH=$SYNTH"
  echo "ROUNDS=$ROUNDS"
  echo "JOBNAME='$JOBNAME'"
  echo "CMDLINE='$CMDLINE'"
  declare -p SEL SEL_EXTRA QUICK_ARG  # (empty arrays stay empty)
} > "$RES/run.env"

SIM=$(sbatch --parsable --array=0-$((SHARDS - 1)) -J "$JOBNAME" -o "$RES/logs/sim-%a.out" \
  --wrap "$(printf '%q ' "$BIN" sweep "${SEL[@]}") --shard \$SLURM_ARRAY_TASK_ID/$SHARDS --out '$RES' && touch '$RES/status/sim-'\$SLURM_ARRAY_TASK_ID.ok || { touch '$RES/status/sim-'\$SLURM_ARRAY_TASK_ID.failed; exit 1; }") ||
  die "sbatch of the simulation array failed"
MERGE=$(sbatch --parsable --dependency=afterok:"$SIM" --kill-on-invalid-dep=yes -J "$JOBNAME" \
  -o "$RES/logs/merge-0.out" --wrap "'$SELF' --stage merge 0 '$RES'") || die "sbatch of the merge job failed"
echo "sweep_slurm.sh: $TASKS tasks in $SHARDS shards: array job $SIM, merge job $MERGE (afterok)$([ "$SYNTH" = 1 ] && echo ", then up to $ROUNDS synthesis rounds"); results in $RES"
[ "$WAIT" = 1 ] || { echo "sweep_slurm.sh: not waiting: $RES/done (or $RES/failed) appears at the end"; exit 0; }

START=$(date +%s)
LAST_SAMPLE=$START
while :; do
  now=$(date +%s)
  if [ $((now - LAST_SAMPLE)) -ge 30 ]; then
    echo "$now $(cut -d' ' -f1-3 /proc/loadavg) wait" >> "$RES/load.txt"
    LAST_SAMPLE=$now
  fi
  [ -f "$RES/done" ] && break
  [ -f "$RES/failed" ] && break
  if [ -z "$(squeue -h -n "$JOBNAME" -o %i 2>/dev/null)" ]; then
    sleep 2  # the last job may be writing its marker
    [ -f "$RES/done" ] || [ -f "$RES/failed" ] || echo "the merge job did not run to its end (a job it depends on failed, or it was cancelled)" > "$RES/failed"
    break
  fi
  sleep 2
done
for f in "$RES"/status/*.failed; do
  [ -f "$f" ] || continue
  n=$(basename "$f" .failed)
  echo "sweep_slurm.sh: job $n failed (log: $RES/logs/$n.out)" >&2
done
if [ -f "$RES/failed" ]; then
  echo "sweep_slurm.sh: FAILED: $(cat "$RES/failed")" >&2
  # Name the tasks without a result file.
  "$BIN" sweep "${SEL[@]}" --merge "$RES" --out "$RES/check" >/dev/null 2>"$RES/logs/check.err" || cat "$RES/logs/check.err" >&2
  exit 1
fi
echo "sweep_slurm.sh: done in $(($(date +%s) - START)) s: $([ "$DOC" = 1 ] && echo "document written by scripts/sweep.sh --merge" || echo "$OUT")"
