#!/usr/bin/env bash
# gen2 study (docs/gen2-design.md, "Fitting the HX8K"): what sharing the edge lanes would cost in
# cycles. Builds the SystemC cycles table (the target trirast_sc_cycles_table of
# scripts/cycles_table.sh) from a git worktree of HEAD in which model/improved2/improved2_unit.cpp's
# lane time L (the slowest of the three lanes) is replaced by
#   shared: L_0 + L_1 + L_2             (one lane serving the three edges in turn)
#   pair:   min over a of max(L_a, L_b + L_c)   (one lane for edge a, one shared by the other two,
#                                        the best assignment per triangle)
# and prints the second-generation table of each beside the unchanged one. Every other stage
# keeps the contract of docs/timing.md, and the hand-over between the edges of a shared lane is
# counted free, so each is a lower bound on the cycles of such a unit.
#   scripts/gen2_study/lane_share_cycles.sh [WORKDIR]   (default /tmp/trirast-lane-share)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="${1:-/tmp/trirast-lane-share}"
max_line='    r.lane_cycles = std::max(r.lane_cycles, r.lane[k].cycles);'
grep -qF "$max_line" "$root/model/improved2/improved2_unit.cpp" || {
  echo "lane_share_cycles.sh: model/improved2/improved2_unit.cpp has no line '$max_line'" >&2; exit 1; }
cleanup() { git -C "$root" worktree remove --force "$work/src" >/dev/null 2>&1 || true; }
trap cleanup EXIT
trap 'exit 130' INT TERM
mkdir -p "$work"
cleanup
git -C "$root" worktree add --detach "$work/src" HEAD >/dev/null 2>&1
table() {  # table VARIANT: the gen2 table of the cycles table built with that lane time
  local variant="$1" src="$work/src" build="$work/build"
  git -C "$src" checkout -q -- model/improved2/improved2_unit.cpp
  /usr/bin/python3 - "$src/model/improved2/improved2_unit.cpp" "$variant" "$max_line" <<'EOF'
import sys
path, variant, max_line = sys.argv[1:]
text = open(path).read()
loop_end = max_line + "\n  }\n"
if variant == "shared":
    text = text.replace(max_line, "    r.lane_cycles += r.lane[k].cycles;")
elif variant == "pair":
    text = text.replace(loop_end, loop_end +
        "  r.lane_cycles = ~uint64_t(0);\n"
        "  for (int a = 0; a < 3; ++a)\n"
        "    r.lane_cycles = std::min(r.lane_cycles, std::max(r.lane[a].cycles,\n"
        "        r.lane[(a + 1) % 3].cycles + r.lane[(a + 2) % 3].cycles));\n")
open(path, "w").write(text)
EOF
  [ -f "$build/CMakeCache.txt" ] || cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j2 --target trirast_sc_cycles_table >/dev/null
  echo "## lane time: $variant"
  SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$build/trirast_sc_cycles_table" "$src" | sed -n '/^@@$/,$p' |
    tail -n +2 | cut -d'|' -f1-9
  echo
}
table max
table shared
table pair
