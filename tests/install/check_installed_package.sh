#!/usr/bin/env bash
# ctest install_find_package: the install is usable from outside the tree (docs/embedding.md).
# Installs BUILD into a fresh temporary prefix, checks what the package names (no path into the
# source or build tree, every RTL source and file list there, every file list's paths resolving),
# then builds examples/stream_golden, copied out of the tree, against that prefix with
# -DCMAKE_PREFIX_PATH alone, and runs it: it must find the golden's spans equal to the improved2
# datapath's on its stream and on tests/data/two_tris.tri. The same program built with the flags
# of pkg-config's trirast.pc must agree too. Then examples/sc_platform, a SystemC platform of its
# own with the improved2 and half-space units as components, built the same way and run on a
# mesh: each unit's spans equal the golden's; with fragment stages always ready its per-triangle
# cycles equal `trirast raster --cycles` of the unit's SystemC engine; two instances of each unit
# give the same records as one, with a stalling downstream. Any step failing fails the test,
# naming the step.
#   tests/install/check_installed_package.sh BUILD SOURCE [CMAKE]
set -euo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
cmake=${3:-cmake}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/trirast-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "install_find_package: $*" >&2; exit 1; }
# Runs a step with its output in $tmp/LOG; on failure prints the log's end and fails.
step() {
  local log=$tmp/$1.log
  shift
  "$@" >"$log" 2>&1 || { tail -n 30 "$log" >&2; fail "failed: $*"; }
}

step install "$cmake" --install "$build" --prefix "$prefix"
echo "install_find_package: installed $(find "$prefix" -type f | wc -l) files into a fresh prefix"

# The package must not point back into the trees it was built from.
config=$(find "$prefix" -name trirastConfig.cmake)
[ -n "$config" ] || fail "no trirastConfig.cmake installed"
pcfile=$(find "$prefix" -name trirast.pc)
[ -n "$pcfile" ] || fail "no trirast.pc installed"
if grep -rl -e "$src" -e "$build" "$(dirname "$config")" "$pcfile"; then
  fail "the installed package names the source or build tree (files above)"
fi

# The RTL: the same *.sv, *.svh and *.f as rtl/, and every path a file list names resolves from
# the list's folder (Verilator's -F rule).
rtl=$prefix/share/trirast/rtl
diff <(cd "$src/rtl" && find . -name '*.sv' -o -name '*.svh' -o -name '*.f' | sort) \
     <(cd "$rtl" && find . -type f | sort) || fail "installed RTL differs from rtl/ (above)"
lists=0
for f in "$rtl"/*/*.f; do
  lists=$((lists + 1))
  while read -r path; do
    [ -f "$(dirname "$f")/$path" ] || fail "${f#"$rtl"/} names $path, not installed"
  done < <(sed -e 's#//.*##' -e 's/[[:space:]]//g' "$f" | grep -v '^$' | grep -v '^[-+]')
done
[ $lists -ge 4 ] || fail "$lists file lists installed, expected one per unit"

# The example, as a project of its own outside the tree.
cp -r "$src/examples/stream_golden" "$tmp/example"
step configure "$cmake" -S "$tmp/example" -B "$tmp/example-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix"
step build "$cmake" --build "$tmp/example-build" -j2
program=$tmp/example-build/stream_golden
expect() {  # expect NAME PATTERN COMMAND...: exit status 0 and a line matching PATTERN
  local name=$1 pattern=$2
  shift 2
  local rc=0
  "$@" >"$tmp/$name.out" 2>&1 || rc=$?
  [ $rc -eq 0 ] || { cat "$tmp/$name.out" >&2; fail "$name: exit status $rc"; }
  grep -q "$pattern" "$tmp/$name.out" || { cat "$tmp/$name.out" >&2; fail "$name: no '$pattern'"; }
  tail -n 1 "$tmp/$name.out"
}
expect stream 'improved2-datapath equals the golden on 7 of them' "$program"
expect two_tris 'improved2-datapath equals the golden on 2 of them' \
  "$program" "$src/tests/data/two_tris.tri"

# pkg-config: the same program from trirast.pc's flags alone.
export PKG_CONFIG_PATH=$(dirname "$pcfile")
flags=$(pkg-config --cflags --libs trirast) || fail "pkg-config does not read trirast.pc"
step pkgconfig_build ${CXX:-c++} -std=c++17 -O1 -o "$tmp/stream_golden_pc" \
  "$tmp/example/stream_golden.cpp" $flags
expect pkgconfig 'improved2-datapath equals the golden on 7 of them' "$tmp/stream_golden_pc"
# The SystemC platform, as a project of its own outside the tree.
cp -r "$src/examples/sc_platform" "$tmp/platform"
step platform_configure "$cmake" -S "$tmp/platform" -B "$tmp/platform-build" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix"
step platform_build "$cmake" --build "$tmp/platform-build" -j2
platform=$tmp/platform-build/sc_platform
spans_sorted() { sort -n -k1,1 -k2,2 -k3,3 "$1"; }
for scene in "$src/tests/data/cube.obj" builtin:lowpoly-near; do
  out=$tmp/vp-ready
  rm -rf "$out" && mkdir -p "$out"
  step platform_ready "$platform" "$scene" --always-ready --cycles-out "$out" --spans-out "$out"
  for unit in improved2 halfspace; do
    cmp -s <(spans_sorted "$out/golden.spans") <(spans_sorted "$out/${unit}_0.spans") ||
      fail "sc_platform on $scene: the $unit unit's spans differ from the golden's"
    step "cli_$unit" "$build/trirast" raster --engine "$unit-sc" --scene "$scene" \
      --cycles "$out/$unit.cli.csv"
    cmp -s "$out/$unit.cli.csv" "$out/${unit}_0.csv" ||
      fail "sc_platform on $scene: the $unit unit's cycles differ from trirast raster --cycles"
  done
  one=$tmp/vp-one two=$tmp/vp-two
  rm -rf "$one" "$two" && mkdir -p "$one" "$two"
  step platform_one "$platform" "$scene" --rate 2 --capacity 16 --cycles-out "$one" --spans-out "$one"
  step platform_two "$platform" "$scene" --rate 2 --capacity 16 --instances 2 \
    --cycles-out "$two" --spans-out "$two"
  for unit in improved2 halfspace; do
    for f in "$two/${unit}_0" "$two/${unit}_1"; do
      cmp -s "$one/${unit}_0.csv" "$f.csv" && cmp -s "$one/${unit}_0.spans" "$f.spans" ||
        fail "sc_platform on $scene: ${f##*/} of two instances differs from the one instance's"
    done
    cmp -s <(spans_sorted "$one/golden.spans") <(spans_sorted "$one/${unit}_0.spans") ||
      fail "sc_platform on $scene: the $unit unit's spans behind a stalling stage differ"
    # The stage stalled the unit: its records differ from the always-ready run's.
    ! cmp -s "$one/${unit}_0.csv" "$out/${unit}_0.csv" ||
      fail "sc_platform on $scene: a stage of 2 pixels per cycle never stalled the $unit unit"
  done
  tail -n 2 "$tmp/platform_two.log"
done
echo "install_find_package: passed"
