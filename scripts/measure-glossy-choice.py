#!/usr/bin/env python3
"""Measure which glossy method (prefiltered or localized) reproduces the Monte-Carlo reference better, per roughness,
over every shipped room (issue 36 item 4), and write the table glpreview's planner chooses from.

    python3 scripts/measure-glossy-choice.py [--glpreview build/bin/glpreview] [--out data/glossy-choice.json]

For each room scene of data/scenes (lights removed: the glossy methods differ only in how the environment is
integrated) and each roughness of the grid, every sphere is made rough at that roughness and the scene is rendered
twice by glpreview, once with every sphere `prefiltered` (each keeping its own reflection mode) and once `localized`
(M = 8), both against the same Monte-Carlo reference (fixed seed: the same image in both runs, so the reference's noise
adds the same to both errors and the comparison of RMSEs is a comparison of the methods' own errors). Each sphere's
RMSE comes from glpreview's metrics.json. The table keeps every sphere's figures and, per roughness, how many spheres
each method wins and the ratio localized / prefiltered of their RMSEs (median and worst). The rule that turns the
rows into the planner's choice lives in glpreview (glossy_choice.cpp; docs/preview.md, "Choosing the glossy method").
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOMS = ["empty-room", "difficult-room", "occluder-maze", "rough-room", "sheet", "lit-room", "studio-lights",
         "sky-probe"]
ROUGHNESS = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
METHODS = ["prefiltered", "localized"]


def variant(scene, roughness, method, samples, scale, scene_dir):
    s = json.loads(json.dumps(scene))
    s.pop("lights", None)
    image = s.setdefault("image", {})
    image["width"] = max(16, int(image.get("width", 512) * scale))
    image["height"] = max(16, int(image.get("height", 512) * scale))
    env = s.get("environment", {})
    if "file" in env:  # the variant lives elsewhere: name the room's image by its absolute path
        env["file"] = os.path.abspath(os.path.join(scene_dir, env["file"]))
    for sphere in s["spheres"]:
        sphere["roughness"] = roughness
        sphere["glossy"] = method
        sphere.pop("localized_size", None)
        if method == "localized":
            sphere.pop("reflection", None)  # localized localizes by the area lights' positions
    s["outputs"] = {"beauty": False, "reference": False, "difference": False, "metrics": True, "exr": False,
                    "png": False, "timing_frames": 5, "reference_samples": samples}
    return s


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--glpreview", default="build/bin/glpreview")
    parser.add_argument("--data-dir", default="data")
    parser.add_argument("--out", default="data/glossy-choice.json")
    parser.add_argument("--samples", type=int, default=256, help="Monte-Carlo reference samples per pixel")
    parser.add_argument("--scale", type=float, default=0.5, help="image size as a share of each scene's own")
    parser.add_argument("--roughness", default=",".join(str(r) for r in ROUGHNESS))
    parser.add_argument("--rooms", default=",".join(ROOMS))
    args = parser.parse_args()
    grid = [float(r) for r in args.roughness.split(",")]
    rooms = args.rooms.split(",")

    scene_dir = os.path.join(args.data_dir, "scenes")
    spheres = []
    renderer = None
    with tempfile.TemporaryDirectory(prefix="glossy-choice-") as work:
        files, index = [], []
        for room in rooms:
            with open(os.path.join(scene_dir, room + ".json")) as f:
                scene = json.load(f)
            for r in grid:
                for method in METHODS:
                    name = f"{room}--{r:g}--{method}"
                    path = os.path.join(work, name + ".json")
                    with open(path, "w") as f:
                        json.dump(variant(scene, r, method, args.samples, args.scale, scene_dir), f)
                    files.append(path)
                    index.append((room, r, method, name))
        out = os.path.join(work, "out")
        command = [args.glpreview, "--batch", "--glossy-as-asked", "--allow-paths-outside", "--data-dir", args.data_dir, "-o", out] + files
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit("measure-glossy-choice: glpreview failed: " + done.stderr.strip().splitlines()[-1])
        rmse = {}
        for room, r, method, name in index:
            with open(os.path.join(out, name, "metrics.json")) as f:
                metrics = json.load(f)
            renderer = metrics["renderer"]
            for s in metrics["spheres"]:
                rmse[(room, r, method, s["sphere"])] = s
        for room in rooms:
            for r in grid:
                i = 0
                while (room, r, "prefiltered", i) in rmse:
                    p, l = rmse[(room, r, "prefiltered", i)], rmse[(room, r, "localized", i)]
                    if l["glossy"] != "localized":
                        sys.exit(f"measure-glossy-choice: {room} sphere {i} at roughness {r:g} was not rendered "
                                 f"localized ({l['glossy']})")
                    spheres.append({"room": room, "sphere": i, "material": p["material"], "reflection": p["mode"],
                                    "roughness": r, "prefiltered_rmse": p["rmse"], "localized_rmse": l["rmse"],
                                    "reference_noise": p["reference_noise"]})
                    i += 1

    rows = []
    for r in grid:
        at = [s for s in spheres if s["roughness"] == r]
        ratios = [s["localized_rmse"] / s["prefiltered_rmse"] for s in at]
        rows.append({"roughness": r, "spheres": len(at),
                     "localized_wins": sum(1 for s in at if s["localized_rmse"] < s["prefiltered_rmse"]),
                     "median_ratio": statistics.median(ratios), "worst_ratio": max(ratios),
                     "prefiltered_rmse_median": statistics.median(s["prefiltered_rmse"] for s in at),
                     "localized_rmse_median": statistics.median(s["localized_rmse"] for s in at),
                     "reference_noise_median": statistics.median(s["reference_noise"] for s in at)})
    table = {"schema": "metalfit.glossy-choice/1",
             "command": "python3 scripts/measure-glossy-choice.py" + "".join(
                 f" --{k} {v}" for k, v in (("samples", args.samples), ("scale", args.scale))
                 if v != parser.get_default(k)),
             "renderer": renderer, "reference_samples": args.samples, "localized_size": 8, "image_scale": args.scale,
             "rooms": rooms, "rows": rows, "spheres": spheres}
    directory = os.path.dirname(os.path.abspath(args.out))
    fd, temporary = tempfile.mkstemp(prefix=".glossy-choice-", suffix=".json", dir=directory)
    with os.fdopen(fd, "w") as f:
        json.dump(table, f, indent=1)
        f.write("\n")
    os.replace(temporary, args.out)

    print("| roughness | spheres | localized wins | RMSE ratio localized / prefiltered: median | worst | "
          "prefiltered RMSE (median) | localized RMSE (median) | reference noise (median) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        print(f"| {row['roughness']:g} | {row['spheres']} | {row['localized_wins']} | {row['median_ratio']:.3g} | "
              f"{row['worst_ratio']:.3g} | {row['prefiltered_rmse_median']:.4f} | {row['localized_rmse_median']:.4f} | "
              f"{row['reference_noise_median']:.4f} |")


if __name__ == "__main__":
    main()
