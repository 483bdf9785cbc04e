#!/usr/bin/python3
"""The generated tables of docs/port.md, from the RTL itself, so they cannot drift.

  scripts/gen_port_doc.py            rewrite the generated blocks of docs/port.md
  scripts/gen_port_doc.py --check    exit 1 (naming the stale block) when docs/port.md differs
  scripts/gen_port_doc.py --print    the generated blocks on stdout

Sources:
  * each unit's top, rtl/UNIT/trirast_UNIT_top.sv, read by Yosys (`portlist` after `hierarchy`):
    every port's direction and width at the default parameters and the package's widths;
  * the port's description: the `// text` after its declaration in the top (with the `//` lines
    that continue it), or, for a port a macro of rtl/common/trirast_ports.svh declares, the
    `//   name[, name] : text` line above the macro; a port without a description is an error;
  * the package rtl/common/trirast_pkg.sv (scripts/gen_params.py writes it): the widths table and
    the packed fields of the triangle and span ports.
A block in docs/port.md runs from `<!-- generated: NAME -->` to `<!-- end generated: NAME -->`.
Exit status: 0 done (or current), 1 stale (--check), 2 an error (a message naming the file).
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "port.md")
PKG = os.path.join(ROOT, "rtl", "common", "trirast_pkg.sv")
PORTS_SVH = os.path.join(ROOT, "rtl", "common", "trirast_ports.svh")
UNITS = ("improved", "improved2", "trad", "halfspace")


class GenError(Exception):
    pass


def rel(path):
    return os.path.relpath(path, ROOT)


def package():
    """The package's localparams: name -> (value, comment), in order."""
    out = {}
    for line in open(PKG):
        m = re.match(r"\s*localparam\s+int\s+(\w+)\s*=\s*(\d+);\s*(?://\s*(.*))?$", line)
        if m:
            out[m.group(1)] = (int(m.group(2)), (m.group(3) or "").strip())
    if "VertexBits" not in out:
        raise GenError("%s: no localparam VertexBits" % rel(PKG))
    return out


def comment_table(lines, path):
    """Descriptions from `//   a, b : text` lines (continued by deeper-indented `//` lines)."""
    desc = {}
    last = None
    for no, line in enumerate(lines, 1):
        m = re.match(r"//(\s+)([\w, ]+?)\s:\s(.*)$", line)
        if m and all(re.fullmatch(r"\w+_[io]|\w+_ni", n.strip()) for n in m.group(2).split(",")):
            names = [n.strip() for n in m.group(2).split(",")]
            for n in names:
                desc[n] = m.group(3).strip()
            last = (names, len(m.group(1)))
            continue
        c = re.match(r"//(\s+)(\S.*)$", line)
        if last and c and len(c.group(1)) > last[1] + 1:
            for n in last[0]:
                desc[n] += " " + c.group(2).strip()
            continue
        last = None
    return desc


def macro_ports():
    """Each port macro of trirast_ports.svh: name -> [port names or nested macro names]."""
    text = open(PORTS_SVH).read()
    macros = {}
    for m in re.finditer(r"`define\s+(\w+)\s*\\\n((?:.*\\\n)*.*)", text):
        body = m.group(2)
        items = []
        for part in body.split("\\\n"):
            part = part.strip()
            d = re.match(r"(?:input|output)\s+logic\b.*?(\w+)\s*,?$", part)
            if d:
                items.append(d.group(1))
            elif re.fullmatch(r"`(\w+),?", part):
                items.append("`" + part.strip("`,"))
        macros[m.group(1)] = items
    return macros


def top_descriptions(unit, macros, svh_desc):
    """The top's ports in declaration order: [(name, description, group)]."""
    path = os.path.join(ROOT, "rtl", unit, "trirast_%s_top.sv" % unit)
    lines = open(path).read().split("\n")
    start = next(i for i, l in enumerate(lines) if re.match(r"module\s+trirast_%s_top\b" % unit, l))
    # the port list: from the line `) (` after the parameters to the closing `);`
    i = next(j for j in range(start, len(lines)) if re.match(r"\)\s*\(", lines[j].strip()))
    ports = []
    group = ""
    last = None

    def expand(macro):
        for item in macros.get(macro, []):
            if item.startswith("`"):
                yield from expand(item[1:])
            else:
                yield item

    for line in lines[i + 1:]:
        s = line.strip()
        if s.startswith(");"):
            break
        g = re.match(r"//\s*----\s*(.*?)\s*----", s)
        if g:
            group = g.group(1)
            last = None
            continue
        mac = re.match(r"`(\w+),?\s*(?://\s*(.*))?$", s)
        if mac:
            if mac.group(1) not in macros:
                raise GenError("%s: macro `%s is not a port macro of %s" % (rel(path), mac.group(1), rel(PORTS_SVH)))
            # a comment after the macro: `// name[, name] : text` for those ports, else for all
            note, only = (mac.group(2) or "").strip(), None
            n = re.match(r"([\w, ]+?)\s:\s(.*)$", note)
            if n:
                only, note = [x.strip() for x in n.group(1).split(",")], n.group(2)
            for name in expand(mac.group(1)):
                d = svh_desc.get(name)
                if d is None:
                    raise GenError("%s: port %s has no `//   %s : text` description" % (rel(PORTS_SVH), name, name))
                if note and (only is None or name in only):
                    d += "; %s" % note
                ports.append([name, d, group])
            last = None
            continue
        d = re.match(r"(?:input|output)\s+logic\b[^/]*?(\w+)\s*,?\s*(?://\s*(.*))?$", s)
        if d:
            ports.append([d.group(1), (d.group(2) or "").strip(), group])
            last = ports[-1]
            continue
        c = re.match(r"//\s*(.*)$", s)
        if c and last is not None:
            last[1] = (last[1] + " " + c.group(1).strip()).strip()
    missing = [name for name, desc, _ in ports if not desc]
    if missing:
        raise GenError("%s: port(s) %s have no `// text` description" % (rel(path), ", ".join(missing)))
    return path, ports


# Handshake inputs that must not reach the same port's output in the same cycle (docs/port.md:
# a driver may wait for ready, a downstream for valid): no path without a register between them.
NO_COMBINATIONAL_PATH = (("tri_valid_i", "tri_ready_o"), ("span_ready_i", "span_valid_o"))
REGISTERS = "$adff,$dff,$dffe,$adffe,$sdff,$sdffe,$aldff,$aldffe,$dffsr,$dffsre,$mem_v2"


def yosys_ports(unit):
    """[(direction, width, name)] of the top at its default parameters, as Yosys elaborates it.
    Raises GenError when a pair of NO_COMBINATIONAL_PATH has a path without a register."""
    lst = subprocess.run([os.path.join(ROOT, "scripts", "rtl_filelist.sh"), unit],
                         capture_output=True, text=True)
    if lst.returncode != 0:
        raise GenError(lst.stderr.strip() or "rtl_filelist.sh %s failed" % unit)
    files = " ".join(lst.stdout.split())
    top = "trirast_%s_top" % unit
    # the combinational cone of each input (stopping at registers and memories) and the output
    paths = "; ".join("tee -q -o /dev/stdout select -list w:%s %%co*:-%s w:%s %%i" % (i, REGISTERS, o)
                      for i, o in NO_COMBINATIONAL_PATH)
    script = ("read_verilog -sv -I %s %s; hierarchy -top %s; portlist %s; "
              "proc; flatten; memory -nomap; opt_clean; %s"
              % (os.path.join(ROOT, "rtl", "common"), files, top, top, paths))
    try:
        r = subprocess.run(["yosys", "-p", script], capture_output=True, text=True)
    except FileNotFoundError:
        raise GenError("yosys: not found (scripts/deps.sh installs it)")
    if r.returncode != 0:
        err = [l for l in r.stdout.split("\n") if l.startswith("ERROR")]
        raise GenError("yosys on rtl/%s: %s" % (unit, err[0] if err else "failed"))
    out = []
    for l in r.stdout.split("\n"):
        m = re.match(r"(input|output|inout) \[(\d+):(\d+)\] (\w+)$", l.strip())
        if m:
            out.append((m.group(1), int(m.group(2)) - int(m.group(3)) + 1, m.group(4)))
        for i, o in NO_COMBINATIONAL_PATH:
            if l.strip() == "%s/%s" % (top, o):
                raise GenError("rtl/%s: %s reaches %s without a register (the port contract, docs/port.md)"
                               % (unit, i, o))
    return out


def port_table(unit, macros, svh_desc):
    path, described = top_descriptions(unit, macros, svh_desc)
    elaborated = yosys_ports(unit)
    names = [p[0] for p in described]
    if names != [p[2] for p in elaborated]:
        raise GenError("%s: the ports read from the source (%s) are not Yosys's (%s)"
                       % (rel(path), " ".join(names), " ".join(p[2] for p in elaborated)))
    rows = ["| port | dir | bits | what it carries |", "|---|---|---:|---|"]
    group = None
    for (name, desc, grp), (direction, width, _) in zip(described, elaborated):
        if grp != group:
            rows.append("| *%s* | | | |" % grp)
            group = grp
        rows.append("| `%s` | %s | %d | %s |" % (name, "in" if direction == "input" else "out",
                                                 width, desc.replace("|", "\\|")))
    return "\n".join(rows)


def fields(width, n, count=3):
    return ", ".join("[%d:%d]" % (k * width + width - 1, k * width) for k in range(count))


def packed_table(pkg):
    v = lambda name: pkg[name][0]
    s, f, p = v("SubpixelBits"), v("FracBits"), v("VertexBits")
    c, e, pix, tag = v("CoefBits"), v("EdgeBits"), v("PixBits"), v("TagBits")
    rows = ["| field | bits of the bus (k = 0, 1, 2) | type | value |", "|---|---|---|---|"]
    rows.append("| `tri_vx_i`, `tri_vy_i`: vertex k | %s | signed %d bits, %d.%d fixed point | x or y in 1/%d pixel (vertices snapped to 1/2^%d pixel, y down) |"
                % (fields(p, 3), p, p - f, f, 1 << f, s))
    rows.append("| `tri_a_i`: edge k's A | %s | signed %d bits | v_k.y - v_(k+1).y, in 1/%d pixel |" % (fields(c, 3), c, 1 << f))
    rows.append("| `tri_b_i`: edge k's B | %s | signed %d bits | v_(k+1).x - v_k.x, in 1/%d pixel |" % (fields(c, 3), c, 1 << f))
    rows.append("| `tri_c_i`: edge k's C | %s | signed %d bits | v_k.x * v_(k+1).y - v_k.y * v_(k+1).x, in 1/%d pixel^2 |"
                % (fields(e, 3), e, 1 << (2 * f)))
    rows.append("| `tri_bias_i`: edge k's bias | [0], [1], [2] | 1 bit | 1: bias -1 (not a top-left edge), 0: bias 0 (top-left) |")
    rows.append("| `tri_tag_i` | [%d:0] | %d bits | any value; returned on `span_tag_o` |" % (tag - 1, tag))
    rows.append("| `span_y_o` | [%d:0] | unsigned %d bits | pixel row, 0 at the top |" % (pix - 1, pix))
    rows.append("| `span_x_begin_o` | [%d:0] | unsigned %d bits | first pixel of the span |" % (pix - 1, pix))
    rows.append("| `span_x_end_o` | [%d:0] | unsigned %d bits | one past the last pixel (exclusive) |" % (pix, pix + 1))
    rows.append("| `cfg_vp_xmax_i`, `cfg_vp_ymax_i` | [%d:0] | unsigned %d bits | viewport width - 1, height - 1 |" % (pix - 1, pix))
    return "\n".join(rows)


def widths_table(pkg):
    rows = ["| package width | value | meaning |", "|---|---:|---|"]
    for name, (value, comment) in pkg.items():
        rows.append("| `%s` | %d | %s |" % (name, value, comment.replace("|", "\\|")))
    return "\n".join(rows)


def blocks():
    pkg = package()
    macros = macro_ports()
    svh_desc = comment_table(open(PORTS_SVH).read().split("\n"), PORTS_SVH)
    out = {"widths": widths_table(pkg), "packed-fields": packed_table(pkg)}
    for unit in UNITS:
        out["ports-" + unit] = port_table(unit, macros, svh_desc)
    return out


def splice(doc, gen):
    """doc with each generated block replaced; raises GenError for a block missing in doc."""
    for name, body in gen.items():
        pat = re.compile(r"(<!-- generated: %s -->\n).*?(<!-- end generated: %s -->)" % (re.escape(name), re.escape(name)), re.S)
        if not pat.search(doc):
            raise GenError("%s: no block <!-- generated: %s --> ... <!-- end generated: %s -->" % (rel(DOC), name, name))
        doc = pat.sub(lambda m: m.group(1) + body + "\n" + m.group(2), doc)
    return doc


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--check", action="store_true", help="exit 1 when docs/port.md is stale")
    ap.add_argument("--print", action="store_true", help="print the blocks, write nothing")
    a = ap.parse_args()
    try:
        gen = blocks()
        if a.print:
            for name, body in gen.items():
                print("<!-- generated: %s -->\n%s\n<!-- end generated: %s -->\n" % (name, body, name))
            return 0
        doc = open(DOC).read()
        new = splice(doc, gen)
    except (GenError, OSError) as e:
        print("gen_port_doc.py: %s" % e, file=sys.stderr)
        return 2
    if a.check:
        if new != doc:
            stale = [n for n, b in gen.items() if ("<!-- generated: %s -->\n%s\n" % (n, b)) not in doc]
            print("gen_port_doc.py: %s: stale block(s) %s; run scripts/gen_port_doc.py"
                  % (rel(DOC), ", ".join(stale)), file=sys.stderr)
            return 1
        return 0
    if new != doc:
        tmp = DOC + ".tmp"
        with open(tmp, "w") as f:
            f.write(new)
        os.replace(tmp, DOC)
    return 0


if __name__ == "__main__":
    sys.exit(main())
