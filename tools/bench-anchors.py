#!/usr/bin/env python3
"""RayLab against the native C++ anchors (shared/anchors), in one sitting.

Renders shared/anchors/bench-1080.json (the two-sphere scene at 1920x1080) with jittered 16 spp on 2 threads
through `raylab render --stats` (renderMs: the render loop only, after a warm-up render; see README) and with
each anchor mode (`native.py ... 4 2 MODE`, render only), alternating, ROUNDS times; prints a Markdown table of
medians and ratios. Also the lab's adaptive sampler at its defaults, and any extra rows given as raylab options.

Usage: python3 tools/bench-anchors.py [ROUNDS]     (default 7; needs ../shared beside the repository)
"""
import json, os, statistics, subprocess, sys, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
shared = os.path.join(os.path.dirname(root), "shared", "anchors")
scene = os.path.join(shared, "bench-1080.json")
rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 7
subprocess.run(["dotnet", "build", os.path.join(root, "samples", "RayLab.Console"), "-c", "Release", "-v", "q", "-nologo"],
               check=True, stdout=subprocess.DEVNULL)
raylab = ["dotnet", os.path.join(root, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab.dll")]
tmp = tempfile.mkdtemp()
samples = 1920 * 1080 * 16

ours = {  # label -> raylab options
    "RayLab auto (widest SIMD)": ["--sampler", "jittered", "--samples", "16"],
    "RayLab vector256 (AVX2 width)": ["--sampler", "jittered", "--samples", "16", "--kernel", "vector256"],
    "RayLab scalar (double, one ray at a time)": ["--sampler", "jittered", "--samples", "16", "--kernel", "scalar"],
    "RayLab adaptive, defaults (depth 0-3, contrast 0.1)": ["--sampler", "adaptive"],
}
anchors = ["scalar", "avx2", "avx2v", "avx512"]
times = {k: [] for k in list(ours) + anchors}
extra = {}

def run_ours(label, options):
    stats = os.path.join(tmp, "s.json")
    subprocess.run(raylab + ["render", scene, "-o", os.path.join(tmp, "o.png"), "--threads", "2", "--stats", stats] + options,
                   check=True, stdout=subprocess.DEVNULL)
    s = json.load(open(stats))
    times[label].append(s["renderMs"])
    extra[label] = s

def run_anchor(mode):
    out = subprocess.run(["python3", os.path.join(shared, "native.py"), scene, "4", "2", mode], capture_output=True, text=True)
    line = json.loads(out.stdout.strip().splitlines()[-1])
    if "error" in line:
        times.pop(mode, None)
        return
    times[mode].append(line["seconds"] * 1000)

for r in range(rounds):
    for label, options in ours.items():
        run_ours(label, options)
    for mode in list(anchors):
        if mode in times:
            run_anchor(mode)

med = {k: statistics.median(v) for k, v in times.items() if v}
best = med.get("avx512") or med.get("avx2v")
print(f"Median of {rounds} alternating runs, 2 threads, render only; bench-1080.json (1920x1080, 16 spp = {samples/1e6:.1f} M samples).\n")
print("| renderer | median ms | Msamples/s | vs avx512 anchor |")
print("|---|---:|---:|---:|")
for k in ["avx512", "avx2v", "avx2", "scalar"]:
    if k in med:
        print(f"| C++ anchor `{k}` | {med[k]:.1f} | {samples / med[k] / 1e3:.0f} | {med['avx512'] / med[k] if 'avx512' in med else float('nan'):.2f}x |")
for k in ours:
    rays = extra[k]["rays"]
    per = f" ({extra[k]['raysPerPixel']:.2f} rays/px)" if "adaptive" in k else ""
    ratio = f"{med['avx512'] / med[k]:.2f}x" if 'avx512' in med and "adaptive" not in k else "-"
    print(f"| {k}{per} | {med[k]:.1f} | {rays / med[k] / 1e3:.0f} | {ratio} |")
pairs = [("RayLab auto (widest SIMD)", "avx512"), ("RayLab vector256 (AVX2 width)", "avx2v"), ("RayLab scalar (double, one ray at a time)", "scalar")]
print("\nSame work, same width (anchor time / RayLab time; > 1 means RayLab is faster):\n")
for a, b in pairs:
    if a in med and b in med:
        print(f"- {a} vs `{b}`: {med[b] / med[a]:.2f}")
print(f"\nkernel used by auto: {extra['RayLab auto (widest SIMD)']['kernel']}; retraced samples: {extra['RayLab auto (widest SIMD)']['retracedSamples']}")
