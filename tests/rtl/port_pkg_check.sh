#!/usr/bin/env bash
# Checks rtl/common/trirast_port_pkg.sv against the CLI's setup under one simulator (ctest
# rtl_port_pkg_*): trirast_port_pkg_vectors writes COUNT seeded triangles and setup's results,
# tests/rtl/port_pkg_tb.sv forms each with the package and compares every field.
#   tests/rtl/port_pkg_check.sh icarus|verilator VECTORS_EXE WORKDIR PKG_SV S COORD_BITS COUNT SEED
# PKG_SV is the trirast_pkg.sv of the widths (rtl/common/trirast_pkg.sv, or a generated one, with
# S and COORD_BITS its subpixel and coordinate bits). Exit status 0 only if the simulator ran and
# the testbench printed PASS; a missing simulator is a failure.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -eq 8 ] || { echo "usage: port_pkg_check.sh icarus|verilator VECTORS_EXE WORKDIR PKG_SV S COORD_BITS COUNT SEED" >&2; exit 2; }
SIM="$1" VECTORS="$2" WORK="$3" PKG="$4" S="$5" COORD="$6" COUNT="$7" SEED="$8"
[ -f "$PKG" ] || { echo "port_pkg_check.sh: PKG_SV '$PKG' does not exist" >&2; exit 2; }
mkdir -p "$WORK"
"$VECTORS" "$WORK/vectors.txt" "$S" "$COORD" "$COUNT" "$SEED"
SOURCES=("$PKG" "$ROOT/rtl/common/trirast_port_pkg.sv" "$ROOT/tests/rtl/port_pkg_tb.sv")
case "$SIM" in
  icarus)
    command -v iverilog >/dev/null || { echo "port_pkg_check.sh: iverilog not found" >&2; exit 1; }
    iverilog -g2012 -I "$ROOT/rtl/common" -s port_pkg_tb -o "$WORK/port_pkg_tb.vvp" "${SOURCES[@]}"
    out=$(vvp -n "$WORK/port_pkg_tb.vvp" +vectors="$WORK/vectors.txt" 2>&1) || true
    ;;
  verilator)
    command -v verilator >/dev/null || { echo "port_pkg_check.sh: verilator not found" >&2; exit 1; }
    rm -rf "$WORK/obj_dir"
    verilator --binary -j 2 -Wall -Wno-fatal --assert -I"$ROOT/rtl/common" --top-module port_pkg_tb \
      --Mdir "$WORK/obj_dir" -o port_pkg_tb -CFLAGS -O1 "${SOURCES[@]}" > "$WORK/verilator.log" 2>&1 \
      || { cat "$WORK/verilator.log" >&2; exit 1; }
    out=$("$WORK/obj_dir/port_pkg_tb" +vectors="$WORK/vectors.txt" 2>&1) || true
    ;;
  *) echo "port_pkg_check.sh: simulator '$SIM' is not icarus or verilator" >&2; exit 2 ;;
esac
printf '%s\n' "$out"
grep -q "^port_pkg_tb: PASS" <<< "$out"
