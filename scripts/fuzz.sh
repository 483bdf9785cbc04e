#!/usr/bin/env bash
# The libFuzzer target (tb/fuzz/libfuzzer/): builds it with clang++ -fsanitize=fuzzer,address,undefined in
# build-fuzz/ (or $TRIRAST_FUZZ_BUILD), runs it for SECONDS (default 600, one process) over the
# corpus build-fuzz/corpus (kept between runs, never in git), and prints executions per second.
# The compiler is $TRIRAST_FUZZ_CXX (default clang++); without it the build fails, and so does
# this script (the test suite runs it as fuzz_libfuzzer_60s: it fails, it never skips).
# TRIRAST_FUZZ_INJECT_FAULT=1 makes the unit drop a pixel: the run must then fail (self-test).
# Exit status 0: no finding; otherwise the fuzzer's (a crash file crash-* is left in build-fuzz/).
#
#   scripts/fuzz.sh            # 10 minutes
#   scripts/fuzz.sh 60         # one minute (what the test suite runs)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "fuzz.sh: SECONDS must be a positive integer, got '$seconds'" >&2
  exit 2
fi
build="${TRIRAST_FUZZ_BUILD:-build-fuzz}"
cxx="${TRIRAST_FUZZ_CXX:-clang++}"
if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "fuzz.sh: no $cxx: install clang and libclang-rt-14-dev (scripts/deps.sh)" >&2
  exit 1
fi
mkdir -p "$build"
log="$build/build.log"
if ! { cmake -S tb/fuzz/libfuzzer -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo &&
       cmake --build "$build" -j2; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "fuzz.sh: build failed (full log: $log)" >&2
  exit 1
fi
mkdir -p "$build/corpus"
run_log="$build/fuzz.log"
echo "fuzz.sh: running $build/trirast_fuzz_target for $seconds s (log: $run_log)"
status=0
( cd "$build" &&
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ./trirast_fuzz_target -max_total_time="$seconds" -max_len=512 -timeout=30 -rss_limit_mb=4096 \
    -print_final_stats=1 corpus ) >"$run_log" 2>&1 || status=$?
# "Done N runs in T second(s)" is libFuzzer's last word on a clean run; -print_final_stats adds
# the average executions per second.
runs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1/p' "$run_log" | tail -n 1)
secs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\2/p' "$run_log" | tail -n 1)
rate=$(sed -n 's/^stat::average_exec_per_sec: *\([0-9]*\).*/\1/p' "$run_log" | tail -n 1)
if [ "$status" -ne 0 ] || [ -z "$runs" ]; then
  grep -v '^#[0-9]' "$run_log" | tail -n 60 >&2
  echo "fuzz.sh: FINDING (exit $status); full log $run_log, crash input in $build/" >&2
  exit 1
fi
corpus=$(find "$build/corpus" -type f | wc -l)
cov=$(grep -o 'cov: [0-9]*' "$run_log" | tail -n 1 || true)
echo "fuzz.sh: no finding: $runs executions in $secs s, ${rate:-$((runs / (secs > 0 ? secs : 1)))} exec/s; $cov, corpus $corpus inputs"
