#!/usr/bin/env bash
# Builds tests/rtl/port_check_tb.sv (rtl/common/trirast_triangle_port_check.sv alone, with its
# assertions) with Verilator at the widths of PKG_SV (ctest rtl_port_check_build_*, the fixture of
# rtl_port_check_*): WORKDIR/obj_dir/port_check_tb.
#   tests/rtl/port_check_build.sh PKG_SV WORKDIR
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -eq 2 ] || { echo "usage: port_check_build.sh PKG_SV WORKDIR" >&2; exit 2; }
PKG="$1" WORK="$2"
[ -f "$PKG" ] || { echo "port_check_build.sh: PKG_SV '$PKG' does not exist" >&2; exit 2; }
command -v verilator >/dev/null || { echo "port_check_build.sh: verilator not found" >&2; exit 1; }
mkdir -p "$WORK"
rm -rf "$WORK/obj_dir"
verilator --binary --timing -j 2 -Wall -Wno-fatal --assert -I"$ROOT/rtl/common" \
  --top-module port_check_tb --Mdir "$WORK/obj_dir" -o port_check_tb -CFLAGS -O1 \
  "$PKG" "$ROOT/rtl/common/trirast_port_pkg.sv" "$ROOT/rtl/common/trirast_triangle_port_check.sv" \
  "$ROOT/tests/rtl/port_check_tb.sv" > "$WORK/verilator.log" 2>&1 ||
  { cat "$WORK/verilator.log" >&2; echo "port_check_build.sh: Verilator build failed" >&2; exit 1; }
echo "port_check_build.sh: built $WORK/obj_dir/port_check_tb"
