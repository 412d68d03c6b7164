#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds a CMake preset (default: release).
# Usage: scripts/build.sh [preset] [cmake --build arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
shift || true
bash scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" "$@"
