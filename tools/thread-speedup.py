#!/usr/bin/env python3
"""Two-thread speed-up of every render method on bench-1080 and the 960-sphere field, and one thread against another build.

For each case (bench-1080 = benchmarks/anchors/bench-1080.json; field = `tools/sphere-scenes.py field 24 40`,
1920×1080) and each method (jittered 16, adaptive, adaptive --guard, exact), runs `raylab render SCENE --threads T
--stats` (renderMs: the render loop only, after a warm-up render) at T = 1 and 2, ROUNDS times, every cell of a round
in turn so that load drifts touch them alike. Prints the median renderMs per cell, the speed-up median(1 thread) /
median(2 threads), the median over the rounds of each round's own speed-up (its 1-thread time over the 2-thread time
that follows it, which takes out what drifts between rounds) with that median's 95 % interval, how many rounds' own
speed-ups are below 1.25× (a 2-thread render that ran at about 1-thread speed: on the lab's VMs, the hypervisor did
not run the second vCPU during it; docs/bench/every-core.md, "On 2 cores"), and with --before DIR
(another checkout, built with `dotnet build samples/RayLab.Console -c Release`) the same for that build and this
build's 1-thread time over the other's. With --native EXE it runs that native raylab (`tools/publish-native.sh`, or a
`dotnet publish -r linux-x64` of this checkout) instead of this checkout's JIT build: no tiered compilation, so the
1-thread render pays no JIT. The load average is printed before and after.

Usage: python3 tools/thread-speedup.py [ROUNDS] [--before DIR] [--native EXE] [--cases bench-adaptive,field-exact,...]
"""
import argparse, json, os, statistics, subprocess, tempfile

from pairstats import median_interval

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
parser = argparse.ArgumentParser()
parser.add_argument("rounds", nargs="?", type=int, default=5)
parser.add_argument("--before")
parser.add_argument("--native")
parser.add_argument("--cases", default="bench-jittered16,bench-adaptive,bench-guard,bench-exact,field-jittered16,field-adaptive,field-guard,field-exact")
args = parser.parse_args()
subprocess.run(["dotnet", "build", os.path.join(root, "samples", "RayLab.Console"), "-c", "Release", "-v", "q", "-nologo"],
               check=True, stdout=subprocess.DEVNULL)
tmp = tempfile.mkdtemp()
field = os.path.join(tmp, "field.json")
subprocess.run(["python3", os.path.join(root, "tools", "sphere-scenes.py"), "field", "24", "40", field], check=True)
scenes = {"bench": os.path.join(root, "benchmarks", "anchors", "bench-1080.json"), "field": field}
methods = {"jittered16": ["--sampler", "jittered", "--samples", "16"], "adaptive": ["--sampler", "adaptive"],
           "guard": ["--sampler", "adaptive", "--guard"], "exact": ["--sampler", "exact"]}
dll = lambda d: os.path.join(d, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab.dll")
builds = [("this", [os.path.abspath(args.native)] if args.native else ["dotnet", dll(root)])] + ([("before", ["dotnet", dll(args.before)])] if args.before else [])
# A build from before --warmup existed ran its warm-up render with --stats by itself.
warmup = {b: (["--warmup"] if "--warmup" in subprocess.run(d + ["render", "--help"], capture_output=True, text=True).stdout else [])
          for b, d in builds}
cases = args.cases.split(",")
cells = [(c, b, t) for c in cases for b, _ in builds for t in (1, 2)]
times = {cell: [] for cell in cells}
load = lambda: open("/proc/loadavg").read().split()[:3]
print(f"load average before: {' '.join(load())}")
for _ in range(args.rounds):
    for case, build, threads in cells:
        scene, method = case.split("-")
        stats = os.path.join(tmp, "s.json")
        subprocess.run(dict(builds)[build] + ["render", scenes[scene], "-o", os.path.join(tmp, "x.png"), "--width", "1920",
                        "--height", "1080", "--threads", str(threads), "--stats", stats] + warmup[build] + methods[method],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(stats) as f:
            times[(case, build, threads)].append(json.load(f)["renderMs"])
print(f"load average after: {' '.join(load())}")
m = {cell: statistics.median(t) for cell, t in times.items()}
head = "| case | 1 thread ms | 2 threads ms | speed-up | rounds' speed-ups, median | 95 % interval | rounds below 1.25× |" + (" before: 1 thread | before: 2 threads | before: speed-up | 1 thread, this / before |" if args.before else "")
print(head)
print("|---|" + "---:|" * (head.count("|") - 2))
for case in cases:
    ratios = [one / two for one, two in zip(times[(case, 'this', 1)], times[(case, 'this', 2)])]
    interval = median_interval(ratios)
    shown = f"{interval[0]:.2f}–{interval[1]:.2f}×" if interval else "–"
    row = (f"| {case} | {m[(case, 'this', 1)]:.1f} | {m[(case, 'this', 2)]:.1f} | {m[(case, 'this', 1)] / m[(case, 'this', 2)]:.2f}× |"
           f" {statistics.median(ratios):.2f}× | {shown} | {sum(r < 1.25 for r in ratios)} of {len(ratios)} |")
    if args.before:
        row += (f" {m[(case, 'before', 1)]:.1f} | {m[(case, 'before', 2)]:.1f} | {m[(case, 'before', 1)] / m[(case, 'before', 2)]:.2f}× |"
                f" {m[(case, 'this', 1)] / m[(case, 'before', 1)]:.3f} |")
    print(row)
