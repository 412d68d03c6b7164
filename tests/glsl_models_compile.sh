#!/usr/bin/env bash
# Compiles the GLSL of every model (`metalfit models --glsl`) in a GLSL 4.50 compute shader that calls each model
# function with its parameters, so that a wrong signature or a missing helper fails. Usage: METALFIT GLSLANG_VALIDATOR
set -euo pipefail
metalfit="$1" validator="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
shader="$dir/models.comp"
{
  echo '#version 450'
  "$metalfit" models --glsl
  echo 'layout(local_size_x = 1) in;'
  echo 'layout(std430, binding = 0) buffer Values { vec4 v[]; };'
  echo 'void main() {'
  echo '    float mu = v[0].w;'
  echo '    vec3 p = v[0].xyz;'
  # One call per model, with as many vec3 arguments as the model has parameters.
  "$metalfit" models --json | python3 -c '
import json, sys
for i, m in enumerate(json.load(sys.stdin)):
    fn = m["glsl"].split(" ")[1].split("(")[0]
    args = ", ".join(["p"] * len(m["parameters"]) + ["mu"])
    print(f"    v[{i + 1}].xyz = {fn}({args});")
'
  echo '}'
} > "$shader"
"$validator" "$shader"
echo "glsl_models_compile: $(grep -c '= metalfit_' "$shader") model functions compiled"
