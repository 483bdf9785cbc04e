#!/usr/bin/python3
"""Rejects the two size-cast forms that Yosys 0.23 reads otherwise than Verilator and the language do
(docs/formal.md, "Yosys 0.23's reading of size casts"), so a synthesized or formally checked unit
cannot silently differ from its Verilated model:

  1. a unary operator directly before a size cast: `~W'(x)`, `-W'(x)`, `!W'(x)`
     (Yosys reads `~14'(7)` as 7); write `~(W'(x))`;
  2. a sum with a size cast of a conditional as an operand: `x + W'(c ? 2 : 1)`
     (inside a concatenation Yosys reads the element as 0); write `x + (c ? W'(2) : W'(1))`.

  scripts/check_yosys_casts.py [FILE_OR_DIR ...]   (default: rtl/ of this repository)

Prints one line per finding, FILE:LINE: the form and the text, and exits 1 when there is one;
exit 0 when the sources are clean, 2 on a usage error (a path that does not exist).
"""
import pathlib
import re
import sys

CAST = r"(?:\(\s*[^()]*\)|[A-Za-z_][\w.]*|\d+)'\("
# a unary operator: after an operator, an opening bracket, a separator or the start of the code
UNARY_BEFORE_CAST = re.compile(r"(?:^|[=(,?:&|^+*/<>{}\[]|\breturn\b)\s*[~!-]\s*" + CAST)
SUM_OPERAND_CAST = re.compile(r"[+-]\s*(" + CAST + ")")


def cast_of_conditional(code, start):
    """True when the size cast whose '(' ends at `start` holds a top-level '?'."""
    depth = 1
    for ch in code[start:]:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                return False
        elif ch == "?" and depth == 1:
            return True
    return False


def findings(path):
    in_block_comment = False
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        code = line
        if in_block_comment:
            if "*/" not in code:
                continue
            code = code.split("*/", 1)[1]
            in_block_comment = False
        code = re.sub(r"/\*.*?\*/", "", code)
        if "/*" in code:
            code, in_block_comment = code.split("/*", 1)[0], True
        code = code.split("//", 1)[0]
        if UNARY_BEFORE_CAST.search(code):
            yield number, "unary operator before a size cast (Yosys 0.23 drops the operator)", line
        for m in SUM_OPERAND_CAST.finditer(code):
            if cast_of_conditional(code, m.end()):
                yield number, ("sum with a size cast of a conditional (Yosys 0.23 can read it as 0 "
                               "in a concatenation)"), line


def main(argv):
    root = pathlib.Path(__file__).resolve().parent.parent
    paths = [pathlib.Path(a) for a in argv] or [root / "rtl"]
    files = []
    for p in paths:
        if p.is_dir():
            files += sorted(q for q in p.rglob("*") if q.suffix in (".sv", ".svh", ".v"))
        elif p.is_file():
            files.append(p)
        else:
            print(f"check_yosys_casts: {p}: no such file or directory", file=sys.stderr)
            return 2
    bad = 0
    for f in files:
        for number, form, text in findings(f):
            print(f"{f}:{number}: {form}: {text.strip()}")
            bad += 1
    if bad:
        print(f"check_yosys_casts: {bad} finding(s) in {len(files)} file(s)", file=sys.stderr)
        return 1
    print(f"check_yosys_casts: {len(files)} file(s), no size cast Yosys 0.23 misreads")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
