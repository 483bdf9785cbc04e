#!/usr/bin/env bash
# Where the Verilated RTL's time goes (the RTL engine's simulation speed), in exact instruction
# counts: the improved unit's default build (Vtrirast_improved_top_n1: N = 1, FIFO 8, the build the
# improved-rtl engine runs at the default configuration) simulating one scene in
# trirast_sc_bench, counted by valgrind's callgrind inside the RTL run only (the engine call
# runVtrirast_improved_top_n1: the Verilated model, the harness's cycle loop and its width check),
# once as built and once per variant of the same build:
#   as built      the build's own Verilator arguments (build/, verilator_args.txt) and -O2
#   -O3           the model's fast code compiled with -O3
#   x fast        --x-initial fast --x-assign fast instead of unique
#   no --assert   the assertions of rtl/ left out
# Instruction counts do not depend on the machine's load; the time of the same runs does (it is
# in docs/sc-model.md, scripts/bench_sim.sh).
#   scripts/rtl_profile.sh [--scene NAME] [WORKDIR]
# NAME: a built-in benchmark scene of trirast_sc_bench (default mixed). WORKDIR (default
# build/rtl-profile): the variants' Verilated sources, objects and benches, and callgrind's files.
# Needs build/ configured and built (trirast_sc_bench) and valgrind (apt-get install valgrind).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${TRIRAST_BUILD_DIR:-$ROOT/build}"
SCENE=mixed
WORK=""
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) SCENE="${2:?--scene needs a name}"; shift ;;
    -h|--help) sed -n "2,19p" "$0"; exit 0 ;;
    -*) echo "rtl_profile.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) WORK="$1" ;;
  esac
  shift
done
WORK="${WORK:-$BUILD/rtl-profile}"
command -v valgrind >/dev/null || { echo "rtl_profile.sh: valgrind is missing: apt-get install valgrind" >&2; exit 2; }
MDIR="$BUILD/tb/CMakeFiles/trirast_rtl_models.dir/Vtrirast_improved_top_n1.dir"
ARGS="$MDIR/verilator_args.txt"
LINK="$BUILD/tools/CMakeFiles/trirast_sc_bench.dir/link.txt"
HARNESS="$BUILD/tb/rtl_builds/buildVtrirast_improved_top_n1.cpp"
for f in "$ARGS" "$LINK" "$HARNESS"; do
  [ -f "$f" ] || { echo "rtl_profile.sh: $f: missing (configure and build $BUILD first: cmake --build $BUILD --target trirast_sc_bench)" >&2; exit 2; }
done
cmake --build "$BUILD" -j2 --target trirast_sc_bench >/dev/null
mkdir -p "$WORK"
WORK="$(cd "$WORK" && pwd)"
trap 'echo "rtl_profile.sh: interrupted" >&2; exit 130' INT TERM

# The build's Verilator argument list (one per ';'), without the output directory and the make
# flavour (set below), and with a variant's changes.
IFS=';' read -r -a BASE_ARGS < "$ARGS" || true  # one line, no newline at its end
verilator_args() {  # verilator_args VARIANT OBJDIR
  local skip=0 a out=()
  for a in "${BASE_ARGS[@]:1}"; do
    if [ "$skip" = 1 ]; then skip=0; continue; fi
    case "$a" in
      --Mdir|--make) skip=1; continue ;;
      --assert) [ "$1" = noassert ] && continue ;;
      unique) [ "$1" = xfast ] && a=fast ;;
    esac
    out+=("$a")
  done
  printf '%s\n' --Mdir "$2" "${out[@]}"
}

# Verilate, compile and link one variant's trirast_sc_bench.
build_variant() {  # build_variant NAME CXXFLAGS
  local d="$WORK/$1" f o objs=() fl
  rm -rf "$d"
  mkdir -p "$d"
  mapfile -t va < <(verilator_args "$1" "$d/obj")
  verilator "${va[@]}" >/dev/null
  local inc=(-I"$ROOT/tb" -I"$d/obj" -I/usr/share/verilator/include/vltstd -I"$ROOT/model"
             -isystem /usr/share/verilator/include -DVM_COVERAGE=0 -DVM_SC=0 -DVM_TRACE=1
             -DVM_TRACE_FST=1 -DVM_TRACE_VCD=0 -std=c++17 -w)
  for f in "$d"/obj/Vtrirast_improved_top_n1*.cpp "$HARNESS"; do
    o="$d/$(basename "$f" .cpp).o"
    case "$f" in *Slow*|*Syms*) fl=-O1 ;; *) fl="$2" ;; esac
    c++ "${inc[@]}" $fl -c "$f" -o "$o"
    objs+=("$o")
  done
  # The bench's own link line, with this variant's model and harness first: the library's
  # members for Vtrirast_improved_top_n1 are then never pulled in.
  (cd "$BUILD/tools" && eval "$(sed -e "s# -o ../trirast_sc_bench # -o $d/bench ${objs[*]} #" "$LINK")")
}

# Instructions inside runVtrirast_improved_top_n1, and inside the Verilated model's eval and the width
# check; prints "total eval widths cycles".
count() {  # count NAME
  local d="$WORK/$1" out
  out="$(SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 valgrind --tool=callgrind \
    --callgrind-out-file="$d/callgrind.out" --toggle-collect='trirast::rtl::runVtrirast_improved_top_n1*' \
    "$d/bench" --repeat 1 --rtl-repeat 1 "$SCENE" 2>/dev/null)"
  local cycles total eval widths
  cycles="$(awk -v s="$SCENE" '$1 == s { print $3 }' <<< "$out")"
  local ann
  ann="$(callgrind_annotate --inclusive=yes "$d/callgrind.out" 2>/dev/null)"
  total="$(awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }' <<< "$ann")"
  eval="$(awk '/Vtrirast_improved_top_n1::eval_step\(\)/ { gsub(",", "", $1); print $1; exit }' <<< "$ann")"
  widths="$(awk '/check_widths</ { gsub(",", "", $1); print $1; exit }' <<< "$ann")"
  echo "$total ${eval:-0} ${widths:-0} $cycles"
}

printf '%s\n' "trirast RTL profile: Vtrirast_improved_top_n1 (improved unit, N = 1, FIFO 8), scene $SCENE, callgrind inside runVtrirast_improved_top_n1"
printf '%-12s %14s %12s %10s %10s %10s %10s\n' variant instructions "per cycle" eval "width chk" harness "vs built"
base=""
for v in "built:-O2" "o3:-O3" "xfast:-O2" "noassert:-O2"; do
  name="${v%%:*}"
  echo "rtl_profile.sh: building and counting $name" >&2
  build_variant "$name" "${v#*:}"
  read -r total eval widths cycles <<< "$(count "$name")"
  [ -n "$cycles" ] && [ "$cycles" -gt 0 ] || { echo "rtl_profile.sh: $name: no cycle count from the bench" >&2; exit 1; }
  base="${base:-$total}"
  awk -v n="$name" -v t="$total" -v e="$eval" -v w="$widths" -v c="$cycles" -v b="$base" 'BEGIN {
    printf "%-12s %14d %12.0f %10.0f %10.0f %10.0f %+9.1f%%\n", n, t, t / c, e / c, w / c,
           (t - e - w) / c, 100 * (t - b) / b }'
done
