#!/usr/bin/env python3
"""gen2 study (scripts/gen2_study.sh --check): the lanes' inputs of a scene's triangles.

    lane_edges.py TRI_FILE OUT

TRI_FILE is `trirast raster --export-tris A:B:TRI_FILE` (snapped vertices in pixels, header with
--width/--height/--subpixel-bits). For every triangle with a non-empty box, OUT gets one line per
edge, "A B E_L E_R Xmax Ymax tiny" (decimal), computed as model/core/setup.cpp and
rtl/trirast_interface.sv do: vertices swapped to a positive area, A = a.y - b.y, B = b.x - a.x,
C = a.x*b.y - a.y*b.x, bias 1 unless top-left, E at the box's left and right pixel centres of row
0. tiny = 1 for a box of at most 2x2 pixels (gen2's direct test, not the lanes)."""
import re
import sys
from fractions import Fraction


def main():
    if len(sys.argv) != 3:
        sys.exit("lane_edges.py: usage: lane_edges.py TRI_FILE OUT")
    src, dst = sys.argv[1:]
    try:
        f = open(src)
    except OSError as e:
        sys.exit(f"lane_edges.py: {src}: {e.strerror}")
    head = f.readline()
    m = re.search(r"--width (\d+) --height (\d+) --subpixel-bits (\d+)", head)
    if not m:
        sys.exit(f"lane_edges.py: {src}: no viewport in the export's header")
    W, H, S = (int(v) for v in m.groups())
    F = max(S, 1)
    u, h = 1 << F, 1 << (F - 1)
    n = 0
    with open(dst, "w") as out:
        for line in f:
            if "# tri" not in line:
                continue
            c = [int(Fraction(t) * (1 << S)) << (F - S) for t in line.split("#")[0].split()]
            v = [(c[0], c[1]), (c[2], c[3]), (c[4], c[5])]
            area2 = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
            if area2 == 0:
                continue
            if area2 < 0:
                v[1], v[2] = v[2], v[1]
            xs, ys = [p[0] for p in v], [p[1] for p in v]
            x0, y0 = max(0, -((h - min(xs)) // u)), max(0, -((h - min(ys)) // u))
            x1, y1 = min(W - 1, (max(xs) - h) // u), min(H - 1, (max(ys) - h) // u)
            if x0 > x1 or y0 > y1:
                continue
            xmax, ymax = x1 - x0, y1 - y0
            tiny = int(xmax <= 1 and ymax <= 1)
            for k in range(3):
                a, b = v[k], v[(k + 1) % 3]
                A, B = a[1] - b[1], b[0] - a[0]
                C = a[0] * b[1] - a[1] * b[0]
                bias = 0 if (A > 0 or (A == 0 and B > 0)) else 1
                cy = y0 * u + h
                el = A * (x0 * u + h) + B * cy + C - bias
                er = A * (x1 * u + h) + B * cy + C - bias
                out.write(f"{A} {B} {el} {er} {xmax} {ymax} {tiny}\n")
                n += 1
    print(f"lane_edges.py: {n} edges", file=sys.stderr)


if __name__ == "__main__":
    main()
