#!/usr/bin/env bash
# The test command of the README (and of CI): installs what is missing, builds, runs every test.
# Usage: scripts/test.sh [preset]   (release by default; asan for AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/build.sh "$preset"
ctest --preset "$preset" -j "$(nproc)"
