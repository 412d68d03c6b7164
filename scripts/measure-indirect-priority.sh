#!/usr/bin/env bash
# The thesis's priority scheme for virtual light sources at several evaluation rates (docs/preview.md, "Indirect light:
# virtual light sources"): renders data/scenes/indirect-room.json at 160 × 120 with indirect.evaluation_rate set to
# each value (and 256 Monte-Carlo directions per reference point) and prints, from each metrics.json's "indirect", the
# shadow rays traced and saved, the error against the gather with every shadow ray and against the Monte-Carlo
# reference (a Markdown table).
# Usage: scripts/measure-indirect-priority.sh   (needs build/bin/glpreview)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| evaluation rate | virtual lights | shadow rays (every sample) | shadow rays (priority) | saved | vs every sample (rel. RMS) | vs Monte Carlo (rel. RMS) |"
echo "|---:|---:|---:|---:|---:|---:|---:|"
for rate in 0.5 0.75 0.9 0.99 1; do
  python3 - "$rate" "$work/scene.json" <<'PY'
import json, sys
scene = json.load(open("data/scenes/indirect-room.json"))
scene["indirect"]["evaluation_rate"] = float(sys.argv[1])
scene["indirect"]["reference_samples"] = 256
scene["outputs"] = {"png": False, "reference_samples": 16}
json.dump(scene, open(sys.argv[2], "w"))
PY
  cp -r data/scenes/*.hdr "$work/" 2>/dev/null || true
  build/bin/glpreview "$work/scene.json" --size 160x120 --data-dir data -o "$work/out" > /dev/null 2>&1
  python3 - "$rate" "$work/out/metrics.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[2]))["indirect"]
print(f"| {sys.argv[1]} | {m['virtual_lights']} | {m['shadow_rays_every_sample']} | {m['shadow_rays_priority']} | "
      f"{100 * m['shadow_rays_saved']:.1f} % | {100 * m['priority_vs_every_sample_rel_rms']:.2f} % | "
      f"{100 * m['priority_vs_reference_rel_rms']:.1f} % |")
PY
done
