#!/usr/bin/env bash
# The whole suite, twice: install what is missing, configure, build with -j2 and run every test
# through ctest in build/ (this includes one minute of the libFuzzer target), then the same suite
# built with AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/
# (scripts/test_sanitize.sh), then the multi-threaded golden's tests under ThreadSanitizer in
# build-tsan/ (scripts/test_tsan.sh). The exit status is non-zero if any of them fails. Extra
# arguments go to both ctest runs (e.g. -R cli). TRIRAST_SKIP_SANITIZE=1 runs the first suite only
# (local use; CI runs all three). A ctest selection that matches no test fails (--no-tests=error).
#   scripts/test.sh [CTEST_ARGS ...]     scripts/test.sh -h | --help   (this text)
set -euo pipefail
if [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit 0
fi
cd "$(dirname "$0")/.."
./scripts/deps.sh
start=$SECONDS
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTRIRAST_RTL_EXTRA_WIDTHS=ON -DTRIRAST_RTL_DEFAULT_RUN_ONLY=OFF >/dev/null
cmake --build build -j2
status=0
( cd build && ctest --output-on-failure --no-tests=error -j2 "$@" ) || status=1
echo "test.sh: suite $([ $status -eq 0 ] && echo passed || echo FAILED) in build/ ($((SECONDS - start)) s)"
if [ "${TRIRAST_SKIP_SANITIZE:-0}" != 1 ]; then
  start=$SECONDS
  sanitize=0
  ./scripts/test_sanitize.sh "$@" || sanitize=1
  echo "test.sh: sanitizer suite $([ $sanitize -eq 0 ] && echo passed || echo FAILED) in build-asan/ ($((SECONDS - start)) s)"
  [ $sanitize -eq 0 ] || status=1
  start=$SECONDS
  tsan=0
  ./scripts/test_tsan.sh || tsan=1
  echo "test.sh: thread sanitizer run $([ $tsan -eq 0 ] && echo passed || echo FAILED) in build-tsan/ ($((SECONDS - start)) s)"
  [ $tsan -eq 0 ] || status=1
fi
exit $status
