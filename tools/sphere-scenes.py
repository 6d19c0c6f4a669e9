#!/usr/bin/env python3
"""Writes the scenes behind docs/performance.md's cost-against-sphere-count table.

  python3 tools/sphere-scenes.py field COLUMNS ROWS OUT.json      a receding field (the 960-sphere field of the targets is 24 40)
  python3 tools/sphere-scenes.py aliasing OUT.json                samples/scenes/sphere-field.json: 40 × 120, seen low and narrow
  python3 tools/sphere-scenes.py random N OUT.json [SEED]         N random spheres in a box in front of the camera

Add --no-acceleration to write "acceleration": "none" (every sphere tested for every ray) for the before/after pairs.
"""
import json
import random
import sys


def field(columns, rows):
    spheres = []
    for j in range(rows):
        for i in range(columns):
            colour = [0.95, 0.95, 0.9] if (i + j) % 2 == 0 else [0.15, 0.3, 0.8]
            spheres.append({"center": [round(i - (columns - 1) / 2, 6), 0, -j], "radius": 0.35, "color": colour})
    return {
        "image": {"width": 1920, "height": 1080},
        "background": [0.05, 0.05, 0.08],
        "ambient": [1, 1, 1],
        "camera": {"type": "perspective", "position": [0, 1.6, 4], "target": [0, 0, -rows / 2], "up": [0, 1, 0],
                   "fov": 50, "near": 0.1, "far": 1000},
        "spheres": spheres,
    }


def random_spheres(n, seed):
    rng = random.Random(seed)
    # Spheres in [-10, 10] × [-6, 6] × [-40, -8]; radius so that together they cover the view about twice.
    radius = 1.6 * (20 * 12 * 32 / n) ** (1 / 3) / 4
    spheres = [{"center": [round(rng.uniform(-10, 10), 6), round(rng.uniform(-6, 6), 6), round(rng.uniform(-40, -8), 6)],
                "radius": round(radius * rng.uniform(0.5, 1.0), 6),
                "color": [round(rng.uniform(0.1, 1), 3), round(rng.uniform(0.1, 1), 3), round(rng.uniform(0.1, 1), 3)]}
               for _ in range(n)]
    return {
        "image": {"width": 320, "height": 240},
        "background": [0.1, 0.1, 0.15],
        "ambient": [1, 1, 1],
        "camera": {"type": "perspective", "position": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0],
                   "fov": 50, "near": 0.1, "far": 1000},
        "spheres": spheres,
    }


def main(args):
    off = "--no-acceleration" in args
    args = [a for a in args if a != "--no-acceleration"]
    if args[0] == "aliasing":
        scene, out = field(40, 120), args[1]
        scene["image"] = {"width": 640, "height": 360}
        scene["camera"].update({"position": [0, 1.2, 4], "target": [0, 0, -60], "fov": 30})
        scene["sampler"] = {"type": "regular", "samples": 1}
    elif args[0] == "field":
        scene, out = field(int(args[1]), int(args[2])), args[3]
    elif args[0] == "random":
        scene, out = random_spheres(int(args[1]), int(args[3]) if len(args) > 3 else 1), args[2]
    else:
        sys.exit(__doc__)
    if off:
        scene["acceleration"] = "none"
    with open(out, "w") as f:
        json.dump(scene, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1:])
