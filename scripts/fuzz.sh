#!/usr/bin/env bash
# Runs every libFuzzer target of fuzz/ for SECONDS each (default 60) from its seeds (data/, tests/fixtures and the
# committed fuzz/corpus/<target>/), one after another, and fails on any finding (crash, sanitizer report, timeout
# of 10 s, 2 GiB of memory). Prints each target's executions. Needs the fuzz build (docs/development.md, "Fuzzing"):
#   cmake --preset fuzz && cmake --build --preset fuzz -j2 && bash scripts/fuzz.sh 60
# Findings and the grown corpora stay in $FUZZ_WORK (default: a fresh folder under /tmp, printed).
set -uo pipefail
seconds=${1:-60}
src=$(cd "$(dirname "$0")/.." && pwd)
bin=${FUZZ_BIN:-$src/build-fuzz/bin}
work=${FUZZ_WORK:-$(mktemp -d /tmp/metalfit-fuzz.XXXXXX)}
export OCIO=  # metalfit's own config where a target needs one
failed=0
printf '%-28s %12s %10s %s\n' target executions exec/s result
for pair in fuzz_refractiveindex_yaml:yml fuzz_csv:csv fuzz_catalog:catalog fuzz_ocio_config:ocio fuzz_scene:scene \
            fuzz_image_header:image; do
  target=${pair%%:*} kind=${pair##*:}
  if [ ! -x "$bin/$target" ]; then
    printf '%-28s %12s %10s %s\n' "$target" - - "not built ($bin/$target)"; failed=1; continue
  fi
  mkdir -p "$work/$target"
  log="$work/$target.log"
  (cd "$work/$target" && bash "$src/fuzz/run-fuzz-target.sh" "$bin/$target" "$kind" "$work/$target/corpus" "$seconds" "$src") >"$log" 2>&1
  rc=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  if [ $rc -eq 0 ]; then result=ok; else result="FINDING (exit $rc; $log, $(ls "$work/$target" | grep -E '^(crash|timeout|oom|leak)-' | tr '\n' ' '))"; failed=1; fi
  printf '%-28s %12s %10s %s\n' "$target" "${runs:-?}" "${rate:-?}" "$result"
done
echo "logs and corpora: $work"
exit $failed
