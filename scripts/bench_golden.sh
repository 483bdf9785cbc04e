#!/usr/bin/env bash
# Measures the golden traversals (tools/bench_golden.cpp) and writes docs/golden-performance.md:
# the shape of Table 1 of Mileff, Nehez & Dudra (speed-up of each traversal over `simple` per scene
# type, the paper's figures beside ours), triangles and pixels per second, thread scaling, and the
# throughput targets.
# All ratios come from one run of one program (the machine is shared and noisy).
# Usage: scripts/bench_golden.sh [extra Google Benchmark flags, e.g. --benchmark_min_time=0.1]
#        scripts/bench_golden.sh --report-only   (re-render the document from the last run's data)
#        scripts/bench_golden.sh --quick         (a few iterations of everything, with the program
#            already built, into $build/golden-performance.quick.md: checks that the program and
#            the rendering work; the suite runs it; its numbers mean nothing)
# TRIRAST_BUILD_DIR selects the build directory (default build/), e.g.
#   TRIRAST_BUILD_DIR=build-golden scripts/bench_golden.sh
# Takes about 3 minutes; the thread benchmarks alone take about 80 s of it.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${TRIRAST_BUILD_DIR:-build}"
json="$build/bench_golden.json"
loads="$build/bench_golden.loads"
doc=docs/golden-performance.md
bin="$build/bench_golden"
case "$bin" in /*) ;; *) bin="./$bin" ;; esac
mode=full
case "${1:-}" in
  --report-only) mode=report; shift ;;
  --quick) mode=quick; shift
    json="$build/bench_golden.quick.json"
    loads="$build/bench_golden.quick.loads"
    doc="$build/golden-performance.quick.md" ;;
esac
if [ "$mode" = report ]; then
  if [ ! -s "$json" ] || [ ! -s "$loads" ]; then
    echo "bench_golden.sh: --report-only: no data from an earlier run in $build/ (run without it first)" >&2
    exit 2
  fi
else
  if [ "$mode" = full ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$build" -j2 --target bench_golden >/dev/null
  elif [ ! -x "$bin" ]; then
    echo "bench_golden.sh: --quick: $build/bench_golden is not built" >&2
    exit 2
  fi
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  TRIRAST_BENCH_QUICK=$([ "$mode" = quick ] && echo 1 || echo 0) \
    "$bin" --benchmark_out="$json" --benchmark_out_format=json \
    --benchmark_enable_random_interleaving=true "$@" >/dev/null
  load_after=$(cut -d' ' -f1-3 /proc/loadavg)
  printf '%s\n%s\n%s\n' "$load_before" "$load_after" "$*" >"$loads"
fi
load_before=$(sed -n 1p "$loads")
load_after=$(sed -n 2p "$loads")
set -- $(sed -n 3p "$loads")
trap 'rm -f "$doc.tmp"' EXIT
label="scripts/bench_golden.sh"
if [ "$mode" = quick ]; then label="$label --quick"; fi
label="$label $*"
python3 - "$json" "$label" "$load_before" "$load_after" >"$doc.tmp" <<'PY'
import json, statistics, sys
data = json.load(open(sys.argv[1]))
command = sys.argv[2].strip()
load_before, load_after = sys.argv[3], sys.argv[4]
rows = {}
for b in data["benchmarks"]:
    if b.get("run_type") == "aggregate":
        continue
    name = b["run_name"].split("/min_time")[0]
    rows[name] = b
def get(kind, scene, trav, threads=None):
    key = f"{kind}/{scene}/{trav}" + (f"/{threads}" if threads else "")
    return rows[key]
travs = ["simple", "incremental", "block", "adaptive", "bisector", "sat-block", "window", "scanline", "auto"]
cases = [("C1", "lowpoly-far", "low poly, far"), ("C2", "lowpoly-near", "low poly, near (80% of screen)"),
         ("C3", "highpoly-far", "high poly, far"), ("C4", "highpoly-near", "high poly, whole screen"),
         ("C5", "mixed", "mixed small and large")]
paper = {"C1": [112, 294, 456, 506, 517], "C2": [58, 165, 552, 552, 564], "C3": [60, 67, 51, 67, 69],
         "C4": [23, 37, 35, 40, 45], "C5": [69, 97, 106, 125, 132]}
def t(scene, trav):
    return get("traversal", scene, trav)["real_time"]
ctx = data["context"]
out = []
w = out.append
w("# Golden traversal performance\n")
w("Made by `" + command + "` (tools/bench_golden.cpp, Google Benchmark) on " + ctx.get("date", "?") +
  f", {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, a shared and noisy machine: "
  "compare ratios within this one run, not absolute times across runs. Viewport 1024x768, S = 8, "
  "no culling. Times cover the traversal of already set-up triangles (setup is common to every "
  "engine and measured on its own below); every traversal produces identical spans "
  "(tests/test_golden_variants.cpp).\n")
w("## Speed-up over `simple`, in the shape of Table 1 of Mileff, Nehéz & Dudra, \"Accelerated half-space triangle rasterization\"\n")
w("The paper (Mileff, Nehéz & Dudra, Table 1) gives frames per second of a full pipeline (z-buffer, shading) on an "
  "i7-870; we give the traversal alone. Both are shown as speed-up over the simple rasterizer, "
  "paper first, ours second. The paper's last column is its adaptive model combined with the "
  "bisector; our `bisector` runs the bisector block walk on every triangle.\n")
w("| Case | Scene | Simple | Incremental | Block | Adaptive | Bisector (paper: adaptive+bisector) | sat-block | window | scanline | auto |")
w("|---|---|---|---|---|---|---|---|---|---|---|")
def ratio_row(code, scene, label):
    base = t(scene, "simple")
    ours = [base / t(scene, x) for x in travs]
    p = paper.get(code)
    cells = []
    for i, x in enumerate(travs):
        if p and i < 5:
            cells.append(f"{p[i] / p[0]:.2f} / **{ours[i]:.2f}**")
        else:
            cells.append(f"**{ours[i]:.2f}**")
    w(f"| {code} | `{scene}` ({label}) | " + " | ".join(cells) + " |")
for code, scene, label in cases:
    ratio_row(code, scene, label)
for scene, label in [("sphere", "mesh"), ("torus", "mesh"), ("tri10", "10-pixel triangles"), ("large", "large triangles")]:
    ratio_row("-", scene, label)
w("\nThe paper's Table 1 in frames per second (quoted from Mileff, Nehéz & Dudra):\n")
w("| Case | Simple | Incremental | Block-based | Adaptive | Adaptive and Bisector |")
w("|---|---|---|---|---|---|")
for code in ["C1", "C2", "C3", "C4", "C5"]:
    w(f"| {code} | " + " | ".join(str(v) for v in paper[code]) + " |")
w("\n## Triangles and covered pixels per second (single thread)\n")
w("Millions per second: triangles / pixels.\n")
scenes = [s for _, s, _ in cases] + ["sphere", "torus", "tri10", "large"]
w("| Traversal | " + " | ".join(f"`{s}`" for s in scenes) + " |")
w("|---|" + "---|" * len(scenes))
for x in travs:
    cells = []
    for s in scenes:
        b = get("traversal", s, x)
        cells.append(f"{b['tris_per_s'] / 1e6:.2f} / {b['pixels_per_s'] / 1e6:.0f}")
    w(f"| `{x}` | " + " | ".join(cells) + " |")
tris = {s: int(get("traversal", s, "auto")["tris"]) for s in scenes}
w("\nTriangles per scene (accepted by setup): " + ", ".join(f"`{s}` {n}" for s, n in tris.items()) + ".")
st = rows["setup/tri10"]
w(f"Setup alone (`setup_scene`, 10-pixel triangles): {st['tris_per_s'] / 1e6:.2f} M triangles/s.\n")
w("## Threads\n")
def batches(name):
    return [b for b in data["benchmarks"] if b.get("run_type") != "aggregate" and b["run_name"].split("/min_time")[0] == name]
def med(name, counter):
    return statistics.median(b[counter] for b in batches(name))
def rng(name, counter):
    v = [b[counter] for b in batches(name)]
    return min(v), max(v)
nbatch = len(batches("threads/highpoly-near/auto"))
w("The golden engine `make_golden_engine(traversal, threads)`. The calling thread is the writer, "
  "the only one that touches the output; the other is a helper, started with the engine's first "
  "parallel run and asleep between runs. The triangles are cut into chunks of up to 256 "
  "consecutive triangles. The writer rasterizes a front range of chunks straight into the output "
  "list; the helper rasterizes the back range, chunk by chunk, into lists of its own, which the "
  "writer appends in order (one copy each); whichever side runs out of work takes the lowest "
  "chunk left in the other's range, so both end together and only the last chunk or two are "
  "copied after the helper is done. The split between the ranges comes from a guess of each "
  "triangle's cost (every 64th box). So the output is the one-thread list, span for span, for any "
  "thread count (tests/test_golden_variants.cpp, GoldenParallel.*, on scenes of 101,760 to "
  "132,060 triangles and on one engine reused over scenes of 0 to 70,000), with no merge, sort or "
  "zero-fill.\n")
w("**How it is measured.** This machine's two CPUs are shared with other jobs, and what they take "
  "drifts over seconds: medians of the same benchmark taken a minute apart differ by 10-20%. So "
  "each iteration of a `threads/...` benchmark runs four things a few milliseconds apart, in an "
  "order that rotates from one iteration to the next: the engine on one thread (\"1 thread\"), "
  "the engine on two (\"2 threads\"), and the *twin* workload on one thread and on two. The twin "
  "workload is the golden's own work with nothing to balance, order, copy or join: one thread "
  "rasterizes every triangle twice, into two lists, against two threads rasterizing every "
  "triangle once each, into lists of their own (kept between runs, each on a cache line of its "
  "own; the second thread is woken, not created, as the engine's helper is). Its speed-up is what "
  "the machine gave two threads of this very workload, with its memory traffic and instruction "
  "mix, at that moment: the ceiling for any 2-thread golden, not a strict one (it writes into "
  "warm lists, the engine into a fresh output). \"Of ceiling\" is the engine's speed-up divided by "
  "the twin's, taken within each iteration and then the median. Engine times are the wall clock "
  "of `Engine::run`, everything its caller pays once the scene is set up: waking the helper, the "
  "chunk lists, and a fresh output list (allocation, page faults, growth) holding every span in "
  f"triangle order. Each benchmark ran {nbatch} batches of at least 3 s; the table gives the "
  "median batch's medians and, in brackets, the range over the batches. "
  f"Load average (1, 5, 15 min) when the benchmark started: {load_before}; when it ended: "
  f"{load_after}.\n")
w("| Scene | Traversal | Spans | 1 thread (ms) | 2 threads (ms) | Speed-up | Ceiling (twin) | Of ceiling | With serial setup |")
w("|---|---|---|---|---|---|---|---|---|")
speedups, ceilings, shares, setup_ms = {}, {}, {}, {}
for sc in ["highpoly-near", "random100k"]:
    setup_ms[sc] = rows[f"setup/{sc}"]["real_time"]
    for x in ["auto", "incremental", "simple"]:
        k = f"threads/{sc}/{x}"
        one, two = med(k, "one_ms"), med(k, "two_ms")
        sp, ce, sh = med(k, "speedup"), med(k, "ceiling"), med(k, "of_ceiling")
        speedups[(sc, x)], ceilings[(sc, x)], shares[(sc, x)] = sp, ce, sh
        lo, hi = rng(k, "speedup")
        clo, chi = rng(k, "ceiling")
        slo, shi = rng(k, "of_ceiling")
        with_setup = (setup_ms[sc] + one) / (setup_ms[sc] + two)
        b0 = batches(k)[0]
        w(f"| `{sc}` ({int(b0['tris'])} triangles) | `{x}` | {int(b0['spans'])} | {one:.2f} | {two:.2f} | "
          f"**{sp:.2f}x** ({lo:.2f}..{hi:.2f}) | {ce:.2f}x ({clo:.2f}..{chi:.2f}) | {sh:.2f} ({slo:.2f}..{shi:.2f}) | {with_setup:.2f}x |")
arith = med("ceiling/arithmetic", "speedup")
alo, ahi = rng("ceiling/arithmetic", "speedup")
stream = med("ceiling/stream", "speedup")
stlo, sthi = rng("ceiling/stream", "speedup")
wake_us = rows["threads/wake"]["real_time"]
copy_ms = {sc: rows[f"copy/{sc}"]["real_time"] for sc in ["highpoly-near", "random100k"]}
one_ms = {sc: med(f"threads/{sc}/auto", "one_ms") for sc in ["highpoly-near", "random100k"]}
w(f"\nThe same pairing on work with no golden in it, one thread doing both halves against two "
  f"threads one half each: pure arithmetic (`ceiling/arithmetic`: a chain of multiply-adds, no "
  f"memory) **{arith:.2f}x** ({alo:.2f}..{ahi:.2f}); streaming memory (`ceiling/stream`: each half "
  f"reads a 16 MB array and writes a running sum into another) **{stream:.2f}x** "
  f"({stlo:.2f}..{sthi:.2f}). Two of the engine's own "
  f"costs, measured on their own in the same run: waking the sleeping helper and learning that "
  f"it is done, {wake_us:.1f} us (`threads/wake`, the least it can cost; a helper asleep for "
  f"milliseconds takes longer); copying a whole scene's spans to the end of another list, "
  + " and ".join(f"{copy_ms[sc]:.2f} ms on `{sc}` ({100 * copy_ms[sc] / one_ms[sc]:.1f}% of a one-thread `auto` run)" for sc in copy_ms)
  + " (`copy/...`): the writer copies the helper's share of the spans, at most all of them.\n")
w("Setup (`setup_scene`: snapping, edge functions, boxes) is not part of the golden engine: it "
  "runs once, on one thread, before any engine, and costs "
  + " and ".join(f"{setup_ms[sc]:.2f} ms on `{sc}`" for sc in setup_ms) +
  " (mean of repeated runs). The column \"With serial setup\" is the speed-up of setup plus engine, for a caller "
  "that sets up a scene just to rasterize it once with the golden; the target is read on the "
  "engine (the Speed-up column).\n")
w("\n## Targets\n")
tri10 = get("traversal", "tri10", "auto")["tris_per_s"]
tri10_best = max(get("traversal", "tri10", x)["tris_per_s"] for x in travs)
large = get("traversal", "large", "scanline")["pixels_per_s"]
w("| Target | Measured | Met |")
w("|---|---|---|")
w(f"| >= 5 M triangles/s on 10-pixel triangles (1 thread) | `auto` {tri10 / 1e6:.2f} M/s (best traversal {tri10_best / 1e6:.2f} M/s) | {'yes' if tri10 >= 5e6 else 'no'} |")
w(f"| >= 1 G covered pixels/s on large triangles (1 thread) | `scanline` {large / 1e9:.2f} G/s | {'yes' if large >= 1e9 else 'no'} |")
best = max(speedups.values())
worst_key = min(speedups, key=speedups.get)
met = min(speedups.values()) >= 1.8
below = [k for k in speedups if speedups[k] < 1.8]
w(f"| >= 1.8x on 2 threads vs 1 for >= 100,000 triangles | medians {speedups[worst_key]:.3f}x (`{worst_key[1]}` on `{worst_key[0]}`) to {best:.3f}x; "
  f"the machine's ceiling for the same work {min(ceilings.values()):.2f}x to {max(ceilings.values()):.2f}x; the engine at "
  f"{min(shares.values()):.2f} to {max(shares.values()):.2f} of it | "
  + ("yes" if met else f"no: {len(below)} of {len(speedups)} rows below (see the gap below)") + " |")
w("\n## Notes\n")
w("- **Exactness.** Every traversal decides coverage with the same integer edge test (or, for "
  "`scanline`, the same rule solved per row with exact floor/ceil), and all emit identical spans "
  "in the same order; `tests/test_golden_variants.cpp` checks each against the independent "
  "per-pixel reference on random, lattice, tiny, sliver, large-coordinate and 4096x4096 cases.")
w("- **Why scanline wins almost everywhere.** It costs per row, not per pixel: a span's pixels are "
  "counted, never visited, which is what the >= 1 G pixels/s target asks for. The pixel and block "
  "traversals must visit every covered pixel (the block ones at least every partial block's pixels), "
  "so their pixel rate is bounded by a few G/s. The paper's figures include shading every pixel, "
  "which compresses its ratios.")
w("- **Block traversals on small triangles** (C3, C4, meshes) lose to `incremental`, as in the "
  "paper's C3/C4: most blocks are partial, and the corner tests are pure overhead. `adaptive` "
  "avoids most of that loss by the orientation metric, as the paper reports.")
w("- **`auto`** uses `incremental` for boxes of at most kAutoPixelBoxLimit (100) pixels (no "
  "divisions to set up) and `scanline` above; the threshold was picked by sweeping 16..200 on "
  "these scenes (differences near the noise).")
if met:
    w("- **Threads.** Every row reached 1.8x in this run.")
else:
    machine = [k for k in below if ceilings[k] < 1.8 / 0.95]
    w("- **The gap to 1.8x in this run.** Below 1.8x: "
      + ", ".join(f"`{x}` on `{sc}` {speedups[(sc, x)]:.3f}x (ceiling {ceilings[(sc, x)]:.2f}x, {shares[(sc, x)]:.2f} of it)" for (sc, x) in below)
      + ". Two things stand between 2x and the engine. First, the machine: "
      f"two threads of pure arithmetic ran {arith:.2f}x, but two threads of the golden's own work "
      "with nothing shared (the twin) ran only "
      f"{min(ceilings.values()):.2f}x to {max(ceilings.values()):.2f}x in the same iterations, and "
      f"two threads streaming through memory of their own {stream:.2f}x: the two virtual CPUs share "
      "the host's caches and memory with each other and with other machines' jobs, and a "
      "rasterizer that streams 184-byte triangles in and 16-byte spans out loses some of its "
      "second thread to that, as a multiply chain does not"
      + (f"; on {', '.join(f'`{x}` on `{sc}`' for (sc, x) in machine)} the ceiling itself was "
         "below 1.8 / 0.95, so no 2-thread golden doing 5% of extra work could have reached 1.8x "
         "in that run" if machine else "")
      + ". Second, the engine's own extra work over one thread: waking the helper (above; the "
      "writer works meanwhile) and copying the helper's share of the spans into the output "
      "(about 5% of a one-thread run if every span is copied, above; how many are depends on "
      "where in the triangle order a scene's spans lie). With the engine at "
      f"{min(shares.values()):.2f} to {max(shares.values()):.2f} of the ceiling, a row reaches 1.8x "
      "when the machine gives the same work about 1.8x divided by that share ("
      + ", ".join(f"`{x}` on `{sc}` {1.8 / shares[(sc, x)]:.2f}x" for (sc, x) in speedups)
      + "). Which rows get that changes from run to run on this host (the ranges in brackets).")
w("- **Relation to Ritz's thesis (\"Software renderer for the GR3 library\"), chapter 4.** The "
  "thesis splits the work two ways: by content, "
  "parts of the triangle meshes handed to the threads through queues, each thread drawing into "
  "buffers of its own that are merged at the end (4.1.3), and by area, thread i taking every "
  "row z with z = i mod n (4.2). It keeps the first and drops the second as much slower: every "
  "thread has to walk every triangle to find its rows, and a triangle's incremental set-up is "
  "paid once per thread. The golden's threads split by content as well (chunks of consecutive "
  "triangles taken from two ranges), for the same reason; its output is a span list in triangle "
  "order rather than a frame buffer, so the merge becomes the writer appending the helper's "
  "chunk lists in order, which it does while the helper still works. As in 4.3.1 and 4.1.3.1, "
  "what can be kept between runs is kept: the chunk lists and the helper thread.")
w("- **The 2-thread engine, what changed and why.** The first engine (chunks from one shared "
  "counter, a list per chunk, joined by `resize` and a parallel copy) measured 0.74..1.03x: it "
  "summed every triangle's box before starting (a cache and TLB miss per triangle), zero-filled "
  "the whole output on one thread and copied every span twice. The second rasterized the "
  "writer's range straight into the output and copied only the helper's chunks, but created and "
  "joined a thread per run, and a side out of work took chunks from the far end of the other's "
  "range, so the chunks the writer took over were copied after the helper had finished, by the "
  "writer alone. Now the helper is kept asleep between runs (`HelperPool`), is woken before the "
  "writer plans the split, and both sides take the lowest chunk left, so the copying overlaps "
  "with the helper's rasterizing to the end; the split is set by a guess of each triangle's cost "
  "(rows, or pixels for small boxes) instead of the triangle count. The three changes were found "
  "by timestamping the second engine's writer and helper on `highpoly-near` (a throwaway build, "
  "so its figures are not quoted here): thread creation and join, and the tail copy, were each "
  "a few percent of a 2-thread run.")
print("\n".join(out))
PY
mv "$doc.tmp" "$doc"
echo "wrote $doc"
