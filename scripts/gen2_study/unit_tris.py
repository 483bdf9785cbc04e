#!/usr/bin/env python3
"""gen2 study (scripts/gen2_study.sh --check): a scene's triangles for the whole-unit check.

    unit_tris.py TRI_FILE OUT_HEX

TRI_FILE is `trirast raster --export-tris A:B:TRI_FILE` (snapped vertices in pixels, header with
--width/--height/--subpixel-bits). OUT_HEX gets one $readmemh line per triangle with a non-zero
area (degenerate ones never reach a unit), the triangle port's fields packed as
{bias[2:0], C[3], B[3], A[3], vy[3], vx[3]} (edge / vertex k at k's slot, two's complement), set up
as model/core/setup.cpp does (vertices swapped to a positive area, A = a.y - b.y, B = b.x - a.x,
C = a.x*b.y - a.y*b.x, bias 1 unless top-left; the same rules as lane_edges.py). Prints
"+n=N +w=WIDTH +h=HEIGHT" (the testbench's plusargs) on stdout."""
import re
import sys
from fractions import Fraction

P, CB, EB = 24, 25, 50   # VertexBits, CoefBits, EdgeBits of the default configuration


def pack(vals, bits):
    out = 0
    for k, v in enumerate(vals):
        if not -(1 << (bits - 1)) <= v < (1 << (bits - 1)):
            sys.exit(f"unit_tris.py: value {v} does not fit {bits} bits")
        out |= (v & ((1 << bits) - 1)) << (k * bits)
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("unit_tris.py: usage: unit_tris.py TRI_FILE OUT_HEX")
    src, dst = sys.argv[1:]
    try:
        f = open(src)
    except OSError as e:
        sys.exit(f"unit_tris.py: {src}: {e.strerror}")
    head = f.readline()
    m = re.search(r"--width (\d+) --height (\d+) --subpixel-bits (\d+)", head)
    if not m:
        sys.exit(f"unit_tris.py: {src}: no viewport in the export's header")
    W, H, S = (int(v) for v in m.groups())
    F = max(S, 1)
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
            A, B, C, bias = [], [], [], 0
            for k in range(3):
                a, b = v[k], v[(k + 1) % 3]
                A.append(a[1] - b[1])
                B.append(b[0] - a[0])
                C.append(a[0] * b[1] - a[1] * b[0])
                if not (A[k] > 0 or (A[k] == 0 and B[k] > 0)):
                    bias |= 1 << k
            word = pack([p[0] for p in v], P)
            word |= pack([p[1] for p in v], P) << (3 * P)
            word |= pack(A, CB) << (6 * P)
            word |= pack(B, CB) << (6 * P + 3 * CB)
            word |= pack(C, EB) << (6 * P + 6 * CB)
            word |= bias << (6 * P + 6 * CB + 3 * EB)
            out.write(f"{word:x}\n")
            n += 1
    print(f"+n={n} +w={W} +h={H}")


if __name__ == "__main__":
    main()
