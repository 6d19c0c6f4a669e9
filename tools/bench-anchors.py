#!/usr/bin/env python3
"""RayLab against the native C++ anchors (benchmarks/anchors), in one run.

Renders benchmarks/anchors/bench-1080.json (the two-sphere scene at 1920x1080) with jittered 16 spp on 2 threads
through `raylab render --stats --warmup` (renderMs: the render loop only, after a warm-up render; see README) and with
each anchor mode (`native.py ... 4 2 MODE`, render only), alternating, ROUNDS times; prints a Markdown table of
medians and ratios. Also the lab's adaptive sampler at its defaults, and any extra rows given as raylab options.

Also an AVX2-only machine, emulated on this one: RayLab with DOTNET_EnableAVX512=0 (the JIT then uses no AVX-512
instruction and `auto` picks the 8-lane kernel) against `avx2v` built with -march=x86-64-v3 (AVX2 + FMA, no AVX-512:
a copy of native.py and native_ref.cpp in a temporary folder with only that flag changed).

Usage: python3 tools/bench-anchors.py [ROUNDS]     (default 7)
"""
import json, os, shutil, statistics, subprocess, sys, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
anchor_dir = os.path.join(root, "benchmarks", "anchors")
scene = os.path.join(anchor_dir, "bench-1080.json")
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
avx2_only = "RayLab on an AVX2-only machine (DOTNET_EnableAVX512=0)"
ours[avx2_only] = ["--sampler", "jittered", "--samples", "16"]
environments = {avx2_only: {"DOTNET_EnableAVX512": "0"}}

# The avx2v anchor as a compiler targeting an AVX2-only CPU builds it.
v3 = os.path.join(tmp, "anchor-x86-64-v3")
os.makedirs(v3)
shutil.copy2(os.path.join(anchor_dir, "native_ref.cpp"), v3)  # keeps its time, so native.py compiles it once, not per run
native = open(os.path.join(anchor_dir, "native.py")).read()
assert '"-march=native"' in native and '"raylab_native_anchor"' in native, "native.py changed: update bench-anchors.py"
with open(os.path.join(v3, "native.py"), "w") as f:
    f.write(native.replace('"-march=native"', '"-march=x86-64-v3"').replace('"raylab_native_anchor"', '"raylab_native_anchor_x86_64_v3"'))
v3_label = "avx2v built for x86-64-v3"
anchors = ["scalar", "avx2", "avx2v", "avx512"]
times = {k: [] for k in list(ours) + anchors + [v3_label]}
extra = {}

def run_ours(label, options):
    stats = os.path.join(tmp, "s.json")
    subprocess.run(raylab + ["render", scene, "-o", os.path.join(tmp, "o.png"), "--threads", "2", "--stats", stats, "--warmup"] + options,
                   check=True, stdout=subprocess.DEVNULL, env={**os.environ, **environments.get(label, {})})
    s = json.load(open(stats))
    times[label].append(s["renderMs"])
    extra[label] = s

def run_anchor(mode, label=None, folder=anchor_dir):
    label = label or mode
    out = subprocess.run(["python3", os.path.join(folder, "native.py"), scene, "4", "2", mode], capture_output=True, text=True)
    line = json.loads(out.stdout.strip().splitlines()[-1])
    if "error" in line:
        times.pop(label, None)
        return
    times[label].append(line["seconds"] * 1000)

for r in range(rounds):
    for label, options in ours.items():
        run_ours(label, options)
    for mode in list(anchors):
        if mode in times:
            run_anchor(mode)
    if v3_label in times:
        run_anchor("avx2v", v3_label, v3)

med = {k: statistics.median(v) for k, v in times.items() if v}
best = med.get("avx512") or med.get("avx2v")
print(f"Median of {rounds} alternating runs, 2 threads, render only; bench-1080.json (1920x1080, 16 spp = {samples/1e6:.1f} M samples).\n")
print("| renderer | median ms | Msamples/s | vs avx512 anchor |")
print("|---|---:|---:|---:|")
for k in ["avx512", "avx2v", "avx2", "scalar", v3_label]:
    if k in med:
        print(f"| C++ anchor `{k}` | {med[k]:.1f} | {samples / med[k] / 1e3:.0f} | {med['avx512'] / med[k] if 'avx512' in med else float('nan'):.2f}x |")
for k in ours:
    rays = extra[k]["rays"]
    per = f" ({extra[k]['raysPerPixel']:.2f} rays/px)" if "adaptive" in k else ""
    ratio = f"{med['avx512'] / med[k]:.2f}x" if 'avx512' in med and "adaptive" not in k else "-"
    print(f"| {k}{per} | {med[k]:.1f} | {rays / med[k] / 1e3:.0f} | {ratio} |")
pairs = [("RayLab auto (widest SIMD)", "avx512"), ("RayLab vector256 (AVX2 width)", "avx2v"),
         (avx2_only, v3_label), ("RayLab scalar (double, one ray at a time)", "scalar")]
print("\nSame work, same width (anchor time / RayLab time; > 1 means RayLab is faster):\n")
for a, b in pairs:
    if a in med and b in med:
        print(f"- {a} vs `{b}`: {med[b] / med[a]:.2f}")
print(f"\nkernel used by auto: {extra['RayLab auto (widest SIMD)']['kernel']}; retraced samples: {extra['RayLab auto (widest SIMD)']['retracedSamples']};"
      f" kernel used with DOTNET_EnableAVX512=0: {extra[avx2_only]['kernel']}")
