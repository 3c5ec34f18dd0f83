#!/usr/bin/env python3
"""Compare the summary.json files of two result trees number by number.

For every case directory that holds a summary.json in both trees, walk both
JSON trees (keys under "timing_s" are wall and processor times and are left
out; so are keys only one side has, which are listed), and print the largest
relative change |a - b| / max(|a|, |b|, floor) with the key where it occurs,
and whether the Newton iteration counts are equal. Exits non-zero if any
case differs by more than --tolerance or its iteration counts differ.

Usage: scripts/compare_results.py OLD_DIR NEW_DIR [--tolerance 1e-10] [--floor 1e-12]
"""
import argparse
import json
import os
import sys


def numbers(tree, prefix=""):
    """Flatten a JSON tree into {path: number} (booleans and strings left out)."""
    out = {}
    if isinstance(tree, dict):
        for key, value in tree.items():
            if key == "timing_s":
                continue
            out.update(numbers(value, f"{prefix}{key}."))
    elif isinstance(tree, list):
        for i, value in enumerate(tree):
            out.update(numbers(value, f"{prefix}{i}."))
    elif isinstance(tree, (int, float)) and not isinstance(tree, bool):
        out[prefix.rstrip(".")] = float(tree)
    return out


def cases(root):
    found = {}
    for directory, _, files in os.walk(root):
        if "summary.json" in files:
            found[os.path.relpath(directory, root)] = os.path.join(directory, "summary.json")
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--floor", type=float, default=1e-12,
                        help="magnitude below which values count as zero")
    args = parser.parse_args()

    old, new = cases(args.old), cases(args.new)
    failed = False
    for name in sorted(set(old) & set(new)):
        with open(old[name]) as f:
            a = json.load(f)
        with open(new[name]) as f:
            b = json.load(f)
        na, nb = numbers(a), numbers(b)
        worst, where = 0.0, "-"
        for key in sorted(set(na) & set(nb)):
            x, y = na[key], nb[key]
            change = abs(x - y) / max(abs(x), abs(y), args.floor)
            if abs(x - y) <= args.floor:
                change = 0.0
            if change > worst:
                worst, where = change, key
        same_newton = a.get("newton", {}).get("iterations_per_step") == \
            b.get("newton", {}).get("iterations_per_step")
        only = sorted((set(na) ^ set(nb)))
        bad = worst > args.tolerance or not same_newton
        failed = failed or bad
        print(f"{name}: largest relative change {worst:.2e} ({where}); "
              f"Newton iterations {'equal' if same_newton else 'DIFFER'}"
              + (f"; keys on one side only: {', '.join(only)}" if only else ""))
    for name in sorted(set(old) ^ set(new)):
        print(f"{name}: only in {'the old' if name in old else 'the new'} tree")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
