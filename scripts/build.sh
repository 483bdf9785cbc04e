#!/usr/bin/env bash
# Configures and builds trirast in build/ (Release, -j2): every target, or only the targets named
# as arguments (e.g. scripts/build.sh trirast). The full log goes to build/build.log; the terminal
# gets one progress line per step of ten percent (and the time), or with --quiet nothing on
# success. On failure prints the end of the log and exits non-zero. Extra configuration:
#   --cmake-arg ARG   passed to cmake's configure step (e.g. -DTRIRAST_RTL_EXTRA_WIDTHS=OFF);
#                     without one naming TRIRAST_RTL_DEFAULT_RUN_ONLY, it is set OFF (every model
#                     the tests use; scripts/demo.sh's first build sets it ON)
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
log=build/build.log
targets=()
cmake_args=()
quiet=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quiet) quiet=1 ;;
    --cmake-arg) [ $# -ge 2 ] || { echo "build.sh: --cmake-arg needs a value" >&2; exit 2; }
                 cmake_args+=("$2"); shift ;;
    -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "build.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) targets+=(--target "$1") ;;
  esac
  shift
done
[[ " ${cmake_args[*]-} " == *TRIRAST_RTL_DEFAULT_RUN_ONLY* ]] ||
  cmake_args+=(-DTRIRAST_RTL_DEFAULT_RUN_ONLY=OFF)
start=$SECONDS
# Progress: make's "[ NN%]" lines, one line each time the tens digit moves, with the elapsed time.
progress() {
  local last=-1 line pct
  while IFS= read -r line; do
    printf '%s\n' "$line" >>"$log"
    [ $quiet = 1 ] && continue
    if [[ "$line" =~ ^\[\ *([0-9]+)%\] ]]; then
      pct=$((BASH_REMATCH[1] / 10 * 10))
      if [ "$pct" -gt "$last" ]; then
        last=$pct
        printf 'build.sh: %3d%% after %d s\n' "$pct" $((SECONDS - start)) >&2
      fi
    elif [[ "$line" == *"Executing Verilator"* ]] && [ "$last" -lt 0 ]; then
      last=0
      printf 'build.sh: configuring (Verilating the RTL models) after %d s\n' $((SECONDS - start)) >&2
    fi
  done
}
: >"$log"
if ! { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${cmake_args[@]+"${cmake_args[@]}"} &&
       cmake --build build -j2 ${targets[@]+"${targets[@]}"}; } 2>&1 | progress; then
  tail -n 40 "$log" >&2
  echo "build.sh: build failed (full log: $log)" >&2
  exit 1
fi
[ $quiet = 1 ] || echo "build.sh: built in $((SECONDS - start)) s (log: $log)" >&2
