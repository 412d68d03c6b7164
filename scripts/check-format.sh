#!/usr/bin/env bash
# Fails (exit 1) when a C++ source of the given folders differs from what clang-format makes of it (.clang-format at
# the root), naming each file; exit 0 when all are formatted. The ctest format.check runs it.
# Usage: scripts/check-format.sh [folder...]   (default: every source folder)
# Format a folder in place: clang-format -i $(git ls-files 'libfit/*.cpp' 'libfit/*.hpp')
set -euo pipefail
cd "$(dirname "$0")/.."
folders=("$@")
[ ${#folders[@]} -gt 0 ] || folders=(libfit tools bench tests fuzz glpreview)
# Debian installs clang-format as clang-format (package clang-format) and clang-format-<version>.
formatter=""
for candidate in clang-format clang-format-14 clang-format-15 clang-format-16; do
  if command -v "$candidate" >/dev/null 2>&1; then formatter="$candidate"; break; fi
done
if [ -z "$formatter" ]; then
  echo "check-format: clang-format not found (scripts/install-deps.sh installs it)" >&2
  exit 2
fi
files=()
for folder in "${folders[@]}"; do
  [ -d "$folder" ] || { echo "check-format: no folder $folder" >&2; exit 2; }
  while IFS= read -r -d '' f; do files+=("$f"); done < <(find "$folder" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print0 | sort -z)
done
# One clang-format process for every file (a process per file spent most of the check starting clang-format): it
# goes on after a file that differs and names each one in a "FILE:LINE:COL: error: code should be clang-formatted"
# line; any other failure (an unreadable file, a bad .clang-format) is printed as it is.
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
bad=0
if ! "$formatter" --style=file --dry-run -Werror "${files[@]}" >/dev/null 2>"$log"; then
  unformatted=()
  while IFS= read -r f; do unformatted+=("$f"); done < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' "$log" | sort -u)
  if [ ${#unformatted[@]} -eq 0 ]; then
    cat "$log" >&2
    echo "check-format: $formatter failed" >&2
    exit 2
  fi
  for f in "${unformatted[@]}"; do echo "check-format: $f is not formatted ($formatter -i $f)"; done
  bad=${#unformatted[@]}
fi
if [ "$bad" -gt 0 ]; then
  echo "check-format: $bad of ${#files[@]} files not formatted (${folders[*]})"
  exit 1
fi
echo "check-format: ${#files[@]} files formatted (${folders[*]}, $("$formatter" --version | sed 's/.*version //'))"
