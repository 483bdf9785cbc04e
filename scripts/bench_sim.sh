#!/bin/bash
# Speed of the SystemC models (docs/sc-model.md): for the built-in benchmark scenes
# (lowpoly-far, lowpoly-near, highpoly-far, highpoly-near, mixed), triangles per second and
# simulated cycles per second of the improved unit's model, the traditional unit's model beside
# it, and the Verilated RTL's time on the same scenes in the same run with the RTL/model wall-time
# ratio (target: >= 20) and CPU-time ratio. Runs alternate model, trad, RTL, so that the load of a
# shared machine hits all of them; each time is the best of its runs.
# Usage: scripts/bench_sim.sh [--doc] [--unit improved|improved2] [--repeat R] [--rtl-repeat R] [scene ...]
#   --doc  also rewrites the section "Model against RTL wall time" of docs/sc-model.md
#          (the table of this run, the command and the date); with --unit improved2 the section
#          "The second generation: model against RTL wall time" (improved2-sc, improved2-rtl)
# Build directory: $TRIRAST_BUILD_DIR, default build/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${TRIRAST_BUILD_DIR:-$root/build}"
doc=0
args=()
head="## Model against RTL wall time"
prev=""
for a in "$@"; do
  if [ "$a" = --doc ]; then doc=1; else args+=("$a"); fi
  [ "$prev" = --unit ] && [ "$a" = improved2 ] && head="## The second generation: model against RTL wall time"
  prev="$a"
done
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j2 --target trirast_sc_bench >/dev/null
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
if [ "$doc" = 0 ]; then
  exec "$build/trirast_sc_bench" ${args[@]+"${args[@]}"}
fi

md="$(mktemp)"
trap 'rm -f "$md"' EXIT
"$build/trirast_sc_bench" ${args[@]+"${args[@]}"} --md "$md"
cmd="scripts/bench_sim.sh --doc${args[*]:+ ${args[*]}}"
section="$(mktemp)"
trap 'rm -f "$md" "$section"' EXIT
{
  echo "$head"
  echo
  echo "\`$cmd\` ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores shared with other jobs, load"
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
