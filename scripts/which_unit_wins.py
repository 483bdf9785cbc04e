#!/usr/bin/python3
"""docs/which-unit-wins.md and its plots from a run of build/trirast_unit_compare.

    /usr/bin/python3 scripts/which_unit_wins.py --data DIR --synth docs/synth.csv \
        --doc docs/which-unit-wins.md --img docs/img/which-unit-wins --command "..."

Reads DIR/scenes.csv, DIR/tris-*.csv and DIR/sweep.csv (tools/unit_compare.cpp says what they
hold) and the areas and routed clocks of docs/synth.csv; every number in the document comes from
those files. Time is cycles at each unit's routed iCE40 clock: the fmax_mhz of its default
configuration's `ice40` row (the rule of `trirast compare`'s time column, AreaModel::csv_fmax_mhz);
a unit without one has no time (n/a), never an assumed clock. scripts/which_unit_wins.sh runs the
whole chain (the one command); tests/which_unit_wins_test.py checks this script on synthetic data.
"""
import argparse
import csv
import math
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNITS = ["improved", "improved2", "improved2p", "trad", "hs1", "hs2", "hs4", "hsr1", "hsr2", "hsr4"]
LABEL = {"improved": "improved", "improved2": "improved2 radix-16",
         "improved2p": "improved2 products", "trad": "traditional", "hs1": "half-space S1",
         "hs2": "half-space S2", "hs4": "half-space S4", "hsr1": "half-space radix-16 S1",
         "hsr2": "half-space radix-16 S2", "hsr4": "half-space radix-16 S4"}
SYNTH_UNIT = {"improved": "improved", "improved2": "improved2", "improved2p": "improved2-products",
              "trad": "trad", "hs1": "halfspace-s1", "hs2": "halfspace-s2", "hs4": "halfspace-s4",
              "hsr1": "halfspace-radix16-s1", "hsr2": "halfspace-radix16-s2",
              "hsr4": "halfspace-radix16-s4"}
COLOR = {"improved": "tab:blue", "improved2": "tab:purple", "improved2p": "tab:cyan",
         "trad": "tab:orange", "hs1": "tab:olive", "hs2": "tab:green", "hs4": "tab:red",
         "hsr1": "tab:brown", "hsr2": "tab:pink", "hsr4": "tab:gray"}
EXACT = [u for u in UNITS if u != "trad"]  # the traditional unit draws its own pixels
NA = "n/a[^noclock]"
MIN_BIN = 20  # bins with fewer triangles are shown but do not decide the winners' ranges
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def synth_rows(path):
    """{unit: {"xilinx7": (luts, ffs, dsp, bram), "ice40": (...), "fmax": MHz or None,
    "fmax_row": the synth.csv row it comes from}} of the default configuration."""
    out = {u: {"fmax": None, "fmax_row": None} for u in UNITS}
    if not os.path.exists(path):
        return out
    for r in read_csv(path):
        for u in UNITS:
            if r["unit"] != SYNTH_UNIT[u] or r["config"] != "default" or not r["luts"]:
                continue
            out[u][r["target"]] = (int(r["luts"]), int(r["ffs"] or 0), int(r["dsp"] or 0),
                                   int(r["bram"] or 0))
            # The routed clock: the ice40 row's fmax_mhz (empty when it was not placed and routed).
            if r["target"] == "ice40" and r.get("fmax_mhz", "").strip():
                out[u]["fmax"] = float(r["fmax_mhz"])
                out[u]["fmax_row"] = ",".join(r[k] for k in ("unit", "config", "target"))
    return out


class Cost:
    """n triangles that take c cycles on unit u, in cycles, time and per area."""

    def __init__(self, u, n, c, synth):
        s = synth[u]
        f = s["fmax"]
        x, i = s.get("xilinx7"), s.get("ice40")
        self.n, self.c = n, c
        self.cpt = c / n
        # Time at the routed clock: c cycles / (f MHz) = 1000 c / f ns.
        self.ns = 1000.0 * c / (f * n) if f else None
        self.tps = n * f * 1e6 / c if f and c else None  # triangles per second
        self.tps_x = self.tps / (x[0] / 1000) if self.tps and x else None
        self.tps_i = self.tps / (i[0] / 1000) if self.tps and i else None
        # Without a clock: triangles per 1,000 cycles per 1,000 LUTs.
        self.tkc_x = n * 1e6 / (c * x[0]) if c and x else None
        self.tkc_i = n * 1e6 / (c * i[0]) if c and i else None


# metric: (attribute, higher is better, column title, formatter)
METRICS = {
    "cycles": ("c", False, "cycles", lambda v: f"{v:,}"),
    "cpt": ("cpt", False, "cycles / triangle", lambda v: fmt(v)),
    "ns": ("ns", False, "ns / triangle", lambda v: f"{v:,.1f}"),
    "tps": ("tps", True, "M triangles/s", lambda v: f"{v / 1e6:,.3f}"),
    "tps_x": ("tps_x", True, "k triangles/s per 1,000 xc7 LUTs", lambda v: f"{v / 1e3:,.1f}"),
    "tps_i": ("tps_i", True, "k triangles/s per 1,000 iCE40 cells", lambda v: f"{v / 1e3:,.1f}"),
    "tkc_x": ("tkc_x", True, "triangles / 1,000 cycles / 1,000 xc7 LUTs", lambda v: f"{v:,.2f}"),
    "tkc_i": ("tkc_i", True, "triangles / 1,000 cycles / 1,000 iCE40 cells", lambda v: f"{v:,.2f}"),
}
TIMED = {"ns", "tps", "tps_x", "tps_i"}


def value(cost, metric):
    return getattr(cost, METRICS[metric][0])


def cell(cost, metric, best=None):
    v = value(cost, metric)
    if v is None:
        return NA if metric in TIMED else "-"
    s = METRICS[metric][3](v)
    return f"**{s}**" if best is not None and v == best else s


def best_value(costs, metric):
    vs = [value(c, metric) for c in costs.values() if value(c, metric) is not None]
    if not vs:
        return None
    return max(vs) if METRICS[metric][1] else min(vs)


def leaders(costs, metric):
    """The units with the best value of metric (ties all), [] when none has one."""
    b = best_value(costs, metric)
    return [u for u in costs if b is not None and value(costs[u], metric) == b]


def lead_label(costs, metric):
    ls = leaders(costs, metric)
    return " = ".join(LABEL[u] for u in ls) if ls else "-"


def lead_cell(costs, metric):
    """'winner (value; runner-up value)'."""
    ls = leaders(costs, metric)
    if not ls:
        return "-"
    higher = METRICS[metric][1]
    rest = sorted([u for u in costs if u not in ls and value(costs[u], metric) is not None],
                  key=lambda u: value(costs[u], metric), reverse=higher)
    s = f"{' = '.join(LABEL[u] for u in ls)} ({cell(costs[ls[0]], metric)}"
    if rest:
        s += f"; {LABEL[rest[0]]} {cell(costs[rest[0]], metric)}"
    return s + ")"


def log2bin(v):
    return int(math.floor(math.log2(v))) if v >= 1 else -1


def bin_label(k):
    if k < 0:
        return "0"
    lo, hi = 2 ** k, 2 ** (k + 1) - 1
    return f"{lo}" if lo == hi else f"{lo}-{hi}"


def fmt(v):
    return f"{v:,.0f}" if v >= 100 else f"{v:.1f}"


def pow2_ticks(axis, xs):
    axis.set_xticks(xs)
    axis.set_xticklabels(["0" if x < 0 else f"2^{x}" for x in xs], rotation=90, fontsize=7)


def scene_plot(label, rows, synth, path):
    """Four panels: box area and pixel histograms, aspect histogram, cycles and ns per triangle
    by box-area bin."""
    fig, ax = plt.subplots(1, 4, figsize=(19, 3.8))
    box = [int(r["box_w"]) * int(r["box_h"]) for r in rows]
    pix = [int(r["pixels"]) for r in rows]
    kb = [log2bin(b) for b in box]
    kp = [log2bin(p) for p in pix]
    xs = list(range(min(kb + kp), max(kb + kp) + 1))
    ax[0].bar([x - 0.2 for x in xs], [kb.count(x) for x in xs], width=0.4, label="box area")
    ax[0].bar([x + 0.2 for x in xs], [kp.count(x) for x in xs], width=0.4, label="covered pixels")
    pow2_ticks(ax[0], xs)
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
    xb = sorted(set(kb))
    for u in UNITS:
        cs = [Cost(u, sum(1 for k in kb if k == x),
                   sum(int(r[u]) for r, k in zip(rows, kb) if k == x), synth) for x in xb]
        ax[2].plot(xb, [c.cpt for c in cs], marker="o", ms=3, color=COLOR[u], label=LABEL[u])
        if synth[u]["fmax"]:
            ax[3].plot(xb, [c.ns for c in cs], marker="o", ms=3, color=COLOR[u],
                       label=f"{LABEL[u]} @ {synth[u]['fmax']:g} MHz")
    for axis, title in ((ax[2], "cycles per triangle by box area"),
                        (ax[3], "ns per triangle at the routed clock")):
        axis.set_yscale("log")
        pow2_ticks(axis, xb)
        axis.set_title(title)
        axis.set_xlabel("box area (pixels)")
        axis.legend(fontsize=7)
    fig.suptitle(label)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def sweep_cost(r, u, synth):
    return Cost(u, int(r["triangles"]), int(r[u]), synth)


def sweep_plot(sweep, synth, path):
    aspects = sorted({float(r["aspect"]) for r in sweep})
    panels = [("cpt", "cycles per triangle"), ("ns", "ns per triangle (routed clock)"),
              ("tps_i", "k triangles/s per 1,000 iCE40 cells"),
              ("tkc_x", "triangles / 1,000 cycles / 1,000 xc7 LUTs")]
    fig, ax = plt.subplots(len(panels), len(aspects), figsize=(4 * len(aspects), 3.6 * len(panels)),
                           sharey="row", squeeze=False)
    for j, a in enumerate(aspects):
        rs = sorted([r for r in sweep if float(r["aspect"]) == a], key=lambda r: float(r["mean_box"]))
        for i, (m, title) in enumerate(panels):
            axis = ax[i][j]
            for u in UNITS:
                vs = [value(sweep_cost(r, u, synth), m) for r in rs]
                if any(v is None for v in vs):
                    continue
                scale = 1e-3 if m == "tps_i" else 1
                axis.plot([float(r["mean_box"]) for r in rs], [v * scale for v in vs], marker="o",
                          ms=3, color=COLOR[u], label=LABEL[u])
            axis.set_xscale("log", base=2)
            axis.set_yscale("log", base=2)
            axis.grid(True, which="major", alpha=0.3)
            if i == 0:
                axis.set_title(f"aspect w/h = {a:g}")
            if i == len(panels) - 1:
                axis.set_xlabel("box area (pixels)")
            if j == 0:
                axis.set_ylabel(title)
                axis.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def crossings(rs, a, b, f):
    """Box areas where sign(f(a) - f(b)) changes between consecutive sweep points (points where
    the two are equal are skipped), with the unit that is lower above it."""
    pts = [r for r in rs if f(r, a) != f(r, b)]
    out = []
    for r0, r1 in zip(pts, pts[1:]):
        d0 = f(r0, a) - f(r0, b)
        d1 = f(r1, a) - f(r1, b)
        if (d0 < 0) != (d1 < 0):
            # log-linear interpolation of the zero of the difference
            x0, x1 = math.log2(float(r0["mean_box"])), math.log2(float(r1["mean_box"]))
            x = x0 + (x1 - x0) * d0 / (d0 - d1)
            out.append((2 ** x, float(r0["mean_box"]), float(r1["mean_box"]), a if d1 < 0 else b))
    return out


def no_crossing(rs, a, b, f):
    """The phrase for a pair without a crossover: who is lower at every size."""
    d = [f(r, a) - f(r, b) for r in rs]
    if all(v == 0 for v in d):
        return "equal at every size"
    lead = a if all(v <= 0 for v in d) else b
    return f"{LABEL[lead]} at every size" + (" (equal at some)" if any(v == 0 for v in d) else "")


def trad_short(r):
    """The traditional unit draws under 90% of the rule's pixels in this sweep row (inexact)."""
    return float(r["trad_mean_pixels"]) < 0.9 * float(r["mean_pixels"])


def ranges(seq):
    """'A up to x px, B from y to z px, ...' from [(label, size)] in size order."""
    runs = []
    for wn, size in seq:
        if runs and runs[-1][0] == wn:
            runs[-1][2] = size
        else:
            runs.append([wn, size, size])
    parts = []
    for i, (wn, lo, hi) in enumerate(runs):
        if len(runs) == 1:
            parts.append(f"{wn} at every size")
        elif i == 0:
            parts.append(f"{wn} up to {hi} px")
        elif i == len(runs) - 1:
            parts.append(f"{wn} from {lo} px")
        else:
            parts.append(f"{wn} {lo}" + (f"-{hi}" if hi != lo else "") + " px")
    return ", ".join(parts)


def sweep_ranges(rs, units, metric, synth):
    """Who is best at metric along sweep rows sorted by box area (the mean box of each row)."""
    seq = []
    for r in rs:
        costs = {u: sweep_cost(r, u, synth) for u in units}
        seq.append((lead_label(costs, metric), f"{float(r['mean_box']):,.0f}"))
    return ranges(seq)


def bin_ranges(bins, units, metric, synth):
    """Who is best at metric over the box-area bins with at least MIN_BIN triangles (the empty
    boxes are not a size), the bins' bounds as sizes."""
    seq = []
    for k in sorted(bins):
        if k < 0 or len(bins[k]) < MIN_BIN:
            continue
        costs = bin_costs(bins[k], units, synth)
        seq.append((lead_label(costs, metric), (bin_label(k).split("-")[0],
                                                  bin_label(k).split("-")[-1])))
    runs = []
    for wn, (lo, hi) in seq:
        if runs and runs[-1][0] == wn:
            runs[-1][2] = hi
        else:
            runs.append([wn, lo, hi])
    if not runs:
        return "-"
    if len(runs) == 1:
        return f"{runs[0][0]} at every size"
    parts = [f"{runs[0][0]} up to {runs[0][2]} px"]
    for wn, lo, hi in runs[1:-1]:
        parts.append(f"{wn} {lo}-{hi} px" if lo != hi else f"{wn} {lo} px")
    parts.append(f"{runs[-1][0]} from {runs[-1][1]} px")
    return ", ".join(parts)


def bin_costs(rows, units, synth):
    return {u: Cost(u, len(rows), sum(int(r[u]) for r in rows), synth) for u in units}


LONG_METRICS = ["cycles", "cpt", "ns", "tps", "tps_x", "tps_i", "tkc_x", "tkc_i"]


def long_table(w, first_title, groups, break_even=False):
    """Rows (group, unit): every metric, the best of each group in bold; units in time order
    (those with a clock first), then by cycles. break_even: a last column, the clock at which
    the unit's cycles would take the fastest unit's time (1,000 x cycles / (triangles x ns))."""
    w(f"| {first_title} | unit | " + " | ".join(METRICS[m][2] for m in LONG_METRICS) +
      (" | break-even clock (MHz) |" if break_even else " |"))
    w("|---|---|" + "---:|" * (len(LONG_METRICS) + break_even))
    for name, costs in groups:
        best = {m: best_value(costs, m) for m in LONG_METRICS}
        order = sorted(costs, key=lambda u: (costs[u].ns is None, costs[u].ns or 0, costs[u].c))
        for i, u in enumerate(order):
            be = ""
            if break_even:
                c = costs[u]
                be = f" {1000 * c.c / (c.n * best['ns']):,.2f} |" if best["ns"] else " - |"
            w(f"| {name if i == 0 else ''} | {LABEL[u]} | " +
              " | ".join(cell(costs[u], m, best[m]) for m in LONG_METRICS) + " |" + be)


SUMMARY_COLS = [("ns", UNITS, "fastest (ns / triangle)"),
                ("cpt", UNITS, "fewest cycles / triangle"),
                ("cpt", EXACT, "fewest cycles / triangle, exact units"),
                ("tps_x", UNITS, "most triangles/s per 1,000 xc7 LUTs (k)"),
                ("tps_i", UNITS, "most triangles/s per 1,000 iCE40 cells (k)"),
                ("tkc_x", UNITS, "most triangles / 1,000 cycles / 1,000 xc7 LUTs"),
                ("tkc_i", UNITS, "most triangles / 1,000 cycles / 1,000 iCE40 cells")]


def summary_table(w, first_title, groups):
    w(f"| {first_title} | triangles | " + " | ".join(t for _, _, t in SUMMARY_COLS) + " |")
    w("|---|---:|" + "---|" * len(SUMMARY_COLS))
    for name, costs in groups:
        n = next(iter(costs.values())).n
        w(f"| {name} | {n:,} | " + " | ".join(
            lead_cell({u: costs[u] for u in us}, m) for m, us, _ in SUMMARY_COLS) + " |")


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
    synth = synth_rows(a.synth)
    clocked = [u for u in UNITS if synth[u]["fmax"]]
    unclocked = [u for u in UNITS if not synth[u]["fmax"]]
    L = []
    w = L.append
    w("# Which unit wins where, in time and per area: every unit")
    w("")
    w(f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by `{a.command}` "
      "(tools/unit_compare.cpp runs the timed SystemC models, scripts/which_unit_wins.py writes this "
      f"page and the plots in [{img_rel}]({img_rel})). The units: the improved unit, the "
      "second-generation improved unit in both corner forms (radix-16: digit-serial corners, the "
      "iCE40 form and the default, `--corner-form radix16`; products: DSP products, the xc7 form, "
      "`--corner-form dsp`), the traditional unit and the half-space unit at stamp sizes 1, 2 and "
      "4 (S1, S2, S4; tile 8, forward walk) in both of its corner forms (products, the default and "
      "the xc7 form, `--hs-corner-form dsp`; radix-16, the iCE40 form, `--hs-corner-form "
      "radix16`). The cycles are the SystemC models' (`improved-sc`, "
      "`improved2-sc`, `trad-sc`, `halfspace-sc`; equal to the RTL's for every triangle, which the "
      "test suite checks) at the CLI defaults: 1024x768, S = 8, coordinates 16 bits, box 14 bits, "
      "N = 1, FIFO 8, sink always ready.")
    w("")
    w("**Time.** A unit's time is its exact cycle count at its routed clock: ns = 1,000 x cycles / "
      "Fmax (MHz), triangles/s = triangles x Fmax x 10^6 / cycles, exact conversions of exact cycle "
      "counts and the synth.csv Fmax, rounded only for display. The Fmax is the `fmax_mhz` of the "
      "unit's default-configuration `ice40` row of [synth.csv](synth.csv) (nextpnr on the iCE40 "
      "HX8K, scripts/synth.sh; the rule `trirast compare` uses for its `us@Fmax` column). A unit "
      "whose row has no `fmax_mhz` has no time: its time columns say n/a, no clock is assumed. "
      "synth.csv holds no routed xc7 clock, so the xc7 per-area column divides the same "
      "iCE40-clocked triangles/s by the unit's xc7 LUTs. **Area**: the `luts` of the default "
      "configuration's `xilinx7` row (xc7 LUTs, the fewer of Yosys's two LUT mappers, ABC and "
      "ABC9, every unit the same way: the row's `xc7_mapper`; its DSP48 slices and block RAMs "
      "are not counted) "
      "and of its `ice40` row (iCE40 cells: LUT4s). The clock-free per-area columns, triangles "
      "per 1,000 cycles per 1,000 LUTs, cover every unit.")
    w("")
    w("Scenes: those of [cycles-improved-vs-trad.md](cycles-improved-vs-trad.md) (the five "
      "benchmark scenes, the built-in sphere, torus and surface meshes, tests/data/cube.obj) and "
      "the meshes of Debian's assimp-testmodels that scripts/which_unit_wins.sh passes "
      "(/usr/share/assimp/models/OBJ/WusonOBJ.obj and spider.obj), each through the default mesh "
      "camera. A scene's totals are what `trirast raster --engine E --scene SCENE --cycles "
      "FILE.csv` reports for it (1 + the largest `done_cycle`), E = `improved-sc`, "
      "`improved2-sc [--corner-form dsp]`, `trad-sc` or `halfspace-sc --stamp S "
      "[--hs-corner-form radix16]`; the tool calls "
      "the same SystemC models directly. Per triangle, a unit's cycles are what the triangle adds "
      "to the scene's total: its done cycle minus the latest done cycle of the triangles "
      "completed before it (so a scene's per-triangle cycles sum to its total).")
    w("")
    summary_at = len(L)

    # ---- units: areas and clocks ----
    w("## The units: areas and clocks (default configuration)")
    w("")
    w("| unit | synth.csv unit | xc7 LUTs | xc7 FFs | DSP48 | xc7 BRAM | iCE40 cells (LUT4) | "
      "iCE40 FFs | iCE40 BRAM | routed Fmax (MHz) | Fmax source |")
    w("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for u in UNITS:
        x, i = synth[u].get("xilinx7"), synth[u].get("ice40")
        f = synth[u]["fmax"]
        src = (f"synth.csv row `{synth[u]['fmax_row']}`, fmax_mhz {f:.2f}" if f else
               f"none[^noclock]")
        xs = [f"{v:,}" for v in x] if x else ["-"] * 4
        is_ = [f"{v:,}" for k, v in enumerate(i) if k != 2] if i else ["-"] * 3
        w(f"| {LABEL[u]} | `{SYNTH_UNIT[u]}` | " + " | ".join(xs) + " | " + " | ".join(is_) +
          f" | {f'{f:.2f}' if f else NA} | {src} |")
    w("")
    missing = [LABEL[u] for u in UNITS if "xilinx7" not in synth[u] or "ice40" not in synth[u]]
    if missing:
        w(f"No default-configuration row in synth.csv for: {', '.join(missing)} (a dash; their "
          "per-area columns are left out).")
        w("")

    # ---- per scene ----
    per_scene = {}
    allrows = []
    for s in scenes:
        rows = read_csv(os.path.join(a.data, f"tris-{s['scene']}.csv"))
        per_scene[s["scene"]] = rows
        allrows += rows
    scene_groups = [(s["label"], {u: Cost(u, int(s["triangles"]), int(s[u]), synth) for u in UNITS})
                    for s in scenes if int(s["triangles"]) > 0]
    ntot = sum(c["improved"].n for _, c in scene_groups)
    tot = {u: Cost(u, ntot, sum(c[u].c for _, c in scene_groups), synth) for u in UNITS}
    w("## Per scene: who wins in time, cycles and per area")
    w("")
    w("Winner of each column (its value; the runner-up's). Time only among the units with a "
      "routed clock (" + ", ".join(LABEL[u] for u in clocked) + "); the clock-free per-area "
      "column among all.")
    w("")
    summary_table(w, "scene", scene_groups + [("**all scenes**", tot)])
    w("")
    w("Every unit on every scene, fastest first (the units without a clock after, by cycles); "
      "the best of a scene in each column in **bold**:")
    w("")
    long_table(w, "scene", scene_groups + [("**all scenes**", tot)])
    w("")

    # ---- pooled bins ----
    bins = {}
    for r in allrows:
        bins.setdefault(log2bin(int(r["box_w"]) * int(r["box_h"])), []).append(r)
    bin_groups = [(bin_label(k) if k >= 0 else "0 (empty box)", bin_costs(bins[k], UNITS, synth))
                  for k in sorted(bins)]
    w("## Per triangle size: the scenes' triangles by box area")
    w("")
    w("All triangles of all scenes, binned by box area (powers of 2); per bin the cycles its "
      "triangles add per unit, in time and per area as above. Scene triangles mix shapes, and "
      "their cycles depend on their neighbours (a set-up hidden behind the previous walk costs "
      "nothing), so these crossovers are where the winner changes in practice. The winners' "
      f"ranges (in the summary) use the bins with at least {MIN_BIN} triangles; box area 0: the "
      "box is empty, the triangle off-screen (the traditional unit still walks its rows).")
    w("")
    summary_table(w, "box area (px)", bin_groups)
    w("")
    long_table(w, "box area (px)", bin_groups)
    w("")

    # ---- sweep ----
    sweep_plot(sweep, synth, os.path.join(a.img, "sweep.png"))
    w("## The crossover: box size and aspect ratio, in time and in cycles")
    w("")
    w("Scenes of equal-shaped triangles (tools/unit_compare.cpp `shaped`: each triangle spans its "
      "box, one vertex on three of its sides, mirrored four ways, at random positions and "
      "sub-pixel offsets; 16 to 1,024 triangles a scene), one scene per box area (powers of 2 "
      "from 1 to 65,536 pixels) and aspect ratio w/h (1/16 to 16); per triangle = the scene's "
      "total / triangles. The triangle covers about 43% of its box. Rows of the plot: cycles per "
      "triangle (every unit); ns per triangle and triangles/s per 1,000 iCE40 cells (the units "
      "with a routed clock); triangles per 1,000 cycles per 1,000 xc7 LUTs (every unit).")
    w("")
    w(f"![time, cycles and per area per triangle against box area]({img_rel}/sweep.png)")
    w("")
    aspects = sorted({float(r["aspect"]) for r in sweep})
    by_aspect = {x: sorted([r for r in sweep if float(r["aspect"]) == x],
                           key=lambda r: float(r["mean_box"])) for x in aspects}
    cols = [("ns", UNITS, "fastest (ns)"), ("cycles", UNITS, "fewest cycles (all units)"),
            ("cycles", EXACT, "fewest cycles (exact units)"),
            ("tps_i", UNITS, "most triangles/s per 1,000 iCE40 cells"),
            ("tkc_x", UNITS, "most triangles / 1,000 cycles / 1,000 xc7 LUTs")]
    w("Who wins, by box area (the mean box of the sweep point where the winner starts or stops); "
      "the exact units are all but the traditional one, which draws its own pixels, not the "
      "coverage rule's (docs/timing.md):")
    w("")
    w("| aspect w/h | " + " | ".join(t for _, _, t in cols) + " |")
    w("|---:|" + "---|" * len(cols))
    for x in aspects:
        w(f"| {x:g} | " + " | ".join(sweep_ranges(by_aspect[x], us, m, synth) for m, us, _ in cols)
          + " |")
    w("")
    w("Winner in time and in cycles at each box area: the winner's value and the runner-up's in "
      "brackets, the box in square brackets. Where the traditional unit draws under 90% of the "
      "rule's pixels (thin slivers: it rounds the vertices to whole pixels and then often draws "
      "nothing) its cycles are for less work: the box is marked with the share it drew.")
    w("")
    w("| box area | w/h | box | fastest (ns / triangle) | fewest cycles / triangle | "
      "most triangles / 1,000 cycles / 1,000 xc7 LUTs |")
    w("|---:|---:|---|---|---|---|")
    for ar in sorted({float(r["box_area"]) for r in sweep}):
        for x in aspects:
            rs = [r for r in by_aspect[x] if float(r["box_area"]) == ar]
            if not rs:
                continue
            r = rs[0]
            costs = {u: sweep_cost(r, u, synth) for u in UNITS}
            note = ""
            if trad_short(r):
                note = (f" (trad. draws {100 * float(r['trad_mean_pixels']) / float(r['mean_pixels']):.0f}%"
                        " of the pixels)")
            w(f"| {ar:,.0f} | {x:g} | {r['box_w']}x{r['box_h']}{note} | {lead_cell(costs, 'ns')} | "
              f"{lead_cell(costs, 'cpt')} | {lead_cell(costs, 'tkc_x')} |")
    w("")
    pairs = [("improved2", "trad"), ("improved", "improved2"), ("improved2", "improved2p"),
             ("improved2", "hs4"), ("improved", "trad"), ("improved", "hs4"), ("trad", "hs4"),
             ("hs2", "hs4"), ("hsr1", "hsr2")]
    time_pairs = [(p, q) for i, p in enumerate(clocked) for q in clocked[i + 1:]]

    def f_ns(r, u):
        return sweep_cost(r, u, synth).ns

    def f_cyc(r, u):
        return int(r[u]) / int(r["triangles"])

    def cross_rows(pairs, f):
        for x in aspects:
            for p, q in pairs:
                cs = crossings(by_aspect[x], p, q, f)
                if not cs:
                    w(f"| {x:g} | {LABEL[p]} vs {LABEL[q]} | none | | "
                      f"{no_crossing(by_aspect[x], p, q, f)} |")
                for at, lo, hi, up in cs:
                    w(f"| {x:g} | {LABEL[p]} vs {LABEL[q]} | **{at:,.0f}** | {lo:,.0f} .. {hi:,.0f} "
                      f"| {LABEL[up]} |")

    w("Crossovers of pairs: the box area (log-interpolated between the two sweep points around "
      "it, whose mean boxes are given) where one unit stops beating the other, and the unit that "
      "wins above it. **In time** (ns per triangle at the routed clocks), the pairs of units with a "
      "routed clock; every other pair: n/a[^noclock].")
    w("")
    w("| aspect w/h | pair | crossover box area (px) | between | faster above |")
    w("|---:|---|---:|---|---|")
    cross_rows(time_pairs, f_ns)
    w("")
    w("**In cycles**:")
    w("")
    w("| aspect w/h | pair | crossover box area (px) | between | fewer cycles above |")
    w("|---:|---|---:|---|---|")
    cross_rows(pairs, f_cyc)
    w("")

    # ---- per scene plots ----
    w("## Per scene: triangle sizes, box shapes, cycles and time")
    w("")
    w("Left: histogram of the triangles' box areas and covered pixels (bins of powers of 2, "
      "log scale; \"0\": an empty box, no pixel). Second: histogram of the box aspect ratio w/h "
      "(non-empty boxes). Third: mean cycles a triangle adds, per unit, by box-area bin. Right: "
      "the same in ns at the routed clock (the units with one). Log scales.")
    w("")
    for s, (_, costs) in zip([s for s in scenes if int(s["triangles"]) > 0], scene_groups):
        rows = per_scene[s["scene"]]
        png = f"scene-{s['scene']}.png"
        scene_plot(s["label"], rows, synth, os.path.join(a.img, png))
        box = sorted(int(r["box_w"]) * int(r["box_h"]) for r in rows)
        pix = sorted(int(r["pixels"]) for r in rows)
        spec = s["spec"]
        if spec.startswith(ROOT + "/"):
            spec = os.path.relpath(spec, ROOT)
        w(f"### {s['label']} (`{spec}`)")
        w("")
        w(f"{len(rows):,} triangles; median box area {box[len(box) // 2]:,} px, median covered "
          f"pixels {pix[len(pix) // 2]:,}. Fastest: **{lead_label(costs, 'ns')}**; fewest cycles: "
          f"**{lead_label(costs, 'cycles')}**.")
        w("")
        w(f"![{s['label']}]({img_rel}/{png})")
        w("")

    # ---- footnote ----
    w("[^noclock]: No routed clock in [synth.csv](synth.csv): the default-configuration `ice40` "
      "row" + ("s" if len(unclocked) > 1 else "") + " of " + ", ".join(
          f"{LABEL[u]} (`{SYNTH_UNIT[u]}`" +
          (f", {synth[u]['ice40'][0]:,} LUT4s)" if "ice40" in synth[u] else ": no row)")
          for u in unclocked) +
      " hold no `fmax_mhz`: nextpnr has no routed result for them ([synth.md, Fmax]"
      "(synth.md#fmax-nextpnr-ice40-hx8k-ct256-seed-1) lists each design that does not fit the "
      "HX8K's logic cells). Their time is n/a; their cycles and clock-free per-area columns "
      "stand.")
    w("")

    # ---- the answer, at the top ----
    sq = by_aspect.get(1.0, [])
    S = ["## The answer", ""]
    S.append("All scenes together (" + f"{ntot:,} triangles): every unit in time, cycles and per "
             "area; the best of each column in **bold**. The break-even clock is the Fmax at which "
             "a unit's cycles would take the fastest unit's time (a requirement, not a measured "
             "clock).")
    S.append("")
    long_at = len(S)
    S.append("")
    clocks = " and ".join(f"{LABEL[u]} ({synth[u]['fmax']:.2f} MHz)" for u in clocked)
    S.append(f"- **Clocks**: only {clocks or 'no unit'} "
             "have a routed clock; " + ", ".join(LABEL[u] for u in unclocked) +
             " have none (no routed row[^noclock]), so time ranks "
             f"{'these ' + str(len(clocked)) if len(clocked) != 1 else 'this one'} only.")
    ranked = sorted(clocked, key=lambda u: tot[u].ns)
    if ranked:
        S.append("- **Time, all scenes**: " + ", ".join(
            f"{LABEL[u]} {tot[u].ns:,.1f} ns per triangle ({tot[u].tps / 1e6:,.3f} M triangles/s)"
            for u in ranked) + ".")
        fastest = {}
        for name, costs in scene_groups:
            fastest.setdefault(lead_label(costs, "ns"), []).append(name)
        S.append("- **Fastest per scene**: " + "; ".join(
            f"{k} on {len(v)} of {len(scene_groups)} ({', '.join(v)})" for k, v in
            sorted(fastest.items(), key=lambda kv: -len(kv[1]))) + ".")
        for m in ("tps_x", "tps_i"):
            rk = sorted([u for u in clocked if value(tot[u], m)], key=lambda u: -value(tot[u], m))
            S.append(f"- **{METRICS[m][2]}, all scenes**: " + ", ".join(
                f"{LABEL[u]} {cell(tot[u], m)}" for u in rk) + ".")
    rk = sorted([u for u in UNITS if tot[u].tkc_x], key=lambda u: -tot[u].tkc_x)
    S.append("- **Per area without a clock (triangles / 1,000 cycles / 1,000 xc7 LUTs), all "
             "scenes, every unit**: " + ", ".join(f"{LABEL[u]} {cell(tot[u], 'tkc_x')}" for u in rk)
             + ".")
    for p, q in [(p, q) for i, p in enumerate(clocked) for q in clocked[i + 1:]]:
        parts = []
        for x in aspects:
            cs = crossings(by_aspect[x], p, q, lambda r, u: sweep_cost(r, u, synth).ns)
            parts.append(f"w/h = {x:g}: " + (", ".join(
                f"{at:,.0f} px ({LABEL[up]} faster above)" for at, _, _, up in cs) if cs else
                "none, " + no_crossing(by_aspect[x], p, q,
                                       lambda r, u: sweep_cost(r, u, synth).ns)))
        S.append(f"- **Crossovers in time, {LABEL[p]} vs {LABEL[q]} (sweep)**: " + "; ".join(parts)
                 + ".")
    if "trad" in clocked:
        wins = [r for r in sweep if "trad" in
                leaders({u: sweep_cost(r, u, synth) for u in clocked}, "ns")]
        short = [r for r in wins if trad_short(r)]
        S.append(f"- The traditional unit is the fastest at {len(wins)} of the sweep's {len(sweep)} "
                 f"points; at {len(short)} of them it draws under 90% of the coverage rule's pixels "
                 "(thin slivers whose whole-pixel vertices leave little or nothing to draw).")
    if sq and clocked:
        S.append("- **Square boxes (sweep, w/h = 1), in time**: "
                 f"{sweep_ranges(sq, UNITS, 'ns', synth)}; per 1,000 iCE40 cells: "
                 f"{sweep_ranges(sq, UNITS, 'tps_i', synth)}.")
    if clocked:
        S.append("- **The scenes' triangles by box area, in time**: "
                 f"{bin_ranges(bins, UNITS, 'ns', synth)}; per 1,000 iCE40 cells: "
                 f"{bin_ranges(bins, UNITS, 'tps_i', synth)}; per 1,000 xc7 LUTs: "
                 f"{bin_ranges(bins, UNITS, 'tps_x', synth)}.")
    S.append("- **In cycles** (every unit, all scenes): " + ", ".join(
        f"{LABEL[u]} {tot[u].c:,}" for u in sorted(UNITS, key=lambda u: tot[u].c)) +
        f". By box area, fewest cycles: {bin_ranges(bins, UNITS, 'cycles', synth)}; among the "
        f"exact units: {bin_ranges(bins, EXACT, 'cycles', synth)}.")
    S.append("- The traditional unit is not exact (docs/timing.md: it walks whole-pixel vertices and "
             "draws its own coverage, not the rule's), so its cycles are not always for the same "
             "pixels; the cycle rankings among the exact units stand beside.")
    S.append("")
    T = []
    long_table(T.append, "all scenes", [("", tot)], break_even=True)
    S[long_at:long_at] = T
    L[summary_at:summary_at] = S
    with open(a.doc, "w") as f:
        f.write("\n".join(L))
    print(f"which_unit_wins.py: wrote {a.doc} and {a.img}")


if __name__ == "__main__":
    main()
