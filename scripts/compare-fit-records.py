#!/usr/bin/env python3
"""Compare two fit records (metalfit fit --json) value by value.

Usage: compare-fit-records.py BEFORE.json AFTER.json

For every field (the record's key path with the material, model and closed-form names left out, e.g.
materials.models.fit.metrics.max_rel) prints how many values changed and the largest relative change
|a - b| / max(|a|, |b|) with where it occurs; texts that differ count as changed. The provenance (paths,
versions) is not compared. Exit status 0 when nothing changed, 1 otherwise, 2 when the records' shapes differ.
"""
import collections
import json
import sys

NAMED = ("materials", "models", "closed_forms")  # their keys are names, not fields


def field(path):
    parts = [p for p in path if not isinstance(p, int)]
    out, skip = [], False
    for p in parts:
        if skip:
            skip = False
            continue
        out.append(p)
        skip = p in NAMED
    return ".".join(out)


def main(before, after):
    a, b = (json.load(open(f, encoding="utf-8")) for f in (before, after))
    worst = {}
    changed, total = collections.Counter(), collections.Counter()
    shape = []

    def walk(x, y, path):
        if path[:1] == ["provenance"]:
            return
        if isinstance(x, dict) and isinstance(y, dict):
            if set(x) != set(y):
                shape.append(f"{'/'.join(map(str, path))}: keys {sorted(set(x) ^ set(y))}")
            for k in x.keys() & y.keys():
                walk(x[k], y[k], path + [k])
        elif isinstance(x, list) and isinstance(y, list):
            if len(x) != len(y):
                shape.append(f"{'/'.join(map(str, path))}: {len(x)} against {len(y)} items")
            for i, (u, v) in enumerate(zip(x, y)):
                walk(u, v, path + [i])
        else:
            f = field(path)
            total[f] += 1
            if x == y:
                return
            changed[f] += 1
            numbers = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in (x, y))
            r = abs(x - y) / max(abs(x), abs(y)) if numbers else float("inf")
            if f not in worst or r > worst[f][0]:
                worst[f] = (r, f"{'/'.join(map(str, path))}: {x!r} -> {y!r}")

    walk(a, b, [])
    for line in shape:
        print("shape differs at", line)
    for f in sorted(changed):
        print(f"{f}: {changed[f]} of {total[f]} changed, largest relative change {worst[f][0]:.3g} ({worst[f][1]})")
    print(f"{sum(total.values())} values in {len(total)} fields compared, {sum(changed.values())} changed")
    return 2 if shape else 1 if changed else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
