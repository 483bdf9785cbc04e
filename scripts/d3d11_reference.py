#!/usr/bin/env python3
"""An independent program that holds trirast against the D3D11 rasterization rule.

It writes a .tri scene of random triangles whose vertices lie on the 1/256 pixel grid inside the
viewport, and the spans the D3D11 rule gives for it (16.8 fixed point, pixel centres, top-left
rule), computed here in Python integers pixel by pixel, sharing no code with trirast.

usage: d3d11_reference.py OUT.tri OUT.spans [--count N] [--seed S] [--width W] [--height H]
"""
import argparse
import random
import sys


def covered(v, px, py):
    """D3D11: sample at the pixel centre; inside if on the interior side of all three edges, or on
    an edge that is a top edge or a left edge (for a clockwise triangle on a y-down screen)."""
    cx, cy = px * 256 + 128, py * 256 + 128
    for i in range(3):
        (ax, ay), (bx, by) = v[i], v[(i + 1) % 3]
        e = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if e < 0:
            return False
        if e == 0:
            is_top = ay == by and bx > ax
            is_left = by < ay
            if not (is_top or is_left):
                return False
    return True


def spans_of(index, v, width, height):
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
    if area == 0:
        return []
    if area < 0:
        v = [v[0], v[2], v[1]]
    xs = [p[0] for p in v]
    ys = [p[1] for p in v]
    out = []
    for py in range(max(0, min(ys) // 256 - 1), min(height, max(ys) // 256 + 2)):
        run = None
        for px in range(max(0, min(xs) // 256 - 1), min(width, max(xs) // 256 + 2) + 1):
            inside = px < min(width, max(xs) // 256 + 2) and covered(v, px, py)
            if inside and run is None:
                run = px
            if not inside and run is not None:
                out.append((index, py, run, px))
                run = None
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tri")
    ap.add_argument("spans")
    ap.add_argument("--count", type=int, default=400)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=240)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    tris = []
    for _ in range(a.count):
        # Half the triangles on the half-pixel lattice (ties), half anywhere on the 1/256 grid.
        step = 128 if rng.random() < 0.5 else 1
        size = rng.choice([3, 20, 80]) * 256
        x0 = rng.randrange(0, a.width * 256 // step) * step
        y0 = rng.randrange(0, a.height * 256 // step) * step
        v = [(x0, y0)]
        for _ in range(2):
            x = min(max(x0 + rng.randrange(-size, size + 1) // step * step, 0), a.width * 256 - 1)
            y = min(max(y0 + rng.randrange(-size, size + 1) // step * step, 0), a.height * 256 - 1)
            v.append((x, y))
        tris.append(v)
    with open(a.tri, "w") as f:
        f.write("# written by scripts/d3d11_reference.py (seed %d)\n" % a.seed)
        for v in tris:
            f.write(" ".join("%.8f %.8f" % (x / 256, y / 256) for x, y in v) + "\n")
    spans = []
    for i, v in enumerate(tris):
        spans.extend(spans_of(i, v, a.width, a.height))
    spans.sort()
    with open(a.spans, "w") as f:
        for s in spans:
            f.write("%d %d %d %d\n" % s)
    print("%d triangles, %d spans" % (len(tris), len(spans)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
