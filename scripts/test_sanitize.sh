#!/usr/bin/env bash
# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer (TRIRAST_SANITIZE=ON)
# in build-asan/, -j2, run through ctest. The exit status is the suite's. Extra arguments go to
# ctest (e.g. -R fuzz). scripts/test.sh (CI) runs it after the normal suite.
#
# Every test program runs under both sanitizers, the SystemC ones included; only the benchmark
# programs are not built, and the libFuzzer test (sanitized itself) and the gen2 model-vs-RTL
# prototype check (a Verilator testbench; tests/sc/CMakeLists.txt) run in the normal suite only.
# The Verilated models' generated C++ is not instrumented (Verilator's code, not ours;
# tb/CMakeLists.txt), and is taken from build/ when that exists (below); the harnesses
# around the models are compiled here and checked.
# SystemC switches stacks between its coroutines (QuickThreads in Debian's libsystemc, not
# annotated for ASan), after which ASan no longer knows the main thread's stack and cannot clean
# it up when an exception unwinds it: stack-use-after-return detection is off (ASAN_OPTIONS below)
# and the stack redzones are not built (CMakeLists.txt, TRIRAST_SANITIZE: --param=asan-stack=0,
# -fno-sanitize-address-use-after-scope), or every exception after a SystemC run would leave false
# stack-buffer-overflow reports behind. Heap, globals, use-after-free, leaks and UBSan are checked.
set -euo pipefail
if [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then  # this text (as scripts/test.sh)
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit 0
fi
cd "$(dirname "$0")/.."
build=build-asan
mkdir -p "$build"
log="$build/build.log"
# The Verilated models are not instrumented here (above), so when build/ (the normal suite's
# build, not sanitized) exists, the models it compiled are brought up to date there and linked in
# (TRIRAST_RTL_MODELS_FROM, tb/CMakeLists.txt) instead of compiling the same generated
# C++ again. TRIRAST_ASAN_OWN_MODELS=1 compiles them here.
models=(-DTRIRAST_RTL_MODELS_FROM=)
if [ "${TRIRAST_ASAN_OWN_MODELS:-0}" != 1 ] && [ -f build/CMakeCache.txt ] &&
   ! grep -q '^TRIRAST_SANITIZE:BOOL=ON' build/CMakeCache.txt; then
  if ! cmake --build build -j2 --target trirast_rtl_models >"$log" 2>&1; then
    tail -n 40 "$log" >&2
    echo "test_sanitize.sh: building build/'s Verilated models failed (full log: $log)" >&2
    exit 1
  fi
  models=(-DTRIRAST_RTL_MODELS_FROM="$PWD/build")
fi
# -O1 -g1: about half the build time of -O2 -g, line numbers in every report.
if ! { cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRIRAST_SANITIZE=ON \
         -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" "${models[@]}" &&
       cmake --build "$build" -j2; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "test_sanitize.sh: build failed (full log: $log)" >&2
  exit 1
fi
# Leak checking stays on, except for Debian's libassimp, which leaks ~2.5 kB of its own on some
# files it refuses (not our allocations); a finding aborts the test that made it.
# The sanitizers write to files in $build/sanitizer-logs/ (one per process), not to stderr: after
# a SystemC run ASan warns on stderr at the next exception ("ignoring requested
# __asan_handle_no_return"), which would break the CLI tests' one-line-error checks. A finding
# still aborts its process (the test fails); its report is printed below after the run.
supp="$PWD/$build/lsan.supp"
printf 'leak:libassimp.so\n' >"$supp"
logs="$PWD/$build/sanitizer-logs"
rm -rf "$logs"
mkdir -p "$logs"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$supp:print_suppressions=0}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=0:detect_leaks=1:abort_on_error=1:log_path=$logs/asan}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:log_path=$logs/ubsan}"
status=0
( cd "$build" && ctest --output-on-failure --no-tests=error -j2 "$@" ) || status=$?
found=$(grep -l -E "ERROR: |runtime error|SUMMARY: " "$logs"/* 2>/dev/null || true)
if [ -n "$found" ]; then
  for f in $found; do
    echo "==== $f" >&2
    head -n 60 "$f" >&2
  done
  echo "test_sanitize.sh: sanitizer findings in $(echo "$found" | wc -l) process(es) (logs: $logs)" >&2
  [ "$status" -ne 0 ] || status=1
fi
exit "$status"
