#!/usr/bin/env bash
# Runs one fuzz target for a bounded time from its seeds: run-fuzz-target.sh TARGET KIND CORPUS_DIR SECONDS SOURCE_DIR.
# KIND: yml | csv | catalog | ocio | scene | image: which files of data/ and tests/fixtures seed it, besides the
# target's committed corpus fuzz/corpus/<target>/. Exits non-zero on a finding: a crash, a sanitizer report, an
# input over 10 s or 2 GiB (libFuzzer leaves crash-*, timeout-* or oom-* in the current folder).
set -euo pipefail
target=$1 kind=$2 corpus=$3 seconds=$4 src=$5
mkdir -p "$corpus"
# Seeds named after their path, so that data/nk/Au/Johnson.yml and data/nk/Cu/Johnson.yml are both kept.
seed() { for f in "$@"; do cp "$f" "$corpus/$(printf '%s' "$f" | sha256sum | cut -c1-16)-$(basename "$f")"; done; }
case $kind in
  yml) mapfile -t files < <(find "$src/data/nk" "$src/tests/fixtures" -name '*.yml'); seed "${files[@]}" ;;
  csv) mapfile -t files < <(find "$src/tests/fixtures" -name '*.csv'); seed "${files[@]}" ;;
  catalog) seed "$src/data/catalog.json" ;;
  ocio) seed "$src/data/ocio/config.ocio" ;;
  scene) mapfile -t files < <(find "$src/data/scenes" -name '*.json'); seed "${files[@]}" ;;
  image) ;;  # fuzz/corpus/fuzz_image_header: a tiny .hdr and .exr (the first byte picks the extension)
esac
committed="$src/fuzz/corpus/$(basename "$target")"
if [ -d "$committed" ]; then mapfile -t files < <(find "$committed" -type f); seed "${files[@]}"; fi
# -rss_limit_mb: a header that makes a reader allocate gigabytes is a finding too.
exec "$target" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 -timeout=10 -print_final_stats=1
