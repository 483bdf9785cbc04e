#!/usr/bin/python3
"""Draws the triangle and span handshakes of a unit's top from a real RTL trace (docs/port.md).

  scripts/port_waveform.py --trirast BUILD/trirast [--engine E] [--cycles N] [--out FILE.png]

Writes a scene of four small triangles into a temporary folder, runs
`trirast raster --engine E --scene it --sink-stall periodic:2:1 --trace t.vcd` (the RTL's own
trace: the unit's top ports as the Verilated model drove them) and draws the first N cycles of the
top's handshake signals: each signal's value in cycle c (sampled with the clock low, docs/rtl.md
"Traces"), a mark on every cycle whose rising edge completes a handshake. Defaults: improved2-rtl,
36 cycles, docs/img/port-handshake.png. Exit status 0, or 1 with a one-line message.
"""
import argparse
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIGNALS = ["clk_i", "tri_valid_i", "tri_ready_o", "tri_tag_i", "span_valid_o", "span_ready_i",
           "span_tag_o", "span_y_o", "span_x_begin_o", "span_x_end_o"]
SCENE = """# four small triangles (pixels), one after the other on the triangle port
2 2  7 2  2 6
10 2  14 3  11 6
3 9  8 10  4 12
12 9  15 13  10 13
"""


def read_vcd(path, names):
    """{name: [(time, int value)]} of the top-level signals named (the first scope's)."""
    ids, changes, t = {}, {}, 0
    depth = 0
    with open(path) as f:
        header = True
        for line in f:
            w = line.split()
            if not w:
                continue
            if header:
                if w[0] == "$scope":
                    depth += 1
                elif w[0] == "$upscope":
                    depth -= 1
                elif w[0] == "$var" and depth == 1 and w[4] in names and w[4] not in ids.values():
                    ids[w[3]] = w[4]
                elif w[0] == "$enddefinitions":
                    header = False
                continue
            if w[0].startswith("#"):
                t = int(w[0][1:])
            elif w[0][0] in "01" and len(w) == 1 and w[0][1:] in ids:
                changes.setdefault(ids[w[0][1:]], []).append((t, int(w[0][0])))
            elif w[0][0] == "b" and len(w) == 2 and w[1] in ids:
                changes.setdefault(ids[w[1]], []).append((t, int(w[0][1:].replace("x", "0").replace("z", "0"), 2)))
    missing = [n for n in names if n not in changes]
    if missing:
        raise RuntimeError("%s: no signal %s in the top scope" % (path, ", ".join(missing)))
    return changes


def value_at(changes, time):
    v = changes[0][1]
    for t, x in changes:
        if t > time:
            break
        v = x
    return v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--trirast", required=True, help="the trirast binary")
    ap.add_argument("--engine", default="improved2-rtl", help="an RTL engine (default improved2-rtl)")
    ap.add_argument("--cycles", type=int, default=36, help="cycles drawn (default 36)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "img", "port-handshake.png"))
    a = ap.parse_args()
    if not a.engine.endswith("-rtl"):
        print("port_waveform.py: --engine %s: not an RTL engine (UNIT-rtl)" % a.engine, file=sys.stderr)
        return 1
    if not 4 <= a.cycles <= 200:
        print("port_waveform.py: --cycles %d: not in 4..200" % a.cycles, file=sys.stderr)
        return 1
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "four.tri")
        with open(scene, "w") as f:
            f.write(SCENE)
        cmd = [a.trirast, "raster", "--engine", a.engine, "--scene", scene, "--width", "16",
               "--height", "16", "--sink-stall", "periodic:2:1", "--trace", os.path.join(tmp, "t.vcd")]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            print("port_waveform.py: %s: %s" % (" ".join(cmd[1:]), (r.stderr.strip().split("\n") or ["failed"])[-1]),
                  file=sys.stderr)
            return 1
        try:
            ch = read_vcd(os.path.join(tmp, "t.vcd"), SIGNALS)
        except (RuntimeError, OSError, ValueError) as e:
            print("port_waveform.py: %s" % e, file=sys.stderr)
            return 1
    # The recording's time unit is 100 ps: cycle c's values at 10 c + 5 (clock low).
    first = min(t for t, _ in ch["tri_valid_i"]) // 10
    cyc = list(range(first, first + a.cycles))
    vals = {n: [value_at(ch[n], 10 * c + 5) for c in cyc] for n in SIGNALS if n != "clk_i"}
    buses = {"tri_tag_i", "span_tag_o", "span_y_o", "span_x_begin_o", "span_x_end_o"}
    rows = [n for n in SIGNALS]
    fig, ax = plt.subplots(figsize=(0.34 * a.cycles + 2.2, 0.42 * len(rows) + 0.8))
    h = 0.6
    for i, n in enumerate(rows):
        y0 = (len(rows) - 1 - i)
        ax.text(-0.4, y0 + h / 2, n, ha="right", va="center", family="monospace", fontsize=8)
        if n == "clk_i":
            xs, ys = [], []
            for k in range(a.cycles):
                xs += [k, k, k + 0.5, k + 0.5]
                ys += [y0, y0 + h, y0 + h, y0]
            ax.plot(xs, ys, color="0.35", lw=0.8)
            continue
        v = vals[n]
        valid = vals["tri_valid_i"] if n.startswith("tri_") else vals["span_valid_o"]
        ready = vals["tri_ready_o"] if n.startswith("tri_") else vals["span_ready_i"]
        # a bus segment ends where its value or valid changes or a handshake takes it
        ends = [k + 1 == a.cycles or v[k + 1] != v[k] or valid[k + 1] != valid[k] or (valid[k] and ready[k])
                for k in range(a.cycles)]
        if n in buses:
            for k in range(a.cycles):
                if k == 0 or ends[k - 1]:
                    start = k
                end = k + 1
                if ends[k]:
                    if valid[k]:
                        ax.fill([start + 0.08, start + 0.16, end - 0.08, end, end - 0.08, start + 0.16, start + 0.08],
                                [y0 + h / 2, y0 + h, y0 + h, y0 + h / 2, y0, y0, y0 + h / 2],
                                facecolor="#e8eef8", edgecolor="#3060a0", lw=0.8)
                        ax.text((start + end) / 2, y0 + h / 2, str(v[k]), ha="center", va="center", fontsize=7)
                    else:
                        ax.plot([start, end], [y0 + h / 2] * 2, color="0.7", lw=0.8)
        else:
            xs, ys = [], []
            for k in range(a.cycles):
                xs += [k, k + 1]
                ys += [y0 + h * v[k]] * 2
            ax.plot(xs, ys, color="#3060a0", lw=1.2)
    # handshakes complete at the rising edge that ends the cycle
    for k in range(a.cycles):
        for pair, color in ((("tri_valid_i", "tri_ready_o"), "#c04000"), (("span_valid_o", "span_ready_i"), "#008040")):
            if vals[pair[0]][k] and vals[pair[1]][k]:
                ax.axvline(k + 1, color=color, lw=0.6, ls=":", alpha=0.8)
    ax.set_xlim(-0.2, a.cycles)
    ax.set_ylim(-0.3, len(rows))
    ax.set_yticks([])
    ax.set_xticks([k + 0.5 for k in range(0, a.cycles, 2)])
    ax.set_xticklabels([str(cyc[k]) for k in range(0, a.cycles, 2)], fontsize=7)
    ax.set_xlabel("cycle (each from one rising edge to the next; dotted: a handshake at that edge, "
                  "orange triangle port, green span port)", fontsize=8)
    for s in ("top", "right", "left"):
        ax.spines[s].set_visible(False)
    ax.set_title("%s: triangle and span handshakes, downstream periodic:2:1" % a.engine, fontsize=9)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    tmp_out = a.out + ".tmp.png"
    fig.savefig(tmp_out, dpi=110)
    os.replace(tmp_out, a.out)
    print("port_waveform.py: wrote %s (%s, cycles %d..%d)" % (os.path.relpath(a.out), a.engine, cyc[0], cyc[-1]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
