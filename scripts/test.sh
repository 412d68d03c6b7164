#!/usr/bin/env bash
# The test command of the README (and of CI): installs what is missing, builds, runs every test, printing the wall
# time of each phase (deps, <preset> build, <preset> tests).
# Usage: scripts/test.sh [preset]   (release by default; asan for AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase-timer.sh
preset="${1:-release}"
bash scripts/build.sh "$preset"
timed_phase "$preset tests" ctest --preset "$preset" -j "$(nproc)"
