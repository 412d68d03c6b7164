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
"$node" "$(dirname "$0")/gltf_validator.mjs" "$modules" "$dir"/*/gltf/*.gltf
