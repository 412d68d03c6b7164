#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds a CMake preset (default: release), printing the wall time
# of each phase (deps, <preset> build).
# Usage: scripts/build.sh [preset] [cmake --build arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase-timer.sh
preset="${1:-release}"
shift || true
timed_phase deps bash scripts/install-deps.sh
configure_and_build() {  # one && chain: errexit does not apply inside a function timed_phase calls
  cmake --preset "$preset" >/dev/null && cmake --build --preset "$preset" -j "$(nproc)" "$@"
}
timed_phase "$preset build" configure_and_build "$@"
