#!/usr/bin/env python3
"""The lanes' inputs of a scene's triangles for the edge lane check (tb/improved2/run_checks.sh
--check-all: improved2_edge_lane_tb.sv).

    lane_edges.py TRI_FILE OUT

TRI_FILE is `trirast raster --export-tris A:B:TRI_FILE` (snapped vertices in pixels, header with
--width/--height/--subpixel-bits). For every triangle with a non-empty box, OUT gets one line per
edge, "A B E_L E_R Xmax Ymax tiny" (decimal), computed as model/common/setup.cpp and
rtl/common/trirast_box_stage.sv do (tri_setup.py: vertices swapped to a positive area, A, B, C, bias),
E at the box's left and right pixel centres of row 0. tiny = 1 for a box of at most 2x2 pixels (the improved2 unit's
direct test, not the lanes)."""
import sys

from tri_setup import read_export


def main():
    if len(sys.argv) != 3:
        sys.exit("lane_edges.py: usage: lane_edges.py TRI_FILE OUT")
    src, dst = sys.argv[1:]
    W, H, F, tris = read_export(src, "lane_edges.py")
    u, h = 1 << F, 1 << (F - 1)
    n = 0
    with open(dst, "w") as out:
        for v, edges in tris:
            xs, ys = [p[0] for p in v], [p[1] for p in v]
            x0, y0 = max(0, -((h - min(xs)) // u)), max(0, -((h - min(ys)) // u))
            x1, y1 = min(W - 1, (max(xs) - h) // u), min(H - 1, (max(ys) - h) // u)
            if x0 > x1 or y0 > y1:
                continue
            xmax, ymax = x1 - x0, y1 - y0
            tiny = int(xmax <= 1 and ymax <= 1)
            cy = y0 * u + h
            for A, B, C, bias in edges:
                el = A * (x0 * u + h) + B * cy + C - bias
                er = A * (x1 * u + h) + B * cy + C - bias
                out.write(f"{A} {B} {el} {er} {xmax} {ymax} {tiny}\n")
                n += 1
    print(f"lane_edges.py: {n} edges", file=sys.stderr)


if __name__ == "__main__":
    main()
