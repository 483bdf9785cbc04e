#!/bin/bash
# Speed of the SystemC models (docs/sc-model.md): for the built-in benchmark scenes
# (lowpoly-far, lowpoly-near, highpoly-far, highpoly-near, mixed), triangles per second and
# simulated cycles per second of the improved unit's model, the traditional unit's model beside
# it, and the RTL/model wall-time ratio once this build has an "rtl" engine (target: >= 20).
# Usage: scripts/bench_sim.sh [--repeat R] [scene ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j2 --target trirast_sc_bench >/dev/null
SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 exec "$build/model/sc/trirast_sc_bench" "$@"
