#!/usr/bin/env bash
# ctest gltf.validator: exports gold (F0 > 1 in red: clipped, and scaled with --gamut scale), copper, titanium nitride
# and osmium with every model as glTF (Linear Rec.709), and has the Khronos glTF-Validator (npm gltf-validator)
# validate each asset (gltf_validator.mjs): any error fails.
# Usage: METALFIT NODE NODE_MODULES
set -euo pipefail
metalfit="$1" node="$2" modules="$3"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
OCIO= "$metalfit" export Au,Cu,TiN,Os --model all --format gltf -o "$dir/clip"
OCIO= "$metalfit" export Au --model all --format gltf --gamut scale --roughness 0.05 -o "$dir/scale"
# Layered materials (docs/export.md, Layered exports): KHR_materials_iridescence, KHR_materials_clearcoat and both.
OCIO= "$metalfit" export Ti --film TiO2:80nm --model f82-tint,conductor-rgb --format gltf -o "$dir/layered-film"
OCIO= "$metalfit" export lacquered-brass --model f82-tint,conductor-rgb --format gltf -o "$dir/layered-coat"
OCIO= "$metalfit" export Au --coat 1.5 --film 2.2:300nm --model f82-tint --format gltf -o "$dir/layered-both"
"$node" "$(dirname "$0")/gltf_validator.mjs" "$modules" "$dir"/*/gltf/*.gltf
