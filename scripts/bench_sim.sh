#!/bin/bash
# Speed of the SystemC models against the Verilated RTL (docs/sc-model.md), process CPU time.
#
#   scripts/bench_sim.sh [--doc] [--repeat R] [--rtl-repeat R] [scene ...]
#     (default) every timed unit -- improved, improved2 in both corner forms (radix-16
#     digit-serial, DSP products), trad, halfspace -- on each scene (default builtin
#     highpoly-far and mixed): the SystemC model's and the RTL's cycles per CPU-second and the
#     ratio model / RTL. Runs alternate model, RTL, model, ...; each time is the best of its
#     runs (model 5, RTL 3). `uptime` is printed before and after (the machine's load).
#   scripts/bench_sim.sh [--doc] --unit improved|improved2 [--repeat R] [--rtl-repeat R] [scene ...]
#     one unit in detail on the five benchmark scenes (lowpoly-far, lowpoly-near, highpoly-far,
#     highpoly-near, mixed): triangles per second and simulated cycles per wall-second of the
#     model (and per CPU-second), the timed trad model beside it, the RTL's wall and CPU time and
#     the RTL/model ratios.
#   --doc  also rewrites the run's section of docs/sc-model.md (the table, the command, the date
#          and the load): "Every unit: model and RTL cycles per CPU-second" (default),
#          "Model against RTL wall time" (--unit improved), "The second generation: model
#          against RTL wall time" (--unit improved2)
#   -h, --help  this text
# The RTL runs the Verilated builds a default run takes: the speed builds (docs/rtl.md, "Speed and
# checked builds"; improved2 has one in each corner form).
# Build directory: $TRIRAST_BUILD_DIR, default build/ (configured and built here if needed: the
# target trirast_sc_bench; its RTL engines need the Verilated models of that build).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
doc=0
args=()
head="## Every unit: model and RTL cycles per CPU-second"
units=1
prev=""
for a in "$@"; do
  case "$a" in
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    --doc) doc=1 ;;
    *) args+=("$a") ;;
  esac
  if [ "$a" = --unit ]; then units=0; head="## Model against RTL wall time"; fi
  [ "$prev" = --unit ] && [ "$a" = improved2 ] && head="## The second generation: model against RTL wall time"
  prev="$a"
done
[ "$units" = 1 ] && args=(--units ${args[@]+"${args[@]}"})
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j2 --target trirast_sc_bench >/dev/null
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
if [ "$doc" = 0 ]; then
  echo "uptime before: $(uptime)"
  status=0
  "$build/trirast_sc_bench" ${args[@]+"${args[@]}"} || status=$?
  echo "uptime after: $(uptime)"
  exit "$status"
fi

md="$(mktemp)"
trap 'rm -f "$md"' EXIT
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
"$build/trirast_sc_bench" ${args[@]+"${args[@]}"} --md "$md"
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
shown=("${args[@]}")
[ "$units" = 1 ] && shown=("${args[@]:1}")
cmd="scripts/bench_sim.sh --doc${shown[*]:+ ${shown[*]}}"
section="$(mktemp)"
trap 'rm -f "$md" "$section"' EXIT
if [ "$units" = 1 ]; then
{
  echo "$head"
  echo
  echo "\`$cmd\` ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores; load"
  echo "averages (1, 5, 15 min) $load_before before and $load_after after; Release build, 1024x768,"
  echo "S=8, N=1, FIFO 8, sink always ready). For every timed unit, its SystemC model (\`UNIT-sc\`)"
  echo "and its Verilated RTL (\`UNIT-rtl\`, the build a default run takes: its speed build,"
  echo "improved2's in each corner form; docs/rtl.md) on the same set-up scene in the same process,"
  echo "alternating; each time is the best of its runs in process CPU time (model 5, RTL 3 unless"
  echo "--repeat / --rtl-repeat say otherwise), so the ratio model / RTL holds under load better"
  echo "than either speed. The RTL's cycles equal the model's (the bench checks it)."
  echo
  cat "$md"
  echo
} > "$section"
else
{
  echo "$head"
  echo
  echo "\`$cmd\` ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load"
  echo "average $(cut -d' ' -f1 /proc/loadavg) at the end; Release build, 1024x768, S=8, N=1, FIFO 8, sink always"
  echo "ready). The model, the timed trad model and the Verilated RTL run the same set-up scene in"
  echo "the same process, alternating; each time is the best of its runs (model and trad 5, RTL 3"
  echo "unless --repeat / --rtl-repeat say otherwise). The ratio columns are RTL time / model time:"
  echo "wall clock (the target: >= 20) and process CPU time (steadier when the machine is loaded)."
  echo "The RTL's cycles equal the model's (the bench checks it)."
  if [ "$head" != "## Model against RTL wall time" ]; then
    echo "Here the model is \`improved2-sc\` and the RTL \`improved2-rtl\` (the second-generation unit,"
    echo "its radix-16 form); the trad columns are the traditional unit's model as above."
  fi
  echo
  cat "$md"
  echo
} > "$section"
fi
/usr/bin/python3 - "$root/docs/sc-model.md" "$section" "$head" <<'EOF'
import sys
path, sec, head = sys.argv[1], open(sys.argv[2]).read(), sys.argv[3]
text = open(path).read()
if head in text:
    a = text.index(head)
    b = text.find("\n## ", a + len(head))
    text = text[:a] + sec + (text[b + 1:] if b >= 0 else "")
else:
    a = text.find("\n## Improved vs traditional")
    text = (text[:a + 1] + sec + text[a + 1:]) if a >= 0 else (text.rstrip("\n") + "\n\n" + sec)
open(path, "w").write(text)
EOF
echo "bench_sim.sh: wrote the section \"${head#\#\# }\" of docs/sc-model.md" >&2
