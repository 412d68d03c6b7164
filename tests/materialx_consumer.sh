#!/usr/bin/env bash
# ctest materialx.consumer: exports gold (out of gamut, the artistic_ior clamp) and titanium nitride with every
# model as mtlx and openpbr in Linear Rec.709, and copper in ACEScg (another colorspace tag), then has the MaterialX
# library itself load, validate and generate GLSL for every document (materialx_consumer.mjs).
# Usage: METALFIT NODE NODE_MODULES GLSLANG_VALIDATOR
set -euo pipefail
metalfit="$1" node="$2" modules="$3" validator="$4"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
OCIO= "$metalfit" export Au,TiN --model all --format mtlx,openpbr -o "$dir/rec709"
OCIO= "$metalfit" export Cu --model all --format mtlx,openpbr --space ACEScg -o "$dir/acescg"
mkdir "$dir/glsl"
"$node" "$(dirname "$0")/materialx_consumer.mjs" "$modules" "$validator" "$dir/glsl" "$dir"/*/*/*.mtlx
