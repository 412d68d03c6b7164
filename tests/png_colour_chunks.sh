#!/usr/bin/env bash
# ctest preview.png_colour_chunks: glpreview renders a small scene as PNG through metalfit's sRGB display, and pngcheck
# (Debian's, an independent PNG reader that also checks every chunk's CRC) must find in each PNG the sRGB chunk, gAMA
# 0.45455 and cHRM of Rec.709 / D65 (docs/preview.md, "Outputs").
# Usage: GLPREVIEW PNGCHECK
set -euo pipefail
glpreview="$1" pngcheck="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cat > "$dir/scene.json" <<'JSON'
{
  "image": {"width": 24, "height": 16},
  "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "Au", "fresnel": "f82-tint", "reflection": "classic"}],
  "outputs": {"exr": false, "png": true, "metrics": false}
}
JSON
OCIO= "$glpreview" "$dir/scene.json" -o "$dir/out" > /dev/null
status=0
for png in "$dir"/out/*.png; do
  report="$("$pngcheck" -v "$png")" || { echo "$png: pngcheck failed"; echo "$report"; status=1; continue; }
  for expected in "chunk sRGB" "chunk gAMA at offset .*: 0.45455" "White x = 0.3127 y = 0.329,  Red x = 0.64 y = 0.33" \
                  "Green x = 0.3 y = 0.6,  Blue x = 0.15 y = 0.06"; do
    grep -q -- "$expected" <<< "$report" || { echo "$png: no '$expected' in:"; echo "$report"; status=1; }
  done
  echo "$png: sRGB, gAMA 0.45455, cHRM Rec.709 / D65"
done
exit $status
