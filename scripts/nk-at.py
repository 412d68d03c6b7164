#!/usr/bin/env python3
"""Print n, k and what they imply at a few wavelengths of refractiveindex.info `tabulated nk` files, for reviewing a
data set against another (docs/data.md, "Why these primaries"): eps1 = n^2 - k^2, the normal-incidence reflectance
R(0) = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) against air, and the intensity decay length lambda / (4 pi k), which
says whether a film of a given thickness is opaque. n and k are interpolated linearly in wavelength, as metalfit's
default --interp.

Usage: scripts/nk-at.py FILE.yml... [--nm 360,450,550,650,830]

Reads only the first `tabulated nk` block (the one metalfit reads). python3 stdlib only.
"""
import math
import sys


def tabulated_nk(path):
    """(wavelength in nm, n, k) rows of the file's first `type: tabulated nk` block."""
    rows, inside = [], False
    with open(path, encoding="utf-8-sig") as fh:
        for line in fh:
            text = line.strip()
            if text.startswith("- type:"):
                if rows:
                    break
                inside = text.split(":", 1)[1].strip() == "tabulated nk"
                continue
            if not inside or not text or text.startswith("data:"):
                continue
            fields = text.split()
            if len(fields) != 3:
                if rows:
                    break
                continue
            try:
                um, n, k = (float(f) for f in fields)
            except ValueError:
                if rows:
                    break
                continue
            rows.append((um * 1000.0, n, k))
    if not rows:
        raise SystemExit(f"{path}: no `tabulated nk` block")
    return sorted(rows)


def at(rows, nm):
    if not rows[0][0] <= nm <= rows[-1][0]:
        return None
    for (x0, n0, k0), (x1, n1, k1) in zip(rows, rows[1:]):
        if x0 <= nm <= x1:
            t = 0.0 if x1 == x0 else (nm - x0) / (x1 - x0)
            return n0 + t * (n1 - n0), k0 + t * (k1 - k0)
    return rows[-1][1], rows[-1][2]


def main(argv):
    files, wavelengths = [], [360.0, 450.0, 550.0, 650.0, 830.0]
    args = iter(argv[1:])
    for a in args:
        if a == "--nm":
            wavelengths = [float(v) for v in next(args).split(",")]
        else:
            files.append(a)
    if not files:
        print(__doc__, file=sys.stderr)
        return 2
    for path in files:
        rows = tabulated_nk(path)
        print(path)
        print(f"  {'nm':>6} {'n':>7} {'k':>7} {'eps1':>8} {'R(0)':>6} {'decay nm':>9}")
        for nm in wavelengths:
            v = at(rows, nm)
            if v is None:
                print(f"  {nm:6.0f}  outside {rows[0][0]:.1f}-{rows[-1][0]:.1f} nm")
                continue
            n, k = v
            r0 = ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k)
            decay = nm / (4 * math.pi * k) if k > 0 else math.inf
            print(f"  {nm:6.0f} {n:7.3f} {k:7.3f} {n * n - k * k:+8.2f} {r0:6.3f} {decay:9.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
