#!/usr/bin/env python3
"""Markdown summary of a fit record (`metalfit fit --all --json`): worst-channel rel_rms in % of every model,
fitted / best closed form ("—" where no closed form is defined), one row per material, plus the catalog median.

Usage: scripts/fit-summary.py FIT.json [> summary.md]
"""
import json
import statistics
import sys


def worst(metrics, key="rel_rms"):
    values = metrics[key]
    return None if any(v is None for v in values) else max(values)


def percent(x):
    return "—" if x is None else f"{100 * x:.2f}"


def main(path):
    record = json.load(open(path, encoding="utf-8"))
    p = record["provenance"]
    materials = record["materials"]
    models = list(next(iter(materials.values()))["models"].keys())
    print(f"Worst-channel `rel_rms` in %, fit / best closed form; {p['color_space']}, {p['illuminant']}, {p['cmf']}, "
          f"{p['interpolation']} interpolation, {p['metric']} metric, {p['weight']} weight, {p['nodes']} nodes "
          f"(metalfit {p['metalfit_version']}).\n")
    print("| material | " + " | ".join(models) + " |")
    print("|---|" + "---|" * len(models))
    fitted = {m: [] for m in models}
    for mid, material in materials.items():
        cells = []
        for m in models:
            result = material["models"][m]
            fit = worst(result["fit"]["metrics"])
            closed = worst(result["closed"]["metrics"]) if "metrics" in result["closed"] else None
            fitted[m].append(fit)
            cells.append(f"{percent(fit)} / {percent(closed)}")
        print(f"| {mid} | " + " | ".join(cells) + " |")
    medians = [percent(statistics.median(v for v in fitted[m] if v is not None)) for m in models]
    worsts = [percent(max(v for v in fitted[m] if v is not None)) for m in models]
    print("| **median fit** | " + " | ".join(medians) + " |")
    print("| **worst fit** | " + " | ".join(worsts) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
