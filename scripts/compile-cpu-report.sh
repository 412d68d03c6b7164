#!/usr/bin/env bash
# Sums the log of scripts/compile-cpu-time.sh: CPU seconds (user + system) of the compiles and of the links, the
# projected wall time of each on 2 cores (CPU / 2), and the most expensive outputs.
# Usage: scripts/compile-cpu-report.sh LOG [how many of the most expensive to list, default 25]
set -euo pipefail
log="$1"
top="${2:-25}"
# /usr/bin/time writes "Command exited with non-zero status N" before the line of a failed command: skipped.
grep -E '^[0-9.]+ [0-9.]+ [0-9.]+ ' "$log" | awk -v top="$top" '
  { cpu = $1 + $2; kind = ($4 ~ /\.(o|gch)$/) ? "compile" : "link"; sum[kind] += cpu; n[kind]++; total += cpu
    line[NR] = sprintf("%8.1f %s", cpu, $4) }
  END {
    printf "compiles: %d, %.0f CPU s; links: %d, %.0f CPU s; all: %.0f CPU s = %.0f s on 2 cores\n",
           n["compile"], sum["compile"], n["link"], sum["link"], total, total / 2
    for (i in line) print line[i] | ("sort -rn | head -" top)
  }'
