#!/usr/bin/env bash
# Benchmark (not a test): what `metalfit report` costs next to the fits it shows. In one run, ROUNDS interleaved
# rounds (default 3) of `metalfit fit --all --model all --json`, `metalfit report --all --model all --renders off`
# and `... --renders on`, wall seconds each; prints the medians and the ratios to the fit (docs/report.md).
# Usage: scripts/bench-report.sh [ROUNDS] [METALFIT]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds="${1:-3}"
metalfit="${2:-build/bin/metalfit}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export OCIO=
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" > /dev/null 2>&1; t1=$(date +%s.%N); awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
fit=() off=() on=()
for ((i = 0; i < rounds; ++i)); do
  fit+=("$(seconds "$metalfit" fit --all --model all --json -o "$scratch/fit.json")")
  off+=("$(seconds "$metalfit" report --all --model all --renders off -o "$scratch/report")")
  on+=("$(seconds "$metalfit" report --all --model all --renders on -o "$scratch/report")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
f=$(median "${fit[@]}") a=$(median "${off[@]}") b=$(median "${on[@]}")
printf 'bench-report: %d rounds, %s threads, median wall seconds\n' "$rounds" "$(nproc)"
printf '  fit --all --model all --json        %7.2f s\n' "$f"
printf '  report --all --renders off          %7.2f s   x%s of the fit\n' "$a" "$(ratio "$a" "$f")"
printf '  report --all --renders on           %7.2f s   x%s of the fit\n' "$b" "$(ratio "$b" "$f")"
