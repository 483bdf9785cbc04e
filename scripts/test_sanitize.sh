#!/usr/bin/env bash
# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer (TRIRAST_SANITIZE=ON)
# in build-asan/, -j2, run through ctest. The exit status is the suite's. Extra arguments go to
# ctest (e.g. -R fuzz). scripts/test.sh (CI) runs it after the normal suite.
#
# Every test program runs under both sanitizers, the SystemC ones included; only the benchmark
# programs are not built, and the libFuzzer test (sanitized itself) runs in the normal suite only.
# SystemC switches stacks between its coroutines (QuickThreads in Debian's libsystemc, not
# annotated for ASan), after which ASan no longer knows the main thread's stack and cannot clean
# it up when an exception unwinds it: stack-use-after-return detection is off (ASAN_OPTIONS below)
# and the stack redzones are not built (CMakeLists.txt, TRIRAST_SANITIZE: --param=asan-stack=0,
# -fno-sanitize-address-use-after-scope), or every exception after a SystemC run would leave false
# stack-buffer-overflow reports behind. Heap, globals, use-after-free, leaks and UBSan are checked.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
mkdir -p "$build"
log="$build/build.log"
# -O1 -g1: about half the build time of -O2 -g, line numbers in every report.
if ! { cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRIRAST_SANITIZE=ON \
         -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" &&
       cmake --build "$build" -j2; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "test_sanitize.sh: build failed (full log: $log)" >&2
  exit 1
fi
# Leak checking stays on, except for Debian's libassimp, which leaks ~2.5 kB of its own on some
# files it refuses (not our allocations); a finding aborts the test that made it.
supp="$PWD/$build/lsan.supp"
printf 'leak:libassimp.so\n' >"$supp"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$supp:print_suppressions=0}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=0:detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build"
ctest --output-on-failure -j2 "$@"
