#!/usr/bin/env bash
# gen2 study: what the parts of the redesigned lane cost on xc7 (docs/gen2-design.md section 2).
#   scripts/gen2_study/lane_parts.sh [WORKDIR]   (default build/gen2_study; needs its trirast_pkg.sv,
#                                                 written by scripts/gen2_study.sh)
# Yosys `synth_xilinx -family xc7 -top trirast_improved2_edge_lane` of rtl/improved2/trirast_improved2_edge_lane.sv as it is (default
# parameters: adaptive, PreIter = 0), then with
# one part at a time replaced by a stub (the sed expression below): the difference in LUT (LUT1-6)
# is what the part costs, the lane's one module not splitting further in `stat`. Parts interact
# through the LUT mapping, so the differences do not add up exactly to the total.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
WORK="${1:-$ROOT/build/gen2_study}"
PKG="$WORK/trirast_pkg.sv"
[ -f "$PKG" ] || { echo "lane_parts.sh: $PKG missing (run scripts/gen2_study.sh --only g2.lane first)" >&2; exit 1; }
command -v yosys >/dev/null || { echo "lane_parts.sh: yosys not found in PATH" >&2; exit 1; }
SRC="$ROOT/rtl/improved2/trirast_improved2_edge_lane.sv"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
luts() {  # luts FILE: "LUT FF" of trirast_improved2_edge_lane on xc7
  yosys -q -p "read_verilog -sv -I $ROOT/rtl $PKG $1; synth_xilinx -family xc7 -top trirast_improved2_edge_lane;
    tee -q -o $TMP/stat stat" >/dev/null 2>&1 || { echo "- -"; return; }
  awk '/Number of cells/ {l = 0; f = 0} $1 ~ /^LUT[1-6]$/ {l += $2} $1 ~ /^FD/ {f += $2}
       END {print l, f}' "$TMP/stat"
}
PARTS=(
"numerator shifter n >> m (the adaptive divider's alignment: R's high bits, 24 of 41)|s/assign shifted = .*/assign shifted = num >> 4;/"
"numerator select (abs(B) or the column value) before the shifter|s/assign num     = .*/assign num = u_q[HB-1:0];/"
"bits above R at the set-up (sticky OR)|s/assign stk_set = .*/assign stk_set = 1'b0;/"
"R - D (25 bits: the saturation test's sign, and dir - e's high bits ~(r - D))|s/assign r_minus_d = .*/assign r_minus_d = {1'b0, rh_q};/"
"trial subtraction {R, bit} - D (25 bits)|s/assign trial   = .*/assign trial = {1'b0, x_hi};/"
"entry X' = Xmax - 1 - q for dir - (adder with a register operand, complement of q)|s/assign entry_x_o  = .*/assign entry_x_o = XB'(qe_q);/"
"entry e's select (r, or ~(r - D) for dir -)|s/    assign entry_e_o = {dir_q.*/    assign entry_e_o = {rh_q, elo_q}; wire [F-1:0] unused_e = {/"
"traversal adder u + s|s/assign u_d        = .*/assign u_d = u_q;/"
"column value load select (E_L, E_R, complement; it folds into the adder's LUTs)|s/assign u_load   = .*/assign u_load = el_i;/"
"row test j <= Ymax|s/assign in_box     = .*/assign in_box = 1'b1;/"
"abs(A) and abs(B) (two 25-bit negations at the load)|s/assign abs_a    = .*/assign abs_a = a_i;/; s/assign abs_b    = .*/assign abs_b = b_i;/"
)
read -r base_l base_f <<< "$(luts "$SRC")"
echo "| part of trirast_improved2_edge_lane (replaced by a stub) | xc7 LUT without it | LUT it costs |"
echo "|---|---:|---:|"
echo "| (whole lane, nothing replaced: $base_l LUT, $base_f FF) | $base_l | - |"
for row in "${PARTS[@]}"; do
  what="${row%%|*}"; expr="${row#*|}"
  sed "$expr" "$SRC" > "$TMP/v.sv"
  cmp -s "$TMP/v.sv" "$SRC" && { echo "lane_parts.sh: the stub for '$what' no longer applies to $SRC" >&2; exit 1; }
  read -r l _ <<< "$(luts "$TMP/v.sv")"
  echo "| $what | $l | $((base_l - l)) |"
done
