#!/usr/bin/env python3
"""Write each catalog source's coverage into data/catalog.json: "range_nm" (where n and k are both defined) and
"points_360_830" (tabulated samples inside 360-830 nm), as metalfit computes them from the table (`metalfit show
--json`), so that `metalfit list` reads them from the catalog instead of parsing every table.

Usage: scripts/catalog-coverage.py METALFIT [DATA_DIR]     (default DATA_DIR: <repo>/data)

Run it after adding or replacing a table; the test CatalogCoverage.MetadataMatchesEveryTable fails while the
catalog and the tables disagree. python3 stdlib only.
"""
import json
import os
import subprocess
import sys


def coverage(metalfit, data_dir, material, source):
    out = subprocess.run([metalfit, "--data-dir", data_dir, "show", material, "--source", source, "--extrapolate", "--json"],
                         check=True, capture_output=True, text=True).stdout
    p = json.loads(out)["provenance"]
    return p["range_nm"], p["points_360_830"]


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    metalfit = argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    data_dir = os.path.normpath(argv[2] if len(argv) > 2 else os.path.join(here, "..", "data"))
    path = os.path.join(data_dir, "catalog.json")
    with open(path, encoding="utf-8") as fh:
        catalog = json.load(fh)
    for m in catalog["materials"]:
        for src in [m["primary"]] + m.get("alternates", []):
            src["range_nm"], src["points_360_830"] = coverage(metalfit, data_dir, m["id"], src["source"])
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as fh:
        fh.write(json.dumps(catalog, indent=2, ensure_ascii=False) + "\n")
    os.replace(tmp, path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
