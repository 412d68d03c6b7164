#!/usr/bin/env bash
# Runs one fuzz target for a bounded time from its seeds: run-fuzz-target.sh TARGET KIND CORPUS_DIR SECONDS SOURCE_DIR.
# KIND: yml | csv | catalog | ocio | scene | image: which files of data/ and tests/fixtures seed it. Exits non-zero on
# a finding (libFuzzer leaves crash-* in the current folder).
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
  image) printf '\0#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n\x80\x80\x80\x81\x80\x80\x80\x81\x80\x80\x80\x81\x80\x80\x80\x81' > "$corpus/tiny-hdr" ;;
esac
# -rss_limit_mb: a header that makes a reader allocate gigabytes is a finding too.
exec "$target" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 -timeout=10 -print_final_stats=1
