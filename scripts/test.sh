#!/usr/bin/env bash
# The whole suite: install what is missing, configure, build with -j2, run every test through
# ctest. The exit status is the suite's.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
cd build
ctest --output-on-failure -j2 "$@"
