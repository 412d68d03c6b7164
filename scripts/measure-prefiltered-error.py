#!/usr/bin/env python3
"""What limits the prefiltered glossy lookup (issue 36 item 4): its error against the Monte-Carlo reference split into
the split sum, the cube's resolution and the localization of the lookup, each measured by removing the others.

    python3 scripts/measure-prefiltered-error.py [--glpreview build/bin/glpreview] [--samples 1024]

The scene: data/scenes/sky.hdr on a sphere proxy around the capture point o, one gold sphere (reference Fresnel,
prefiltered, distance impostor) centred on o, seen from 3 m. Per roughness it is rendered
- with the proxy at 10^4 m (the environment at infinity: the localization is exact, what is left is the split sum and
  the cube) at cube sizes 64 … 512: the error that does not shrink with the cube is the split sum's;
- with the proxy at 1.5 m (a near environment) at the largest cube, the sphere centred on o and 0.6 m from it: the
  error the localization adds (only the lobe's centre is localized; the rest of the lobe is the environment seen
  from o, which is further off the farther the sphere is from o).
Each error is the method's own, sqrt(RMSE² − noise²) (the reference's noise, from its standard error, taken out).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROUGHNESS = [0.2, 0.4, 0.6]
CUBES = [64, 128, 256, 512]
FAR, NEAR = 1e4, 1.5
OFFSETS = [0.0, 0.6]  # the sphere's centre from o, near


def scene(sky, roughness, proxy, cube, samples, offset):
    return {"image": {"width": 160, "height": 160},
            "camera": {"position": [offset, 0.2, 3.0], "look_at": [offset, 0.2, 0], "fov_y_deg": 22},
            "environment": {"type": "equirect", "file": sky, "reference_point": [0, 0.2, 0], "cube_size": cube,
                            "proxy": {"sphere": proxy}},
            "spheres": [{"center": [offset, 0.2, 0], "radius": 0.5, "material": "Au", "fresnel": "reference",
                         "roughness": roughness, "glossy": "prefiltered", "reflection": "distance-impostor"}],
            "outputs": {"beauty": False, "reference": False, "difference": False, "metrics": True, "exr": False,
                        "png": False, "reference_samples": samples}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--glpreview", default="build/bin/glpreview")
    parser.add_argument("--data-dir", default="data")
    parser.add_argument("--samples", type=int, default=1024)
    args = parser.parse_args()
    sky = os.path.abspath(os.path.join(args.data_dir, "scenes", "sky.hdr"))
    variants = ([(r, FAR, c, 0.0) for r in ROUGHNESS for c in CUBES] +
                [(r, NEAR, CUBES[-1], offset) for r in ROUGHNESS for offset in OFFSETS])
    with tempfile.TemporaryDirectory(prefix="prefiltered-error-") as work:
        files = []
        for r, proxy, cube, offset in variants:
            path = os.path.join(work, f"v-{r:g}-{proxy:g}-{cube}-{offset:g}.json")
            with open(path, "w") as f:
                json.dump(scene(sky, r, proxy, cube, args.samples, offset), f)
            files.append(path)
        out = os.path.join(work, "out")
        done = subprocess.run([args.glpreview, "--batch", "--allow-paths-outside", "--data-dir", args.data_dir, "-o",
                               out] + files, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit("measure-prefiltered-error: glpreview failed: " + done.stderr.strip().splitlines()[-1])
        error = {}
        for (r, proxy, cube, offset), path in zip(variants, files):
            stem = os.path.splitext(os.path.basename(path))[0]
            with open(os.path.join(out, stem, "metrics.json")) as f:
                s = json.load(f)["spheres"][0]
            own = math.sqrt(max(0.0, s["rmse"] ** 2 - s["reference_noise"] ** 2))
            error[(r, proxy, cube, offset)] = (own, s["rmse"], s["reference_noise"])

    print(f"Own error sqrt(RMSE² − noise²) of the prefiltered lookup, gold, {args.samples} reference samples "
          f"(RMSE and the reference's noise in brackets)\n")
    print("| roughness | " + " | ".join(f"at infinity, cube {c}" for c in CUBES) + " | " +
          " | ".join(f"near ({NEAR:g} m), cube {CUBES[-1]}, sphere {o:g} m from o" for o in OFFSETS) + " |")
    print("|---:|" + "---:|" * (len(CUBES) + len(OFFSETS)))
    for r in ROUGHNESS:
        cells = [error[(r, FAR, c, 0.0)] for c in CUBES] + [error[(r, NEAR, CUBES[-1], o)] for o in OFFSETS]
        print(f"| {r:g} | " + " | ".join(f"{e:.4f} ({rmse:.4f}, {noise:.4f})" for e, rmse, noise in cells) + " |")


if __name__ == "__main__":
    main()
