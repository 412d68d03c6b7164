#!/usr/bin/env bash
# ctest export.blender_published_inputs and export.blender_headless (docs/export.md, Blender): exports gold (F0 > 1 in
# red; conductor-rgb's k beyond the Metallic BSDF's [0, 100]), copper and osmium with the models of every Blender
# mode, and a user file whose name holds a quote, an apostrophe, a backslash, a newline and U+202E, as Blender scripts
# (and the JSON record whose written parameters give the expected values), then checks them with
# tests/blender_export_check.py:
#   published: each script run against Blender's published node inputs for 4.3 (Metallic BSDF) and 4.0 (Principled v2);
#   headless:  each script run by Blender itself (Debian's, headless: one process for all the scripts), the material it
#              makes read back.
# Broken copies must be refused (a socket Blender does not have, n above the socket's range, another roughness).
# Usage: METALFIT PYTHON3 DATA_DIR published | METALFIT PYTHON3 DATA_DIR headless BLENDER
set -euo pipefail
metalfit="$1" python="$2" data="$3" mode="$4" blender="${5:-}"
check="$(dirname "$0")/blender_export_check.py"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "blender_export: $*"; exit 1; }

models=f82-tint,schlick,lazanyi,lazanyi-comp,conductor-rgb,gulbrandsen
OCIO= "$metalfit" export Au,Cu,Os --model "$models" --format json,blender --roughness 0.15 -o "$dir/catalog" 2>/dev/null
cp "$data/nk/Au/Johnson.yml" "$dir/gold.yml"
odd=$'it\'s "gold" \\ and\na \u202Eline'
OCIO= "$metalfit" export "$dir/gold.yml" --name "$odd" --model f82-tint,conductor-rgb --format json,blender \
  -o "$dir/odd" 2>/dev/null
# The odd name is in the record exactly (the expected material name comes from there).
"$python" -c 'import json, sys; r = json.load(open(sys.argv[1])); assert [m["name"] for m in r["materials"].values()] == [sys.argv[2]]' \
  "$dir/odd/metalfit_export.json" "$odd" || fail "the record does not hold the odd name"
# Every script is Python that parses, and holds only printable ASCII outside its comments.
"$python" - "$dir"/catalog/blender/*.py "$dir"/odd/blender/*.py <<'EOF' || fail "a script does not parse or holds a raw byte"
import ast, io, sys, tokenize
for path in sys.argv[1:]:
    source = open(path, encoding="utf-8").read()
    ast.parse(source, path)
    for token in tokenize.generate_tokens(io.StringIO(source).readline):
        if token.type != tokenize.COMMENT and not all(32 <= ord(c) < 127 or c in "\n" for c in token.string):
            raise SystemExit(f"{path}:{token.start[0]}: {token.string!r} holds a character outside printable ASCII")
EOF

run_check() {  # RECORD SCRIPT...
  if [ "$mode" = published ]; then
    "$python" "$check" --published "$@"
  else
    "$blender" -b --factory-startup --python-exit-code 1 --python "$check" -- "$@" 2>&1 | grep -v '^$'
    return "${PIPESTATUS[0]}"
  fi
}
run_check "$dir/catalog/metalfit_export.json" "$dir"/catalog/blender/*.py > "$dir/log" || { cat "$dir/log"; fail "catalog scripts"; }
grep -q "18 materials as expected\|36 materials as expected" "$dir/log" || { cat "$dir/log"; fail "not every script was checked"; }
run_check "$dir/odd/metalfit_export.json" "$dir"/odd/blender/*.py > "$dir/log2" || { cat "$dir/log2"; fail "the odd name"; }
cat "$dir/log" "$dir/log2"

# Broken copies are refused.
refuse() {  # WHAT SCRIPT SED
  local what="$1" script="$2" edit="$3" copy
  copy="$dir/broken/$(basename "$script")"
  mkdir -p "$dir/broken" && rm -f "$dir"/broken/*.py
  sed "$edit" "$script" > "$copy"
  cmp -s "$script" "$copy" && fail "broken copy '$what': the edit changed nothing"
  if run_check "$dir/catalog/metalfit_export.json" "$copy" > "$dir/log3" 2>&1; then
    cat "$dir/log3"; fail "broken copy '$what' was accepted"
  fi
  echo "blender_export: broken copy refused: $what ($(grep -m1 -o 'AssertionError: .*' "$dir/log3" | cut -c1-150))"
}
cu="$dir/catalog/blender/metalfit_cu_conductor_rgb.py"
refuse "another roughness" "$dir/catalog/blender/metalfit_cu_f82_tint.py" 's/^ROUGHNESS = .*/ROUGHNESS = 0.25/'
if [ "$mode" = published ]; then
  refuse "a socket Blender does not have" "$dir/catalog/blender/metalfit_cu_f82_tint.py" "s/inputs\['Edge Tint'\]/inputs['Edge Color']/"
  refuse "n above the IOR socket's 100" "$cu" 's/^IOR = (\([^,]*\),/IOR = (150.0,/'
  refuse "an enum value Blender does not have" "$cu" "s/bsdf.distribution = 'MULTI_GGX'/bsdf.distribution = 'SHARP'/"
else
  refuse "another Base Color" "$dir/catalog/blender/metalfit_os_schlick.py" 's/^BASE_COLOR_BEFORE_4_0 = (/BASE_COLOR_BEFORE_4_0 = (0.5 + /'
fi
echo "blender_export: $mode: every script as expected, broken copies refused"
