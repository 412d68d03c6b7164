#!/usr/bin/env bash
# Compiles every GLSL and HLSL export of the catalog (every material and model) with the Khronos reference compiler:
# per material, the shared model functions, then each of its constants files, in a compute shader that calls every
# material function (so a wrong constant or signature fails). Usage: METALFIT GLSLANG_VALIDATOR
set -euo pipefail
metalfit="$1" validator="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
OCIO= "$metalfit" export --all --model all --format glsl,hlsl -o "$dir/out"
models=$("$metalfit" models --json | python3 -c 'import json,sys; print(" ".join(m["id"].replace("-", "_") for m in json.load(sys.stdin)))')
materials=$("$metalfit" list --json | python3 -c 'import json,re,sys; print(" ".join(re.sub("[^a-z0-9]", "_", m["id"].lower()) for m in json.load(sys.stdin)))')
glsl=0 hlsl=0
for mat in $materials; do
  {
    echo '#version 450'
    cat "$dir/out/glsl/metalfit_models.glsl"
    for m in $models; do cat "$dir/out/glsl/metalfit_${mat}_${m}.glsl"; done
    echo 'layout(local_size_x = 1) in;'
    echo 'layout(std430, binding = 0) buffer Values { vec4 v[]; };'
    echo 'void main() {'
    i=1; for m in $models; do echo "    v[$i].xyz = metalfit_${mat}_${m}(v[0].w);"; i=$((i + 1)); done
    echo '}'
  } > "$dir/shader.comp"
  "$validator" "$dir/shader.comp" > "$dir/log" || { cat "$dir/log"; echo "export_shaders_compile: GLSL of $mat does not compile"; exit 1; }
  {
    cat "$dir/out/hlsl/metalfit_models.hlsl"
    for m in $models; do cat "$dir/out/hlsl/metalfit_${mat}_${m}.hlsl"; done
    echo 'RWStructuredBuffer<float4> v : register(u0);'
    echo '[numthreads(1, 1, 1)] void main() {'
    i=1; for m in $models; do echo "    v[$i].xyz = metalfit_${mat}_${m}(v[0].w);"; i=$((i + 1)); done
    echo '}'
  } > "$dir/shader.hlsl"
  # HLSL input (-D) needs SPIR-V generation (-V) and the entry point (-e).
  "$validator" -V -D -S comp -e main -o "$dir/shader.spv" "$dir/shader.hlsl" > "$dir/log" ||
    { cat "$dir/log"; echo "export_shaders_compile: HLSL of $mat does not compile"; exit 1; }
  n=$(echo $models | wc -w)
  glsl=$((glsl + n)) hlsl=$((hlsl + n))
done
files=$(ls "$dir"/out/glsl/metalfit_*.glsl | grep -vc metalfit_models.glsl)
echo "export_shaders_compile: $glsl GLSL and $hlsl HLSL exports compiled ($files constants files written per language)"
[ "$glsl" -eq "$files" ]
