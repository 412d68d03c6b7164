#!/usr/bin/env bash
# A compiler (and linker) launcher that appends the CPU seconds of each command to a log: one line
# "<user s> <system s> <wall s> <output file>" per compile or link, the output being the argument after -o.
# CPU time (user + system) is what a build costs whatever else the machine runs; wall time is not.
# Usage (a build folder of its own, without the compiler cache, which this launcher replaces):
#   cmake --preset release -B /tmp/cpu-release -DCMAKE_CXX_COMPILER_LAUNCHER="$PWD/scripts/compile-cpu-time.sh;/tmp/cpu-release.log" \
#         -DCMAKE_CXX_LINKER_LAUNCHER="$PWD/scripts/compile-cpu-time.sh;/tmp/cpu-release.log"
#   cmake --build /tmp/cpu-release -j2 && bash scripts/compile-cpu-report.sh /tmp/cpu-release.log
set -euo pipefail
log="$1"
shift
output=unknown
previous=
for argument in "$@"; do
  if [ "$previous" = "-o" ]; then output="$argument"; fi
  previous="$argument"
done
exec /usr/bin/time -a -o "$log" -f "%U %S %e $output" "$@"
