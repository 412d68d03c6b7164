#!/usr/bin/env bash
# Compiles every GLSL and HLSL export of the catalog (every material and model) with the Khronos reference compiler,
# unchanged, as GLSL 3.30 and GLSL ES 3.00 (fragment shaders: ES has no default float precision there, so the
# models file's `#ifdef GL_ES` precision block is what makes it compile), GLSL 4.50 (compute) and HLSL (compute):
# per material, the shared model functions — twice, to check the include guards — then each of its constants files
# (also twice), in a shader that calls every material function (so a wrong constant or signature fails).
# Usage: METALFIT GLSLANG_VALIDATOR [EXPORT_DIR]   (EXPORT_DIR: an `export --all --model all` with glsl and hlsl, as the
# build makes it for the tests; without it the script makes its own)
set -euo pipefail
metalfit="$1" validator="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
if [ $# -ge 3 ]; then
  ln -s "$(realpath "$3")" "$dir/out"
else
  OCIO= "$metalfit" export --all --model all --format glsl,hlsl -o "$dir/out"
fi
models=$("$metalfit" models --json | python3 -c 'import json,sys; print(" ".join(m["id"].replace("-", "_") for m in json.load(sys.stdin)))')
materials=$("$metalfit" list --json | python3 -c 'import json,re,sys; print(" ".join(re.sub("[^a-z0-9]", "_", m["id"].lower()) for m in json.load(sys.stdin)))')
# One shader per language holding every export: the models file and every constants file, each included twice. The
# body is written once (one cat of every file) and each GLSL version puts its own first and last lines around it; the
# calls are made with bash's own substitution: a cat or a sed per file and per call (2,700 processes) were most of
# this test's time.
glsl_files=("$dir/out/glsl/metalfit_models.glsl" "$dir/out/glsl/metalfit_models.glsl")
for mat in $materials; do for m in $models; do
  glsl_files+=("$dir/out/glsl/metalfit_${mat}_${m}.glsl" "$dir/out/glsl/metalfit_${mat}_${m}.glsl")
done; done
cat "${glsl_files[@]}" > "$dir/body.glsl"
glsl_body() { cat "$dir/body.glsl"; }
calls() {  # every material function, into PREFIX[i] or a sum
  local i=1 mat m line
  for mat in $materials; do for m in $models; do
    line="    $1 metalfit_${mat}_${m}($2);"
    echo "${line//#/$i}"
    i=$((i + 1))
  done; done
}
compile() {  # FILE WHAT [glslangValidator options]
  local file="$1" what="$2"; shift 2
  "$validator" "$@" "$file" > "$dir/log" || { head -40 "$dir/log"; echo "export_shaders_compile: $what does not compile"; exit 1; }
}
for version in "330" "300 es"; do
  {
    echo "#version $version"
    glsl_body
    echo 'uniform float mu;'
    echo 'out vec4 colour;'
    echo 'void main() {'
    echo '    vec3 sum = vec3(0.0);'
    calls 'sum +=' mu
    echo '    colour = vec4(sum, 1.0);'
    echo '}'
  } > "$dir/shader.frag"
  compile "$dir/shader.frag" "GLSL $version"
done
{
  echo '#version 450'
  glsl_body
  echo 'layout(local_size_x = 1) in;'
  echo 'layout(std430, binding = 0) buffer Values { vec4 v[]; };'
  echo 'void main() {'
  calls 'v[#].xyz =' 'v[0].w'
  echo '}'
} > "$dir/shader.comp"
compile "$dir/shader.comp" "GLSL 450"
# HLSL per material (glslang's HLSL front end takes ~30 s on one shader of every export, 0.1 s per material).
called=0
for mat in $materials; do
  hlsl_files=("$dir/out/hlsl/metalfit_models.hlsl" "$dir/out/hlsl/metalfit_models.hlsl")
  for m in $models; do hlsl_files+=("$dir/out/hlsl/metalfit_${mat}_${m}.hlsl" "$dir/out/hlsl/metalfit_${mat}_${m}.hlsl"); done
  {
    cat "${hlsl_files[@]}"
    echo 'RWStructuredBuffer<float4> v : register(u0);'
    echo '[numthreads(1, 1, 1)] void main() {'
    i=1; for m in $models; do echo "    v[$i].xyz = metalfit_${mat}_${m}(v[0].w);"; i=$((i + 1)); done
    echo '}'
  } > "$dir/shader.hlsl"
  # HLSL input (-D) needs SPIR-V generation (-V) and the entry point (-e).
  compile "$dir/shader.hlsl" "HLSL of $mat" -V -D -S comp -e main -o "$dir/shader.spv"
  called=$((called + $(grep -c 'v\[[0-9]*\].xyz = metalfit_' "$dir/shader.hlsl")))
done
n=$(( $(echo $models | wc -w) * $(echo $materials | wc -w) ))
files=$(ls "$dir"/out/glsl/metalfit_*.glsl | grep -vc metalfit_models.glsl)
echo "export_shaders_compile: $n GLSL exports compiled as GLSL 3.30, ES 3.00 and 4.50, $called HLSL ($files constants files written per language)"
[ "$n" -eq "$files" ] && [ "$called" -eq "$files" ]
