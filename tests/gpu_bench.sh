#!/usr/bin/env bash
# ctest scripts.gpu_bench: scripts/gpu-bench.sh (docs/development.md, "Timing on a GPU").
# - Without a GPU (this project's test machines) it says so, exits 0 and writes nothing; with one, its file is checked
#   like the next.
# - --allow-software: the GPU side on llvmpipe through GPU timer queries: the JSON validates against
#   schemas/gpu-bench.schema.json (and broken copies do not: json_schemas.mjs --broken), names the timer of each side
#   (gpu-time-elapsed, process-cpu), holds every model of the shader benchmark on both sides with conductor-rgb at
#   exactly 1, and every localization row with classic at 1.
# - An unknown option is a usage error (2), nothing written.
# Usage: SOURCE_DIR BUILD_DIR NODE NODE_MODULES
set -euo pipefail
source_dir="$1" build_dir="$2" node="$3" modules="$4"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
script="$source_dir/scripts/gpu-bench.sh"

check() {  # FILE SOFTWARE(true|false)
  "$node" "$source_dir/tests/json_schemas.mjs" "$modules" "$source_dir/schemas" "$1"
  "$node" "$source_dir/tests/json_schemas.mjs" "$modules" "$source_dir/schemas" --broken "$1"
  python3 - "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
software = sys.argv[2] == "true"
assert j["gpu"]["clock"] == "gpu-time-elapsed", j["gpu"]
assert j["llvmpipe"]["clock"] == "process-cpu", j["llvmpipe"]
assert j["llvmpipe"]["software"] and "llvmpipe" in j["llvmpipe"]["renderer"], j["llvmpipe"]
assert j["gpu"]["software"] == software, j["gpu"]
assert j["localization"]["gpu"]["clock"] == "gpu-time-elapsed" and j["localization"]["llvmpipe"]["clock"] == "process-cpu"
models = [m["model"] for m in j["models"]]
assert "conductor-rgb" in models and "schlick" in models and "reference-lut" in models, models
assert len(set(models)) == len(models), models
for m in j["models"]:
    for side in ("gpu", "llvmpipe"):
        if m["model"] == "conductor-rgb":
            assert m[side]["ratio"] == 1.0 and m[side]["noise"] == 0.0, m
        assert m[side]["quartiles"][0] <= m[side]["quartiles"][1], m
rooms = j["localization"]["rooms"]
assert [r["room"] for r in rooms] == ["empty", "difficult"], [r["room"] for r in rooms]
for room in rooms:
    first = room["rows"][0]
    assert first["mode"] == "classic" and first["gpu"]["ratio"] == 1.0 and first["llvmpipe"]["ratio"] == 1.0, first
print(f"gpu-bench JSON: {len(models)} models, {sum(len(r['rows']) for r in rooms)} localization rows")
PY
}

# 1. The machine's GPU, if any.
status=0
bash "$script" --quick -o "$dir/gpu.json" "$build_dir" 2> "$dir/gpu.err" || status=$?
cat "$dir/gpu.err"
[ "$status" -eq 0 ] || { echo "FAIL: exit $status without --allow-software"; exit 1; }
if [ -e "$dir/gpu.json" ]; then
  check "$dir/gpu.json" false
else
  grep -q "^gpu-bench: no GPU: .*nothing measured" "$dir/gpu.err" || { echo "FAIL: no file and no 'no GPU' line"; exit 1; }
  [ -z "$(ls "$dir" | grep -v '^gpu.err$')" ] || { echo "FAIL: something written without a GPU: $(ls "$dir")"; exit 1; }
fi

# 2. The timer queries and the JSON on llvmpipe.
bash "$script" --quick --allow-software -o "$dir/software.json" "$build_dir"
check "$dir/software.json" true

# 3. A usage error.
status=0
bash "$script" --bogus -o "$dir/bogus.json" "$build_dir" 2> /dev/null || status=$?
[ "$status" -eq 2 ] && [ ! -e "$dir/bogus.json" ] || { echo "FAIL: --bogus gave exit $status"; exit 1; }
echo "gpu-bench: checks passed"
