#!/usr/bin/env bash
# The GPU's shader-cost and localization ratios beside llvmpipe's (issue 32 item 6; docs/development.md, "Timing on a
# GPU"): runs glpreview's --bench-shaders and --bench-localization twice, on the machine's GPU (an EGL device that is
# not a software rasteriser, GLPREVIEW_EGL_PLATFORM=device) timed by GPU timer queries (GL_TIME_ELAPSED,
# GLPREVIEW_FRAME_TIMER=gpu-time-elapsed), and on Mesa's llvmpipe timed by the process's CPU time, as
# data/model-costs.json's llvmpipe column is; writes one JSON (schema metalfit.gpu-bench/1, schemas/gpu-bench.schema.json)
# with each model's ratio to conductor-rgb and each localization row's ratio to classic from both, side by side, and
# the timer each used.
# Without a GPU (no EGL device, or only software ones) it says so on stderr, writes nothing and exits 0, so that it
# can run anywhere; any other failure exits non-zero. --allow-software runs the GPU side on llvmpipe with timer queries
# (the queries' path and the JSON's shape without a GPU: the test scripts.gpu_bench_software; its GPU numbers are
# llvmpipe's and say so in `gpu.renderer`).
# Usage: scripts/gpu-bench.sh [--quick] [--allow-software] [-o FILE] [BUILD_DIR]
#   FILE: default gpu-bench.json; BUILD_DIR: default build (needs BUILD_DIR/bin/glpreview). A few minutes; --quick
#   (fewer frames, smaller images) well under one.
set -euo pipefail
quick=() allow_software=0 out=gpu-bench.json build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=(--quick) ;;
    --allow-software) allow_software=1 ;;
    -o) [ $# -ge 2 ] || { echo "gpu-bench: -o needs a file" >&2; exit 2; }; out="$2"; shift ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "gpu-bench: unknown option $1 (--quick, --allow-software, -o FILE, BUILD_DIR)" >&2; exit 2 ;;
    *) build="$1" ;;
  esac
  shift
done
glpreview="$build/bin/glpreview"
[ -x "$glpreview" ] || { echo "gpu-bench: $glpreview not found (build first: cmake --build --preset release)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# One benchmark on one side: glpreview's JSON into $tmp/<side>-<bench>.json. Exit code 5 is glpreview's "no GL
# context" (on the GPU side: no GPU); it is passed on for the caller to read.
run_bench() {
  local side="$1" bench="$2"
  shift 2
  local status=0
  env "$@" "$glpreview" "--bench-$bench" "${quick[@]}" --json > "$tmp/$side-$bench.json" 2> "$tmp/$side-$bench.err" \
    || status=$?
  if [ "$status" -ne 0 ] && [ "$status" -ne 5 ]; then
    echo "gpu-bench: glpreview --bench-$bench on the $side side failed (exit $status): $(tail -n 1 "$tmp/$side-$bench.err")" >&2
    exit "$status"
  fi
  return "$status"
}

if [ "$allow_software" = 1 ]; then
  gpu_env=(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe GLPREVIEW_FRAME_TIMER=gpu-time-elapsed)
else
  gpu_env=(GLPREVIEW_EGL_PLATFORM=device GLPREVIEW_FRAME_TIMER=gpu-time-elapsed)
fi
llvmpipe_env=(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe GLPREVIEW_EGL_PLATFORM=surfaceless GLPREVIEW_FRAME_TIMER=process-cpu)

if ! run_bench gpu shaders "${gpu_env[@]}"; then
  echo "gpu-bench: no GPU: $(tail -n 1 "$tmp/gpu-shaders.err" | sed 's/^glpreview: //'); nothing measured, $out not written" >&2
  exit 0
fi
run_bench gpu localization "${gpu_env[@]}" \
  || { echo "gpu-bench: the GPU went away between two benchmarks: $(tail -n 1 "$tmp/gpu-localization.err")" >&2; exit 5; }
run_bench llvmpipe shaders "${llvmpipe_env[@]}" \
  || { echo "gpu-bench: no llvmpipe context: $(tail -n 1 "$tmp/llvmpipe-shaders.err")" >&2; exit 5; }
run_bench llvmpipe localization "${llvmpipe_env[@]}" \
  || { echo "gpu-bench: no llvmpipe context: $(tail -n 1 "$tmp/llvmpipe-localization.err")" >&2; exit 5; }

command="scripts/gpu-bench.sh${quick[*]:+ ${quick[*]}}"
if [ "$allow_software" = 1 ]; then command+=" --allow-software"; fi
python3 - "$tmp" "$command" > "$tmp/gpu-bench.json" <<'PY'
import json, sys

tmp, command = sys.argv[1], sys.argv[2]
load = lambda name: json.load(open(f"{tmp}/{name}.json"))
shaders = {side: load(f"{side}-shaders") for side in ("gpu", "llvmpipe")}
local = {side: load(f"{side}-localization") for side in ("gpu", "llvmpipe")}


SOFTWARE = ("llvmpipe", "softpipe", "SwiftShader", "swrast")


def timing(j):
    return {"renderer": j["renderer"], "clock": j["clock"], "rounds": j["frames"], "size": j["size"][0],
            "evaluations_per_pixel": j["evaluations_per_pixel"],
            "software": any(s in j["renderer"] for s in SOFTWARE)}


def ratio(row):  # data/model-costs.json's shape: {ratio, noise, quartiles}
    return {"ratio": row["ratio_to_conductor_rgb"], "noise": row["ratio_noise"], "quartiles": row["ratio_quartiles"]}


gpu_rows = {m["model"]: m for m in shaders["gpu"]["models"]}
models = [{"model": m["model"], "llvmpipe": ratio(m), "gpu": ratio(gpu_rows[m["model"]])}
          for m in shaders["llvmpipe"]["models"] if m["model"] in gpu_rows]

row_key = lambda r: (r["mode"], r["strategy"], r["iterations"], r["search_steps"])
rooms = []
for room in local["llvmpipe"]["rooms"]:
    gpu_room = next(g for g in local["gpu"]["rooms"] if g["room"] == room["room"])
    gpu_by_key = {row_key(r): r for r in gpu_room["rows"]}
    rooms.append({"room": room["room"], "rows": [
        {"mode": r["mode"], "strategy": r["strategy"], "iterations": r["iterations"], "search_steps": r["search_steps"],
         "llvmpipe": {"ratio": r["ratio_to_classic"], "noise": r["ratio_noise"]},
         "gpu": {"ratio": gpu_by_key[row_key(r)]["ratio_to_classic"], "noise": gpu_by_key[row_key(r)]["ratio_noise"]}}
        for r in room["rows"] if row_key(r) in gpu_by_key]})

doc = {
    "schema": "metalfit.gpu-bench/1",
    "command": command,
    "baseline": "conductor-rgb",
    "gpu": timing(shaders["gpu"]),
    "llvmpipe": timing(shaders["llvmpipe"]),
    "models": models,
    "localization": {
        "baseline": "classic",
        "gpu": {"renderer": local["gpu"]["renderer"], "clock": local["gpu"]["clock"], "rounds": local["gpu"]["frames"],
                "size": local["gpu"]["size"]},
        "llvmpipe": {"renderer": local["llvmpipe"]["renderer"], "clock": local["llvmpipe"]["clock"],
                     "rounds": local["llvmpipe"]["frames"], "size": local["llvmpipe"]["size"]},
        "rooms": rooms,
    },
}
json.dump(doc, sys.stdout, indent=2)
print()
PY
# Written as a unit: the whole file appears, or nothing.
mv "$tmp/gpu-bench.json" "$out.tmp.$$" && mv "$out.tmp.$$" "$out"
echo "gpu-bench: $out ($(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["gpu"]["renderer"] + ", " + j["gpu"]["clock"])' "$out"))" >&2
