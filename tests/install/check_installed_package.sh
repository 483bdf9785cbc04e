#!/usr/bin/env bash
# ctest install_find_package: the install is usable from outside the tree (docs/embedding.md).
# Installs BUILD into a fresh temporary prefix, checks what the package names (no path into the
# source or build tree, every RTL source and file list there, every file list's paths resolving),
# then builds examples/stream_golden, copied out of the tree, against that prefix with
# -DCMAKE_PREFIX_PATH alone, and runs it: it must find the golden's spans equal to the improved2
# datapath's on its stream and on tests/data/two_tris.tri. The same program built with the flags
# of pkg-config's trirast.pc must agree too. Any step failing fails the test, naming the step.
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
echo "install_find_package: passed"
