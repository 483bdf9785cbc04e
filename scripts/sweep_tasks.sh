# Sourced by scripts/sweep_slurm.sh and scripts/sweep_parallel.sh (not run on its own): resolves
# the trirast binary and writes the distributed sweep's task list. Needs ROOT, RES (the results
# directory, existing), BIN (may be empty), QUICK (0/1), SHARDS and die(); takes the sweep's
# extra selection options as arguments. Sets BIN (absolute), QUICK_ARG, SEL (the options every
# task and the merge pass to `trirast sweep`), TASKS (the task count) and caps SHARDS at TASKS; writes
# RES/tasks.txt; removes RES/synth's results of other sources (scripts/sweep_synth_task.sh
# --prune: a results directory reused after an RTL change synthesizes those configurations again).
sweep_tasks_prepare() {
  BIN="${BIN:-${TRIRAST_BIN:-$ROOT/build/trirast}}"
  [ -x "$BIN" ] || die "no trirast binary at $BIN (build it, or --bin PATH)"
  BIN="$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")"
  QUICK_ARG=(); [ "$QUICK" = 1 ] && QUICK_ARG=(--quick)
  SEL=("${QUICK_ARG[@]}" --no-progress --synth-csv "$ROOT/docs/synth.csv" --synth-script "$ROOT/scripts/synth.sh" "$@")
  "$BIN" sweep "${SEL[@]}" --list-tasks > "$RES/tasks.txt" || die "trirast sweep --list-tasks failed"
  TASKS=$(wc -l < "$RES/tasks.txt")
  "$ROOT/scripts/sweep_synth_task.sh" --prune "$RES" || die "sweep_synth_task.sh --prune $RES failed"
  [ "$SHARDS" -le "$TASKS" ] || SHARDS=$TASKS
}
