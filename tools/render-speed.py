#!/usr/bin/env python3
"""Every render method's speed on benchmarks/anchors/bench-1080.json, in one run, as ratios to jittered.

Runs `raylab render bench-1080.json --threads 2 --stats --warmup` (renderMs: the render loop only, after a warm-up render)
for each row below, ROUNDS times, the rows interleaved round by round so that load drifts touch them alike, and
prints a Markdown table: median renderMs, and jittered's median time at the same sample count divided by the
row's (for a point sampler: its samples per second as a fraction of jittered's; for adaptive and exact: how much
faster than jittered 16 spp). With --before DIR, also renders jittered 16 and exact with the raylab.dll built in
DIR (another checkout's samples/RayLab.Console/bin/Release/net10.0) in the same rounds, for a before/after check;
--before-all renders every row with it too. --kernel passes `--kernel K` to every render (e.g. vector256 on an
AVX-512 machine); --points keeps only the point samplers named.

Usage: python3 tools/render-speed.py [ROUNDS] [--samples 16,256] [--points jittered,...] [--kernel K] [--before DIR [--before-all]]
"""
import argparse, json, os, statistics, subprocess, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "benchmarks", "anchors", "bench-1080.json")
parser = argparse.ArgumentParser()
parser.add_argument("rounds", nargs="?", type=int, default=5)
parser.add_argument("--samples", default="16,256")
parser.add_argument("--before")
parser.add_argument("--before-all", action="store_true")
parser.add_argument("--kernel")
parser.add_argument("--points", default="jittered,regular,random,cmj,multijittered,nrooks,hammersley,sobol,pmj02,pmj02bn,zsobol")
args = parser.parse_args()
subprocess.run(["dotnet", "build", os.path.join(root, "samples", "RayLab.Console"), "-c", "Release", "-v", "q", "-nologo"],
               check=True, stdout=subprocess.DEVNULL)
dll = os.path.join(root, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab.dll")
tmp = tempfile.mkdtemp()
points = args.points.split(",")
rows = []  # (label, dll, options, samples for the ratio)
for n in [int(s) for s in args.samples.split(",")]:
    rows += [(f"{name}, {n} spp", dll, ["--sampler", name, "--samples", str(n)], n) for name in points]
rows += [("adaptive, defaults (depth 0–3, contrast 0.1)", dll, ["--sampler", "adaptive"], 16),
         ("adaptive --guard (depth 0–3)", dll, ["--sampler", "adaptive", "--guard"], 16),
         ("exact", dll, ["--sampler", "exact"], 16)]
if args.before:
    old = os.path.join(args.before, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab.dll")
    rows += ([("before: " + label, old, options, n) for label, _path, options, n in rows] if args.before_all else
             [("before: jittered, 16 spp", old, ["--sampler", "jittered", "--samples", "16"], 16),
              ("before: exact", old, ["--sampler", "exact"], 16)])
kernel = ["--kernel", args.kernel] if args.kernel else []
times = {label: [] for label, *_ in rows}
for _ in range(args.rounds):
    for label, path, options, _n in rows:
        stats = os.path.join(tmp, "s.json")
        subprocess.run(["dotnet", path, "render", scene, "-o", os.path.join(tmp, "x.png"), "--threads", "2", "--stats", stats, "--warmup"] + options + kernel,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(stats) as f:
            times[label].append(json.load(f)["renderMs"])
median = {label: statistics.median(t) for label, t in times.items()}
print(f"| render (bench-1080.json, 2 threads{', --kernel ' + args.kernel if args.kernel else ''}, medians of {args.rounds}) | renderMs | jittered's time / this |")
print("|---|---:|---:|")
for label, _path, _options, n in rows:
    base = (median[f"jittered, {n} spp"] if not label.startswith("before")
            else median[f"before: jittered, {n} spp"] if args.before_all
            else median["jittered, 16 spp" if "jittered" in label else "exact"])
    print(f"| {label} | {median[label]:.1f} | {base / median[label]:.2f}× |")
