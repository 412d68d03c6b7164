#!/usr/bin/env python3
"""Summary of a `metalfit export` folder (docs/export.md): per material, the worst-channel rel_rms (%) of what the
MaterialX documents compute where they differ from the model's own fit: lazanyi-comp (written as its f82-tint
stand-in) and gulbrandsen (reflectivity clamped to 0.99 by MaterialX's artistic_ior).
Usage: export-summary.py EXPORT_DIR  (made with --format json,mtlx and models lazanyi-comp, gulbrandsen)"""
import json
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
record = json.loads((root / "metalfit_export.json").read_text())


def header_rel_rms(path):
    """Worst channel of the rel_rms line in a document's header comment: the figures of what it computes."""
    values = re.search(r"rel_rms\s+= ([^\n]+)", path.read_text()).group(1).split(",")
    return max(float(v) for v in values)


def stem(material, model):
    return "metalfit_" + re.sub("[^a-z0-9]", "_", f"{material}_{model}".lower())


print(f"Worst-channel rel_rms in %, {record['provenance']['color_space']}, metalfit {record['provenance']['metalfit_version']}.")
print()
print("| material | lazanyi-comp fit | its MaterialX stand-in (f82-tint) | gulbrandsen fit | gulbrandsen in MaterialX |")
print("|---|---|---|---|---|")
for material, m in record["materials"].items():
    own = lambda model: 100 * max(m["models"][model]["export"]["metrics"]["rel_rms"])
    mtlx = lambda model: 100 * header_rel_rms(root / "mtlx" / (stem(material, model) + ".mtlx"))
    print(f"| {material} | {own('lazanyi-comp'):.2f} | {mtlx('lazanyi-comp'):.2f} | {own('gulbrandsen'):.2f} | {mtlx('gulbrandsen'):.2f} |")
