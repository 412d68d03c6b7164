#!/usr/bin/env python3
"""The coverage of film and coat tables (refractiveindex.info YAML) over the colour range 360-830 nm, as a Markdown
table for docs/data.md: file, where n and k are both defined (nm), tabulated samples of n inside 360-830 nm, n and k
at 550 nm (linear interpolation, metalfit's default --interp; formulas 1 and 2 evaluated), and whether the file
covers 360-830 nm.

Usage: scripts/film-coverage.py FILE.yml...          (e.g. data/films/*/*.yml)

Reads the blocks metalfit reads: `tabulated nk`, `tabulated n`, `tabulated k`, `formula 1`, `formula 2`; a file with
another formula is listed as not read. python3 stdlib only.
"""
import math
import os
import sys

VISIBLE = (360.0, 830.0)


def blocks(path):
    """[(type, dict)] of the DATA blocks: rows (nm, values...) for tables, range and coefficients for formulas."""
    out, current, in_data = [], None, False
    with open(path, encoding="utf-8-sig") as fh:
        for line in fh:
            text = line.strip()
            if text.startswith("- type:"):
                current = {"type": text.split(":", 1)[1].strip(), "rows": []}
                out.append(current)
                in_data = False
                continue
            if current is None:
                continue
            if text.startswith("data:"):
                in_data = True
                continue
            if text.startswith("wavelength_range:"):
                current["range"] = [float(v) * 1000.0 for v in text.split(":", 1)[1].split()]
                in_data = False
                continue
            if text.startswith("coefficients:"):
                current["coefficients"] = [float(v) for v in text.split(":", 1)[1].split()]
                in_data = False
                continue
            if in_data:
                try:
                    values = [float(v) for v in text.split()]
                except ValueError:
                    in_data = False
                    continue
                if values:
                    current["rows"].append((values[0] * 1000.0,) + tuple(values[1:]))
            if not line.startswith((" ", "\t", "-")) and text and ":" in text:
                current = None if text.split(":")[0] in ("SPECS", "CONDITIONS", "COMMENTS", "REFERENCES") else current
    return out


def interpolate(rows, column, nm):
    rows = sorted(rows)
    if not rows[0][0] <= nm <= rows[-1][0]:
        return None
    for a, b in zip(rows, rows[1:]):
        if a[0] <= nm <= b[0]:
            t = 0.0 if b[0] == a[0] else (nm - a[0]) / (b[0] - a[0])
            return a[column] + t * (b[column] - a[column])
    return rows[-1][column]


def formula(block, nm):
    c, um = block["coefficients"], nm / 1000.0
    lo, hi = block["range"]
    if not lo <= nm <= hi:
        return None
    n2 = 1.0 + c[0]
    for i in range(1, len(c), 2):
        b, pole = c[i], (c[i + 1] if i + 1 < len(c) else 0.0)
        n2 += b * um * um / (um * um - (pole * pole if block["type"] == "formula 1" else pole))
    return math.sqrt(n2)


def describe(path):
    n_range = k_range = None
    n_at = k_at = None
    points = None
    unread = []
    for b in blocks(path):
        t = b["type"]
        if t in ("tabulated nk", "tabulated n") and n_range is None:
            rows = sorted(b["rows"])
            n_range = (rows[0][0], rows[-1][0])
            n_at = interpolate(rows, 1, 550.0)
            points = sum(1 for r in rows if VISIBLE[0] <= r[0] <= VISIBLE[1])
            if t == "tabulated nk":
                k_range, k_at = n_range, interpolate(rows, 2, 550.0)
        elif t == "tabulated k" and k_range is None:
            rows = sorted(b["rows"])
            k_range, k_at = (rows[0][0], rows[-1][0]), interpolate(rows, 1, 550.0)
        elif t in ("formula 1", "formula 2") and n_range is None:
            n_range, n_at = tuple(b["range"]), formula(b, 550.0)
        elif t.startswith("formula"):
            unread.append(t)
    if n_range is None:
        return None, unread
    both = n_range if k_range is None else (max(n_range[0], k_range[0]), min(n_range[1], k_range[1]))
    return (both, points, n_at, 0.0 if k_range is None else k_at), unread


def fmt(v, digits):
    return "—" if v is None else f"{v:.{digits}f}"


def main(files):
    if not files:
        print(__doc__, file=sys.stderr)
        return 2
    print("| file | n, k defined (nm) | points in 360–830 | n at 550 nm | k at 550 nm | covers 360–830 |")
    print("|---|---|---|---|---|---|")
    for path in files:
        name = os.path.join(os.path.basename(os.path.dirname(path)), os.path.basename(path))
        d, unread = describe(path)
        if d is None:
            print(f"| `{name}` | {', '.join(unread) or 'no data'}: not read by metalfit | | | | no |")
            continue
        (lo, hi), points, n, k = d
        covers = "yes" if lo <= VISIBLE[0] and hi >= VISIBLE[1] else "no"
        print(f"| `{name}` | {lo:g}–{hi:g} | {'formula' if points is None else points} | {fmt(n, 3)} | {fmt(k, 4)} | {covers} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
