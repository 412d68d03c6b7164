#!/usr/bin/env bash
# The main job on the embedded default (the built-in database), written into a folder (default: out/).
# Installs what is missing, builds, then runs metalfit on the built-in catalog:
#   list.txt / list.json            every material, its source and wavelength coverage
#   show-<id>.txt / show-<id>.json  reference reflectance (F0, F82, R at μ = 0.5, 0.25, 0.1) of a few metals
#   fit.txt / fit.json              closed forms and Ceres fits of every model for every catalog material
#                                   (docs/fitting.md, docs/fit-record.md); fit-timings.txt: where the time went;
#                                   fit-summary.md: worst-channel rel_rms of every model, fit / closed form
#   export/                         `metalfit export --all --model all --format all`: JSON, GLSL, HLSL, MaterialX,
#                                   OpenPBR and C++ constants of every catalog material and model (docs/export.md);
#                                   export-summary.md: what the MaterialX documents cost where they differ from the fit
#   preview/                        glpreview (docs/preview.md): the difficult room (beauty | CPU reference | difference,
#                                   EXR + PNG, metrics.json; fit-error.png/.exr, the models' error alone, and error.png,
#                                   the total error in false colour) and the sphere sheet sheet.png: per metal, reference |
#                                   best fitted model | its signed error in false colour, labelled
#   report/                         `metalfit report --all --model all`: open report/index.html in a browser (the catalog,
#                                   a page per material, report.json; docs/report.md); renders through glpreview
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out}"
bash scripts/build.sh release --target metalfit glpreview
metalfit=build/bin/metalfit
mkdir -p "$out"
"$metalfit" list -o "$out/list.txt"
"$metalfit" list --json -o "$out/list.json"
for material in Au Ag Cu Al Cr Ti TiN Cu-Zn; do
  "$metalfit" show "$material" -o "$out/show-$material.txt"
  "$metalfit" show "$material" --json -o "$out/show-$material.json"
done
"$metalfit" fit --all --model all --json -o "$out/fit.json" --summary "$out/fit-summary.md" --timings 2> "$out/fit-timings.txt" \
  || { cat "$out/fit-timings.txt" >&2; exit 1; }
"$metalfit" fit --all --model all -o "$out/fit.txt"
"$metalfit" export --all --model all --format all -o "$out/export"
python3 scripts/export-summary.py "$out/export" > "$out/export-summary.md"
build/bin/glpreview data/scenes/difficult-room.json -o "$out/preview" > "$out/preview-metrics.txt"
build/bin/glpreview data/scenes/sheet.json --sheet Au,Cu,Al,Ag,TiN,Cu-Zn -o "$out/preview" > "$out/preview-sheet.txt"
"$metalfit" report --all --model all -o "$out/report" > /dev/null
echo "main job: open $out/report/index.html in a browser (the catalog report)"
echo "main job: wrote $(ls "$out" | wc -l) files into $out/"
