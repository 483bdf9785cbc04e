#!/usr/bin/env python3
"""What-if for the improved unit's next generation (issue 13): cycles per triangle if its set-up
were a pipeline and small boxes took a direct test, estimated from today's per-triangle cycles.

For each scene it runs `trirast raster --cycles` with the timed models of the improved unit
(improved-sc) and the traditional unit (trad-sc), then replays the improved unit's triangles through
an in-order pipeline of three stages with one buffer between stages:
  F      accept, box and corner values: one triangle per cycle (today: accept, box, corner and a
         hold cycle that waits for the hand-off, paid by every triangle);
  lanes  the edge lanes, L cycles (today's accept-to-hand-off minus its 3 fixed cycles);
  walk   today's walk cycles of the triangle.
A box with no pixel centre retires in F. With --direct WxH, a box of at most W x H pixel centres
skips lanes and walk: a direct test of its centres from the corner values, max(1, spans) cycles
in the walk stage's place (one span per cycle out).
This is an estimate, not a model: it assumes the lanes' and walk's cycles stay as they are.

  scripts/pipeline_whatif.py [--build DIR] [--direct WxH ...] [scene ...]
Default scenes: those of docs/cycles-improved-vs-trad.md; default --direct 2x2 and 4x4.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["builtin:lowpoly-far", "builtin:lowpoly-near", "builtin:highpoly-far",
          "builtin:highpoly-near", "builtin:mixed", "builtin:sphere", "builtin:torus",
          "builtin:surface", os.path.join(ROOT, "tests/data/cube.obj")]


def cycles(trirast, engine, scene, tmp):
    path = os.path.join(tmp, "c.csv")
    env = dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1")
    r = subprocess.run([trirast, "raster", "--engine", engine, "--scene", scene, "--cycles", path],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"pipeline_whatif.py: {engine} on {scene}: {r.stderr.strip()}")
    with open(path) as f:
        return [{k: int(v) for k, v in row.items()} for row in csv.DictReader(f)]


def total(rows):
    return max(r["done_cycle"] for r in rows) + 1 if rows else 0


def estimate(rows, direct):
    t_f = t_lanes = t_walk = 0
    for r in rows:
        t_f += 1
        w, h = r["box_width"], r["box_height"]
        if w == 0:
            continue
        if direct and w <= direct[0] and h <= direct[1]:
            t_walk = max(t_walk, t_f) + max(1, r["spans"])
            continue
        lanes = max(1, r["handoff_cycle"] - r["accept_cycle"] - 3)
        walk = r["walk_end_cycle"] - r["walk_start_cycle"] + 1
        t_lanes = max(t_lanes, t_f) + lanes
        t_walk = max(t_walk, t_lanes) + walk
    return max(t_f, t_lanes, t_walk)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.environ.get("TRIRAST_BUILD_DIR", os.path.join(ROOT, "build")))
    ap.add_argument("--direct", action="append", default=[], metavar="WxH")
    ap.add_argument("scenes", nargs="*")
    a = ap.parse_args()
    trirast = os.path.join(a.build, "trirast")
    if not os.access(trirast, os.X_OK):
        sys.exit(f"pipeline_whatif.py: --build {a.build}: no trirast program there")
    directs = []
    for d in a.direct or ["2x2", "4x4"]:
        try:
            w, h = (int(v) for v in d.lower().split("x"))
            assert w > 0 and h > 0
        except (ValueError, AssertionError):
            sys.exit(f"pipeline_whatif.py: --direct {d}: expected WxH, e.g. 2x2")
        directs.append((w, h))
    print("| scene | triangles | improved today | trad | pipelined set-up | "
          + " | ".join(f"+ direct {w}x{h}" for w, h in directs) + " |")
    print("|---|---:|---:|---:|---:|" + "---:|" * len(directs))
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes or SCENES:
            imp = cycles(trirast, "improved-sc", scene, tmp)
            trad = cycles(trirast, "trad-sc", scene, tmp)
            n = max(1, len(imp))
            cols = [total(imp) / n, total(trad) / n, estimate(imp, None) / n]
            cols += [estimate(imp, d) / n for d in directs]
            name = os.path.basename(scene) if "/" in scene else scene
            print(f"| {name} | {len(imp)} | " + " | ".join(f"{c:.2f}" for c in cols) + " |")
    print("\ncycles per triangle (1024x768, S = 8, N = 1, FIFO 8, sink always ready)")


if __name__ == "__main__":
    main()
