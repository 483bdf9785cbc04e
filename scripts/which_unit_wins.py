#!/usr/bin/python3
"""docs/which-unit-wins.md and its plots from a run of build/trirast_unit_compare.

    /usr/bin/python3 scripts/which_unit_wins.py --data DIR --synth docs/synth.csv \
        --doc docs/which-unit-wins.md --img docs/img/which-unit-wins --command "..."

Reads DIR/scenes.csv, DIR/tris-*.csv and DIR/sweep.csv (tools/unit_compare.cpp says what they
hold) and the areas of docs/synth.csv; every number in the document comes from those files.
scripts/which_unit_wins.sh runs the whole chain (the one command).
"""
import argparse
import csv
import math
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNITS = ["improved", "trad", "hs1", "hs2", "hs4"]
LABEL = {"improved": "improved", "trad": "traditional", "hs1": "half-space S1",
         "hs2": "half-space S2", "hs4": "half-space S4"}
SYNTH_UNIT = {"improved": "improved", "trad": "trad", "hs1": "halfspace-s1",
              "hs2": "halfspace-s2", "hs4": "halfspace-s4"}
COLOR = {"improved": "tab:blue", "trad": "tab:orange", "hs1": "tab:olive", "hs2": "tab:green",
         "hs4": "tab:red"}
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def areas(path):
    """{unit: {target: luts}} of the default configuration in docs/synth.csv."""
    out = {u: {} for u in UNITS}
    if not os.path.exists(path):
        return out
    for r in read_csv(path):
        for u in UNITS:
            if r["unit"] == SYNTH_UNIT[u] and r["config"] == "default" and r["luts"]:
                out[u][r["target"]] = (int(r["luts"]), int(r["ffs"] or 0), int(r["dsp"] or 0))
    return out


def log2bin(v):
    return int(math.floor(math.log2(v))) if v >= 1 else -1


def bin_label(k):
    if k < 0:
        return "0"
    lo, hi = 2 ** k, 2 ** (k + 1) - 1
    return f"{lo}" if lo == hi else f"{lo}-{hi}"


def fmt(v):
    return f"{v:,.0f}" if v >= 100 else f"{v:.1f}"


def winner(vals):
    return min(vals, key=lambda u: vals[u])


def tied(vals):
    """The label of the unit(s) with the fewest: 'A' or 'A = B' when equal."""
    best = min(vals.values())
    return " = ".join(LABEL[u] for u in vals if vals[u] == best)


def scene_plot(label, rows, path):
    """Three panels: box area and pixel histograms, aspect histogram, cycles per box-area bin."""
    fig, ax = plt.subplots(1, 3, figsize=(15, 3.8))
    box = [int(r["box_w"]) * int(r["box_h"]) for r in rows]
    pix = [int(r["pixels"]) for r in rows]
    kb = [log2bin(b) for b in box]
    kp = [log2bin(p) for p in pix]
    lo = min(kb + kp)
    hi = max(kb + kp)
    xs = list(range(lo, hi + 1))
    ax[0].bar([x - 0.2 for x in xs], [kb.count(x) for x in xs], width=0.4, label="box area")
    ax[0].bar([x + 0.2 for x in xs], [kp.count(x) for x in xs], width=0.4, label="covered pixels")
    ax[0].set_xticks(xs)
    ax[0].set_xticklabels(["0" if x < 0 else f"2^{x}" for x in xs], rotation=90, fontsize=7)
    ax[0].set_ylabel("triangles")
    ax[0].set_yscale("log")
    ax[0].set_title("triangle size (pixels)")
    ax[0].legend(fontsize=8)
    asp = [math.log2(int(r["box_w"]) / int(r["box_h"])) for r in rows if int(r["box_h"]) > 0
           and int(r["box_w"]) > 0]
    ka = [int(math.floor(a + 0.5)) for a in asp]
    if ka:
        xa = list(range(min(ka), max(ka) + 1))
        ax[1].bar(xa, [ka.count(x) for x in xa], width=0.8)
        ax[1].set_xticks(xa)
        ax[1].set_xticklabels([f"{2.0 ** x:g}" for x in xa], rotation=90, fontsize=7)
    ax[1].set_title("box aspect w/h (nearest power of 2; non-empty boxes)")
    ax[1].set_ylabel("triangles")
    # Mean added cycles per triangle in each box-area bin.
    xb = sorted(set(kb))
    for u in UNITS:
        ys = []
        for x in xb:
            c = [int(r[u]) for r, k in zip(rows, kb) if k == x]
            ys.append(sum(c) / len(c))
        ax[2].plot(xb, ys, marker="o", ms=3, color=COLOR[u], label=LABEL[u])
    ax[2].set_yscale("log")
    ax[2].set_xticks(xb)
    ax[2].set_xticklabels(["0" if x < 0 else f"2^{x}" for x in xb], rotation=90, fontsize=7)
    ax[2].set_title("cycles per triangle by box area")
    ax[2].set_xlabel("box area (pixels)")
    ax[2].legend(fontsize=7)
    fig.suptitle(label)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def sweep_plot(sweep, path):
    aspects = sorted({float(r["aspect"]) for r in sweep})
    fig, ax = plt.subplots(1, len(aspects), figsize=(4 * len(aspects), 4), sharey=True)
    for a, axis in zip(aspects, ax):
        rs = sorted([r for r in sweep if float(r["aspect"]) == a], key=lambda r: float(r["mean_box"]))
        for u in UNITS:
            axis.plot([float(r["mean_box"]) for r in rs], [float(r[u]) for r in rs], marker="o",
                      ms=3, color=COLOR[u], label=LABEL[u])
        axis.set_xscale("log", base=2)
        axis.set_yscale("log", base=2)
        axis.set_title(f"aspect w/h = {a:g}")
        axis.set_xlabel("box area (pixels)")
        axis.grid(True, which="major", alpha=0.3)
    ax[0].set_ylabel("cycles per triangle")
    ax[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def crossings(rs, a, b, key="mean_box"):
    """Box areas where sign(cycles a - cycles b) changes between consecutive sweep points (points
    where the two are equal are skipped), with the unit that needs fewer cycles above it."""
    pts = [r for r in rs if float(r[a]) != float(r[b])]
    out = []
    for r0, r1 in zip(pts, pts[1:]):
        d0 = float(r0[a]) - float(r0[b])
        d1 = float(r1[a]) - float(r1[b])
        if (d0 < 0) != (d1 < 0):
            # log-linear interpolation of the zero of the difference
            x0, x1 = math.log2(float(r0[key])), math.log2(float(r1[key]))
            x = x0 + (x1 - x0) * d0 / (d0 - d1)
            out.append((2 ** x, float(r0[key]), float(r1[key]), a if d1 < 0 else b))
    return out


def no_crossing(rs, a, b):
    """The phrase for a pair without a crossover: who needs fewer cycles at every size."""
    d = [float(r[a]) - float(r[b]) for r in rs]
    if all(v == 0 for v in d):
        return "equal at every size"
    lead = a if all(v <= 0 for v in d) else b
    return f"{LABEL[lead]} at every size" + (" (equal at some)" if any(v == 0 for v in d) else "")


def trad_short(r):
    """The traditional unit draws under 90% of the rule's pixels in this sweep row (inexact)."""
    return float(r["trad_mean_pixels"]) < 0.9 * float(r["mean_pixels"])


def winner_ranges(rs, units):
    """'A up to x px, B from y to z px, ...' over sweep rows sorted by box area."""
    seq = []
    for r in rs:
        wn = tied({u: float(r[u]) for u in units})
        if seq and seq[-1][0] == wn:
            seq[-1][2] = float(r["mean_box"])
        else:
            seq.append([wn, float(r["mean_box"]), float(r["mean_box"])])
    parts = []
    for i, (wn, lo, hi) in enumerate(seq):
        if len(seq) == 1:
            parts.append(f"{wn} at every size")
        elif i == 0:
            parts.append(f"{wn} up to {hi:,.0f} px")
        elif i == len(seq) - 1:
            parts.append(f"{wn} from {lo:,.0f} px")
        else:
            parts.append(f"{wn} {lo:,.0f}" + (f"-{hi:,.0f}" if hi != lo else "") + " px")
    return ", ".join(parts)


def bin_ranges(changes, last):
    """'A up to a px, B b-c px, C from d px' from the winner changes between box-area bins."""
    if not changes:
        return f"{LABEL[last]} at every size"
    parts = [f"{LABEL[changes[0][2]]} up to {bin_label(changes[0][0]).split('-')[-1]} px"]
    for i, (k0, k1, a0, b0) in enumerate(changes):
        lo = bin_label(k1).split("-")[0]
        if i + 1 < len(changes):
            hi = bin_label(changes[i + 1][0]).split("-")[-1]
            parts.append(f"{LABEL[b0]} {lo}-{hi} px")
        else:
            parts.append(f"{LABEL[b0]} from {lo} px")
    return ", ".join(parts)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--synth", default=os.path.join(ROOT, "docs/synth.csv"))
    ap.add_argument("--doc", required=True)
    ap.add_argument("--img", required=True)
    ap.add_argument("--command", default="scripts/which_unit_wins.sh")
    a = ap.parse_args()
    os.makedirs(a.img, exist_ok=True)
    img_rel = os.path.relpath(a.img, os.path.dirname(os.path.abspath(a.doc)))
    scenes = read_csv(os.path.join(a.data, "scenes.csv"))
    sweep = read_csv(os.path.join(a.data, "sweep.csv"))
    area = areas(a.synth)
    L = []
    w = L.append
    w("# Which unit wins where: improved, traditional and half-space")
    w("")
    w(f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by `{a.command}` "
      "(tools/unit_compare.cpp runs the timed SystemC models, scripts/which_unit_wins.py writes this "
      "page and the plots in "
      f"[{img_rel}]({img_rel})). The cycles are the SystemC models' (`improved-sc`, `trad-sc`, "
      "`halfspace-sc`; equal to the RTL's for every triangle, which the test suite checks) at the "
      "CLI defaults: 1024x768, S = 8, coordinates 16 bits, box 14 bits, N = 1, FIFO 8, sink always "
      "ready; the half-space unit with tile 8 and the zig-zag walk at stamp sizes 1, 2 and 4 (S1, "
      "S2, S4). The areas are the default configuration's rows of [synth.csv](synth.csv) "
      "(scripts/synth.sh; [synth.md](synth.md) names the command and run behind each row).")
    w("")
    w("Scenes: those of [cycles-improved-vs-trad.md](cycles-improved-vs-trad.md) (the five "
      "benchmark scenes, the built-in sphere, torus and surface meshes, tests/data/cube.obj) and "
      "the meshes of Debian's assimp-testmodels that scripts/which_unit_wins.sh passes "
      "(/usr/share/assimp/models/OBJ/WusonOBJ.obj and spider.obj), each through the default mesh "
      "camera.")
    w("")
    w("A scene's totals are what `trirast raster --engine E --scene SCENE --cycles FILE.csv` "
      "reports for it (1 + the largest `done_cycle`), E = `improved-sc`, `trad-sc` or "
      "`halfspace-sc --stamp S` (`model` and `trad` in trees before the engine names "
      "`<unit>-<view>`); the tool calls the same SystemC models directly.")
    w("")
    w("Per triangle, a unit's cycles are what the triangle adds to the scene's total: its done "
      "cycle minus the latest done cycle of the triangles completed before it (so a scene's "
      "per-triangle cycles sum to its total, and a triangle whose set-up overlapped the previous "
      "walk is charged only what it adds).")
    w("")
    summary_at = len(L)
    # ---- areas ----
    w("## Areas (default configuration)")
    w("")
    w("| unit | Xilinx 7 LUTs | Xilinx 7 FFs | DSP48 | iCE40 LUT4 | iCE40 FFs |")
    w("|---|---:|---:|---:|---:|---:|")
    for u in UNITS:
        x = area[u].get("xilinx7")
        i = area[u].get("ice40")
        w(f"| {LABEL[u]} | {x[0] if x else '-'} | {x[1] if x else '-'} | {x[2] if x else '-'} | "
          f"{i[0] if i else '-'} | {i[1] if i else '-'} |")
    w("")
    missing = [LABEL[u] for u in UNITS if "xilinx7" not in area[u]]
    if missing:
        w(f"No default-configuration row in synth.csv for: {', '.join(missing)} (a dash; their "
          "cycles x area are left out).")
        w("")
    # ---- per scene totals ----
    w("## Per scene: total cycles, winner, cycles x area")
    w("")
    w("Fewest cycles in **bold**. \"cycles x LUTs\" multiplies a unit's total cycles by its Xilinx 7 "
      "LUTs (millions; the DSP48 slices of the area table are not counted); its winner is the unit "
      "with the least work per unit of area.")
    w("")
    w("| scene | triangles | " + " | ".join(LABEL[u] for u in UNITS) +
      " | fewest cycles | fewest cycles x LUTs | " +
      " | ".join(f"{LABEL[u]} cycles x LUTs (M)" for u in UNITS) + " |")
    w("|---|---:|" + "---:|" * len(UNITS) + "---|---|" + "---:|" * len(UNITS))
    tot = {u: 0 for u in UNITS}
    for s in scenes:
        c = {u: int(s[u]) for u in UNITS}
        for u in UNITS:
            tot[u] += c[u]
        win = winner(c)
        cxa = {u: c[u] * area[u]["xilinx7"][0] for u in UNITS if "xilinx7" in area[u]}
        wa = LABEL[winner(cxa)] if cxa else "-"
        cells = [f"**{c[u]:,}**" if u == win else f"{c[u]:,}" for u in UNITS]
        cx = [f"{cxa[u] / 1e6:,.1f}" if u in cxa else "-" for u in UNITS]
        w(f"| {s['label']} | {int(s['triangles']):,} | " + " | ".join(cells) +
          f" | {LABEL[win]} | {wa} | " + " | ".join(cx) + " |")
    win = winner(tot)
    cxa = {u: tot[u] * area[u]["xilinx7"][0] for u in UNITS if "xilinx7" in area[u]}
    w("| **all** | | " + " | ".join(f"**{tot[u]:,}**" if u == win else f"{tot[u]:,}" for u in UNITS)
      + f" | {LABEL[win]} | {LABEL[winner(cxa)] if cxa else '-'} | "
      + " | ".join(f"{cxa[u] / 1e6:,.1f}" if u in cxa else "-" for u in UNITS) + " |")
    w("")
    # ---- sweep crossover ----
    sweep_png = os.path.join(a.img, "sweep.png")
    sweep_plot(sweep, sweep_png)
    w("## The crossover: cycles per triangle against box size and aspect ratio")
    w("")
    w("Scenes of equal-shaped triangles (tools/unit_compare.cpp `shaped`: each triangle spans its "
      "box, one vertex on three of its sides, mirrored four ways, at random positions and "
      "sub-pixel offsets; 16 to 1,024 triangles a scene), one scene per box area (powers of 2 "
      "from 1 to 65,536 pixels) and aspect ratio w/h (1/16 to 16); cycles per triangle = total "
      "cycles / triangles. The triangle covers about 43% of its box.")
    w("")
    w(f"![cycles per triangle against box area]({img_rel}/sweep.png)")
    w("")
    aspects = sorted({float(r["aspect"]) for r in sweep})
    exact = [u for u in UNITS if u != "trad"]
    w("Who wins, by box area (the mean box of the sweep point where the winner starts or stops), "
      "among all units and among the exact ones (the traditional unit draws its own pixels, "
      "not the coverage rule's, docs/timing.md):")
    w("")
    w("| aspect w/h | fewest cycles (all units) | fewest cycles (exact units) |")
    w("|---:|---|---|")
    for x in aspects:
        rs = sorted([r for r in sweep if float(r["aspect"]) == x], key=lambda r: float(r["mean_box"]))
        w(f"| {x:g} | {winner_ranges(rs, UNITS)} | {winner_ranges(rs, exact)} |")
    w("")
    w("Where the traditional unit draws under 90% of the rule's pixels (thin slivers: it rounds "
      "the vertices to whole pixels and then often draws nothing) its cycles are for less work; "
      "the table below marks those points with the share it drew.")
    w("")
    w("Winner (fewest cycles per triangle) at each box area; the cycles of the winner and of the "
      "runner-up in brackets, the box in square brackets:")
    w("")
    w("| box area | " + " | ".join(f"w/h = {x:g}" for x in aspects) + " |")
    w("|---:|" + "---|" * len(aspects))
    by_area = sorted({float(r["box_area"]) for r in sweep})
    for ar in by_area:
        cells = []
        for x in aspects:
            r = [r for r in sweep if float(r["aspect"]) == x and float(r["box_area"]) == ar]
            if not r:
                cells.append("")
                continue
            r = r[0]
            c = {u: float(r[u]) for u in UNITS}
            order = sorted(UNITS, key=lambda u: c[u])
            note = ""
            if "trad" in order[:2] and trad_short(r):
                note = (f" (trad. draws {100 * float(r['trad_mean_pixels']) / float(r['mean_pixels']):.0f}%"
                        " of the pixels)")
            cells.append(f"{LABEL[order[0]]} ({fmt(c[order[0]])}; {LABEL[order[1]]} "
                         f"{fmt(c[order[1]])}) [{r['box_w']}x{r['box_h']}]{note}")
        w(f"| {ar:,.0f} | " + " | ".join(cells) + " |")
    w("")
    w("Crossovers of pairs: the box area (log-interpolated between the two sweep points around "
      "it, whose mean boxes are given) where one unit stops needing fewer cycles than the other, "
      "and the unit that needs fewer above it.")
    w("")
    w("| aspect w/h | pair | crossover box area (pixels) | between | winner above |")
    w("|---:|---|---:|---|---|")
    pairs = [("improved", "trad"), ("improved", "hs1"), ("improved", "hs2"), ("improved", "hs4"),
             ("trad", "hs4"), ("hs2", "hs4")]
    for x in aspects:
        rs = sorted([r for r in sweep if float(r["aspect"]) == x], key=lambda r: float(r["box_area"]))
        for p, q in pairs:
            cs = crossings(rs, p, q)
            if not cs:
                w(f"| {x:g} | {LABEL[p]} vs {LABEL[q]} | none | | {no_crossing(rs, p, q)} |")
            for at, lo, hi, up in cs:
                w(f"| {x:g} | {LABEL[p]} vs {LABEL[q]} | **{at:,.0f}** | {lo:,.0f} .. {hi:,.0f} | "
                  f"{LABEL[up]} |")
    w("")
    # ---- pooled scene bins ----
    w("## The crossover in the scenes: cycles per triangle by box area")
    w("")
    w("All triangles of all scenes below, binned by box area (powers of 2); per bin the mean "
      "cycles a triangle adds for each unit, and the winner. Scene triangles mix shapes, and their "
      "cycles depend on their neighbours (a set-up hidden behind the previous walk costs nothing), "
      "so these crossovers are where the winner changes in practice.")
    w("")
    allrows = []
    per_scene = {}
    for s in scenes:
        rows = read_csv(os.path.join(a.data, f"tris-{s['scene']}.csv"))
        per_scene[s["scene"]] = rows
        allrows += rows
    bins = {}
    for r in allrows:
        k = log2bin(int(r["box_w"]) * int(r["box_h"]))
        bins.setdefault(k, []).append(r)
    w("| box area | triangles | " + " | ".join(LABEL[u] for u in UNITS) +
      " | winner | winner, exact units | winner by cycles x LUTs | ... exact units |")
    w("|---:|---:|" + "---:|" * len(UNITS) + "---|---|---|---|")
    prev = None
    changes = []
    prev_e = None
    changes_e = []  # among the exact units
    prev_x = None
    changes_x = []  # the same by cycles x LUTs
    prev_xe = None
    changes_xe = []  # ... among the exact units
    for k in sorted(bins):
        rs = bins[k]
        m = {u: sum(int(r[u]) for r in rs) / len(rs) for u in UNITS}
        win = winner(m)
        if k >= 0 and len(rs) >= 20:  # the empty boxes (k < 0) are not a size
            if prev is not None and win != prev[1]:
                changes.append((prev[0], k, prev[1], win))
            prev = (k, win)
            we = winner({u: m[u] for u in exact})
            if prev_e is not None and we != prev_e[1]:
                changes_e.append((prev_e[0], k, prev_e[1], we))
            prev_e = (k, we)
        mx = {u: m[u] * area[u]["xilinx7"][0] for u in UNITS if "xilinx7" in area[u]}
        if mx and k >= 0 and len(rs) >= 20:
            wx = winner(mx)
            if prev_x is not None and wx != prev_x[1]:
                changes_x.append((prev_x[0], k, prev_x[1], wx))
            prev_x = (k, wx)
            wxe = winner({u: v for u, v in mx.items() if u != "trad"})
            if prev_xe is not None and wxe != prev_xe[1]:
                changes_xe.append((prev_xe[0], k, prev_xe[1], wxe))
            prev_xe = (k, wxe)
        w(f"| {bin_label(k) if k >= 0 else '0 (empty box)'} | {len(rs):,} | " +
          " | ".join(f"**{fmt(m[u])}**" if u == win else fmt(m[u]) for u in UNITS) +
          f" | {LABEL[win]} | {LABEL[winner({u: m[u] for u in exact})]} | "
          f"{LABEL[winner(mx)] if mx else '-'} | "
          f"{LABEL[winner({u: v for u, v in mx.items() if u != 'trad'})] if len(mx) > 1 else '-'} |")
    w("")
    if changes:
        w(f"Winners over the bins with at least 20 triangles: {bin_ranges(changes, prev[1])}; "
          f"among the exact units: {bin_ranges(changes_e, prev_e[1])}. (Box area 0: the box is empty, the triangle "
            "off-screen; the traditional unit still walks its rows.)")
        w("")
    # ---- per scene ----
    w("## Per scene: triangle sizes, box shapes and cycles")
    w("")
    w("Left: histogram of the triangles' box areas and covered pixels (bins of powers of 2, "
      "log scale; \"0\": an empty box, no pixel). Middle: histogram of the box aspect ratio w/h "
      "(non-empty boxes). Right: mean cycles a triangle adds, per unit, by box-area bin (log "
      "scale).")
    w("")
    for s in scenes:
        rows = per_scene[s["scene"]]
        if not rows:
            continue
        png = f"scene-{s['scene']}.png"
        scene_plot(s["label"], rows, os.path.join(a.img, png))
        box = sorted(int(r["box_w"]) * int(r["box_h"]) for r in rows)
        pix = sorted(int(r["pixels"]) for r in rows)
        c = {u: int(s[u]) for u in UNITS}
        w(f"### {s['label']} (`{os.path.relpath(s['spec'], ROOT) if s['spec'].startswith('/') and s['spec'].startswith(ROOT) else s['spec']}`)")
        w("")
        w(f"{len(rows):,} triangles; median box area {box[len(box) // 2]:,} px, median covered "
          f"pixels {pix[len(pix) // 2]:,}; total cycles " +
          ", ".join(f"{LABEL[u]} {c[u]:,}" for u in UNITS) + f": **{LABEL[winner(c)]}** wins.")
        w("")
        w(f"![{s['label']}]({img_rel}/{png})")
        w("")
    # ---- the summary, at the top ----
    order = sorted(UNITS, key=lambda u: tot[u])
    cx_all = {u: tot[u] * area[u]["xilinx7"][0] for u in UNITS if "xilinx7" in area[u]}
    sq = sorted([r for r in sweep if float(r["aspect"]) == 1.0], key=lambda r: float(r["mean_box"]))
    S = ["## In short", ""]
    S.append("- **Cycles, all scenes together**: " + ", ".join(
        f"{LABEL[u]} {tot[u]:,}" for u in order) + "; per scene the winner is in the table below.")
    if cx_all:
        S.append("- **Cycles x Xilinx 7 LUTs, all scenes together**: " + ", ".join(
            f"{LABEL[u]} {cx_all[u] / 1e9:,.2f} G" for u in sorted(cx_all, key=lambda u: cx_all[u]))
            + (f" (no area yet for {', '.join(missing)})" if missing else "") + ".")
    if sq:
        S.append("- **Square boxes (sweep, w/h = 1)**, fewest cycles per triangle: "
                 f"{winner_ranges(sq, UNITS)}; among the exact units: {winner_ranges(sq, exact)}.")
    if changes:
        S.append("- **The scenes' triangles binned by box area** (at least 20 a bin), fewest "
                 f"cycles: {bin_ranges(changes, prev[1])}; among the exact units: "
                 f"{bin_ranges(changes_e, prev_e[1])}.")
    if cx_all:
        S.append("- **The same bins by cycles x Xilinx 7 LUTs**: "
                 f"{bin_ranges(changes_x, prev_x[1])}; among the exact units: "
                 f"{bin_ranges(changes_xe, prev_xe[1])}.")
    S.append("- The traditional unit is not exact (docs/timing.md: it walks whole-pixel vertices and "
             "draws its own coverage, not the rule's), so its cycles are not always for the same "
             "pixels; hence the rankings among the exact units beside each.")
    S.append("- Why: the improved unit walks a row per cycle but sets up with divisions (at least "
             f"{min(float(r['improved']) for r in sweep):.1f} cycles per triangle in the sweep); the "
             "traditional unit sets up in 3 cycles and steps every pixel of its x-major edges; the "
             "half-space unit sets up in 2 cycles and then pays per tile and per stamp of its box, "
             "so its cycles grow with the box area (over the stamp's S x S), the Bresenham units' "
             "with the rows (and the traditional one's with the width too).")
    S.append("")
    L[summary_at:summary_at] = S
    with open(a.doc, "w") as f:
        f.write("\n".join(L))
    print(f"which_unit_wins.py: wrote {a.doc} and {a.img}")


if __name__ == "__main__":
    main()
