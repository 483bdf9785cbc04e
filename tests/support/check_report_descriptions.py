#!/usr/bin/env python3
"""Checks that every statistic of a trirast --report JSON has a one-line description.

Statistics are the leaves of the report (numbers, strings, booleans) outside "descriptions";
array elements are named by "[]" (engines[].pixels), so one description covers every row. The
report's "descriptions" object maps each such dotted name to one line of text."""
import json
import sys


def leaves(value, prefix):
    if isinstance(value, dict):
        for key, v in value.items():
            yield from leaves(v, prefix + "." + key if prefix else key)
    elif isinstance(value, list):
        if value and all(isinstance(v, (dict, list)) for v in value):
            for v in value:
                yield from leaves(v, prefix + "[]")
        else:
            yield prefix  # a list of plain values (or pairs) is one statistic
    else:
        yield prefix


def main(path):
    with open(path) as f:
        report = json.load(f)
    descriptions = report.get("descriptions")
    if not isinstance(descriptions, dict):
        print(f"{path}: no \"descriptions\" object")
        return 1
    bad = 0
    for name in sorted(set(leaves({k: v for k, v in report.items() if k != "descriptions"}, ""))):
        text = descriptions.get(name)
        if not isinstance(text, str) or not text.strip() or "\n" in text or text == "(no description)":
            print(f"{path}: {name}: no one-line description")
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
