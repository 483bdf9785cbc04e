#!/usr/bin/python3
"""Plots and report of a `trirast sweep` run (docs/speed-vs-error.md).

    /usr/bin/python3 scripts/plot_sweep.py --data DIR --doc FILE.md --img DIR [--start EPOCH]

Reads DIR/sweep.json and DIR/fit_*.json (written by trirast sweep / trirast fit in the same run
of scripts/sweep.sh), writes the PNG plots into --img and the Markdown report to --doc. Every
number in the report comes from those files, except the paper's, which are quoted and marked.
"""
import argparse
import glob
import json
import math
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Zhang & Ruan, "A triangle rasterization based on improved Bresenham algorithm": the improved
# unit about 32% faster; Table 1, FPGA resources.
PAPER_SPEEDUP_PCT = 32
PAPER_TABLE1 = {"improved": (3120, 4653), "trad": (3728, 6936)}  # (registers, LUTs)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_CONFIG = "S8 c16 b14 K- N1"
TRAD_DEFAULT = "S8 c16"
# The second-generation unit's default widths; its corner forms, the default (iCE40) form first.
GEN2_DEFAULT = "S8 c16 b14 N1 gen2"
GEN2_FORMS = ("radix16", "dsp")
FORM_NAME = {"radix16": "radix-16 corner form", "dsp": "products corner form"}


def fmt_ppm(v):
    if v == 0:
        return "0"
    if v < 0.1:
        return f"{v:.3f}"
    if v < 100:
        return f"{v:.1f}"
    return f"{v:,.0f}"


def fmt_int(v):
    return "" if v is None else f"{int(round(v)):,}"


def stale_synth(s):
    """Synthesized, but read from docs/synth.csv (scripts/synth.sh: maybe an older RTL) rather
    than from the distributed run's own synthesis jobs (a .synth file)."""
    return (s.get("area_source", "").startswith("synth")
            and not s.get("area_origin", "").endswith(".synth"))


def fmt_area(s, key, merged=False):
    if key not in s:
        return "-"
    v = fmt_int(s[key])
    if s.get("area_source") == "estimate":
        return v + (" (estimate)" if s.get("rtl", True) else " (estimate: no RTL)")
    if merged and stale_synth(s):
        return v + " (docs/synth.csv)"
    return v


def fmt_cracks(s):
    """A configuration's (or a scene's) cracks and double hits, blank where not counted."""
    return f"{fmt_int(s.get('cracks'))} / {fmt_int(s.get('doubles'))}"


def fmt_cycles(s, key, digits):
    """Cycles per triangle or per pixel, "-" for an untimed engine."""
    return f"{s[key]:.{digits}f}" if key in s else "-"


def error_cells(s):
    """A configuration's error columns: mean and max ppm, rejected triangles, cracks / doubles."""
    return [fmt_ppm(s["error_ppm"]), fmt_ppm(s["max_error_ppm"]), fmt_int(s["rejected"]),
            fmt_cracks(s)]


def area_cells(s, merged):
    """A configuration's LUTs and FFs, marked where estimated or read from docs/synth.csv."""
    return [fmt_area(s, "luts", merged), fmt_area(s, "ffs", merged)]


def rel(path):
    """A path of this machine as the report names it: relative to the repository."""
    return path.replace(ROOT + "/", "") if isinstance(path, str) else path


def table(header, rows, align=None):
    align = align or ["---"] * len(header)
    out = ["| " + " | ".join(header) + " |", "| " + " | ".join(align) + " |"]
    for r in rows:
        out.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(out)


def find(points, engine, config):
    for p in points:
        if p["engine"] == engine and p["config"] == config:
            return p
    return None


def symlog_x(ax):
    ax.set_xscale("symlog", linthresh=1.0)
    ax.set_xlim(left=-0.3)


COLORS = {"improved-sc": "tab:blue", "trad-sc": "tab:red", "improved-rtl": "tab:green",
          "float-scanline": "tab:purple", "golden": "black", "improved-datapath": "tab:cyan",
          "improved2-sc": "tab:brown", "improved2-datapath": "tab:olive"}
MARKERS = {"S x N x K": "o", "box bits": "s", "coord bits": "^", "fixed divider": "v",
           "boundary divide": "D", "synthesized": "*", "narrow": "P", "traditional": "X",
           "RTL": "h", "CPU baseline": "d", "reference": "o"}


def pareto_plot(points, ykey, ylabel, title, path, flag, whatif_flag):
    fig, ax = plt.subplots(figsize=(12, 6))
    seen = set()
    for p in points:
        s = p["summary"]
        if ykey not in s or s["failures"]:
            continue
        if not s.get("rtl", True) and "area_source" in s:
            # A model-only what-if (quotient truncation K): its own series, apart from hardware.
            label = ("model only (K: no RTL" + (", area estimated)" if ykey == "luts" else ")"))
            ax.scatter(s["error_ppm"], s[ykey], c="lightgray" if not s.get(whatif_flag) else "gray",
                       marker="x", s=30, label=None if label in seen else label, alpha=0.9)
            seen.add(label)
            continue
        est = s.get("area_source") == "estimate" and ykey == "luts"
        group, m = p["group"], MARKERS.get(p["group"], "o")
        if p.get("unit") == "improved2":
            # One series per engine and corner form: its groups are width axes of one unit.
            group = "gen2" + (f' {p["corner_form"]}' if p.get("corner_form") else "")
            m = "p" if p.get("corner_form") == "dsp" else "o"
        label = f'{p["engine"]}: {group}' + (" (area estimate)" if est else "")
        c = COLORS.get(p["engine"], "gray")
        ax.scatter(s["error_ppm"], s[ykey], c="none" if est else c, edgecolors=c, marker=m, s=40,
                   label=None if label in seen else label, alpha=0.85)
        seen.add(label)
    front = sorted(((p["summary"]["error_ppm"], p["summary"][ykey], p) for p in points
                    if p["summary"].get(flag) and ykey in p["summary"]),
                   key=lambda f: (f[0], f[1]))
    if front:
        xs = [f[0] for f in front]
        ys = [f[1] for f in front]
        ax.step(xs, ys, where="post", color="orange", linewidth=1.5,
                label="Pareto front (buildable hardware)")
        ax.scatter(xs, ys, s=140, facecolors="none", edgecolors="orange", linewidths=1.5)
        for i, (x, y, p) in enumerate(front):
            ax.annotate(str(i + 1), (x, y), textcoords="offset points", xytext=(3, 5), fontsize=7,
                        color="darkorange")
    symlog_x(ax)
    ax.set_yscale("log")
    ax.set_xlabel("error against the golden at S = 8: mean over scenes of (missing + extra) ppm "
                  "(symlog)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    fig.savefig(path, dpi=110, metadata={"Software": None})
    plt.close(fig)


def load_text(d):
    """The machine's load during a distributed run: RESULTS/load.txt (scripts/sweep_slurm.sh:
    "EPOCH LOAD1 LOAD5 LOAD15 WHAT" lines) and RESULTS/cpus.txt."""
    res = d.get("merged_from") or ""
    path = os.path.join(res, "load.txt")
    if not res or not os.path.isfile(path):
        return ("Load during the run: not recorded (the results directory has no load.txt; "
                "scripts/sweep_slurm.sh writes it).\n")
    samples = []
    for line in open(path):
        f = line.split()
        if len(f) >= 4:
            samples.append((int(f[0]), float(f[1])))
    cpus = ""
    cp = os.path.join(res, "cpus.txt")
    if os.path.isfile(cp):
        cpus = open(cp).read().strip()
    if not samples:
        return "Load during the run: load.txt is empty.\n"
    loads = [l for _, l in samples]
    span = (samples[-1][0] - samples[0][0]) / 60.0
    return (f"Load during the run: the 1-minute load average, sampled {len(samples)} times over "
            f"{span:.0f} minutes (at submission, every 30 s while scripts/sweep_slurm.sh waited, "
            f"and at each merge job): mean **{sum(loads) / len(loads):.1f}**, from "
            f"{min(loads):.1f} to {max(loads):.1f}, on a machine of {cpus or '?'} CPUs shared "
            "with other work (the tasks' wall times and the synthesis jobs' durations are "
            "stretched by it; cycles, pixels and areas are not). Samples: `"
            + rel(path) + "` (not checked in).\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--doc", required=True)
    ap.add_argument("--img", required=True)
    ap.add_argument("--start", type=float, default=None, help="epoch seconds the run started")
    ap.add_argument("--command", default="scripts/sweep.sh")
    args = ap.parse_args()

    d = json.load(open(os.path.join(args.data, "sweep.json")))
    fits = [json.load(open(f)) for f in sorted(glob.glob(os.path.join(args.data, "fit_*.json")))]
    points, scenes = d["points"], d["scenes"]
    os.makedirs(args.img, exist_ok=True)
    img_rel = os.path.relpath(args.img, os.path.dirname(os.path.abspath(args.doc)))
    am = d["area_model"]

    # ---- plots ----
    pareto_plot(points, "cycles_per_triangle", "cycles per scene triangle (all scenes, log)",
                "Cycles against error (timed engines; Pareto front of buildable hardware in "
                "orange,\nnumbered as in the table; x: model-only K what-ifs)",
                os.path.join(args.img, "cycles_vs_error.png"), "pareto_cycles", "whatif_cycles")
    pareto_plot(points, "luts", "LUTs, log" + ("" if am["have_synth"] else " (estimate)"),
                "Area against error (hollow: estimated area; Pareto front of buildable hardware "
                "in orange,\nnumbered as in the table; x: model-only K what-ifs, area estimated)",
                os.path.join(args.img, "area_vs_error.png"), "pareto_area", "whatif_area")

    # Error against subpixel bits.
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for engine, cfg_of, label in [
            ("improved-sc", lambda S: f"S{S} c16 b14 K- N1", "improved unit (the exact rule at S)"),
            ("trad-sc", lambda S: f"S{S} c16", "traditional Bresenham"),
            ("float-scanline", lambda S: f"S{S} c16", "float scanline (CPU)")]:
        xs, ys = [], []
        for S in range(0, 9):
            p = find(points, engine, cfg_of(S))
            if p and not p["summary"]["failures"]:
                xs.append(S)
                ys.append(p["summary"]["error_ppm"])
        if xs:
            ax.plot(xs, ys, marker="o", label=label, color=COLORS[engine])
    ax.set_yscale("symlog", linthresh=1.0)
    ax.set_xlabel("subpixel bits S")
    ax.set_ylabel("mean error, ppm (symlog)")
    ax.set_title("Error against subpixel precision", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.img, "error_vs_subpixel.png"), dpi=110, metadata={"Software": None})
    plt.close(fig)

    # Improved vs traditional cycles per scene.
    imp, trad = find(points, "improved-sc", DEFAULT_CONFIG), find(points, "trad-sc", TRAD_DEFAULT)
    # The second generation at the default widths, each corner form (cycles differ by a few).
    gen2 = {form: find(points, "improved2-sc", f"{GEN2_DEFAULT} {form}") for form in GEN2_FORMS}
    g2 = gen2[GEN2_FORMS[0]]
    cmp_rows = []  # (scene, improved, trad, gen2 or None)
    have_g2 = False  # the second generation on every compared scene: its columns and bars
    if imp and trad:
        labels, ic, tc, gc = [], [], [], []
        for i, sc in enumerate(scenes):
            a, b = imp["scenes"][i], trad["scenes"][i]
            c = g2["scenes"][i] if g2 and "total_cycles" in g2["scenes"][i] else None
            if "total_cycles" in a and "total_cycles" in b:
                labels.append(sc["label"])
                ic.append(a["total_cycles"])
                tc.append(b["total_cycles"])
                gc.append(c["total_cycles"] if c else 0)
                cmp_rows.append((sc, a, b, c))
        have_g2 = bool(cmp_rows) and all(r[3] for r in cmp_rows)
        w = 0.27 if have_g2 else 0.4
        fig, ax = plt.subplots(figsize=(9, 4.5))
        x = range(len(labels))
        ax.bar([i - w / (1 if have_g2 else 2) for i in x], ic, width=w,
               label="improved, first generation (improved-sc, default)", color=COLORS["improved-sc"])
        if have_g2:
            ax.bar(list(x), gc, width=w, label="improved, second generation (improved2-sc, "
                   f"{GEN2_FORMS[0]})", color=COLORS["improved2-sc"])
        ax.bar([i + w / (1 if have_g2 else 2) for i in x], tc, width=w,
               label="traditional (trad-sc, S = 8)", color=COLORS["trad-sc"])
        ax.set_yscale("log")
        ax.set_xticks(list(x))
        ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=7)
        ax.set_ylabel("total cycles (log)")
        ax.set_title("Improved (both generations) vs traditional unit, cycles per scene", fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(True, axis="y", alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(args.img, "improved_vs_trad.png"), dpi=110,
                    metadata={"Software": None})
        plt.close(fig)

    # ---- the report ----
    elapsed = (time.time() - args.start) if args.start else None
    L = []
    L.append("# Speed against error: configuration sweep, Pareto fronts, smallest configurations\n")
    L.append(f"Generated by `{args.command}`"
             + ((f" (its final merge and report: **{elapsed:.0f} s** wall time; the tasks and "
                 "synthesis jobs ran before, into the results directory it names;"
                 if d.get("merged_from") else f" in **{elapsed:.0f} s** wall time")
                if elapsed is not None else "")
             + (f" `trirast sweep --merge` {d['wall_seconds']['total']:.1f} s for " if d.get("merged_from")
                else f" ({d['jobs']} jobs; `trirast sweep` itself {d['wall_seconds']['total']:.1f} s for ")
             + f"{len(points)} configurations x {len(scenes)} scenes"
             + (", **quick mode**" if d["quick"] else "") + "). Sweep command: `"
             + rel(d["command"]) + "`. Data: `sweep.csv` (one row per configuration and scene), "
             "`sweep_configs.csv` (one row per configuration), `sweep.json`, `fit_*.json` in `"
             + os.path.relpath(args.data, os.path.dirname(os.path.abspath(args.doc))) + "`.\n")
    L.append("Every number below was produced by that command in that run, except the paper's "
             "(Zhang & Ruan, \"A triangle rasterization based on improved Bresenham algorithm\"), "
             "which are quoted and marked *paper*"
             + ("; LUT and flip-flop counts marked *synth* were read from "
                f"`{rel(am['synth_csv'])}` (scripts/synth.sh)"
                + (" or from the run's own synthesis jobs (the table *Synthesized area and the "
                   "estimate's error* names each one's file)" if d.get("merged_from") else "")
                if am["have_synth"] else "")
             + ". Cycles are exact (SystemC model, docs/timing.md); wall times are noisy (a shared "
             "machine) and shown only as ratios within this run.\n")
    # The buildable configurations on a front, and those whose area is not this run's synthesis.
    on_front = [p for p in points if p["summary"].get("pareto_cycles") or p["summary"].get("pareto_area")]
    hw_front = [p for p in on_front if "area_source" in p["summary"]]
    est_front = [p for p in hw_front if p["summary"]["area_source"] == "estimate"]
    stale_front = [p for p in hw_front if d.get("merged_from") and stale_synth(p["summary"])]
    if d.get("merged_from"):
        task_wall = sum(r["wall_seconds"] for p in points for r in p["scenes"])
        L.append(f"The simulation ran as {len(points) * len(scenes)} independent tasks "
                 "(configuration x scene) of the distributed sweep, each writing its own result "
                 "file; `trirast sweep --merge` built `sweep.csv`, `sweep_configs.csv` and "
                 "`sweep.json` from them (the engines' own wall time summed over the tasks: "
                 f"{task_wall:.1f} s)"
                 + (", **partial: " + str(len(d["missing_tasks"])) + " tasks had no result**"
                    if d.get("partial") else "")
                 + (". Every buildable configuration on a hardware front (and the default "
                    "improved and traditional units) was synthesized in this run"
                    if not est_front and not stale_front else
                    f". The buildable configurations on a hardware front (and the default "
                    f"improved and traditional units) were synthesized in this run but "
                    f"{len(est_front) + len(stale_front)} (named in the table *Synthesized area "
                    "and the estimate's error*: the synthesis rounds ended before it reached "
                    "the front)")
                 + ", on this tree's RTL, by "
                 "synthesis jobs into the same results directory (scripts/sweep_synth_task.sh, "
                 "`scripts/synth.sh --one`, one configuration each; a docs/synth.csv row for the "
                 "same configuration is replaced, not reused); their results are in the table "
                 "*Synthesized area and the estimate's error* below, each with its result file.\n")
        L.append(load_text(d))
    if d.get("skipped_engines"):
        L.append("Engines left out (they do not run in this build): "
                 + ", ".join(d["skipped_engines"]) + ".\n")

    L.append("## How it is measured\n")
    L.append("- **Reference**: per scene, the golden at S = 8 with the default coordinate width "
             "(16) on the same float input and culling. Every configuration sets the same float "
             "triangles up at its own S and coordinate width.\n"
             "- **Error**: missing and extra pixels against the reference, in parts per million of "
             "the reference's pixels; the aggregate is the mean of the scenes' ppm (each scene "
             "counts once), and *max* the worst scene.\n"
             "- **Cracks and double hits** on the closed meshes (marked *closed* below, culled "
             "back faces): a crack is an uncovered pixel whose centre lies inside or on a set-up "
             "triangle and not on the mesh's outline; a double hit is a pixel covered more than "
             "once (app/sweep/sweep.cpp, `count_closed`).\n"
             "- **Rejected** triangles: a vertex outside the coordinate range (`--coord-bits`) or "
             "a box wider or taller than 2^box_bits pixels; they are not drawn (their pixels count "
             "as missing).\n"
             "- **Cycles per triangle**: total cycles over all scenes / the triangles the "
             "reference accepted (a rejected triangle still counts); **cycles per pixel**: total "
             "cycles / pixels the configuration covered.\n"
             "- **Configuration names**: `S` subpixel bits, `c` coordinate bits, `b` box bits "
             "(the divider's quotient is Q = b + 1 bits), `K` quotient truncation (`K-` none: the "
             "exact default; `K6`: every division capped at 6 quotient bits, so a larger quotient "
             "saturates and is read as \"beyond the box\"), `N` endpoints per cycle, `fixed` the "
             "fixed divider (Q iterations per division), `divide` the divide boundary mode."
             + (" The half-space unit (`halfspace-*` engines): `s` stamp size (s x s pixels "
                "tested per cycle), `t` tile size for hierarchical rejection (`t-` none), `row`, "
                "`zigzag` or `forward` tile walk; its area is synthesized per stamp size at tile 8, forward "
                "(scripts/synth.sh) and unknown (`-`) elsewhere (it has no width formula)."
                if any(p.get("unit") == "halfspace" for p in points) else "")
             + (" The second-generation unit (`improved2-*` engines, docs/improved2.md): "
                "`gen2` plus its corner form, `dsp` (products, 1 cycle) or `radix16` "
                "(digit-serial; the untimed improved2-datapath, whose spans the form does not "
                "change, has none); always the step boundary and the adaptive, untruncated "
                "divider with N = 1; buildable hardware (`rtl` = 1: rtl/improved2/trirast_improved2.f, "
                "parametric in the widths, each corner form a build parameter) whose area is "
                "synthesized per corner form (scripts/synth.sh; the `improved2-products` and "
                "`improved2` rows) and elsewhere its own width formula scaled to that synthesis, "
                "never the first generation's."
                if any(p.get("unit") == "improved2" for p in points) else "") + "\n"
             "- **Fronts** (columns of `sweep_configs.csv` and `sweep.json`): `pareto_cycles` "
             "and `pareto_area` mark the fronts of buildable hardware (`rtl` = 1: the "
             "configuration the RTL implements); `whatif_cycles` and `whatif_area` mark a "
             "model-only configuration (`rtl` = 0: quotient truncation K) that no other "
             "configuration, buildable or not, dominates. `rtl`, `whatif_cycles` and "
             "`whatif_area` are the last three columns (added after `failures`).\n"
             "- **Area**: " + ("LUTs and flip-flops from synthesis (" + am["target"] + ") where "
                               "the run's synthesis jobs or docs/synth.csv cover the "
                               "configuration (a number without a mark; from docs/synth.csv, "
                               "which may be of an older RTL, marked *(docs/synth.csv)* in a "
                               "distributed run), otherwise "
                               if am["have_synth"] else "no synthesis results were found "
                               f"(`{rel(am['synth_csv'])}`), so every area is ")
             + "an estimate from the datapath widths, marked *estimate*. " + am["formula"] + "\n")

    L.append("## Scenes\n")
    rows = []
    for sc in scenes:
        rows.append([f"`{sc['spec']}`", sc["cull"], "closed" if sc["closed"] else "",
                     fmt_int(sc["triangles"]), fmt_int(sc["reference_triangles"]),
                     fmt_int(sc["reference_pixels"]),
                     "" if not sc["closed"] else f"{sc['reference_cracks']} / {sc['reference_doubles']}"])
    L.append(table(["scene", "cull", "mesh", "triangles", "accepted (S = 8)", "reference pixels",
                    "reference cracks / double hits"], rows,
                   ["---", "---", "---", "---:", "---:", "---:", "---:"]) + "\n")

    L.append("## Pareto fronts\n")
    L.append(f"![cycles against error]({img_rel}/cycles_vs_error.png)\n")
    L.append(f"![area against error]({img_rel}/area_vs_error.png)\n")
    L.append("Points on a front: no other configuration has both less error and fewer cycles "
             "(or LUTs). Both fronts are fronts of **buildable hardware**: the configurations "
             "the RTL implements (the improved unit without quotient truncation, the traditional "
             "unit, and the second-generation unit when the run sweeps it), whose area is "
             "synthesized. A configuration with quotient truncation `K` "
             "exists only in the C++ models (the RTL's divider always has Q = box bits + 1 "
             "quotient bits; the improved-rtl engine refuses K, tb/improved/improved_rtl_engine.cpp): "
             "there is nothing to synthesize, its area is an estimate, and it is shown apart, "
             "as the grey x series of the plots and the table *Model-only what-ifs* below, "
             "never on a front. The float scanline has neither cycles nor area (a CPU baseline) "
             "and is in the tables only.\n")
    merged = bool(d.get("merged_from"))

    for flag, ykey, what in (("pareto_cycles", "cycles_per_triangle", "cycles"),
                             ("pareto_area", "luts", "area")):
        front = sorted((p for p in points if p["summary"].get(flag)),
                       key=lambda p: (p["summary"]["error_ppm"], p["summary"][ykey]))
        rows = []
        for i, p in enumerate(front):
            s = p["summary"]
            rows.append([str(i + 1), p["engine"], f"`{p['config']}`", *error_cells(s),
                         fmt_cycles(s, "cycles_per_triangle", 2), *area_cells(s, merged)])
        L.append(f"The {what} front of buildable hardware (error, "
                 f"{'cycles per triangle' if what == 'cycles' else 'LUTs'}):\n")
        L.append(table(["#", "engine", "configuration", "error ppm (mean)", "max ppm", "rejected",
                        "cracks / doubles", "cycles/tri", "LUTs", "FFs"], rows,
                       ["---:", "---", "---", "---:", "---:", "---:", "---:", "---:", "---:",
                        "---:"]) + "\n")

    # The model-only what-ifs: K configurations that would be on a front if they were hardware.
    whatif = sorted((p for p in points
                     if p["summary"].get("whatif_cycles") or p["summary"].get("whatif_area")),
                    key=lambda p: (p["summary"]["error_ppm"], p["config"]))
    L.append("### Model-only what-ifs (no RTL, area estimated)\n")
    if whatif:
        rows = []
        for p in whatif:
            s = p["summary"]
            rows.append([p["engine"], f"`{p['config']}`", *error_cells(s),
                         fmt_cycles(s, "cycles_per_triangle", 2), *area_cells(s, merged),
                         ", ".join(w for w, f in (("cycles", "whatif_cycles"),
                                                  ("area", "whatif_area")) if s.get(f))])
        L.append(f"{len(whatif)} configurations with quotient truncation `K` (C++ model only: no "
                 "RTL, so no synthesis; their LUTs and flip-flops are the width estimate, whose "
                 "error against synthesis is reported below) would lie on the cycles or the area "
                 "front if every configuration competed (column *undominated on*). They are not "
                 "hardware and are not on the fronts above; their cycles and error are exact.\n")
        L.append(table(["engine", "configuration", "error ppm (mean)", "max ppm", "rejected",
                        "cracks / doubles", "cycles/tri", "LUTs", "FFs", "undominated on"], rows,
                       ["---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
                        "---"]) + "\n")
    else:
        L.append("No configuration with quotient truncation `K` would lie on a front if every "
                 "configuration competed.\n")

    # Synthesized area on the fronts and the estimate's error against synthesis.
    distinct = lambda ps: len({(p["summary"].get("area_origin"), p["config"]) for p in ps})
    L.append("### Synthesized area and the estimate's error\n")
    L.append(f"{len(hw_front)} points of buildable hardware are on a front: "
             f"{len(hw_front) - len(est_front) - len(stale_front)} with area synthesized "
             f"({am['target'] or '-'})" + (" in this run" if merged else "")
             + (f", {len(stale_front)} with area read from docs/synth.csv ("
                + ", ".join(f"`{p['engine']} {p['config']}`" for p in stale_front) + ")"
                if stale_front else "")
             + (f", {len(est_front)} with an estimate ("
                + ", ".join(f"`{p['engine']} {p['config']}`" for p in est_front) + ")"
                if est_front else ", none with an estimate")
             + ".\n")
    rows, errs = [], {}
    # A distributed run: the rows of its own synthesis jobs (this tree's RTL) only; the estimate's
    # error is measured against them.
    for r in am.get("synth_rows", []):
        e = r.get("estimate")
        if not e or (merged and not r.get("from_run")):
            continue
        # The calibration points: each unit's default widths (each unit's estimate is scaled to
        # its own synthesis there; the second generation per corner form).
        calib = (r["unit"] in ("improved", "trad", "improved2", "improved2-products")
                 and r["subpixel_bits"] == 8 and r["coord_bits"] == 16
                 and r["box_bits"] == 14 and r.get("endpoints", 1) == 1)
        el = 100.0 * (e["luts"] - r["luts"]) / r["luts"] if r["luts"] else 0.0
        ef = 100.0 * (e["ffs"] - r["ffs"]) / r["ffs"] if r["ffs"] else 0.0
        if not calib:
            errs.setdefault(r["unit"], ([], []))
            errs[r["unit"]][0].append(el)
            errs[r["unit"]][1].append(ef)
        src = os.path.relpath(r["file"], ROOT) if r["file"].startswith(ROOT) else r["file"]
        src = src if not src.startswith("/") else os.path.basename(src)
        rows.append([r["unit"], f"S{r['subpixel_bits']} c{r['coord_bits']} b{r['box_bits']} "
                     f"N{r.get('endpoints', 1)}", fmt_int(r["luts"]), fmt_int(e["luts"]),
                     "calibration" if calib else f"{el:+.1f}%", fmt_int(r["ffs"]),
                     fmt_int(e["ffs"]), "calibration" if calib else f"{ef:+.1f}%", f"`{src}`"])
    if rows:
        L.append(table(["unit", "widths", "LUTs synth", "LUTs estimate", "LUT error",
                        "FFs synth", "FFs estimate", "FF error", "result file"], rows,
                       ["---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---"]) + "\n")
    if errs:
        mean_abs = lambda v: sum(abs(x) for x in v) / len(v)
        parts = []
        for unit, (el, ef) in sorted(errs.items()):
            parts.append(f"the {unit} unit, {len(el)} configuration{'s' if len(el) != 1 else ''}: LUTs mean |error| "
                         f"**{mean_abs(el):.1f}%** (from {min(el):+.1f}% to {max(el):+.1f}%), "
                         f"flip-flops mean |error| **{mean_abs(ef):.1f}%** (from {min(ef):+.1f}% "
                         f"to {max(ef):+.1f}%)")
        L.append("The estimate against synthesis, every configuration synthesized "
                 + ("in this run " if merged else "") + "but the "
                 "calibration points (each unit's estimate is scaled to its own synthesis at "
                 "the default widths: the improved and traditional units', and the "
                 "second-generation unit's per corner form): " + "; ".join(parts) + ". Error = (estimate - synthesis) / "
                 "synthesis." + (" Synthesis job results: `" + rel(d["merged_from"]) + "/synth/` "
                                 "(not checked in)." if merged else "") + "\n")
    fm = d.get("ice40_fmax", [])
    if fm:
        L.append("iCE40 Fmax (nextpnr-ice40, HX8K, seed 1, from the synthesis jobs' place and route; "
                 "only the traditional unit fits the HX8K at these widths): "
                 + ", ".join(f"`{f['engine']} {f['config']}` {f['fmax_mhz']:.2f} MHz" for f in fm)
                 + ".\n")

    # Improved vs traditional.
    L.append("## Improved vs traditional unit\n")
    if cmp_rows:
        L.append(f"![improved vs trad]({img_rel}/improved_vs_trad.png)\n")

        def gain(a, b):  # (trad - unit) / trad, in %
            return 100.0 * (b - a) / b

        def median(v):
            v = sorted(v)
            m = len(v) // 2
            return v[m] if len(v) % 2 else (v[m - 1] + v[m]) / 2

        rows, ti, tt, tg = [], 0, 0, 0
        for sc, a, b, c in cmp_rows:
            ti += a["total_cycles"]
            tt += b["total_cycles"]
            ntri = max(sc["reference_triangles"], 1)
            row = [sc["label"], fmt_int(a["total_cycles"]), fmt_int(b["total_cycles"]),
                   f"{gain(a['total_cycles'], b['total_cycles']):+.1f}%",
                   f"{a['total_cycles'] / ntri:.1f}", f"{b['total_cycles'] / ntri:.1f}"]
            if have_g2:
                tg += c["total_cycles"]
                row += [fmt_int(c["total_cycles"]), f"{gain(c['total_cycles'], b['total_cycles']):+.1f}%",
                        f"{c['total_cycles'] / ntri:.2f}"]
            rows.append(row)
        gain_all = gain(ti, tt)
        gains = [gain(a["total_cycles"], b["total_cycles"]) for _, a, b, _ in cmp_rows]
        gain_median = median(gains)
        n_win = sum(1 for _, a, b, _ in cmp_rows if a["total_cycles"] < b["total_cycles"])
        extra = 3 if have_g2 else 0
        rows.append(["**all scenes**", fmt_int(ti), fmt_int(tt), f"**{gain_all:+.1f}%**", "", ""]
                    + ([fmt_int(tg), f"**{gain(tg, tt):+.1f}%**", ""] if have_g2 else []))
        g2_gains = [gain(c["total_cycles"], b["total_cycles"]) for _, _, b, c in cmp_rows] if have_g2 else []
        rows.append(["**median of the scenes**", "", "", f"**{gain_median:+.1f}%**", "", ""]
                    + (["", f"**{median(g2_gains):+.1f}%**", ""] if have_g2 else []))
        rows.append(["*paper* (Zhang & Ruan)", "", "", f"*about +{PAPER_SPEEDUP_PCT}%*", "", ""]
                    + [""] * extra)
        L.append(f"Improved = `improved-sc {DEFAULT_CONFIG}` (the first generation, default), "
                 f"traditional = `trad-sc {TRAD_DEFAULT}`"
                 + (f", gen2 = `improved2-sc {GEN2_DEFAULT} {GEN2_FORMS[0]}` (the second "
                    "generation, docs/improved2.md, at the same widths; its default corner form)"
                    if have_g2 else "")
                 + "; \"vs trad\" is (trad - unit) / trad, positive when the unit needs fewer "
                 "cycles than the traditional one.\n")
        L.append(table(["scene", "improved cycles", "trad cycles", "improved vs trad",
                        "improved cyc/tri", "trad cyc/tri"]
                       + (["gen2 cycles", "gen2 vs trad", "gen2 cyc/tri"] if have_g2 else []), rows,
                       ["---", "---:", "---:", "---:", "---:", "---:"] + ["---:"] * extra) + "\n")
        L.append(f"The first-generation improved unit needs fewer cycles on {n_win} of "
                 f"{len(cmp_rows)} scenes and {gain_all:+.1f}% over all of them together (the "
                 f"median scene: {gain_median:+.1f}%), against the paper's about +"
                 f"{PAPER_SPEEDUP_PCT}%. It wins where triangles are large or have long x-major "
                 "edges (near scenes, low-poly meshes, off-screen parts, which the traditional "
                 "unit walks row by row) and loses where triangles are a few pixels (its "
                 "divisions cost more than a few Bresenham steps), as docs/cycles-improved-vs-trad"
                 ".md explains.\n")
        if have_g2:
            g2_win = sum(1 for _, _, b, c in cmp_rows if c["total_cycles"] <= b["total_cycles"])
            g2_best = sum(1 for _, a, _, c in cmp_rows if c["total_cycles"] <= a["total_cycles"])
            L.append(f"The second generation needs no more cycles than the traditional unit on "
                     f"{g2_win} of {len(cmp_rows)} scenes ({gain(tg, tt):+.1f}% over all of them, "
                     f"the median scene {median(g2_gains):+.1f}%) and no more than the first "
                     f"generation on {g2_best} of {len(cmp_rows)}: its set-up is a pipeline that "
                     "overlaps the walk and retires boxes without a pixel centre early "
                     "(docs/timing.md, \"The second-generation improved unit\").\n")
    ai, at = am["default_improved"], am["default_trad"]
    pi, pt = PAPER_TABLE1["improved"], PAPER_TABLE1["trad"]

    def mark(src):
        return "estimate" if src == "estimate" else "synth"

    L.append("Area, the paper's Table 1 beside ours (default configuration, N = 1, FIFO 8):\n")
    L.append(table(["design", "registers (FF)", "LUT", "source"], [
        ["improved Bresenham", fmt_int(pi[0]), fmt_int(pi[1]), "*paper*"],
        ["traditional Bresenham", fmt_int(pt[0]), fmt_int(pt[1]), "*paper*"],
        ["trad / improved", f"{pt[0] / pi[0]:.2f}", f"{pt[1] / pi[1]:.2f}", "*paper*"],
        ["improved (first generation), ours", fmt_int(ai["ffs"]), fmt_int(ai["luts"]), mark(ai["source"])],
        ["traditional, ours", fmt_int(at["ffs"]), fmt_int(at["luts"]), mark(at["source"])],
        ["trad / improved, ours", f"{at['ffs'] / ai['ffs']:.2f}", f"{at['luts'] / ai['luts']:.2f}",
         "estimate" if "estimate" in (ai["source"], at["source"]) else "synth"],
    ] + [[f"improved, second generation, ours ({FORM_NAME[form]})", fmt_int(p["summary"]["ffs"]),
           fmt_int(p["summary"]["luts"]), mark(p["summary"]["area_source"])]
         for form, p in gen2.items() if p and "luts" in p["summary"]],
        ["---", "---:", "---:", "---"]) + "\n")
    if at["source"] == "estimate":
        L.append("Our traditional unit is an estimate here (no synthesis of its RTL was found): "
                 "its datapath has no divider and integer-pixel coordinates, so the width formula "
                 "makes it smaller than the improved unit, the opposite of the paper's Table 1.\n")
    else:
        L.append("Both of ours are synthesized RTL (docs/synth.md). Our traditional unit is "
                 "smaller than our first-generation improved one, the opposite of the paper's Table 1: it has no "
                 "divider, no corner-value multipliers and integer-pixel coordinates (two "
                 "Bresenham walkers and a span filler, docs/rtl.md), while the improved unit "
                 "carries three dividers, nine corner multipliers and 16.8 fixed-point edge "
                 "values. The paper does not describe its traditional design in enough detail to "
                 "say where its extra area comes from.\n")

    if any(p and "luts" in p["summary"] for p in gen2.values()):
        L.append("The second generation's rows are its two corner forms, each synthesized for "
                 "xilinx7 like the others (docs/synth.md): the products form (the corner values' "
                 "products as multipliers, which xc7 maps to DSP blocks; the xc7 form) and the "
                 "radix-16 form (digit-serial corner values, no multipliers; the default and "
                 "iCE40 form). docs/synth.md has their DSP and iCE40 figures.\n")

    # Subpixel bits.
    L.append("## Subpixel bits: error of each engine\n")
    L.append(f"![error against subpixel bits]({img_rel}/error_vs_subpixel.png)\n")
    rows = []
    for S in (8, 6, 4, 2, 0):
        row = [f"S = {S}"]
        for engine, cfg in (("improved-sc", f"S{S} c16 b14 K- N1"), ("trad-sc", f"S{S} c16"),
                            ("float-scanline", f"S{S} c16")):
            p = find(points, engine, cfg)
            if p is None:
                row += ["-", "-"]
                continue
            s = p["summary"]
            row += [fmt_ppm(s["error_ppm"]) + f" ({fmt_ppm(s['missing_ppm'])} / "
                    f"{fmt_ppm(s['extra_ppm'])})",
                    fmt_cracks(s)]
        rows.append(row)
    L.append("Error ppm (missing / extra) and cracks / double hits on the closed meshes. The "
             "improved unit at S < 8 follows the exact rule on vertices snapped to S bits: it has "
             "no cracks, and its error is the snapping. Its few double hits at S <= 2 are the "
             "snapped mesh folding over itself near the silhouette (two front faces overlap after "
             "snapping; the golden at the same S covers the same pixels twice), not rasterization "
             "errors.\n")
    L.append(table(["S", "improved ppm", "improved cracks / doubles", "trad ppm",
                    "trad cracks / doubles", "float scanline ppm",
                    "float cracks / doubles"], rows,
                   ["---", "---:", "---:", "---:", "---:", "---:", "---:"]) + "\n")

    def group_table(title, text, filt, extra_cols=()):
        sel = [p for p in points if filt(p)]
        if not sel:
            return
        L.append(f"## {title}\n")
        if text:
            L.append(text + "\n")
        rows = []
        for p in sel:
            s = p["summary"]
            rows.append([p["engine"], f"`{p['config']}`", *error_cells(s),
                         fmt_cycles(s, "cycles_per_triangle", 3),
                         fmt_cycles(s, "cycles_per_pixel", 4), *area_cells(s, merged),
                         f"{s['wall_ratio']:.2f}"])
        L.append(table(["engine", "configuration", "error ppm", "max ppm", "rejected",
                        "cracks / doubles", "cycles/tri", "cycles/pixel", "LUTs", "FFs",
                        "wall / golden"], rows,
                       ["---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
                        "---:", "---:"]) + "\n")

    group_table("Divider width: quotient truncation K (S = 8, N = 1)",
                "A K-bit divider saturates every quotient above 2^K - 1 and the walker reads a "
                "saturated quotient as \"beyond the box\": boxes wider or taller than about 2^K "
                "pixels lose or gain pixels. Fewer quotient bits also mean fewer divider "
                "iterations (cycles).",
                lambda p: p["engine"] == "improved-sc" and p["group"] == "S x N x K"
                and p["config"].startswith("S8 ") and p["config"].endswith("N1"))
    group_table("Divider width: box bits (the divider's Q = box bits + 1)",
                "A box wider or taller than 2^box_bits pixels is rejected by the unit's interface. "
                "Boxes are clipped to the 1024 x 768 viewport, so 10 bits hold every box.",
                lambda p: p["engine"] == "improved-sc" and (p["group"] == "box bits"
                                                      or p["config"] == DEFAULT_CONFIG))
    group_table("Coordinate width",
                "A vertex outside [-2^(c-1), 2^(c-1)) pixels rejects its triangle; a 1024-pixel "
                "viewport needs c >= 11.",
                lambda p: p["engine"] == "improved-sc" and (p["group"] == "coord bits"
                                                      or p["config"] in (DEFAULT_CONFIG,
                                                                         "S4 c16 b14 K- N1")))
    group_table("Endpoints per cycle N (S = 8), divider and boundary modes",
                "N does not change the output; it trades walk-stage area for cycles, which help "
                "only where the walk, not the set-up, is the bottleneck.",
                lambda p: p["engine"] in ("improved-sc", "improved-rtl") and (
                    (p["group"] == "S x N x K" and p["config"].startswith("S8 ")
                     and " K- " in p["config"]) or p["group"] in ("fixed divider",
                                                                 "boundary divide", "RTL")))
    group_table("Narrow configurations and the synthesized ones", "",
                lambda p: p["group"] in ("narrow", "synthesized"))
    group_table("Traditional unit and the float scanline (CPU baseline)",
                "The float scanline (after the devlog \"Software rasterization: a fast and exact "
                "triangle rasterization algorithm in C\") runs on the CPU: no cycles, no area; its wall time "
                "is a ratio to the golden's in this run.",
                lambda p: p["engine"] in ("trad-sc", "float-scanline", "golden"))

    # Cracks on closed meshes per scene.
    closed = [i for i, sc in enumerate(scenes) if sc["closed"]]
    if closed:
        L.append("## Cracks and double hits on the closed meshes, per scene\n")
        picks = [("golden", "S8 c16"), ("improved-sc", DEFAULT_CONFIG), ("improved-sc", "S0 c16 b14 K- N1"),
                 ("improved-sc", "S8 c16 b14 K6 N1"), ("improved-sc", "S8 c16 b14 K4 N1"),
                 ("trad-sc", "S8 c16"), ("trad-sc", "S0 c16"), ("float-scanline", "S8 c16"),
                 ("float-scanline", "S0 c16")]
        rows = []
        for engine, cfg in picks:
            p = find(points, engine, cfg)
            if not p:
                continue
            row = [engine, f"`{cfg}`"]
            for i in closed:
                r = p["scenes"][i]
                row.append(fmt_cracks(r) if "cracks" in r else "-")
            rows.append(row)
        L.append("Truncated quotients (K) make double hits: a saturated bound is read as \"beyond "
                 "the box\", so an edge stops bounding its span and the triangle spills over its "
                 "neighbour. The traditional unit draws both edges' Bresenham pixels, so shared "
                 "edges are covered twice.\n")
        L.append(table(["engine", "configuration"] + [scenes[i]["label"] + " cracks / doubles"
                                                      for i in closed], rows,
                       ["---", "---"] + ["---:"] * len(closed)) + "\n")

    # Fit results.
    if fits:
        L.append("## The smallest configuration a scene needs (`trirast fit`)\n")
        L.append("For each S from 0 to 8, `trirast fit` narrows the coordinate width, then the box "
                 "bits, then the quotient truncation (binary search, each step checked against "
                 "the reference with the bit-accurate unit model), and keeps the S whose result has "
                 "the fewest LUTs; N = 1 (N does not change the output). Cycles are the SystemC "
                 "model's, the default against the fit. The second-generation unit (`--unit "
                 "improved2`) has no quotient truncation; its area is that of its corner form "
                 "(the radix-16 form unless `--corner-form dsp`), an estimate scaled to its own "
                 "synthesis away from the default widths."
                 + (" Its areas are not the run's synthesis: `trirast fit` reads docs/synth.csv "
                    "(scripts/synth.sh, which may be of an older RTL) where it covers the "
                    "configuration, else the estimate (marked); a fit with quotient truncation "
                    "(K) is a model-only configuration (no RTL, area estimated)."
                    if merged else "") + "\n")
        rows = []
        for f in fits:
            ft, df, sv = f["fit"], f["default"], f["saved"]
            div = (f"K={ft['quotient_bits']} of Q={ft['divider_q']}" if ft["quotient_bits"]
                   else f"Q={ft['divider_q']}")
            unit = f.get("unit", "improved")
            unit = unit + (f" ({f['corner_form']})" if f.get("corner_form") else "")
            rows.append([unit, f"`{f['scene']}`" + (f" (cull {f['cull']})" if f["cull"] != "none" else ""),
                         fmt_ppm(f["error_budget_ppm"]),
                         f"S={ft['subpixel_bits']} c={ft['coord_bits']} b={ft['box_bits']} "
                         f"divider {div} quotient bits, N={ft['endpoints']}",
                         fmt_ppm(ft["error_ppm"]), fmt_int(ft["rejected"]),
                         f"{fmt_int(df['total_cycles'])} -> {fmt_int(ft['total_cycles'])} "
                         f"({sv['cycles_pct']:+.1f}%)",
                         f"{fmt_int(df['luts'])} -> {fmt_int(ft['luts'])} ({sv['luts_pct']:.1f}% "
                         "saved)" + (" (estimate" + (": no RTL" if ft["quotient_bits"] else "")
                                     + ")" if "estimate" in (df["area_source"],
                                                             ft["area_source"]) else ""),
                         f"{fmt_int(df['ffs'])} -> {fmt_int(ft['ffs'])} ({sv['ffs_pct']:.1f}% "
                         "saved)"])
        L.append(table(["unit", "scene", "budget ppm", "smallest configuration", "error ppm",
                        "rejected", "cycles default -> fit (saved)", "LUTs default -> fit",
                        "FFs default -> fit"],
                       rows, ["---", "---", "---:", "---", "---:", "---:", "---:", "---:", "---:"])
                 + "\n")
        for f in fits:
            cmd = "trirast fit"
            if f.get("unit", "improved") != "improved":
                cmd += f" --unit {f['unit']}"
                if f.get("corner_form") == "dsp":
                    cmd += " --corner-form dsp"
            cmd += f" --scene {f['scene']}"
            if f["cull"] != "none":
                cmd += f" --cull {f['cull']}"
            if f["error_budget_ppm"]:
                cmd += f" --error-budget {f['error_budget_ppm']:g}"
            L.append(f"- `{cmd}`: {f['evaluations']} evaluations; feasible S: "
                     + ", ".join(str(s["subpixel_bits"]) for s in f["search"] if s["feasible"])
                     + ".")
        L.append("")

    # Everything.
    L.append("## All configurations\n")
    L.append("<details><summary>every configuration, aggregated over the scenes</summary>\n")
    rows = []
    for p in points:
        s = p["summary"]
        rows.append([p["engine"], p["group"], f"`{p['config']}`", fmt_ppm(s["error_ppm"]),
                     fmt_ppm(s["missing_ppm"]), fmt_ppm(s["extra_ppm"]), fmt_int(s["rejected"]),
                     fmt_cracks(s), fmt_cycles(s, "cycles_per_triangle", 3),
                     fmt_cycles(s, "cycles_per_pixel", 4), *area_cells(s, merged),
                     f"{s['wall_ratio']:.2f}",
                     str(s["failures"]) if s["failures"] else ""])
    L.append(table(["engine", "group", "configuration", "error ppm", "missing ppm", "extra ppm",
                    "rejected", "cracks / doubles", "cycles/tri", "cycles/pixel", "LUTs", "FFs",
                    "wall / golden", "failed scenes"], rows,
                   ["---", "---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
                    "---:", "---:", "---:", "---:"]))
    L.append("\n</details>\n")
    L.append("Regenerate: `scripts/sweep.sh` (full, into docs/), `scripts/sweep.sh --quick --out DIR` "
             "(the test suite's run). Code: app/sweep/sweep.cpp, app/sweep/sweep_area.cpp, "
             "app/cli/cmd_sweep.cpp, scripts/plot_sweep.py.\n")
    tmp = args.doc + ".tmp"
    with open(tmp, "w") as out:
        out.write("\n".join(L))
    os.replace(tmp, args.doc)


if __name__ == "__main__":
    main()
