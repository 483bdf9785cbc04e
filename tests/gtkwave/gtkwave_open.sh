#!/usr/bin/env bash
# Opens the SystemC models' (improved-sc, improved2-sc) and the RTLs' (improved-rtl, improved2-rtl)
# traces through their .gtkw save files in GTKWave,
# headless under Xvfb, FROM ANOTHER WORKING DIRECTORY than the one trirast wrote them in, and
# checks that each loads: exit status 0, nothing on stderr about the dump or the translate
# filters, and every signal the save file lists is displayed (a name GTKWave does not find is
# dropped silently otherwise). It also checks that the check can fail: a save file whose dump
# path is broken must fail to load, and one whose filter path is broken must complain.
#
#   tests/gtkwave/gtkwave_open.sh TRIRAST                 # the test (ctest gtkwave_open_traces)
#   tests/gtkwave/gtkwave_open.sh TRIRAST --screenshot DIR   # also DIR/gtkwave-{model,model2,rtl,rtl2}.png
set -euo pipefail
bin="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
shots=""
if [ "${2:-}" = "--screenshot" ]; then shots="$(mkdir -p "$3" && cd "$3" && pwd)"; fi
for tool in xvfb-run gtkwave; do
  command -v "$tool" >/dev/null || { echo "gtkwave_open: no $tool (scripts/deps.sh)" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/run/traces" "$work/elsewhere"

# The traces, written from $work/run with paths relative to it.
(cd "$work/run" &&
 "$bin" raster --scene builtin:mixed --engine improved-sc --trace traces/model.vcd \
   --trace-tris 100:104 >/dev/null &&
 "$bin" raster --scene builtin:mixed --engine improved2-sc --trace traces/model2.vcd \
   --trace-tris 100:104 >/dev/null &&
 "$bin" raster --scene builtin:mixed --engine improved-rtl --trace traces/rtl.fst \
   --trace-tris 100:104 >/dev/null &&
 "$bin" raster --scene builtin:mixed --engine improved2-rtl --trace traces/rtl2.fst \
   --trace-tris 100:104 >/dev/null)

cat >"$work/count.tcl" <<'EOF'
puts "trirast-displayed [llength [gtkwave::getDisplayedSignals]]"
gtkwave::/File/Quit
EOF

fail=0
# open GTKW: runs GTKWave on it from $work/elsewhere; sets rc, out, err.
open_gtkw() {
  rc=0
  (cd "$work/elsewhere" && timeout 120 xvfb-run -a gtkwave -S ../count.tcl "$1" \
     >"$work/out" 2>"$work/err") || rc=$?
  out="$(cat "$work/out")"
  err="$(cat "$work/err")"
}

for name in model model2 rtl rtl2; do
  gtkw="../run/traces/$name.gtkw"
  open_gtkw "$gtkw"
  listed=$(grep -c -v -e '^[-@^[*]' "$work/run/traces/$name.gtkw" || true)
  shown=$(sed -n 's/^trirast-displayed \([0-9]*\)$/\1/p' <<<"$out")
  if [ "$rc" -ne 0 ]; then
    echo "FAIL $name: gtkwave exited $rc: $err" >&2; fail=1
  elif grep -i -E 'error|warn|could not|cannot|not found|exiting' <<<"$err" >&2; then
    echo "FAIL $name: gtkwave complained on stderr (above)" >&2; fail=1
  elif [ -z "$shown" ] || [ "$shown" -ne "$listed" ]; then
    echo "FAIL $name: $listed signals listed in the .gtkw, ${shown:-none} displayed" >&2; fail=1
  else
    echo "ok   $name: loaded from another directory, $shown of $listed signals displayed," \
         "$(ls "$work/run/traces" | grep -c "^$name\..*\.filter$") filter files"
  fi
done

# The check can fail: a broken dump path, and a broken filter path.
sed 's/^\[dumpfile\] ".*"/[dumpfile] "no-such-dump.vcd"/' "$work/run/traces/model.gtkw" \
  >"$work/run/traces/broken-dump.gtkw"
sed -i 's/^\[savefile\] ".*"/[savefile] "broken-dump.gtkw"/' "$work/run/traces/broken-dump.gtkw"
open_gtkw ../run/traces/broken-dump.gtkw
if [ "$rc" -eq 0 ] && ! grep -q -i 'could not' <<<"$err"; then
  echo "FAIL: a broken dump path loaded without an error (the check could never fail)" >&2; fail=1
else
  echo "ok   a broken dump path fails (exit $rc): $(grep -i 'could not' <<<"$err" | head -n 1)"
fi
sed 's/^\(\^[0-9]* \).*/\1no-such.filter/' "$work/run/traces/model.gtkw" >"$work/run/traces/broken-filter.gtkw"
sed -i 's/^\[savefile\] ".*"/[savefile] "broken-filter.gtkw"/' "$work/run/traces/broken-filter.gtkw"
open_gtkw ../run/traces/broken-filter.gtkw
if ! grep -q -i 'could not open filter' <<<"$err"; then
  echo "FAIL: a broken filter path gave no error on stderr (the check could never fail)" >&2; fail=1
else
  echo "ok   a broken filter path complains: $(grep -i 'filter' <<<"$err" | head -n 1)"
fi

if [ -n "$shots" ]; then
  cat >"$work/shot.sh" <<'EOF'
#!/usr/bin/env bash
gtkwave "$1" >/dev/null 2>&1 &
pid=$!
sleep 5
import -window root "$2"
kill "$pid"
EOF
  chmod +x "$work/shot.sh"
  for name in model model2 rtl rtl2; do
    (cd "$work/elsewhere" && timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" \
       "$work/shot.sh" "../run/traces/$name.gtkw" "$shots/gtkwave-$name.png")
    echo "wrote $shots/gtkwave-$name.png"
  done
fi
exit "$fail"
