#!/usr/bin/env bash
# Runs a command that must fail: exit status 0 only if COMMAND exits non-zero (or is killed) AND
# its output names NAME. For the assertion tests (ctest rtl_assert_*): a run that a broken input
# must stop.
#   tests/rtl/expect_failure.sh NAME COMMAND [ARG...]
set -uo pipefail
name="${1:?usage: expect_failure.sh NAME COMMAND [ARG...]}"
shift
out=$("$@" 2>&1)
status=$?
printf '%s\n' "$out"
if [ "$status" -eq 0 ]; then
  echo "expect_failure: '$*' exited 0; it had to fail naming $name" >&2
  exit 1
fi
if ! grep -qF -- "$name" <<< "$out"; then
  echo "expect_failure: '$*' failed (status $status) without naming $name" >&2
  exit 1
fi
echo "expect_failure: '$*' failed (status $status) naming $name, as it must"
