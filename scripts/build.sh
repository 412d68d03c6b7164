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
# The presets build with Ninja. A build folder that another generator made (Make, before the presets named Ninja) is
# configured afresh: `cmake --preset` would refuse its cache. The folder of each preset, as CMakePresets.json names it.
binary_dir=build
[ "$preset" = release ] || binary_dir="build-$preset"
fresh=()
if [ -f "$binary_dir/CMakeCache.txt" ] && ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' "$binary_dir/CMakeCache.txt"; then
  fresh=(--fresh)
fi
configure_and_build() {  # one && chain: errexit does not apply inside a function timed_phase calls
  cmake --preset "$preset" "${fresh[@]}" >/dev/null && cmake --build --preset "$preset" -j "$(nproc)" "$@"
}
timed_phase "$preset build" configure_and_build "$@"
