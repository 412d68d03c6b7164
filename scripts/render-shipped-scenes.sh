#!/usr/bin/env bash
# Renders every shipped scene (at 160 × 120), its --explain, the QA sheet with rough and lit columns, a probe capture,
# a --batch of two rooms and a localized + localization variant of the rough room into OUT, with SOURCE_DATE_EPOCH
# fixed: two builds' outputs compared with `diff -r` differ only in timings (timings.json, the ms lines). How the
# renderer's refactors were checked byte for byte (docs/pass-graph.md).
# Usage: scripts/render-shipped-scenes.sh OUT   (needs build/bin/glpreview)
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1
bin=build/bin/glpreview
export SOURCE_DATE_EPOCH=1700000000
rm -rf "$out" && mkdir -p "$out"
for scene in data/scenes/*.json; do
  name=$(basename "$scene" .json)
  "$bin" "$scene" --explain > "$out/$name.explain.txt" 2>&1
  "$bin" "$scene" --size 160x120 -o "$out/$name" > "$out/$name.stdout.txt" 2>&1
  echo "$name exit $?" >> "$out/exit-codes.txt"
done
"$bin" data/scenes/sheet.json --sheet Au,Cu --sheet-models f82-tint,lazanyi-comp --sheet-roughness 0,0.3 --size 64x64 \
  -o "$out/sheet-rough" > "$out/sheet-rough.stdout.txt" 2>&1
"$bin" data/scenes/sheet.json --sheet Au,Cu --size 64x64 --explain > "$out/sheet.explain.txt" 2>&1
"$bin" data/scenes/difficult-room.json --capture-probe 64x32 -o "$out/probe" > "$out/probe.stdout.txt" 2>&1
"$bin" data/scenes/difficult-room.json data/scenes/empty-room.json --batch --size 64x48 -o "$out/batch" \
  > "$out/batch.stdout.txt" 2>&1
# The rough room with every other sphere localized (M = 4) and the localization image asked for.
variant=$(mktemp -d)
trap 'rm -rf "$variant"' EXIT
python3 - "$variant/localized-room.json" <<'PY'
import json, sys
scene = json.load(open("data/scenes/rough-room.json"))
for i, sphere in enumerate(scene["spheres"]):
    if i % 2 == 0:
        sphere["glossy"] = "localized"
        sphere["localized_size"] = 4
scene.setdefault("outputs", {})["localization"] = True
scene["outputs"]["reference_samples"] = 16
json.dump(scene, open(sys.argv[1], "w"), indent=1)
PY
"$bin" "$variant/localized-room.json" --allow-paths-outside --size 96x72 -o "$out/localized-room" > "$out/localized-room.stdout.txt" 2>&1
echo "localized-room exit $?" >> "$out/exit-codes.txt"
