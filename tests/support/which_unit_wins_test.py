#!/usr/bin/python3
"""Checks scripts/which_unit_wins.py on a tiny synthetic run (no simulation): every unit appears,
and the time columns are cycles at the routed clock of docs/synth.csv's rule.

    /usr/bin/python3 tests/support/which_unit_wins_test.py SOURCE_ROOT WORK_DIR

The synthetic data: two scenes whose triangles all cost the same per unit, a sweep of three box
areas at two aspect ratios, and a synth.csv with a routed ice40 row for improved2 and trad only,
plus decoys the rule must ignore (an xilinx7 row with an fmax_mhz, a non-default ice40 row with
one). Passes with "which_unit_wins_test: ok"."""
import os
import re
import subprocess
import sys

UNITS = ["improved", "improved2", "improved2p", "trad", "hs1", "hs2", "hs4", "hsr1", "hsr2", "hsr4"]
LABEL = {"improved": "improved", "improved2": "improved2 radix-16",
         "improved2p": "improved2 products", "trad": "traditional", "hs1": "half-space S1",
         "hs2": "half-space S2", "hs4": "half-space S4", "hsr1": "half-space radix-16 S1",
         "hsr2": "half-space radix-16 S2", "hsr4": "half-space radix-16 S4"}
# Per-triangle cycles of each unit (every triangle of a scene costs the same).
PER_TRI = {"improved": 20, "improved2": 105.6, "improved2p": 90, "trad": 30.9, "hs1": 80,
           "hs2": 30, "hs4": 12, "hsr1": 84, "hsr2": 34, "hsr4": 16}
FMAX = {"improved2": 52.80, "trad": 20.60}  # the routed ice40 default rows below
# The default rows' LUTs (xilinx7) and LUT4s (ice40) below.
XC7 = {"improved": 6510, "improved2": 4671, "improved2p": 3819, "trad": 2092, "hs1": 5194,
       "hs2": 5546, "hs4": 8037, "hsr1": 5563, "hsr2": 5978, "hsr4": 7553}
ICE40 = {"improved": 15932, "improved2": 5590, "improved2p": 16787, "trad": 4586, "hs1": 13550,
         "hs2": 14053, "hs4": 14691, "hsr1": 5783, "hsr2": 5908, "hsr4": 6540}
SYNTH = """unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz
improved,default,ice40,15932,2896,3404,0,0,
improved,default,xilinx7,6510,2320,818,0,9,
improved,tiny,ice40,5245,1937,900,0,0,24.92
trad,default,ice40,4586,1418,869,0,0,20.60
trad,default,xilinx7,2092,846,186,0,2,
halfspace-s1,default,ice40,13550,2867,2634,0,0,
halfspace-s1,default,xilinx7,5194,2273,654,0,15,
halfspace-s2,default,ice40,14053,2866,3035,0,0,
halfspace-s2,default,xilinx7,5546,2273,769,0,15,
halfspace-s4,default,ice40,14691,2865,4695,0,0,
halfspace-s4,default,xilinx7,8037,2273,1191,0,33,99.00
halfspace-radix16-s1,default,ice40,5783,3000,2400,5,0,
halfspace-radix16-s1,default,xilinx7,5563,2300,700,2,9,
halfspace-radix16-s2,default,ice40,5908,3000,2500,5,0,
halfspace-radix16-s2,default,xilinx7,5978,2300,750,2,9,
halfspace-radix16-s4,default,ice40,6540,3000,2800,5,0,
halfspace-radix16-s4,default,xilinx7,7553,2300,900,2,21,
improved2,default,ice40,5590,1913,2619,29,0,52.80
improved2,default,xilinx7,4671,2047,697,7,0,
improved2-products,default,ice40,16787,2624,2279,6,0,
improved2-products,default,xilinx7,3819,2056,610,3,12,
"""


def fail(msg):
    print(f"which_unit_wins_test: FAIL: {msg}")
    sys.exit(1)


def write_data(d):
    os.makedirs(d, exist_ok=True)
    scenes = [("a", "scene A", 100, 4, 4), ("b", "scene B", 10, 30, 3)]
    with open(os.path.join(d, "scenes.csv"), "w") as f:
        f.write("scene,label,spec,triangles," + ",".join(UNITS) + "\n")
        for name, label, n, bw, bh in scenes:
            # 10 x per-triangle cycles per 10 triangles: whole numbers
            f.write(f"{name},{label},builtin:{name},{n}," +
                    ",".join(str(round(PER_TRI[u] * n)) for u in UNITS) + "\n")
            with open(os.path.join(d, f"tris-{name}.csv"), "w") as t:
                t.write("tri,box_w,box_h,pixels,trad_pixels," + ",".join(UNITS) + "\n")
                for i in range(n):  # whole cycles per triangle that sum to the total
                    cyc = [round(PER_TRI[u] * (i + 1)) - round(PER_TRI[u] * i) for u in UNITS]
                    t.write(f"{i},{bw},{bh},{bw * bh // 2},{bw * bh // 2}," +
                            ",".join(map(str, cyc)) + "\n")
    with open(os.path.join(d, "sweep.csv"), "w") as f:
        f.write("box_area,aspect,box_w,box_h,triangles,mean_box,mean_pixels,trad_mean_pixels," +
                ",".join(UNITS) + "\n")
        for area, w, h in ((4, 2, 2), (64, 8, 8), (1024, 32, 32)):
            for aspect in (1, 4):
                n = 16
                cyc = {u: round(n * PER_TRI[u] * (area / 64) ** (0.5 if u.startswith("improved") else 1))
                       for u in UNITS}
                f.write(f"{area},{aspect},{w},{h},{n},{area}.0,{area * 0.43:.1f},{area * 0.43:.1f}," +
                        ",".join(str(max(1, cyc[u])) for u in UNITS) + "\n")
    with open(os.path.join(d, "synth.csv"), "w") as f:
        f.write(SYNTH)
    return scenes


def table_rows(doc, header_start):
    """The rows of the first table whose header row starts with header_start, as dicts."""
    lines = doc.split("\n")
    for i, line in enumerate(lines):
        if line.startswith(header_start):
            head = [c.strip() for c in line.strip("|").split("|")]
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append(dict(zip(head, [c.strip() for c in row.strip("|").split("|")])))
            return rows
    fail(f"no table with header {header_start!r}")


def num(cell):
    return float(cell.replace("*", "").replace(",", ""))


def main(root, work):
    data = os.path.join(work, "data")
    scenes = write_data(data)
    doc_path = os.path.join(work, "which-unit-wins.md")
    subprocess.run(["/usr/bin/python3", os.path.join(root, "scripts/which_unit_wins.py"),
                    "--data", data, "--synth", os.path.join(data, "synth.csv"), "--doc", doc_path,
                    "--img", os.path.join(work, "img"), "--command", "scripts/which_unit_wins.sh"],
                   check=True, stdout=subprocess.DEVNULL)
    doc = open(doc_path).read()
    checks = 0
    if "`scripts/which_unit_wins.sh`" not in doc:
        fail("the command is not written in the document")
    # Every unit in the units table, with its Fmax and source row or n/a.
    units = table_rows(doc, "| unit | synth.csv unit |")
    by_unit = {r["unit"]: r for r in units}
    for u in UNITS:
        if LABEL[u] not in by_unit:
            fail(f"{LABEL[u]} missing from the units table")
        f = by_unit[LABEL[u]]["routed Fmax (MHz)"]
        if u in FMAX:
            if num(f) != FMAX[u] or f"{u},default,ice40" not in by_unit[LABEL[u]]["Fmax source"]:
                fail(f"{LABEL[u]}: Fmax {f!r}, source {by_unit[LABEL[u]]['Fmax source']!r}")
        elif not f.startswith("n/a"):
            fail(f"{LABEL[u]}: Fmax {f!r} where synth.csv has no routed default ice40 row")
        checks += 1
    # Every unit on every scene; ns = 1000 x cycles / (triangles x Fmax) for the clocked ones.
    rows = table_rows(doc, "| scene | unit |")
    scene = None
    seen = set()
    for r in rows:
        scene = r["scene"] or scene
        seen.add((scene, r["unit"]))
        n = next((s[2] for s in scenes if s[1] == scene), None)
        u = next((k for k in UNITS if LABEL[k] == r["unit"]), None)
        if n is None or u is None:
            continue
        cycles = num(r["cycles"])
        if cycles != round(PER_TRI[u] * n):
            fail(f"{scene} {u}: cycles {r['cycles']} against {round(PER_TRI[u] * n)}")
        # Per area without a clock, every unit: triangles / 1,000 cycles / 1,000 LUTs.
        col = "triangles / 1,000 cycles / 1,000 xc7 LUTs"
        if r[col].replace("*", "") != f"{n * 1e6 / (cycles * XC7[u]):,.2f}":
            fail(f"{scene} {u}: {col} {r[col]!r} against {n * 1e6 / (cycles * XC7[u]):,.2f}")
        checks += 1
        if u in FMAX:
            want = f"{1000 * cycles / (n * FMAX[u]):,.1f}"
            if r["ns / triangle"].replace("*", "") != want:
                fail(f"{scene} {u}: ns {r['ns / triangle']!r}, cycles / Fmax gives {want}")
            tps = n * FMAX[u] * 1e6 / cycles
            if r["M triangles/s"].replace("*", "") != f"{tps / 1e6:,.3f}":
                fail(f"{scene} {u}: M triangles/s {r['M triangles/s']!r} against {tps / 1e6:,.3f}")
            for col, lut in (("k triangles/s per 1,000 xc7 LUTs", XC7[u]),
                             ("k triangles/s per 1,000 iCE40 cells", ICE40[u])):
                if r[col].replace("*", "") != f"{tps / lut:,.1f}":
                    fail(f"{scene} {u}: {col} {r[col]!r} against {tps / lut:,.1f}")
            checks += 4
        elif not r["ns / triangle"].startswith("n/a"):
            fail(f"{scene} {u}: ns {r['ns / triangle']!r} without a routed clock")
    for _, label, *_ in scenes:
        for u in UNITS:
            if (label, LABEL[u]) not in seen:
                fail(f"{LABEL[u]} missing from the per-scene table on {label}")
    # The one exact figure: improved2 on scene A, 105.6 cycles per triangle at 52.80 MHz.
    a2 = [r for r in rows if r["unit"] == LABEL["improved2"]][0]
    if a2["ns / triangle"].replace("*", "") != "2,000.0":
        fail(f"scene A improved2: {a2['ns / triangle']!r} ns, not 2,000.0")
    if "[^noclock]:" not in doc:
        fail("no footnote for the units without a clock")
    print(f"which_unit_wins_test: ok ({checks} checks, {len(UNITS)} units)")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
