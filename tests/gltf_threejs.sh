#!/usr/bin/env bash
# ctest export.gltf_threejs: exports gold and copper as glTF (f82-tint and conductor-rgb, F0 clipped) and gold again
# with --gamut scale --roughness 0.05, and has three.js's GLTFLoader load each in headless chromium
# (gltf_threejs.mjs): the material and mesh three.js makes must be what the file says.
# Usage: METALFIT NODE NODE_MODULES CHROMIUM
set -euo pipefail
metalfit="$1" node="$2" modules="$3" chromium="$4"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
OCIO= "$metalfit" export Au,Cu --model f82-tint,conductor-rgb --format gltf -o "$dir/clip"
OCIO= "$metalfit" export Au --model f82-tint --format gltf --gamut scale --roughness 0.05 -o "$dir/scale"
"$node" "$(dirname "$0")/gltf_threejs.mjs" "$modules" "$chromium" "$dir"/*/gltf/*.gltf
