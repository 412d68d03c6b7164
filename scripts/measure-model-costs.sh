#!/usr/bin/env bash
# The measured cost table (docs/fitting.md, "Costs"): runs `metalfit bench --model-costs --json`, which times every
# model's shader on the software GPU (glpreview --bench-shaders on llvmpipe, process CPU time) and its C++ array loop
# (thread CPU time), both in interleaved rounds as ratios to conductor-rgb with their noise, counts its SPIR-V
# (plain and class-weighted) and prints the rank correlations; writes data/model-costs.json, which libfit embeds at
# build time as its built-in cost table (rebuild after running this). About 2 minutes on 2 cores.
# Usage: scripts/measure-model-costs.sh [BUILD_DIR]   (needs BUILD_DIR/bin/metalfit and glpreview; default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
# Mesa's software rasteriser whatever the machine has: the table is llvmpipe's.
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
"$build/bin/metalfit" bench --model-costs --json -o data/model-costs.json
