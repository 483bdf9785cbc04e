#!/usr/bin/env python3
"""What-if for a pipelined improved unit (the estimate behind the improved2 unit): cycles per
triangle if its set-up were a pipeline and small boxes took a direct test, estimated from the
improved unit's per-triangle cycles.

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

With --corner SPEC (repeatable; docs/improved2.md), one more column per SPEC: F is split into a
box stage (1 cycle; an empty box retires there) and a corner-value stage of c cycles per
triangle, followed by the direct test of the first --direct size or the lanes and the walk as
above. c comes from the triangle's snapped vertices (`trirast raster --export-tris`), with the
vertex-relative operands dxL = cx0 - vx, dy = cy0 - vy of each edge's first vertex (E_R is assumed
to be formed during the lanes' slope division, at no cycle cost). These columns take the lanes'
L from setup_done_cycle (a + 3 + L); the columns before them take accept-to-hand-off minus 3,
which also counts today's wait in StHold for the walk stage (so they are more pessimistic):
  1       one cycle (all products in one cycle, as gen1's interface);
  sN      shift-add, N operand bits per cycle: c = max(1, ceil(bits / N)), bits = the largest
          bit length of |dxL|, |dy| over the three edges;
  nW+sN   narrow W-bit signed multipliers in one cycle when |A|, |B|, |dxL|, |dy| of every edge
          fit W signed bits and Xmax < 2^(W-1-F), else the sN shift-add;
  sNpD, nW+sNpD  the same with D pipeline registers in the shift-add (D = 1 or 2):
          c = max(1, ceil(bits / N)) + D; the stage takes its next
          triangle only after the D cycles (no overlap of two triangles).
--corner-hold adds the same columns for a unit without a hand-off buffer (the lanes hold a
set-up triangle until the walk stage loads it, as gen1's StHold). Between the other stages the
estimate assumes buffers that never fill (no blocking is counted).
--corner-shared adds the columns of a unit whose three edges share one lane (one divider):
L = the sum of the three edges' lane cycles instead of their maximum; no hand-off buffer.
--corner-stats prints, per scene and SPEC, the share of non-empty boxes on the narrow path and the
mean c.

  scripts/pipeline_whatif.py [--build DIR] [--direct WxH ...] [--corner SPEC ...] [--corner-stats] [scene ...]
Default scenes: those of docs/cycles-improved-vs-trad.md; default --direct 2x2 and 4x4.
"""
import argparse
import collections
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tb", "improved2"))
from tri_setup import read_export  # noqa: E402  (the .tri reader of the improved2 unit's checks)
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


def geometry(trirast, scene, rows, tmp):
    """Per scene index: (empty, xmax, operand bits of |dxL|, |dy|, max |A|, |B|, |dxL|, |dy|).
    Degenerate triangles (left out by tri_setup.read_export) count as empty boxes."""
    path = os.path.join(tmp, "t.tri")
    last = max((r["tri"] for r in rows), default=0)
    env = dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1")
    r = subprocess.run([trirast, "raster", "--engine", "golden", "--scene", scene,
                        "--export-tris", f"0:{last}:{path}"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"pipeline_whatif.py: --export-tris on {scene}: {r.stderr.strip()}")
    W, H, F, tris = read_export(path, "pipeline_whatif.py", indexed=True)
    u, h = 1 << F, 1 << (F - 1)
    geo = collections.defaultdict(lambda: (True, 0, 0, 0))
    for index, v, edges in tris:
        xs, ys = [p[0] for p in v], [p[1] for p in v]
        x0, y0 = max(0, -((h - min(xs)) // u)), max(0, -((h - min(ys)) // u))
        x1, y1 = min(W - 1, (max(xs) - h) // u), min(H - 1, (max(ys) - h) // u)
        if x0 > x1 or y0 > y1:
            continue
        cx0, cy0 = x0 * u + h, y0 * u + h
        ops = [abs(cx0 - p[0]) for p in v] + [abs(cy0 - p[1]) for p in v]
        coefs = [abs(e[0]) for e in edges] + [abs(e[1]) for e in edges]
        geo[index] = (False, x1 - x0, max(ops), max(coefs))
    return geo, F


def corner_cycles(spec, g, F):
    """Cycles of the corner-value stage for one non-empty triangle; (cycles, narrow path)."""
    _, xmax, op, coef = g
    if spec == "1":
        return 1, True
    m = re.fullmatch(r"(?:n(\d+)\+)?s(\d+)(?:p(\d+))?", spec)
    narrow, digit, depth = m.group(1), int(m.group(2)), int(m.group(3) or 0)
    if narrow:
        w = int(narrow)
        if op < (1 << (w - 1)) and coef < (1 << (w - 1)) and xmax < (1 << (w - 1 - F)):
            return 1, True
    return max(1, math.ceil(op.bit_length() / digit)) + depth, False


def estimate_corner(rows, direct, spec, geo, F, hold=False, shared=False):
    """Box stage (1 cycle), corner stage (c cycles), then direct test or lanes + walk.
    hold: no hand-off buffer, the lanes keep their triangle until the walk stage loads it."""
    t_b = t_c = t_lanes = t_walk = 0
    for r in rows:
        t_b += 1
        w, h = r["box_width"], r["box_height"]
        if w == 0:
            continue
        c, _ = corner_cycles(spec, geo[r["tri"]], F)
        t_c = max(t_c, t_b) + c
        if direct and w <= direct[0] and h <= direct[1]:
            t_walk = max(t_walk, t_c) + max(1, r["spans"])
            continue
        # L itself (setup_done_cycle = a + 3 + L), without today's wait in StHold for the walk
        # stage, which the walk term below already counts (estimate() uses the hand-off cycle).
        lanes = max(1, r["setup_done_cycle"] - r["accept_cycle"] - 3)
        if shared:  # one divider for the three edges: their lane work in series
            lanes = max(1, r["divider_iterations"] + r["boundary_steps"])
        walk = r["walk_end_cycle"] - r["walk_start_cycle"] + 1
        done = max(t_lanes, t_c) + lanes
        load = max(t_walk, done)
        t_lanes = load if hold else done
        t_walk = load + walk
    return max(t_b, t_c, t_lanes, t_walk)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.environ.get("TRIRAST_BUILD_DIR", os.path.join(ROOT, "build")))
    ap.add_argument("--direct", action="append", default=[], metavar="WxH")
    ap.add_argument("--corner", action="append", default=[], metavar="SPEC",
                    help="1, sN, nW+sN, sNpD or nW+sNpD: a column with a corner-value stage of "
                         "that many cycles (pD: D pipeline registers in the shift-add, D more "
                         "cycles per triangle)")
    ap.add_argument("--corner-stats", action="store_true")
    ap.add_argument("--corner-hold", action="store_true")
    ap.add_argument("--corner-shared", action="store_true")
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
    for c in a.corner:
        m = re.fullmatch(r"1|(?:n(\d+)\+)?s(\d+)(?:p\d+)?", c)
        if not m or (m.group(2) and int(m.group(2)) < 1) or (m.group(1) and int(m.group(1)) < 2):
            sys.exit(f"pipeline_whatif.py: --corner {c}: expected 1, sN, nW+sN or sNpD "
                     "(e.g. n13+s4, s4p1)")
    print("| scene | triangles | improved today | trad | pipelined set-up | "
          + " | ".join(f"+ direct {w}x{h}" for w, h in directs)
          + "".join(f" | direct {directs[0][0]}x{directs[0][1]}, corners {c}" for c in a.corner)
          + "".join(f" | same, corners {c}, no hand-off buffer" for c in (a.corner if a.corner_hold else []))
          + "".join(f" | same, corners {c}, one shared lane, no buffer" for c in (a.corner if a.corner_shared else []))
          + " |")
    print("|---|---:|---:|---:|---:|" + "---:|" * (len(directs) + len(a.corner) * (1 + a.corner_hold + a.corner_shared)))
    stats = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes or SCENES:
            imp = cycles(trirast, "improved-sc", scene, tmp)
            trad = cycles(trirast, "trad-sc", scene, tmp)
            n = max(1, len(imp))
            cols = [total(imp) / n, total(trad) / n, estimate(imp, None) / n]
            cols += [estimate(imp, d) / n for d in directs]
            if a.corner:
                geo, F = geometry(trirast, scene, imp, tmp)
                bad = [r["tri"] for r in imp if geo[r["tri"]][0] != (r["box_width"] == 0) or
                       (r["box_width"] > 0 and geo[r["tri"]][1] + 1 != r["box_width"])]
                if bad:
                    sys.exit(f"pipeline_whatif.py: {scene}: the box from --export-tris differs from "
                             f"the cycles file's for triangle {bad[0]} ({len(bad)} triangles)")
                cols += [estimate_corner(imp, directs[0], c, geo, F) / n for c in a.corner]
                if a.corner_hold:
                    cols += [estimate_corner(imp, directs[0], c, geo, F, hold=True) / n for c in a.corner]
                if a.corner_shared:
                    cols += [estimate_corner(imp, directs[0], c, geo, F, hold=True, shared=True) / n
                             for c in a.corner]
                if a.corner_stats:
                    ne = [geo[r["tri"]] for r in imp if r["box_width"] > 0]
                    for c in a.corner:
                        cc = [corner_cycles(c, g, F) for g in ne]
                        stats.append((os.path.basename(scene) if "/" in scene else scene, c, len(ne),
                                      sum(1 for _, nar in cc if nar) / max(1, len(ne)),
                                      sum(x for x, _ in cc) / max(1, len(ne))))
            name = os.path.basename(scene) if "/" in scene else scene
            print(f"| {name} | {len(imp)} | " + " | ".join(f"{c:.2f}" for c in cols) + " |")
    print("\ncycles per triangle (1024x768, S = 8, N = 1, FIFO 8, sink always ready)")
    if stats:
        print("\n| scene | corner SPEC | non-empty boxes | on the narrow path | mean corner cycles |")
        print("|---|---|---:|---:|---:|")
        for name, c, ne, frac, mean in stats:
            print(f"| {name} | {c} | {ne} | {100 * frac:.1f}% | {mean:.2f} |")


if __name__ == "__main__":
    main()
