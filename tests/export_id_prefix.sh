#!/usr/bin/env bash
# metalfit export --id-prefix (docs/export.md): a prefixed export renames every per-material identifier and file,
# keeps the shared model functions byte for byte, and can be used beside a default export of the same material in one
# GLSL or HLSL shader (glslangValidator) and one C++ translation unit (the build's compiler, run). Bad prefixes are
# usage errors (exit 2, nothing written); an export into a folder recorded with another prefix is refused (exit 3,
# one line naming the file and both prefixes) and leaves the folder as it was.
# Usage: METALFIT GLSLANG_VALIDATOR CXX
set -euo pipefail
metalfit="$1" validator="$2" cxx="$3"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
export OCIO=
fail() { echo "export_id_prefix: $*"; exit 1; }

# Bad prefixes: one line, exit 2, before any work (no folder made).
for bad in "" Studio 1studio my-studio "my studio" x__y studio_ gl float uniform float3 abcdefghijklmnopqrstuvwxyz012345; do
  rc=0; "$metalfit" export Au --model f82-tint --format glsl --id-prefix "$bad" -o "$dir/bad" 2> "$dir/err" || rc=$?
  [ "$rc" -eq 2 ] || fail "--id-prefix '$bad': exit $rc, expected 2"
  [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q -- "--id-prefix '$bad'" "$dir/err" || { cat "$dir/err"; fail "--id-prefix '$bad': not one line naming it"; }
  [ ! -e "$dir/bad" ] || fail "--id-prefix '$bad' made the folder"
done
# The longest and shortest good prefixes.
"$metalfit" export Au --model schlick --format glsl --id-prefix abcdefghijklmnopqrstuvwxyz01234 -o "$dir/long" 2>/dev/null
[ -f "$dir/long/glsl/abcdefghijklmnopqrstuvwxyz01234_au_schlick.glsl" ] || fail "31-character prefix not written"
"$metalfit" export Au --model schlick --format glsl --id-prefix s -o "$dir/short" 2>/dev/null
[ -f "$dir/short/glsl/s_au_schlick.glsl" ] || fail "one-letter prefix not written"

# The same materials, every model and format, with the default prefix and with "studio".
"$metalfit" export Au,Cu-Zn --model all --format all -o "$dir/default" 2>/dev/null
"$metalfit" export Au,Cu-Zn --model all --format all --id-prefix studio -o "$dir/studio" 2>/dev/null
files=$(cd "$dir/default" && find . -type f | sort)
# File for file the same layout, metalfit_ → studio_ except the shared files.
expected=$(echo "$files" | sed -E '/metalfit_(models\.(glsl|hlsl|hpp|metal|wgsl)|export\.json)$/!s#/metalfit_#/studio_#' | sort)
actual=$(cd "$dir/studio" && find . -type f | sort)
[ "$expected" = "$actual" ] || { diff <(echo "$expected") <(echo "$actual") | head; fail "the studio files are not the default ones renamed"; }
# File for file the same text but for the per-material names (and the record's id_prefix): nothing else moved.
python3 - "$dir/default" "$dir/studio" <<'PY' || fail "a studio file differs from its default one by more than the names"
import pathlib, re, sys
default, studio = map(pathlib.Path, sys.argv[1:])
rename = lambda t: re.sub(r"METALFIT_(AU|CU_ZN)_", r"STUDIO_\1_", re.sub(r"metalfit_(au_|cu_zn_|materials)", r"studio_\1", t))
for f in default.rglob("*"):
    if not f.is_file(): continue
    g = studio / rename(str(f.relative_to(default)))
    want = rename(f.read_text())
    if f.name == "metalfit_export.json": want = want[:want.rindex("}")].rstrip() + ',\n  "id_prefix": "studio"\n}\n'
    if g.read_text() != want: sys.exit(f"{g} is not {f} renamed")
PY
for f in glsl/metalfit_models.glsl hlsl/metalfit_models.hlsl cpp/metalfit_models.hpp msl/metalfit_models.metal wgsl/metalfit_models.wgsl; do
  cmp -s "$dir/default/$f" "$dir/studio/$f" || fail "$f differs between the default and the studio export"
done
# No per-material identifier keeps the default prefix; the shared model functions are still called.
if grep -rniE 'metalfit_(au|cu_zn)_|metalfit_materials' "$dir/studio" > "$dir/left"; then head -5 "$dir/left"; fail "metalfit_<material> identifiers left in the studio export"; fi
grep -q 'return metalfit_f82_tint(STUDIO_AU_F82_TINT_F0, STUDIO_AU_F82_TINT_TINT, mu);' "$dir/studio/glsl/studio_au_f82_tint.glsl" ||
  fail "studio_au_f82_tint.glsl does not call the shared metalfit_f82_tint with STUDIO_ constants"
grep -q '"id_prefix": "studio"' "$dir/studio/metalfit_export.json" || fail "metalfit_export.json does not record the prefix"
! grep -q '"id_prefix"' "$dir/default/metalfit_export.json" || fail "the default export records a prefix"
grep -q 'name="studio_au_f82_tint_material"' "$dir/studio/mtlx/studio_au_f82_tint.mtlx" || fail "MaterialX material name"
grep -q '"name": "studio_au_f82_tint"' "$dir/studio/gltf/studio_au_f82_tint.gltf" || fail "glTF material name"

models=$("$metalfit" models --json | python3 -c 'import json,sys; print(" ".join(m["id"].replace("-", "_") for m in json.load(sys.stdin)))')
compile() {  # FILE WHAT [glslangValidator options]
  local file="$1" what="$2"; shift 2
  "$validator" "$@" "$file" > "$dir/log" || { head -40 "$dir/log"; fail "$what does not compile"; }
}
# GLSL: both folders' models files and constants files in one shader, calling both prefixes' functions.
for version in "330" "300 es"; do
  {
    echo "#version $version"
    cat "$dir/default/glsl/metalfit_models.glsl" "$dir/studio/glsl/metalfit_models.glsl"
    for mat in au cu_zn; do for m in $models; do
      cat "$dir/default/glsl/metalfit_${mat}_${m}.glsl" "$dir/studio/glsl/studio_${mat}_${m}.glsl"
    done; done
    echo 'uniform float mu;'
    echo 'out vec4 colour;'
    echo 'void main() {'
    echo '    vec3 sum = vec3(0.0);'
    for mat in au cu_zn; do for m in $models; do
      echo "    sum += metalfit_${mat}_${m}(mu) - studio_${mat}_${m}(mu);"
    done; done
    echo '    colour = vec4(sum, 1.0);'
    echo '}'
  } > "$dir/shader.frag"
  compile "$dir/shader.frag" "GLSL $version of both prefixes"
done
# HLSL (compute), the same.
{
  cat "$dir/default/hlsl/metalfit_models.hlsl" "$dir/studio/hlsl/metalfit_models.hlsl"
  for m in $models; do cat "$dir/default/hlsl/metalfit_au_${m}.hlsl" "$dir/studio/hlsl/studio_au_${m}.hlsl"; done
  echo 'RWStructuredBuffer<float4> v : register(u0);'
  echo '[numthreads(1, 1, 1)] void main() {'
  i=1; for m in $models; do echo "    v[$i].xyz = metalfit_au_${m}(v[0].w) - studio_au_${m}(v[0].w);"; i=$((i + 1)); done
  echo '}'
} > "$dir/shader.hlsl"
compile "$dir/shader.hlsl" "HLSL of both prefixes" -V -D -S comp -e main -o "$dir/shader.spv"

# C++: a default and a studio export in one folder (cpp only: no record) share cpp/metalfit_models.hpp; one
# translation unit includes both indexes, and every entry of one evaluates to the same values as the other's.
"$metalfit" export Au,Cu-Zn --model all --format cpp -o "$dir/both" 2>/dev/null
"$metalfit" export Au,Cu-Zn --model all --format cpp --id-prefix studio -o "$dir/both" 2>/dev/null
cat > "$dir/both.cpp" <<'EOF'
#include <cstdio>
#include "metalfit_materials.hpp"
#include "studio_materials.hpp"
static_assert(std::tuple_size_v<decltype(metalfit_materials::all)> == std::tuple_size_v<decltype(studio_materials::all)>);
int main() {
    int same = 0;
    for (std::size_t i = 0; i < metalfit_materials::all.size(); ++i) {
        const auto& a = metalfit_materials::all[i];
        const auto& b = studio_materials::all[i];
        const metalfit_shader::vec3 x = a.evaluate(0.3f), y = b.evaluate(0.3f);
        if (std::string_view(a.material) == b.material && std::string_view(a.model) == b.model && x.x == y.x &&
            x.y == y.y && x.z == y.z && a.parameters[0] != b.parameters[0])
            ++same;
    }
    std::printf("%d\n", same);
    return 0;
}
EOF
sed -i '1i #include <string_view>' "$dir/both.cpp"
"$cxx" -std=c++20 -Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Werror -I "$dir/both/cpp" "$dir/both.cpp" -o "$dir/both.exe" ||
  fail "the default and studio C++ headers do not compile in one translation unit"
n=$(echo "$models" | wc -w)
[ "$("$dir/both.exe")" -eq $((2 * n)) ] || fail "C++: $("$dir/both.exe") of $((2 * n)) entries equal across the prefixes"

# A folder holds one prefix: another prefix into a folder with a record is refused, the folder unchanged (both ways).
snapshot() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum); }
for pair in "default studio" "studio metalfit"; do
  set -- $pair
  before=$(snapshot "$dir/$1")
  rc=0; "$metalfit" export Ag --model f82-tint --format json,glsl --id-prefix "$2" -o "$dir/$1" 2> "$dir/err" || rc=$?
  [ "$rc" -eq 3 ] || { cat "$dir/err"; fail "--id-prefix $2 into the $1 folder: exit $rc, expected 3"; }
  there=$([ "$1" = default ] && echo metalfit || echo studio)
  [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q "$dir/$1/metalfit_export.json" "$dir/err" && grep -q "\"$there\"" "$dir/err" &&
    grep -q "\"$2\"" "$dir/err" || { cat "$dir/err"; fail "the refusal is not one line naming the file and both prefixes"; }
  [ "$before" = "$(snapshot "$dir/$1")" ] || fail "the refused export changed the $1 folder"
done
# The same prefix again adds to the folder and its index.
"$metalfit" export Ag --model f82-tint --format json,cpp --id-prefix studio -o "$dir/studio" 2>/dev/null
grep -q '#include "studio_ag_f82_tint.hpp"' "$dir/studio/cpp/studio_materials.hpp" && grep -q '#include "studio_au_f82_tint.hpp"' "$dir/studio/cpp/studio_materials.hpp" ||
  fail "a second studio export did not merge cpp/studio_materials.hpp"
grep -q '"id_prefix": "studio"' "$dir/studio/metalfit_export.json" || fail "the merged record lost its prefix"
echo "export_id_prefix: $(echo "$files" | wc -l) files renamed, GLSL/HLSL of both prefixes in one shader, C++ $((2 * n)) entries equal in one translation unit, mixed prefixes refused"
