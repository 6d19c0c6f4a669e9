#!/usr/bin/env python3
"""Whole-command wall times of raylab, the JIT build against the native (Native AOT) build, interleaved.

For each of four commands — `raylab --help`, an 8×8 render, the exact reference at 1080p and jittered
16 spp at 1080p (benchmarks/anchors/bench-1080.json, 2 threads) — runs every build once per round, ROUNDS rounds
(builds and commands interleaved, so that load drifts touch them alike), and prints a Markdown table of medians:
wall time of the whole process (start to exit, as a user waits for it), and for the 1080p renders renderMs (the
render loop alone) and encodeMs (writing the PNG) from --stats. No --warmup: the commands run as a user runs them, so
the JIT build's renderMs includes compiling the render. With --before DIR, a third build: the JIT build of
another checkout (DIR/samples/RayLab.Console/bin/Release/net10.0/raylab), e.g. the commit before the native build;
with --build NAME=PATH (repeatable), any other raylab, e.g. a native build for another instruction set.

Build first: dotnet build samples/RayLab.Console -c Release
             dotnet publish samples/RayLab.Console -c Release -r linux-x64 -o artifacts/native
Usage: python3 tools/startup-speed.py [ROUNDS] [--before DIR] [--build NAME=PATH …]
"""
import argparse, json, os, statistics, subprocess, tempfile, time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "benchmarks", "anchors", "bench-1080.json")
parser = argparse.ArgumentParser()
parser.add_argument("rounds", nargs="?", type=int, default=9)
parser.add_argument("--before")
parser.add_argument("--build", action="append", default=[])
args = parser.parse_args()

builds = [("JIT", os.path.join(root, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab")),
          ("native", os.path.join(root, "artifacts", "native", "raylab"))]
if args.before:
    builds.insert(0, ("before (JIT)", os.path.join(args.before, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab")))
builds += [tuple(b.split("=", 1)) for b in args.build]
for name, path in builds:
    if not os.access(path, os.X_OK):
        raise SystemExit(f"startup-speed.py: {path} is missing ({name}); build it first (see the docstring)")

tmp = tempfile.mkdtemp()
image, stats = os.path.join(tmp, "x.png"), os.path.join(tmp, "s.json")
commands = [("`raylab --help`", ["--help"], False),
            ("8×8 render", ["render", scene, "--width", "8", "--height", "8", "-o", image], False),
            ("exact, 1080p", ["render", scene, "--sampler", "exact", "--threads", "2", "-o", image, "--stats", stats], True),
            ("jittered 16, 1080p", ["render", scene, "--sampler", "jittered", "--samples", "16", "--threads", "2", "-o", image, "--stats", stats], True)]
wall = {(c, b): [] for c, *_ in commands for b, _ in builds}
render = {(c, b): [] for c, *_ in commands for b, _ in builds}
encode = {(c, b): [] for c, *_ in commands for b, _ in builds}
for _ in range(args.rounds):
    for label, options, has_stats in commands:
        for build, path in builds:
            start = time.perf_counter()
            subprocess.run([path, *options], check=True, cwd=tmp, stdout=subprocess.DEVNULL)
            wall[label, build].append((time.perf_counter() - start) * 1000)
            if has_stats:
                with open(stats) as f:
                    s = json.load(f)
                render[label, build].append(s["renderMs"])
                encode[label, build].append(s["encodeMs"])

med = lambda xs: statistics.median(xs) if xs else float("nan")
print(f"Medians of {args.rounds} interleaved runs (`python3 tools/startup-speed.py {args.rounds}"
      + (" --before DIR" if args.before else "") + "".join(f" --build {b}" for b in args.build) + "`), load average at the end "
      + f"{os.getloadavg()[0]:.1f}.\n")
print("| command | build | wall ms | renderMs | encodeMs | wall vs JIT |")
print("|---|---|---:|---:|---:|---:|")
for label, _options, has_stats in commands:
    for build, _path in builds:
        w = med(wall[label, build])
        r = f"{med(render[label, build]):.1f}" if has_stats else "–"
        e = f"{med(encode[label, build]):.1f}" if has_stats else "–"
        print(f"| {label} | {build} | {w:.1f} | {r} | {e} | {w / med(wall[label, 'JIT']):.2f}× |")
