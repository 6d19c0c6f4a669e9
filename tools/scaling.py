#!/usr/bin/env python3
"""How render time scales: resolution, samples per pixel and sphere count, through `raylab render --stats`.

The two-sphere scene (samples/scenes/two-spheres.json), jittered, 2 threads, auto kernel; renderMs is the median
of REPEATS runs. Sphere counts use N spheres on a jittered grid in front of the camera (the same layout as the
SphereCountBenchmarks). Prints Markdown tables.

Usage: python3 tools/scaling.py [REPEATS]    (default 3)
"""
import json, os, re, statistics, subprocess, sys, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
subprocess.run(["dotnet", "build", os.path.join(root, "samples", "RayLab.Console"), "-c", "Release", "-v", "q", "-nologo"],
               check=True, stdout=subprocess.DEVNULL)
raylab = ["dotnet", os.path.join(root, "samples", "RayLab.Console", "bin", "Release", "net10.0", "raylab.dll")]
tmp = tempfile.mkdtemp()
base_path = os.path.join(root, "samples", "scenes", "two-spheres.json")
base = json.loads(re.sub(r"(?m)^\s*//.*\n", "", open(base_path).read()))

def median_ms(scene_path, *options):
    ms = []
    for _ in range(repeats):
        stats = os.path.join(tmp, "s.json")
        subprocess.run(raylab + ["render", scene_path, "-o", os.path.join(tmp, "o.png"), "--threads", "2", "--stats", stats, "--warmup", *options],
                       check=True, stdout=subprocess.DEVNULL)
        s = json.load(open(stats))
        ms.append(s["renderMs"])
    return statistics.median(ms), s

def lowbias32(x):
    x &= 0xffffffff; x ^= x >> 16; x = (x * 0x7feb352d) & 0xffffffff; x ^= x >> 15; x = (x * 0x846ca68b) & 0xffffffff; x ^= x >> 16
    return x

def spheres(n):
    side = int(-(-n ** 0.5 // 1))
    out = []
    for i in range(n):
        h = lowbias32(i + 12345); h2 = lowbias32(h)
        jx, jy = (h >> 8) / 16777216 - 0.5, (h2 >> 8) / 16777216 - 0.5
        x = -2.4 + 4.8 * ((i % side) + 0.5 + 0.3 * jx) / side
        y = -1.6 + 3.2 * ((i // side) + 0.5 + 0.3 * jy) / side
        out.append({"center": [x, y, -(i % 3)], "radius": 0.35 * 4 / side, "color": [0.2 + 0.6 * (i % 2), 0.8 - 0.6 * (i % 2), 0.3]})
    return out

anchor_dir = os.path.join(root, "benchmarks", "anchors")

def anchor_ms():
    """The C++ avx512 anchor on bench-1080.json, as a yardstick of how quiet the machine was (None without AVX-512)."""
    out = subprocess.run(["python3", os.path.join(anchor_dir, "native.py"), os.path.join(anchor_dir, "bench-1080.json"), "4", "2", "avx512"],
                         capture_output=True, text=True)
    line = json.loads(out.stdout.strip().splitlines()[-1])
    return None if "error" in line else line["seconds"] * 1000

yardstick = [anchor_ms() for _ in range(3)]
print(f"Median renderMs of {repeats} runs, jittered, 2 threads (`python3 tools/scaling.py`).\n")
print("| resolution | 1 spp | 4 spp | 16 spp | 64 spp | Msamples/s at 16 spp |")
print("|---|---:|---:|---:|---:|---:|")
for w, h in [(640, 480), (1280, 720), (1920, 1080), (3840, 2160)]:
    cells = []
    for spp in [1, 4, 16, 64]:
        ms, s = median_ms(base_path, "--width", str(w), "--height", str(h), "--sampler", "jittered", "--samples", str(spp))
        cells.append(ms)
        if spp == 16:
            rate = s["rays"] / ms / 1e3
    print(f"| {w}x{h} | " + " | ".join(f"{c:.1f}" for c in cells) + f" | {rate:.0f} |")

print("\n| spheres (1920x1080, 16 spp) | median ms | Msamples/s | ms per sphere over 2 |")
print("|---:|---:|---:|---:|")
first = None
for n in [2, 8, 32, 128]:
    scene = dict(base, spheres=spheres(n))
    path = os.path.join(tmp, f"spheres-{n}.json")
    json.dump(scene, open(path, "w"))
    ms, s = median_ms(path, "--width", "1920", "--height", "1080", "--sampler", "jittered", "--samples", "16")
    first = first if first is not None else (n, ms)
    per = f"{(ms - first[1]) / (n - first[0]):.2f}" if n != first[0] else "–"
    print(f"| {n} | {ms:.1f} | {s['rays'] / ms / 1e3:.0f} | {per} |")

yardstick += [anchor_ms() for _ in range(3)]
if None not in yardstick:
    print(f"\nYardstick: the C++ `avx512` anchor on bench-1080.json ran in {statistics.median(yardstick):.1f} ms (median of 3 before"
          f" and 3 after, {min(yardstick):.1f}–{max(yardstick):.1f}); ~21 ms means the machine was quiet.")
