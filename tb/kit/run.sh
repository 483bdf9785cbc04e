#!/usr/bin/env bash
# Runs the testbench kit (tb/kit; docs/port.md, "Testbench kit") on a vectors directory written by
# `trirast raster --vectors DIR`.
usage() {
  cat <<'EOF'
usage: tb/kit/run.sh --sim verilator|icarus [options] VECTORS_DIR WORKDIR [+PLUSARG ...]

Builds the kit's bench (tb/kit/trirast_kit.f) around the unit's top (rtl/UNIT/trirast_UNIT.f) at
the parameters of VECTORS_DIR/params.txt, with Verilator (--binary --timing --assert) or Icarus
(iverilog -g2012, vvp), in WORKDIR (a build is reused while its parameters, memory sizes and
sources are unchanged), and runs it with VECTORS_DIR/plusargs.txt. The scoreboard holds every
span and every triangle's accept, first-span and done cycles against the vectors. Exit status 0
only when the bench prints PASS; 1 when it fails (the simulator's own exit status is non-zero
on FAIL in both: vvp 1, a Verilated model 134, from $fatal); 2 on bad input.

options:
  --sim verilator|icarus  the simulator (required)
  --unit UNIT             check that the vectors are of UNIT (improved, improved2, trad,
                          halfspace); the unit is read from VECTORS_DIR/params.txt
  --rtl DIR               the RTL folder holding common/ and UNIT/ (default: the repository's rtl/),
                          e.g. a copy with a change of one's own
  --jobs N                Verilator's C++ build jobs (default 2)
  --cxx-opt FLAG          Verilator's C++ optimization (default -O0: the fastest build; -O2 for
                          long runs); the C++ goes through ccache when it is installed
  -h, --help              this text
+PLUSARG ...              passed to the simulation before the vectors' own (the first given
                          wins): +gap=N (idle cycles between triangles; turns the cycle checks
                          off), +kit_cycles=0, +kit_slack=N, +spans_out=FILE, +sink=... (a
                          downstream other than the vectors' fails the cycle checks)
EOF
}
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
die() { echo "tb/kit/run.sh: $*" >&2; exit 2; }

SIM="" UNIT_ARG="" RTL="$ROOT/rtl" JOBS=2 CXXOPT=-O0
POS=() PLUS=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --sim) [ $# -ge 2 ] || die "--sim: needs verilator or icarus"; SIM="$2"; shift 2 ;;
    --unit) [ $# -ge 2 ] || die "--unit: needs a unit"; UNIT_ARG="$2"; shift 2 ;;
    --rtl) [ $# -ge 2 ] || die "--rtl: needs a folder"; RTL="$(cd "$2" 2>/dev/null && pwd)" || die "--rtl $2: no such folder"; shift 2 ;;
    --jobs) [ $# -ge 2 ] || die "--jobs: needs a number"; JOBS="$2"; shift 2
            [[ "$JOBS" =~ ^[1-9][0-9]*$ ]] || die "--jobs $JOBS: not a positive number" ;;
    --cxx-opt) [ $# -ge 2 ] || die "--cxx-opt: needs a flag, e.g. -O2"; CXXOPT="$2"; shift 2
               [[ "$CXXOPT" =~ ^-O[0-3sg]$ ]] || die "--cxx-opt $CXXOPT: expected -O0, -O1, -O2, -O3, -Os or -Og" ;;
    +*) PLUS+=("$1"); shift ;;
    -*) die "$1: unknown option (see --help)" ;;
    *) POS+=("$1"); shift ;;
  esac
done
case "$SIM" in
  verilator|icarus) ;;
  "") die "--sim verilator|icarus is required" ;;
  *) die "--sim $SIM: expected verilator or icarus" ;;
esac
[ ${#POS[@]} -eq 2 ] || die "expected VECTORS_DIR WORKDIR (see --help)"
VEC="$(cd "${POS[0]}" 2>/dev/null && pwd)" || die "${POS[0]}: no such vectors directory"
WORK="${POS[1]}"
for f in params.txt plusargs.txt tris.hex spans.hex expect.hex; do
  [ -f "$VEC/$f" ] || die "$VEC/$f: missing (write the directory with trirast raster --vectors)"
done

# ---- params.txt: "unit UNIT", then the top's parameters "NAME VALUE" ----
UNIT="" PARAMS=()
lineno=0
while read -r name value rest; do
  lineno=$((lineno + 1))
  [ -n "$name" ] || continue
  [ -z "$rest" ] && [ -n "$value" ] || die "$VEC/params.txt:$lineno: expected NAME VALUE"
  if [ "$name" = unit ]; then UNIT="$value"; continue; fi
  case "$name" in
    NumEndpoints|FifoDepth|CornerForm|StampSize|TileSize|WalkMode) ;;
    *) die "$VEC/params.txt:$lineno: $name is not a parameter of the kit's bench" ;;
  esac
  [[ "$value" =~ ^[0-9]+$ ]] || die "$VEC/params.txt:$lineno: $name $value is not a number"
  PARAMS+=("$name=$value")
done < "$VEC/params.txt"
case "$UNIT" in
  improved|improved2|trad|halfspace) ;;
  "") die "$VEC/params.txt: no 'unit UNIT' line" ;;
  *) die "$VEC/params.txt: unit '$UNIT' is not improved, improved2, trad or halfspace" ;;
esac
[ -z "$UNIT_ARG" ] || [ "$UNIT_ARG" = "$UNIT" ] ||
  die "--unit $UNIT_ARG: the vectors in $VEC are of unit $UNIT"
DEFINE="TRIRAST_KIT_$(echo "$UNIT" | tr a-z A-Z)"

# The memories hold the vectors' counts (rounded up to a power of two, so that one build serves
# vectors of similar sizes).
plusargs="$(cat "$VEC/plusargs.txt")"
count() { sed -n "s/.*+$1=\([0-9]*\).*/\1/p" <<< "$plusargs"; }
ntris="$(count ntris)" nspans="$(count nspans)"
[ -n "$ntris" ] && [ -n "$nspans" ] || die "$VEC/plusargs.txt: +ntris or +nspans missing"
pow2() { local p=1024; while [ "$p" -lt "$1" ]; do p=$((p * 2)); done; echo "$p"; }
PARAMS+=("MaxTris=$(pow2 "$ntris")" "MaxSpans=$(pow2 "$nspans")")

# ---- sources: the unit's file list and the kit's, paths relative to each list's folder ----
list_files() {  # LIST: its files, absolute, in order
  local list="$1" dir f path
  [ -f "$list" ] || die "$list: no such file list"
  dir="$(dirname "$list")"
  sed 's#//.*##' "$list" | while read -r f; do
    [ -n "$f" ] || continue
    path="$(realpath -m "$dir/$f")"
    [ -f "$path" ] || { echo "tb/kit/run.sh: $list: $f does not exist" >&2; exit 2; }
    echo "$path"
  done
}
UNIT_LIST="$RTL/$UNIT/trirast_$UNIT.f"
KIT_LIST="$ROOT/tb/kit/trirast_kit.f"
SOURCES=()
while read -r f; do SOURCES+=("$f"); done < <(list_files "$UNIT_LIST"; list_files "$KIT_LIST")
[ ${#SOURCES[@]} -gt 0 ] || die "no sources"
INCLUDES=("$RTL/common")

# ---- build (reused while the key and the sources are unchanged) ----
mkdir -p "$WORK" || die "$WORK: cannot create"
WORK="$(cd "$WORK" && pwd)"
KEY="$SIM $UNIT $RTL ${PARAMS[*]}"
[ "$SIM" = icarus ] || KEY="$KEY $CXXOPT"
BUILD="$WORK/$SIM-$UNIT"
if [ "$SIM" = verilator ]; then BIN="$BUILD/obj/Vtrirast_kit_bench"; else BIN="$BUILD/bench.vvp"; fi
fresh=1
if [ -f "$BUILD/key" ] && [ "$(cat "$BUILD/key")" = "$KEY" ] && [ -x "$BIN" -o -f "$BIN" ]; then
  for f in "${SOURCES[@]}" "$RTL"/common/*.svh; do
    [ "$f" -nt "$BIN" ] && { fresh=1; break; } || fresh=0
  done
fi
if [ "$fresh" = 1 ]; then
  rm -rf "$BUILD"
  mkdir -p "$BUILD"
  t0=$(date +%s)
  if [ "$SIM" = verilator ]; then
    command -v verilator > /dev/null || die "verilator: not found (the kit needs Verilator 5 for --sim verilator)"
    gflags=()
    for p in "${PARAMS[@]}"; do gflags+=("-G$p"); done
    # ccache, when installed, compiles Verilator's runtime and unchanged model code once.
    objcache=""
    if command -v ccache > /dev/null; then objcache="OBJCACHE=ccache"; fi
    verilator --binary --timing --assert -Wno-fatal -Wno-lint -Wno-style -Wno-TIMESCALEMOD \
      --top-module trirast_kit_bench "-D$DEFINE" "${INCLUDES[@]/#/-I}" "${gflags[@]}" \
      --Mdir "$BUILD/obj" -j "$JOBS" -MAKEFLAGS "OPT_FAST=$CXXOPT OPT_SLOW=$CXXOPT OPT_GLOBAL=$CXXOPT $objcache" "${SOURCES[@]}" > "$BUILD/build.log" 2>&1 ||
      { tail -20 "$BUILD/build.log" >&2; die "verilator build failed (log: $BUILD/build.log)"; }
  else
    command -v iverilog > /dev/null || die "iverilog: not found (the kit needs Icarus 11 for --sim icarus)"
    pflags=()
    for p in "${PARAMS[@]}"; do pflags+=("-Ptrirast_kit_bench.$p"); done
    # Icarus prints "sorry: constant selects in always_* processes" (a sensitivity-list
    # simplification, harmless) and "sorry: Case unique/unique0 qualities are ignored" (Verilator
    # checks them); the rest is shown.
    iverilog -g2012 -s trirast_kit_bench "-D$DEFINE" "${INCLUDES[@]/#/-I}" "${pflags[@]}" \
      -o "$BIN" "${SOURCES[@]}" > "$BUILD/build.log" 2>&1 ||
      { grep -v "constant selects\|qualities are ignored" "$BUILD/build.log" >&2; die "iverilog build failed"; }
  fi
  echo "$KEY" > "$BUILD/key"
  echo "kit: built $SIM bench of $UNIT (${PARAMS[*]}) in $(( $(date +%s) - t0 )) s"
fi

# ---- run ----
t0=$(date +%s)
set +e
if [ "$SIM" = verilator ]; then
  out="$("$BIN" +kit_dir="${POS[0]}" "${PLUS[@]}" $plusargs 2>&1)"
else
  out="$(vvp -n "$BIN" +kit_dir="${POS[0]}" "${PLUS[@]}" $plusargs 2>&1)"
fi
rc=$?
set -e
echo "$out" | grep -v "^- \|^VCD info\|^\*\*\* \|Verilog \$finish" || true
echo "kit: $SIM ran $UNIT on ${POS[0]} in $(( $(date +%s) - t0 )) s, exit status $rc"
# (a Verilated --binary model aborts on $fatal: exit status 134; vvp exits with 1)
if [ $rc -ne 0 ]; then exit 1; fi
if ! grep -q "^PASS:" <<< "$out"; then
  echo "tb/kit/run.sh: the simulation ended without a PASS line" >&2
  exit 1
fi
