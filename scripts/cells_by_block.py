#!/usr/bin/env python3
"""Where a synthesized iCE40 netlist's cells are, by block (not part of a unit).

Reads a Yosys JSON netlist written after synth_ice40 (flattened, e.g. scripts/synth.sh's
pnr/NAME/design.json) and counts its SB_LUT4, SB_CARRY and flip-flop cells per block: a cell
belongs to the hierarchical name (its first DEPTH dot-separated parts) of the net it drives. With
--ff-alone it also counts, per block, the flip-flops that cannot share a logic cell with a LUT
(fed by another flip-flop, a carry or a constant, or by a LUT that has other loads): each takes a
logic cell of its own on the iCE40.

  scripts/cells_by_block.py DESIGN.json [--top MODULE] [--depth N] [--min N] [--ff-alone]
"""
import argparse
import collections
import json
import re
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("json")
    ap.add_argument("--top", help="module (default: the only one, or the one with the most cells)")
    ap.add_argument("--depth", type=int, default=3, help="name parts that make a block (3)")
    ap.add_argument("--min", type=int, default=40, help="list blocks with at least N cells (40)")
    ap.add_argument("--ff-alone", action="store_true", help="also the flip-flops without a LUT")
    a = ap.parse_args()
    try:
        with open(a.json) as f:
            mods = json.load(f)["modules"]
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"cells_by_block.py: {a.json}: not a Yosys JSON netlist ({e})")
    if a.top:
        if a.top not in mods:
            sys.exit(f"cells_by_block.py: {a.json}: no module {a.top}")
        m = mods[a.top]
    else:
        m = max(mods.values(), key=lambda x: len(x.get("cells", {})))
    cells = m.get("cells", {})
    names, driver, loads = {}, {}, collections.Counter()
    for nn, net in m.get("netnames", {}).items():
        if nn.startswith("$"):
            continue
        for b in net["bits"]:
            if isinstance(b, int) and (b not in names or len(nn) < len(names[b])):
                names[b] = nn
    for n, c in cells.items():
        for p, bits in c["connections"].items():
            out = c["port_directions"].get(p) == "output"
            for b in bits:
                if isinstance(b, int):
                    if out:
                        driver[b] = c["type"]
                    else:
                        loads[b] += 1

    def block(bit, cell):
        n = names.get(bit, cell.lstrip("\\$")).split("$")[0]   # a function's nets: its caller's
        return re.sub(r"\[\d+\]$", "", ".".join(n.split(".")[: a.depth]))

    count = collections.defaultdict(collections.Counter)
    for n, c in cells.items():
        t = c["type"]
        kind = "LUT4" if t == "SB_LUT4" else "CARRY" if t == "SB_CARRY" else \
            "FF" if t.startswith("SB_DFF") else t
        outs = [p for p, d in c["port_directions"].items() if d == "output"]
        bit = c["connections"][outs[0]][0] if outs and c["connections"][outs[0]] else None
        b = block(bit, n)
        count[b][kind] += 1
        if a.ff_alone and kind == "FF":
            d = c["connections"]["D"][0]
            if not isinstance(d, int) or driver.get(d) != "SB_LUT4" or loads[d] > 1:
                count[b]["FF alone"] += 1
    total = collections.Counter()
    cols = ["LUT4", "CARRY", "FF"] + (["FF alone"] if a.ff_alone else [])
    print(f"{'block':50s} " + " ".join(f"{c:>8s}" for c in cols))
    for b, c in sorted(count.items(), key=lambda x: -sum(x[1][k] for k in ("LUT4", "CARRY", "FF"))):
        total.update(c)
        if sum(c[k] for k in ("LUT4", "CARRY", "FF")) >= a.min:
            print(f"{b:50s} " + " ".join(f"{c[k]:8d}" for k in cols))
    print(f"{'all':50s} " + " ".join(f"{total[k]:8d}" for k in cols))


if __name__ == "__main__":
    main()
