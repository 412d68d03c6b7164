#!/usr/bin/env bash
# glpreview's start-up and one render, two builds compared (docs/preview.md, "Start-up"): `--version` and a scene,
# run alternately RUNS times each (default 5) under /usr/bin/time; prints the median CPU (user + sys), wall and peak
# memory per build, the number of shared libraries (ldd) and the load average.
# Usage: scripts/bench-glpreview-startup.sh BEFORE_GLPREVIEW AFTER_GLPREVIEW SCENE.json [RUNS]
set -euo pipefail
before="$1" after="$2" scene="$3" runs="${4:-5}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for what in version scene; do
  for ((i = 0; i < runs; ++i)); do
    for build in before after; do
      exe="${!build}"
      if [ "$what" = version ]; then args=(--version); else args=("$scene" -o "$dir/out-$build"); fi
      OCIO= /usr/bin/time -f "%U %S %e %M" -o "$dir/t" "$exe" "${args[@]}" > /dev/null 2>&1
      awk '{printf "%.2f %.2f %d\n", $1 + $2, $3, $4}' "$dir/t" >> "$dir/$what-$build"
    done
  done
done
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf "%-8s %-7s %9s %9s %12s %5s\n" build run "CPU s" "wall s" "peak MiB" libs
for build in before after; do
  exe="${!build}"
  for what in version scene; do
    f="$dir/$what-$build"
    printf "%-8s %-7s %9s %9s %12s %5s\n" "$build" "$what" "$(cut -d' ' -f1 "$f" | median)" "$(cut -d' ' -f2 "$f" | median)" \
      "$(cut -d' ' -f3 "$f" | median | awk '{printf "%.1f", $1 / 1024}')" "$(ldd "$exe" | wc -l)"
  done
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
