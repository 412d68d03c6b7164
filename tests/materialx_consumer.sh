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
# Layered materials (docs/export.md, Layered exports): a thin film (thinfilm_* on the metal's BSDF; OpenPBR thin_film_*),
# a coat (layer of a dielectric_bsdf over the metal; OpenPBR coat_*) and both, every MaterialX form of the metal.
OCIO= "$metalfit" export Ti --film TiO2:80nm --model all --format mtlx,openpbr -o "$dir/layered-film"
OCIO= "$metalfit" export lacquered-brass --model all --format mtlx,openpbr -o "$dir/layered-coat"
OCIO= "$metalfit" export Au --coat 1.5 --film 2.2:300nm --model f82-tint,conductor-rgb,gulbrandsen --format mtlx,openpbr \
  -o "$dir/layered-both"
mkdir "$dir/glsl"
"$node" "$(dirname "$0")/materialx_consumer.mjs" "$modules" "$validator" "$dir/glsl" "$dir"/*/*/*.mtlx
