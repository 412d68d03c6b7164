#!/usr/bin/env bash
# Runs one fuzz target for a bounded time from its seeds: run-fuzz-target.sh TARGET KIND CORPUS_DIR SECONDS SOURCE_DIR.
# KIND: yml | csv | catalog | ocio | scene | image: which files of data/ and tests/fixtures seed it. Exits non-zero on
# a finding (libFuzzer leaves crash-* in the current folder).
set -euo pipefail
target=$1 kind=$2 corpus=$3 seconds=$4 src=$5
mkdir -p "$corpus"
case $kind in
  yml) find "$src/data/nk" "$src/tests/fixtures" -name '*.yml' -exec cp -t "$corpus" {} + ;;
  csv) find "$src/tests/fixtures" -name '*.csv' -exec cp -t "$corpus" {} + ;;
  catalog) cp "$src/data/catalog.json" "$corpus/" ;;
  ocio) cp "$src/data/ocio/config.ocio" "$corpus/" ;;
  scene) find "$src/data/scenes" "$src/tests/fixtures" -name '*.json' -path '*scene*' -exec cp -t "$corpus" {} + ;;
  image) printf '\0#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n\x80\x80\x80\x81\x80\x80\x80\x81\x80\x80\x80\x81\x80\x80\x80\x81' > "$corpus/tiny-hdr" ;;
esac
# -rss_limit_mb: a header that makes a reader allocate gigabytes is a finding too.
exec "$target" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 -timeout=10 -print_final_stats=1
