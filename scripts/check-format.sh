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
bad=0
for f in "${files[@]}"; do
  if ! "$formatter" --style=file --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "check-format: $f is not formatted ($formatter -i $f)"
    bad=$((bad + 1))
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "check-format: $bad of ${#files[@]} files not formatted (${folders[*]})"
  exit 1
fi
echo "check-format: ${#files[@]} files formatted (${folders[*]}, $("$formatter" --version | sed 's/.*version //'))"
