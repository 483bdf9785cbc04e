#!/usr/bin/env bash
# Prints a unit's RTL sources, one absolute path a line, in its file list's order:
#   scripts/rtl_filelist.sh UNIT [--no-pkg]
# UNIT is improved, improved2, trad or halfspace; the list is rtl/UNIT/trirast_UNIT.f (one path a
# line, relative to the list's folder, `//` comments). --no-pkg leaves out the package
# (rtl/common/trirast_pkg.sv), for a flow that reads a generated one instead.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
unit="${1:?usage: scripts/rtl_filelist.sh UNIT [--no-pkg]}"
list="$root/rtl/$unit/trirast_$unit.f"
[ -f "$list" ] || { echo "rtl_filelist.sh: $list: no such file list (units: improved, improved2, trad, halfspace)" >&2; exit 2; }
nopkg=0
[ "${2:-}" = --no-pkg ] && nopkg=1
dir="$(dirname "$list")"
sed 's#//.*##' "$list" | while read -r f; do
  [ -n "$f" ] || continue
  path="$(realpath -m "$dir/$f")"
  [ -f "$path" ] || { echo "rtl_filelist.sh: $list: $f does not exist" >&2; exit 2; }
  [ $nopkg = 1 ] && [ "$(basename "$path")" = trirast_pkg.sv ] && continue
  echo "$path"
done
