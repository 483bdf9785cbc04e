"""Reads a `trirast raster --export-tris A:B:TRI_FILE` file (snapped vertices in pixels,
header with --width/--height/--subpixel-bits) and sets its triangles up as model/common/setup.cpp
does: vertices swapped to a positive area (degenerate triangles left out: they never reach a unit),
edge k from vertex k to vertex k + 1 with A = a.y - b.y, B = b.x - a.x, C = a.x*b.y - a.y*b.x, bias 1
unless the edge is top-left. Shared by lane_edges.py, unit_tris.py (the improved2 checks,
tb/improved2/run_checks.sh) and scripts/pipeline_whatif.py."""
import re
import sys
from fractions import Fraction


def read_export(src, prog, indexed=False):
    """Returns (W, H, F, triangles): the viewport, the fraction bits of the vertices (F =
    max(S, 1), as the unit's package) and a list of (vertices, edges) with vertices
    [(x, y)] * 3 in units of 2^-F pixel and edges [(A, B, C, bias)] * 3; with indexed, of
    (scene index, vertices, edges), the index from the line's "# tri N". Exits naming SRC when it
    cannot be read."""
    try:
        f = open(src)
    except OSError as e:
        sys.exit(f"{prog}: {src}: {e.strerror}")
    with f:
        head = f.readline()
        m = re.search(r"--width (\d+) --height (\d+) --subpixel-bits (\d+)", head)
        if not m:
            sys.exit(f"{prog}: {src}: no viewport in the export's header")
        W, H, S = (int(v) for v in m.groups())
        F = max(S, 1)
        tris = []
        for line in f:
            mt = re.search(r"# tri (\d+)", line)
            if not mt:
                continue
            c = [int(Fraction(t) * (1 << S)) << (F - S) for t in line.split("#")[0].split()]
            v = [(c[0], c[1]), (c[2], c[3]), (c[4], c[5])]
            area2 = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
            if area2 == 0:
                continue
            if area2 < 0:
                v[1], v[2] = v[2], v[1]
            edges = []
            for k in range(3):
                a, b = v[k], v[(k + 1) % 3]
                A, B = a[1] - b[1], b[0] - a[0]
                bias = 0 if (A > 0 or (A == 0 and B > 0)) else 1
                edges.append((A, B, a[0] * b[1] - a[1] * b[0], bias))
            tris.append((int(mt.group(1)), v, edges) if indexed else (v, edges))
    return W, H, F, tris
