#!/usr/bin/env bash
# ctest json_schemas.records: writes every kind of JSON record
# metalfit writes (fit --json plain, pinned, with a budget and of a layered material; metalfit_export.json of the catalog export and of two
# exports merged into one folder, and of a coated metal; openpbr/*.json; the glTF extras; show --json (and of a named finish); table
# --format json (bare and layered) and physicallybased; the oxide colour chart and its renderer scores; report.json (bare, filmed with the renderers' scores, a film under a coat);
# bench --json; glpreview's metrics.json when glpreview is given) and validates each against schemas/ with Ajv
# (json_schemas.mjs); then has json_schemas.mjs --broken break each record in many ways and checks that every broken
# copy is refused (the schemas can fail).
# Usage: METALFIT GLPREVIEW|- NODE NODE_MODULES SCHEMAS_DIR CATALOG_EXPORT_DIR
set -euo pipefail
metalfit="$1" glpreview="$2" node="$3" modules="$4" schemas="$5" catalog_export="$6"
here="$(cd "$(dirname "$0")" && pwd)"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
export OCIO=
"$metalfit" fit Au,Cu,Zn,TiN --model all --json -o "$dir/fit.json"
"$metalfit" fit Au --model f82-tint,schlick --pin F0 --json -o "$dir/fit-pinned.json"
"$metalfit" fit Cu,Al --model all --budget 0.5% --json -o "$dir/fit-budget.json"
# The recommendation under its F0 constraint (issue 29): the record's recommendation and provenance.constraints.
"$metalfit" fit Os,Au --recommend --target openpbr --json -o "$dir/fit-recommend.json"
"$metalfit" export Au --model all --format json,openpbr,gltf -o "$dir/ex" 2>/dev/null
"$metalfit" export Cu --model f82-tint,conductor-rgb --format json,openpbr,gltf --params closed --gamut scale --roughness 0.05 -o "$dir/ex" 2>/dev/null
"$metalfit" export Ag --model f82-tint --format json,openpbr,gltf --id-prefix studio -o "$dir/ex-studio" 2>/dev/null
"$metalfit" show Au --json > "$dir/show.json"
"$metalfit" show Zn --space ACEScg --json > "$dir/show-acescg.json"
# Layered materials (issue 28): the stack in the show and fit records, a constant and a table with a thickness.
"$metalfit" show Ti --film TiO2:80nm --coat 1.5 --json > "$dir/show-layered.json"
"$metalfit" fit Ti --film TiO2:80nm --coat PMMA:20um --extrapolate --model f82-tint,schlick --json -o "$dir/fit-layered.json" 2>/dev/null
"$metalfit" table --format json -o "$dir/table.json"
# The layers on table, report and export, a named finish, and the oxide colour chart with and without --versus.
"$metalfit" table Ti,Au --film TiO2:80nm --coat 1.5 --format json -o "$dir/table-layered.json"
"$metalfit" show anodized-ti-80nm --json > "$dir/show-finish.json"
"$metalfit" table Ti --film TiO2 --thickness 0:300:50nm --versus 2.488 --format json -o "$dir/oxide-chart.json"
"$metalfit" table Fe --film Fe3O4 --coat 1.5 --thickness 20nm --format json -o "$dir/oxide-chart-single.json"
"$metalfit" table Ti --film TiO2 --thickness 0:340:170nm --renderers --format json -o "$dir/renderer-film-scores.json"
"$metalfit" table --format physicallybased -o "$dir/physicallybased.json"
"$metalfit" report Au,Cu --renders off -o "$dir/report" > /dev/null
"$metalfit" report Ti --film TiO2:80nm --model f82-tint --renders off -o "$dir/report-layered" > /dev/null
# A film under a coat: the renderers' scores replaced by why they are not scored.
"$metalfit" report Ti --film TiO2:80nm --coat 1.5 --model schlick --renders off -o "$dir/report-coated-film" > /dev/null
"$metalfit" export Au --coat 1.5 --model f82-tint --format json,openpbr,gltf -o "$dir/ex-layered" 2>/dev/null
# The GPU sections of bench need glpreview: without one they are skipped, which the schema describes too.
"$metalfit" bench --quick --json --glpreview "$dir/no-glpreview" -o "$dir/bench.json" 2>/dev/null
# The catalog export of the build (every material and model) and its OpenPBR and glTF files of the materials a…
files=("$dir"/*.json "$dir/ex/metalfit_export.json" "$dir"/ex/openpbr/*.json "$dir"/ex/gltf/*.gltf "$dir/report/report.json"
       "$dir/report-layered/report.json" "$dir/report-coated-film/report.json" "$dir/ex-layered/metalfit_export.json" "$dir"/ex-layered/openpbr/*.json
       "$dir/ex-studio/metalfit_export.json" "$dir"/ex-studio/openpbr/*.json "$dir"/ex-studio/gltf/*.gltf
       "$catalog_export/metalfit_export.json" "$catalog_export"/openpbr/metalfit_a*.json "$catalog_export"/gltf/metalfit_a*.gltf)
if [ "$glpreview" != - ]; then
  cat > "$dir/scene.json" <<'EOF'
{
  "image": {"width": 48, "height": 32},
  "camera": {"position": [0.0, 1.3, 2.6], "look_at": [0.0, 1.0, 0.0], "fov_y_deg": 50},
  "environment": {"type": "room", "min": [-3, 0, -3], "max": [3, 3, 3], "reference_point": [0, 1.2, 0]},
  "spheres": [
    {"center": [-1.1, 0.9, 0.0], "radius": 0.5, "material": "Au", "fresnel": "reference", "reflection": "classic"},
    {"center": [0.0, 0.9, 0.0], "radius": 0.5, "material": "Cu", "fresnel": "f82-tint", "reflection": "box-parallax", "roughness": 0.2},
    {"center": [1.1, 0.9, 0.0], "radius": 0.5, "material": "Ag", "fresnel": "schlick", "reflection": "distance-impostor",
     "strategy": "false-position", "iterations": 4}
  ],
  "outputs": {"beauty": false, "reference": false, "difference": false, "metrics": true, "reference_samples": 16}
}
EOF
  "$glpreview" "$dir/scene.json" -o "$dir/preview" > /dev/null
  files+=("$dir/preview/metrics.json" "$dir/preview/timings.json")
  # A ring under a light: metrics.json's caustics entry (issue 35).
  cat > "$dir/ring.json" <<'EOF'
{
  "image": {"width": 48, "height": 32},
  "camera": {"position": [0.0, 2.2, 2.6], "look_at": [0, 0.2, 0], "fov_y_deg": 50},
  "environment": {"type": "room"},
  "lights": [{"type": "directional", "direction": [0, -0.35, -1], "intensity": 3}],
  "rings": [{"base": [0, 0, 0], "radius": 1.0, "height": 0.35, "arc_deg": 180, "facing_deg": -90, "material": "Au"}],
  "caustics": {"reference_photons": 4000},
  "indirect": {"paths": 16, "reference_samples": 4, "light_map_size": 8},
  "spheres": [{"center": [1.6, 0.3, 1.0], "radius": 0.3, "material": "Ag"}],
  "outputs": {"beauty": false, "reference": false, "difference": false, "metrics": true}
}
EOF
  "$glpreview" "$dir/ring.json" -o "$dir/ring" > /dev/null
  files+=("$dir/ring/metrics.json")
fi
# The measured cost table in the repository (data/model-costs.json, scripts/measure-model-costs.sh).
files+=("$schemas/../data/model-costs.json")
"$node" "$here/json_schemas.mjs" "$modules" "$schemas" "${files[@]}"
"$node" "$here/json_schemas.mjs" "$modules" "$schemas" --broken "${files[@]}"
