#!/usr/bin/env python3
"""The sphere-count targets in one run: renderMs of this build against another, runs alternating (the order swapped
every pair), medians and the paired ratio.

Scenes: the 960-sphere field (`tools/sphere-scenes.py field 24 40`), 10 000 random spheres (`random 10000`) and
benchmarks/anchors/bench-1080.json (two spheres), each with the options of its target, 2 threads. Prints a Markdown
table. Build both first (dotnet build samples/RayLab.Console -c Release, here and in the other checkout).

Usage: python3 tools/sphere-targets.py --before DIR [--quick]
  DIR     another checkout, built: its samples/RayLab.Console/bin/Release/net10.0/raylab
  --quick fewer runs (3 pairs each)
"""
import argparse, json, os, statistics, subprocess, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
parser = argparse.ArgumentParser()
parser.add_argument("--before", required=True)
parser.add_argument("--quick", action="store_true")
args = parser.parse_args()
relative = os.path.join("samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab")
builds = {"before": os.path.join(args.before, relative), "after": os.path.join(root, relative)}
for name, path in builds.items():
    if not os.access(path, os.X_OK):
        raise SystemExit(f"sphere-targets.py: {path} is missing; build it first (see the docstring)")

tmp = tempfile.mkdtemp()
field, random10k = os.path.join(tmp, "field.json"), os.path.join(tmp, "r10k.json")
subprocess.run(["python3", os.path.join(root, "tools", "sphere-scenes.py"), "field", "24", "40", field], check=True)
subprocess.run(["python3", os.path.join(root, "tools", "sphere-scenes.py"), "random", "10000", random10k], check=True)
bench = os.path.join(root, "benchmarks", "anchors", "bench-1080.json")
small, full = ["--width", "320", "--height", "240"], ["--width", "1920", "--height", "1080"]
exact, jittered = ["--sampler", "exact"], ["--sampler", "jittered", "--samples", "16"]
cases = [("field, 320×240, exact (≤ 100 ms)", field, exact + small, 7),
         ("field, 1920×1080, exact (≤ 2 s)", field, exact + full, 5),
         ("10 000 random, 320×240, exact (≤ 5 s, aim 1 s)", random10k, exact + small, 3),
         ("field, 1920×1080, jittered 16 (≤ 300 ms)", field, jittered + full, 5),
         ("10 000 random, 320×240, jittered 16 (≤ 100 ms)", random10k, jittered + small, 5),
         ("bench-1080, exact (within 3 %)", bench, exact, 21),
         ("bench-1080, jittered 16 (within 3 %)", bench, jittered, 11)]
png, stats = os.path.join(tmp, "x.png"), os.path.join(tmp, "s.json")
print("| scene, target | pairs | before, median (range) | after, median (range) | paired ratio |")
print("|---|---:|---:|---:|---:|")
for name, scene, options, pairs in cases:
    pairs = 3 if args.quick else pairs
    times, ratios = {k: [] for k in builds}, []
    for i in range(pairs):
        run = {}
        for k in (list(builds) if i % 2 == 0 else list(builds)[::-1]):
            subprocess.run([builds[k], "render", scene, "-o", png, *options, "--threads", "2", "--stats", stats, "--warmup"],
                           check=True, stdout=subprocess.DEVNULL)
            with open(stats) as f:
                run[k] = json.load(f)["renderMs"]
            times[k].append(run[k])
        ratios.append(run["after"] / run["before"])
    cell = lambda v: f"{statistics.median(v):.1f} ms ({min(v):.1f}–{max(v):.1f})"
    print(f"| {name} | {pairs} | {cell(times['before'])} | {cell(times['after'])} | {statistics.median(ratios):.3f}× |",
          flush=True)
print(f"\nLoad average at the end: {os.getloadavg()[0]:.1f}.")
