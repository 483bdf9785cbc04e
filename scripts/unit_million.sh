#!/bin/bash
# The improved-Bresenham unit against the golden rasterizer on 1,000,000 random triangles
# (1/256 grid, 1024x768, both boundary modes). Builds test_unit_engine if needed.
# Usage: scripts/unit_million.sh [count]     (default 1000000)
# Prints the number of triangles compared; exits non-zero on any mismatch.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
count="${1:-1000000}"

# Configure (once) and build only the test program this needs.
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j2 --target test_unit_engine >/dev/null

# The RandomViewport family, sized by TRIRAST_RANDOM_COUNT; gtest exits non-zero on a mismatch.
TRIRAST_RANDOM_COUNT="$count" "$build/test_unit_engine" \
  --gtest_filter=UnitEngine.RandomViewport --gtest_brief=1
echo "unit_million: $count random triangles generated, unit matches golden in both boundary modes"
