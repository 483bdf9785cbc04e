#!/usr/bin/env bash
# Measures the golden traversals (tb/bench_golden.cpp) and writes docs/golden-performance.md:
# seed 000's Table 1 shape (speed-up of each traversal over `simple` per scene type, the paper's
# figures beside ours), triangles and pixels per second, thread scaling, and the issue's targets.
# All ratios come from one run of one program (the machine is shared and noisy).
# Usage: scripts/bench_golden.sh [extra Google Benchmark flags, e.g. --benchmark_min_time=0.1]
# TRIRAST_BUILD_DIR selects the build directory (default build/), e.g.
#   TRIRAST_BUILD_DIR=build-golden scripts/bench_golden.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build="${TRIRAST_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target bench_golden >/dev/null
json="$build/bench_golden.json"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
"./$build/bench_golden" --benchmark_out="$json" --benchmark_out_format=json \
  --benchmark_enable_random_interleaving=true "$@" >/dev/null
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
python3 - "$json" "scripts/bench_golden.sh $*" "$load_before" "$load_after" >docs/golden-performance.md.tmp <<'PY'
import json, statistics, sys
data = json.load(open(sys.argv[1]))
command = sys.argv[2].strip()
load_before, load_after = sys.argv[3], sys.argv[4]
rows = {}
reps = {}  # repeated benchmarks: every repetition's wall-clock time (ms)
for b in data["benchmarks"]:
    if b.get("run_type") == "aggregate":
        continue
    name = b["run_name"].split("/min_time")[0]
    rows[name] = b
    reps.setdefault(name, []).append(b["real_time"])
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
w("Made by `" + command + "` (tb/bench_golden.cpp, Google Benchmark) on " + ctx.get("date", "?") +
  f", {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, a shared and noisy machine: "
  "compare ratios within this one run, not absolute times across runs. Viewport 1024x768, S = 8, "
  "no culling. Times cover the traversal of already set-up triangles (setup is common to every "
  "engine and measured on its own below); every traversal produces identical spans "
  "(tests/test_golden_variants.cpp).\n")
w("## Speed-up over `simple`, in the shape of seed 000's Table 1\n")
w("The paper (000, Table 1) gives frames per second of a full pipeline (z-buffer, shading) on an "
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
w("\nThe paper's Table 1 in frames per second (quoted from 000_5c8a4b93fc256fe1.txt):\n")
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
nrep = len(reps[next(k for k in reps if k.startswith("threads/"))])
w("The golden engine `make_golden_engine(traversal, threads)`. The calling thread is the writer, "
  "the only one that touches the output; the triangles are cut into chunks of up to 256 "
  "consecutive triangles. The writer rasterizes a front range of chunks straight into the output "
  "list; the helper rasterizes the back range, chunk by chunk, into lists of its own, which the "
  "writer appends in order (one copy) while the helper is still working; whichever side runs out "
  "of work takes chunks from the far end of the other's range. So the output is the one-thread "
  "list, span for span, for any thread count (tests/test_golden_variants.cpp, GoldenParallel.*, "
  "on scenes of 101,760 to 132,060 triangles), with no merge, sort or zero-fill.\n")
w("Times are the wall clock of `Engine::run`, i.e. everything a caller of the multi-threaded "
  "golden pays once the scene is set up: thread start and join, the chunk lists, and a fresh "
  "output list (allocation and growth) holding every span in triangle order. "
  f"Each configuration ran {nrep} times, interleaved in random order with all the others, so that "
  "load from other jobs falls on 1-thread and 2-thread runs alike; the table gives the median run "
  "and the speed-up of medians (the fastest runs' ratio beside it). "
  f"Load average (1, 5, 15 min) when the benchmark started: {load_before}; when it ended: "
  f"{load_after} (2 cores: a load near 1 or above means other jobs were taking CPU time from these "
  "runs).\n")
w("The last two columns are the floor of any 2-thread golden on the same run: two threads each "
  "rasterizing half of the triangles into a list of their own, with no output list, order or "
  "balancing (`halves/...` in the benchmark), and its speed-up over one thread, i.e. what the "
  "machine gave two threads while the benchmark ran.\n")
w("| Scene | Traversal | Spans | 1 thread (ms) | 2 threads (ms) | Speed-up | Fastest runs | With serial setup | Floor: halves (ms) | Floor speed-up |")
w("|---|---|---|---|---|---|---|---|---|---|")
floors = {}
speedups = {}
setup_ms = {}
for s in ["highpoly-near", "random100k"]:
    setup_ms[s] = rows[f"setup/{s}"]["real_time"]
    for x in ["auto", "incremental", "simple"]:
        k1, k2 = f"threads/{s}/{x}/1", f"threads/{s}/{x}/2"
        a, b = statistics.median(reps[k1]), statistics.median(reps[k2])
        sp = a / b
        fast = min(reps[k1]) / min(reps[k2])
        with_setup = (setup_ms[s] + a) / (setup_ms[s] + b)
        speedups[(s, x)] = sp
        r1 = rows[k1]
        h = statistics.median(reps[f"halves/{s}/{x}"])
        floors[(s, x)] = a / h
        w(f"| `{s}` ({int(r1['tris'])} triangles) | `{x}` | {int(r1['spans'])} | {a:.2f} | {b:.2f} | **{sp:.2f}x** | {fast:.2f}x | {with_setup:.2f}x | {h:.2f} | {a / h:.2f}x |")
w("\nSetup (`setup_scene`: snapping, edge functions, boxes) is not part of the golden engine: it "
  "runs once, on one thread, before any engine, and costs "
  + " and ".join(f"{setup_ms[s]:.2f} ms on `{s}`" for s in setup_ms) +
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
auto_sp = min(speedups[(s, "auto")] for s in ["highpoly-near", "random100k"])
w(f"| >= 1.8x on 2 threads vs 1 for >= 100,000 triangles | medians: `auto` {auto_sp:.2f}x or more; lowest `{worst_key[1]}` on `{worst_key[0]}` {speedups[worst_key]:.2f}x, highest {best:.2f}x | {'yes' if min(speedups.values()) >= 1.8 else 'partly' if best >= 1.8 else 'no'} |")
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
w("- **The 2-thread engine, what changed and why.** The previous engine (chunks from one shared "
  "counter, a list per chunk, joined by `resize` and a parallel copy) measured 0.74..1.03x. "
  "Profiling it (perf, 1 vs 2 threads on `highpoly-near`) showed three serial or extra costs "
  "besides the load: a pass over every triangle's box to reserve the output before the threads "
  "started (a cache and TLB miss per 184-byte `TriangleSetup`: 15% of a one-thread run), "
  "`resize` zero-filling the whole output on one thread (about 6% of the one-thread time on "
  "`random100k`, 22 MB) and every span copied a second time (about 7%); the chunks also summed "
  "their boxes again. In units of the one-thread time that is 0.15 + 0.06 serial plus "
  "(0.85 + 0.15 + 0.07) / 2 in parallel, about 0.75, so 1.35x at best even on idle cores. Now the reservation comes from a "
  "sample of the boxes (every 64th) and overlaps with the helper's first chunks (the one-thread "
  "engine uses the same sample, so it got faster too); the writer's own share is never copied; "
  "the helper's share is copied once, by the writer, while the helper is still rasterizing; the "
  "split gives the writer (1 - c) / (2 - c) of the chunks, c = 0.07 being the copy's cost relative "
  "to rasterizing, so both finish together; chunks taken from the far ends absorb a wrong guess, "
  "a late thread start or a thread that the scheduler holds back. The extra work over one "
  "thread is the copy of the helper's half of the spans, c / 2 (3.5%) of one thread's time, "
  "which bounds the engine at 2 / (1 + c / 2) = 1.93x on idle cores. The total CPU time of a "
  "2-thread run, measured on the loaded machine (load 6..8), was 4..7% above one thread's on "
  "`random100k` and 11..15% on `highpoly-near`, bounds of 1.74..1.92x; those figures include "
  "the chunks the writer took over, with their extra copy, while the scheduler held the helper "
  "back, which idle cores would not see. Starting and joining the helper costs about 10 us "
  "(0.7% of a 2-thread `highpoly-near` run).")
worst_floor = min(floors.values())
met = min(speedups.values()) >= 1.8
if not met:
    below = [k for k in speedups if floors[k] < speedups[k]]
    if below:
      w("- **The gap to 1.8x in this run.** The target is missed on "
        + ", ".join(f"`{x}` on `{s}` ({speedups[(s, x)]:.2f}x)" for (s, x) in speedups if speedups[(s, x)] < 1.8)
        + ". The floor (two threads rasterizing halves into lists of their own) came out below the "
        "engine on " + ", ".join(f"`{x}` on `{s}` ({floors[(s, x)]:.2f}x vs {speedups[(s, x)]:.2f}x)" for (s, x) in below)
        + ", so in this run it is not a bound: it splits the triangles into two halves by count, "
        "with no balancing, while the engine balances by taking chunks from the other's end, and "
        "the load (above) took time from some runs. This run does not separate the engine's own "
        "gap from the machine's; a run on idle cores decides it.")
    else:
     w("- **The gap to 1.8x in this run.** " + (
      f"The floor (two threads rasterizing halves, with nothing to join) reached only "
      f"{worst_floor:.2f}..{max(floors.values()):.2f}x in the same run, so the machine did not give "
      "the benchmark two cores: with a load average above 2 on 2 cores, each thread gets a fraction "
      "of a core, and a run of a few milliseconds waits for the later of its two threads to be "
      "scheduled; no 2-thread golden can show its scaling then. The engine's speed-up is to be read "
      "against the floor's: "
      + ", ".join(f"`{x}` on `{s}` {speedups[(s, x)]:.2f}x vs {floors[(s, x)]:.2f}x" for (s, x) in speedups)
      + "." if worst_floor < 1.8 else
      "The floor reached 1.8x or more in this run, so the gap is the engine's own: "
      + ", ".join(f"`{x}` on `{s}` {speedups[(s, x)]:.2f}x vs floor {floors[(s, x)]:.2f}x" for (s, x) in speedups)
      + "."))
print("\n".join(out))
PY
mv docs/golden-performance.md.tmp docs/golden-performance.md
echo "wrote docs/golden-performance.md"
