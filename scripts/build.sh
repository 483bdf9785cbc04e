#!/usr/bin/env bash
# Configures and builds trirast in build/ (Release, -j2): every target, or only the targets named
# as arguments (e.g. scripts/build.sh trirast). Quiet on success; on failure prints the end of the
# build log and exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
log=build/build.log
targets=()
for t in "$@"; do targets+=(--target "$t"); done
if ! { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2 "${targets[@]}"; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "build.sh: build failed (full log: $log)" >&2
  exit 1
fi
