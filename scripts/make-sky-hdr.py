#!/usr/bin/env python3
"""Writes data/scenes/sky.hdr: a small procedural latitude-longitude sky (Radiance RGBE, flat scanlines), the
example environment at infinity of data/scenes/sky.json. Deterministic; rerun to regenerate.
Row 0 is straight up (+y); u = 0.5 looks along -z, u grows towards +x (docs/scene.md)."""
import math
import sys

WIDTH, HEIGHT = 256, 128


def radiance(u, v):
    phi = (u - 0.5) * 2 * math.pi
    theta = v * math.pi
    d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
    if d[1] < 0:  # ground: a checker seen at infinity
        check = (int(math.floor(8 * u)) + int(math.floor(8 * v))) & 1
        g = 0.25 if check else 0.08
        return (g, g * 0.9, g * 0.8)
    sky = (0.35 + 0.4 * (1 - d[1]), 0.55 + 0.3 * (1 - d[1]), 1.1)
    sun = (0.5, 0.6, -0.62)
    n = math.sqrt(sum(c * c for c in sun))
    cos_sun = sum(a * b / n for a, b in zip(d, sun))
    glow = 40.0 * max(0.0, cos_sun) ** 400
    return tuple(c + glow * w for c, w in zip(sky, (1.0, 0.95, 0.85)))


def rgbe(rgb):
    m = max(rgb)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes([int(c * scale) for c in rgb] + [exponent + 128])


def main(path):
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {HEIGHT} +X {WIDTH}\n".encode())
        for y in range(HEIGHT):
            for x in range(WIDTH):
                f.write(rgbe(radiance((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT)))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "data/scenes/sky.hdr")
