#!/bin/bash
# Improved vs traditional Bresenham unit in cycles: runs the SystemC models on the five
# benchmark scenes of Mileff, Nehez & Dudra and on meshes and writes docs/cycles-improved-vs-trad.md,
# with the paper's "about 32% faster" beside the measured numbers; the first generation of the
# improved unit, then the second (improved2-sc) beside the first and the traditional unit.
# Usage: scripts/cycles_table.sh [OUTPUT.md]     (default docs/cycles-improved-vs-trad.md)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
out="${1:-$root/docs/cycles-improved-vs-trad.md}"
# TRIRAST_NO_BUILD=1: use the program as built (the suite's doc_cycles_table_current test).
if [ "${TRIRAST_NO_BUILD:-0}" != 1 ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  fi
  cmake --build "$build" -j2 --target trirast_sc_cycles_table >/dev/null
fi
tables="$(SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$build/trirast_sc_cycles_table" "$root")"
table="${tables%%$'\n'@@*}"   # gen1, traditional and half-space units
gen2="${tables#*@@$'\n'}"     # the second-generation improved unit
tmp="$out.tmp"
cat >"$tmp" <<DOC
# Improved vs traditional Bresenham unit (and the half-space tile unit), in cycles

Made by \`scripts/cycles_table.sh\` (SystemC models of the four units, docs/timing.md; 1024x768, S = 8,
default camera; N = 1, FIFO 8, sink always ready, boundary \`step\` unless the column says
otherwise). "improved vs trad" is \`(trad - improved) / trad\`: positive when the improved unit
needs fewer cycles. The paper (Zhang & Ruan, "A triangle rasterization based on improved
Bresenham algorithm") reports the improved unit **about 32% faster** than the traditional one.

$table

How to read it. Both units overlap the set-up of the next triangle with the walk of the current
one, so a triangle costs about \`max(setup, walk)\` cycles (the "cyc/tri" columns give the total
and the two stages' busy cycles per triangle):

- The improved unit's set-up is \`3 + L\` cycles, with \`L\` the slowest edge lane: a slope division
  and an entry-x division, plus the boundary steps. With the default adaptive divider a division
  runs \`bits(box extent) + 1\` iterations (4 for an 8-pixel box), with the fixed one always
  \`Q = 15\` (last column). Its walk is one cycle per row (per N rows).
- The traditional unit's set-up is 3 cycles (no divider), and its walk costs, per row, the Bresenham
  steps of the busier of its two edge walkers (at least one cycle): x-major edges cost a cycle per
  pixel of edge, and it walks every row of the triangle, also off-screen.

So the improved unit wins where triangles are large or have long x-major edges (near scenes,
low-poly meshes, whole-screen and off-screen parts), and loses where triangles are a few pixels
(high-poly far, dense meshes), where even a short division per edge costs more than the
traditional unit's few steps. N = 4 changes little while the set-up is the bottleneck; \`divide\`
mode trades boundary steps for a third division, which helps tall boxes only.

The half-space tile unit (docs/timing.md, "The half-space unit"; \`--stamp\`, \`--tile\`,
\`--hs-walk\`) has a 2-cycle set-up (no divider) and walks its box: one cycle per tile test and per
stamp of a partial tile, one span per cycle out of a band buffer. "half-space vs improved" is
\`(improved - half-space) / improved\`: positive when the half-space unit needs fewer cycles.

## The second generation

The second-generation improved unit, improved2 (\`improved2-sc\`, docs/improved2.md), on the
same scenes, beside the first
generation (\`improved-sc\`, "gen1") and the traditional unit (\`trad-sc\`); the same
configuration (N = 1, FIFO 8, sink always ready; boundary \`step\`, adaptive divider, the only
mode the second generation builds). Its default corner form is radix 16 (digit-serial corner
values, no multipliers: the iCE40 form); "DSP corner" is the form with the corner values from
multipliers in one cycle. "vs trad" is \`(trad - gen2) / trad\` and "vs gen1" \`(gen1 - gen2) /
gen1\`: positive when the second generation needs fewer cycles. The paper reports the improved
unit about 32% faster than the traditional one. The model's cycles equal those of the unit's RTL
(\`rtl/improved2/trirast_improved2.f\`, engine \`improved2-rtl\`) triangle for triangle on every built-in
scene of this table (\`tests/rtl/test_rtl_improved2_engine.cpp\`; docs/improved2.md, "Verification").

$gen2

Where the cycles went: the second generation's set-up is a pipeline (box, corner values, lanes,
each holding its own triangle), so the next triangle's box and corner values are formed while the
lanes and the walk stage work; a box of at most 2 x 2 pixel centres skips the lanes (a direct test
of its centres from the corner values), and an empty box retires in the box stage. High-poly far
(0.54 pixels per triangle) is where this matters most; its radix-16 corner values (a cycle for
each 4-bit digit of the operands, signed, for E_L: docs/timing.md's \`d\`) bound that scene, as its
two cycles-per-triangle columns show (radix 16 against DSP products).
DOC
mv "$tmp" "$out"
echo "cycles_table: wrote $out"
