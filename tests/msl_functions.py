#!/usr/bin/env python3
"""ctest export.msl_functions: the catalog's MSL export (SPIRV-Cross's translation of the models' GLSL) compiled as
C++ over tests/fixtures/msl_shim/metal_stdlib (Metal's types and built-ins the files use) and run: every material
function of msl/<stem>.metal, after msl/metalfit_models.metal included twice (the guards), at 35 mu (0 to 1 by 1/32, and
-0.25 and 1.25, which clamp) must equal libfit's evaluation in double (model_values, at the constants the file writes)
within 1e-5 + 1e-5 |F| per channel (as export.wgsl_webgpu). Usage: msl_functions.py CXX SHIM_DIR MODEL_VALUES EXPORT_DIR"""
import pathlib
import re
import subprocess
import sys
import tempfile

cxx, shim, model_values, export_dir = sys.argv[1:5]
msl = pathlib.Path(export_dir) / "msl"
models_file = msl / "metalfit_models.metal"
materials = []  # (file, stem, model function, constants' values channel by channel)
for path in sorted(msl.glob("*.metal")):
    if path == models_file:
        continue
    text = path.read_text()
    constants = {m[1]: m[2].split(", ") for m in re.finditer(r"^constant float3 (\w+) = float3\(([^)]*)\);$", text, re.M)}
    call = re.search(r"^float3 (\w+)\(float mu\) \{\n((?: {4}float3 \w+ = \w+;\n)*) {4}return (\w+)\(([^)]*)\);\n\}$",
                     text, re.M)
    if not call:
        sys.exit(f"msl_functions: {path.name}: no material function")
    locals_ = re.findall(r"float3 (\w+) = (\w+);", call[2])
    args = call[4].split(", ")
    if args[-1] != "mu" or [name for name, _ in locals_] != args[:-1] or any(c not in constants for _, c in locals_):
        sys.exit(f"msl_functions: {path.name}: unexpected function {call[0]!r}")
    materials.append((path.name, call[1], call[3], [v for _, c in locals_ for v in constants[c]]))
if not materials:
    sys.exit(f"msl_functions: no material files in {msl}")
mus = [i / 32 for i in range(33)] + [-0.25, 1.25]

with tempfile.TemporaryDirectory() as tmp:
    source = pathlib.Path(tmp) / "msl.cpp"
    lines = [f'#include "{models_file}"', f'#include "{models_file}"']
    lines += [f'#include "{msl / name}"' for name, *_ in materials]
    lines += ["#include <cstdio>", "int main() {", f"    const float mus[] = {{{', '.join(map(repr, mus))}}};",
              "    for (float mu : mus) {", "        float3 v;"]
    lines += [f'        v = {stem}(mu); std::printf("%.9g %.9g %.9g\\n", v.x, v.y, v.z);' for _, stem, *_ in materials]
    lines += ["    }", "}"]
    source.write_text("\n".join(lines) + "\n")
    binary = pathlib.Path(tmp) / "msl"
    build = subprocess.run([cxx, "-std=c++17", "-O1", "-w", "-I", shim, str(source), "-o", str(binary)],
                           capture_output=True, text=True)
    if build.returncode != 0:
        sys.exit(build.stderr[:4000] + "\nmsl_functions: the MSL does not compile over the shim")
    got = [list(map(float, l.split())) for l in subprocess.run([str(binary)], capture_output=True, text=True,
                                                                 check=True).stdout.splitlines()]
expected = subprocess.run([model_values, *map(repr, mus)], capture_output=True, text=True, check=True,
                          input="".join(f"{fn} {' '.join(values)}\n" for _, _, fn, values in materials)).stdout
expected = [list(map(float, l.split())) for l in expected.splitlines()]
failures, worst = 0, 0.0
for j, (name, *_rest) in enumerate(materials):
    for i, mu in enumerate(mus):
        for c in range(3):
            value, want = got[i * len(materials) + j][c], expected[j][i * 3 + c]
            diff = abs(value - want)
            worst = max(worst, diff)
            if not diff <= 1e-5 + 1e-5 * abs(want):
                failures += 1
                if failures <= 20:
                    print(f"{name}: mu {mu} channel {'rgb'[c]}: MSL {value}, libfit {want}", file=sys.stderr)
print(f"msl_functions: {len(materials)} material functions ({len({m[2] for m in materials})} models) compiled as C++ "
      f"over the Metal shim at {len(mus)} mu; largest difference from libfit {worst:.2e}; {failures} outside tolerance")
sys.exit(1 if failures else 0)
