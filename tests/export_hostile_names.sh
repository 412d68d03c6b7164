#!/usr/bin/env bash
# Names are data (docs/export.md): text that came from an input — `--name`, `--reference`, a file's name, a YAML's
# REFERENCES and COMMENTS — holding a newline, `#error`, `#define`, `*/`, a quote, `<`, `&`, U+202E, `../` and a
# trailing backslash is exported in every format, and
#   - every file lands inside -o (nothing else appears in the scratch folder; the report's page stays in materials/);
#   - the GLSL compiles with the Khronos reference compiler (3.30, 4.50) and the HLSL with its HLSL front end, the C++
#     with g++ -Wall -Wextra -Werror (-Wbidi-chars is on by default), each calling the exported function;
#   - no line of a shader or C++ file starts with the injected directives;
#   - the MaterialX, OpenPBR and glTF/JSON files parse (Python's XML and JSON parsers: independent readers), and the
#     JSON keeps the name exactly as given (data, escaped by the format, not rewritten).
# Usage: METALFIT GLSLANG_VALIDATOR CXX DATA_DIR
set -euo pipefail
metalfit="$1" validator="$2" cxx="$3" data="$4"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export OCIO=
hostile=$'evil\n#error injected by a name\n#define METALFIT_INJECTED 1\n*/ "quoted" <b>bold</b> &amp; \u202Eright-to-left ../../escaped \\'
fail() { echo "export_hostile_names: $*"; exit 1; }

check_export() {  # WHAT OUT_DIR EXPECTED_NAME
  local what="$1" out="$2" expected="$3"
  [ -d "$out/glsl" ] || fail "$what: no glsl folder in $out"
  # No injected directive became a line of code.
  if grep -rlE '^[[:space:]]*#(error|define METALFIT_INJECTED)' "$out/glsl" "$out/hlsl" "$out/cpp" >/dev/null; then
    grep -rnE '^[[:space:]]*#(error|define METALFIT_INJECTED)' "$out/glsl" "$out/hlsl" "$out/cpp" | head -5
    fail "$what: an injected directive is a line of code"
  fi
  local glsl hlsl function
  glsl=$(find "$out/glsl" -name 'metalfit_*_f82_tint.glsl' | head -1)
  hlsl=$(find "$out/hlsl" -name 'metalfit_*_f82_tint.hlsl' | head -1)
  [ -n "$glsl" ] && [ -n "$hlsl" ] || fail "$what: no f82-tint shader files"
  function=$(basename "$glsl" .glsl)
  for version in 330 450; do
    { echo "#version $version"; cat "$out/glsl/metalfit_models.glsl" "$glsl"
      echo 'uniform float mu;'; echo 'out vec4 colour;'
      echo "void main() { colour = vec4($function(mu), 1.0); }"; } > "$scratch/shader.frag"
    "$validator" "$scratch/shader.frag" > "$scratch/log" || { head -20 "$scratch/log"; fail "$what: GLSL $version does not compile"; }
  done
  { cat "$out/hlsl/metalfit_models.hlsl" "$hlsl"
    echo 'RWStructuredBuffer<float4> values : register(u0);'
    echo '[numthreads(1, 1, 1)] void main() {'
    echo "    values[0] = float4($function(values[0].w), 1.0);"
    echo '}'; } > "$scratch/shader.hlsl"
  "$validator" -V -D -S comp -e main -o "$scratch/shader.spv" "$scratch/shader.hlsl" > "$scratch/log" || { head -20 "$scratch/log"; fail "$what: HLSL does not compile"; }
  printf '#include "%s"\nfloat first(float mu) { return metalfit_materials::all[0].evaluate(mu).x; }\n' \
    "$out/cpp/metalfit_materials.hpp" > "$scratch/use.cpp"
  "$cxx" -std=c++20 -Wall -Wextra -Werror -fsyntax-only "$scratch/use.cpp" 2> "$scratch/log" ||
    { head -20 "$scratch/log"; fail "$what: the C++ export does not compile cleanly"; }
  python3 - "$out" "$expected" <<'EOF' || fail "$what: an XML or JSON file does not parse or lost the name"
import json, pathlib, sys, xml.etree.ElementTree as ET
out, expected = pathlib.Path(sys.argv[1]), sys.argv[2]
xml_files = list(out.glob("mtlx/*.mtlx")) + list(out.glob("openpbr/*.mtlx"))
assert xml_files, "no MaterialX files"
for f in xml_files:
    ET.parse(f)  # raises on an ill-formed document (a control character, a broken comment)
for f in list(out.rglob("*.json")) + list(out.rglob("*.gltf")):
    json.loads(f.read_text(encoding="utf-8"))
record = json.loads((out / "metalfit_export.json").read_text(encoding="utf-8"))
names = {m["name"] for m in record["materials"]} if isinstance(record.get("materials"), list) else \
        {m["name"] for m in record["materials"].values()}
assert expected in names, (expected, names)
# The Blender scripts parse as Python, and their MATERIAL_NAME evaluates (Python itself reading the literal) to the name.
import ast
scripts = list(out.glob("blender/*.py"))
assert scripts, "no Blender scripts"
for f in scripts:
    tree = ast.parse(f.read_text(encoding="utf-8"), str(f))
    assigned = {t.targets[0].id: t.value for t in tree.body
                if isinstance(t, ast.Assign) and isinstance(t.targets[0], ast.Name)}
    name = eval(compile(ast.Expression(assigned["MATERIAL_NAME"]), str(f), "eval"), {"__builtins__": {}})
    assert name.startswith(expected + " (metalfit "), (f, name)
EOF
}

# 1. --name and --reference on a well-formed file.
cp "$data/nk/Au/Johnson.yml" "$scratch/gold.yml"
mkdir "$scratch/run1"
(cd "$scratch/run1" && "$metalfit" export "$scratch/gold.yml" --name "$hostile" --reference "$hostile" \
   --model f82-tint,conductor-rgb --format all -o out > /dev/null 2> "$scratch/err") || { cat "$scratch/err"; fail "export with a hostile --name failed"; }
[ "$(ls -A "$scratch/run1")" = "out" ] || fail "run 1 wrote beside out/: $(ls -A "$scratch/run1" | tr '\n' ' ')"
check_export "--name/--reference" "$scratch/run1/out" "$hostile"

# 2. The file's own name and its REFERENCES and COMMENTS (no --name: the file stem is the name).
mkdir "$scratch/run2"
file="$scratch/run2/${hostile//\//_}.yml"  # a file name cannot hold '/': the stem keeps everything else
{ printf 'REFERENCES: "%s"\n' "$(printf '%s' "$hostile" | sed 's/\\/\\\\/g; s/"/\\"/g' | sed ':a;N;$!ba;s/\n/\\n/g')"
  printf 'COMMENTS: "%s"\n' "$(printf '%s' "$hostile" | sed 's/\\/\\\\/g; s/"/\\"/g' | sed ':a;N;$!ba;s/\n/\\n/g')"
  sed -n '/^DATA:/,$p' "$scratch/gold.yml"; } > "$file"
stem="$(basename "$file" .yml)"
(cd "$scratch/run2" && "$metalfit" export "$file" --model f82-tint,conductor-rgb --format all -o out > /dev/null 2> "$scratch/err") ||
  { cat "$scratch/err"; fail "export of a hostile file name failed"; }
[ "$(ls -A "$scratch/run2" | grep -vxF "$(basename "$file")")" = "out" ] || fail "run 2 wrote beside out/"
check_export "file name, REFERENCES, COMMENTS" "$scratch/run2/out" "$stem"

# 3. The report: a name with ../ keeps its page inside the report folder.
mkdir "$scratch/run3"
if (cd "$scratch/run3" && "$metalfit" report "$scratch/gold.yml" --name '../../../x' --renders off -o rep > /dev/null 2> "$scratch/err"); then
  [ "$(ls -A "$scratch/run3")" = "rep" ] || fail "the report wrote beside its folder: $(ls -A "$scratch/run3" | tr '\n' ' ')"
  [ ! -e "$scratch/x.html" ] && [ ! -e "$scratch/run3/x.html" ] || fail "the report wrote x.html outside its folder"
  page=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["materials"][0]["page"])' "$scratch/run3/rep/report.json")
  [ -f "$scratch/run3/rep/$page" ] || fail "the report's page $page is not in the folder"
  case "$page" in materials/*.html) ;; *) fail "the page is $page, not under materials/";; esac
  case "$page" in *..*/*|*/../*) fail "the page $page climbs";; esac
elif grep -q "chart libraries" "$scratch/err"; then
  echo "export_hostile_names: the report part skipped (built without the chart libraries)"
else
  cat "$scratch/err"; fail "the report of a hostile name failed"
fi
echo "export_hostile_names: every format compiles or parses, nothing outside -o"
