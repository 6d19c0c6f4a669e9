#!/usr/bin/env python3
"""Samplers' cost on a loaded machine: CPU seconds of whole `raylab render` processes, not wall-clock time.

When other jobs share the cores, renderMs (wall clock) moves by ±10 % from one render to the next; the CPU time a
process used does not count the time it waited for a core. Renders benchmarks/anchors/bench-1080.json on one thread
with each sampler (jittered first), ROUNDS times, each build given (a folder holding raylab.dll, e.g. a checkout's
samples/RayLab.Console/bin/Release/net10.0) alternating with the others, and prints the median CPU seconds (user +
system, from getrusage of the child) per sampler and build. The time includes start-up and the warm-up render:
compare builds per sampler, or take jittered at two sample counts to estimate that fixed part.

Usage: python3 tools/render-cpu.py ROUNDS SAMPLES SAMPLER[,SAMPLER…] DLLDIR [DLLDIR…]
"""
import os, resource, statistics, subprocess, sys, tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "benchmarks", "anchors", "bench-1080.json")
rounds, spp, samplers, dlls = int(sys.argv[1]), sys.argv[2], ["jittered"] + sys.argv[3].split(","), sys.argv[4:]
out = os.path.join(tempfile.mkdtemp(), "x.png")


def cpu_seconds(folder, sampler):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(["dotnet", os.path.join(folder, "raylab.dll"), "render", scene, "-o", out, "--threads", "1",
                    "--sampler", sampler, "--samples", spp], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


times = {}
for _ in range(rounds):
    for sampler in samplers:
        for folder in dlls:
            times.setdefault((folder, sampler), []).append(cpu_seconds(folder, sampler))
print(f"| sampler, {spp} spp | " + " | ".join(f"CPU s, {d}" for d in dlls) + " |")
print("|---|" + "---:|" * len(dlls))
for sampler in samplers:
    print(f"| {sampler} | " + " | ".join(f"{statistics.median(times[(d, sampler)]):.2f}" for d in dlls) + " |")
