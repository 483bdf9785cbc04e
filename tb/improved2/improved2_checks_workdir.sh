# Sourced by the improved2 unit's block-check scripts (run_checks.sh,
# improved2_corner_forms_exhaustive.sh), after their options are parsed; ME names the script.
# improved2_checks_workdir DEFAULT [WORKDIR]: refuses a second WORKDIR (exit 2) and a missing
# verilator or python3 (exit 1), then sets WORK to WORKDIR (or DEFAULT), created, as an absolute
# path.
improved2_checks_workdir() {
  local default="$1" t
  shift
  [ $# -le 1 ] || { echo "$ME: one WORKDIR at most (got: $*)" >&2; exit 2; }
  for t in verilator python3; do
    command -v "$t" >/dev/null || { echo "$ME: $t not found in PATH" >&2; exit 1; }
  done
  WORK="${1:-$default}"
  mkdir -p "$WORK" || { echo "$ME: cannot create WORKDIR $WORK" >&2; exit 1; }
  WORK="$(cd "$WORK" && pwd)"
}
