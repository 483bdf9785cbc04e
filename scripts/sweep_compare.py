#!/usr/bin/python3
"""Compares two sweep CSVs (sweep.csv or sweep_configs.csv) on every column but the wall times.

    scripts/sweep_compare.py A.csv B.csv

Exit 0 when they have the same header and the same rows in the same order, every column equal
except wall_seconds and wall_ratio (noisy: measured on different runs); else 1, naming the first
differing row and column."""
import csv
import sys

IGNORED = {"wall_seconds", "wall_ratio"}


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    a_path, b_path = sys.argv[1], sys.argv[2]
    with open(a_path, newline="") as f:
        a = list(csv.reader(f))
    with open(b_path, newline="") as f:
        b = list(csv.reader(f))
    if not a or not b or a[0] != b[0]:
        print(f"sweep_compare: {a_path} and {b_path}: different headers", file=sys.stderr)
        return 1
    if len(a) != len(b):
        print(f"sweep_compare: {a_path} has {len(a) - 1} rows, {b_path} {len(b) - 1}", file=sys.stderr)
        return 1
    head = a[0]
    keep = [i for i, h in enumerate(head) if h not in IGNORED]
    for n, (ra, rb) in enumerate(zip(a[1:], b[1:]), start=2):
        for i in keep:
            if ra[i] != rb[i]:
                print(f"sweep_compare: line {n}, column {head[i]}: '{ra[i]}' in {a_path}, "
                      f"'{rb[i]}' in {b_path}", file=sys.stderr)
                return 1
    print(f"sweep_compare: {a_path} = {b_path} ({len(a) - 1} rows, {len(keep)} of {len(head)} "
          f"columns compared; wall times left out)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
