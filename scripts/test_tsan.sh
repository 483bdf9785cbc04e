#!/usr/bin/env bash
# The multi-threaded golden (model/golden/golden_parallel.cpp: writer, sleeping helpers, chunk
# hand-off) under ThreadSanitizer: builds the golden's test program with -fsanitize=thread in
# build-tsan/ (-j2) and runs its GoldenParallel.* tests, which run 2, 3, 4 and 8 threads on scenes
# of up to 132,060 triangles and one engine over many scenes. A data race aborts the test with
# TSan's report. The exit status is the tests'. scripts/test.sh (CI) runs it after the sanitizer
# suite. (The rest of the code is single-threaded; SystemC runs its processes on one thread.)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-tsan
mkdir -p "$build"
log="$build/build.log"
if ! { cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
         -DCMAKE_CXX_FLAGS="-fsanitize=thread" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" &&
       cmake --build "$build" -j2 --target test_golden_variants; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "test_tsan.sh: build failed (full log: $log)" >&2
  exit 1
fi
export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:abort_on_error=1}"
"./$build/test_golden_variants" --gtest_filter='GoldenParallel.*' "$@"
