#!/usr/bin/env python3
"""A scene's triangles for the whole-unit check (tb/improved2/run_checks.sh --check-unit:
improved2_unit_vs_improved_tb.sv).

    unit_tris.py TRI_FILE OUT_HEX

TRI_FILE is `trirast raster --export-tris A:B:TRI_FILE` (snapped vertices in pixels, header with
--width/--height/--subpixel-bits). OUT_HEX gets one $readmemh line per triangle with a non-zero
area (degenerate ones never reach a unit), the triangle port's fields packed as
{bias[2:0], C[3], B[3], A[3], vy[3], vx[3]} (edge / vertex k at k's slot, two's complement), set up
as model/common/setup.cpp does (tri_setup.py). Prints "+n=N +w=WIDTH +h=HEIGHT" (the testbench's
plusargs) on stdout."""
import sys

from tri_setup import read_export

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
    W, H, _, tris = read_export(src, "unit_tris.py")
    n = 0
    with open(dst, "w") as out:
        for v, edges in tris:
            A = [e[0] for e in edges]
            B = [e[1] for e in edges]
            C = [e[2] for e in edges]
            bias = sum(e[3] << k for k, e in enumerate(edges))
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
