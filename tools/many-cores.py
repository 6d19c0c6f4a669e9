#!/usr/bin/env python3
"""The tables of a `tools/many-cores.sh run` folder: the median ms of each case and build at each thread count, the
speed-up over 1 thread, the median of the rounds' own speed-ups (each round's 1-thread time over its time at N, which
takes out what drifts between rounds) with its 95 % interval, and RayLab's jittered 16 against the C++ anchors at
every count (the anchor's time over RayLab's).

Usage: python3 tools/many-cores.py OUT   (OUT: the folder `tools/many-cores.sh run DIR OUT` or `pair` wrote)
"""
import collections, math, os, statistics, sys

from pairstats import median_interval

if len(sys.argv) != 2 or not os.path.isfile(os.path.join(sys.argv[1], "raw.tsv")):
    sys.exit("usage: python3 tools/many-cores.py OUT   (OUT holds raw.tsv from tools/many-cores.sh run)")
out = sys.argv[1]
times = collections.defaultdict(list)
order = []
pairs = collections.defaultdict(list)
rounds_of = collections.defaultdict(dict)
with open(os.path.join(out, "raw.tsv")) as f:
    next(f)
    for line in f:
        r, case, build, threads, ms = line.rstrip("\n").split("\t")
        if case not in order:
            order.append(case)
        if ms != "NaN" and build in ("this", "before"):
            pairs[(case, build)].append(float(ms))
            rounds_of[(case, build)][r] = float(ms)
        elif ms != "NaN":
            times[(case, int(threads))].append(float(ms))
            rounds_of[(case, int(threads))][r] = float(ms)


if pairs:
    # `pair` mode: this build against the other, render by render. Each round renders a case with one build and then
    # the other, so the ratio of a round's two times takes out what drifts between rounds; its median over the rounds,
    # with the median's 95 % interval, says whether a difference is shown.
    print(open(os.path.join(out, "machine.txt")).readline().strip())
    print("\n| case | this ms | before ms | this / before, medians | median of the rounds' ratios | 95 % interval |\n|---|---:|---:|---:|---:|---:|")
    ratios_all = []
    for case in order:
        t, b = statistics.median(pairs[(case, "this")]), statistics.median(pairs[(case, "before")])
        this, before = rounds_of[(case, "this")], rounds_of[(case, "before")]
        ratios = [this[r] / before[r] for r in this if r in before]
        ratios_all.append(statistics.median(ratios))
        interval = median_interval(ratios)
        shown = f"{interval[0]:.3f}–{interval[1]:.3f}" if interval else "–"
        print(f"| {case} | {t:.1f} | {b:.1f} | {t / b:.3f} | {statistics.median(ratios):.3f} | {shown} |")
    print(f"\n{len(order)} cases; geometric mean of the median ratios {math.exp(statistics.fmean(math.log(x) for x in ratios_all)):.3f}")
    sys.exit(0)
threads = sorted({t for _, t in times})
rounds = max(len(v) for v in times.values())
median = {k: statistics.median(v) for k, v in times.items()}
print(open(os.path.join(out, "machine.txt")).readline().strip())
print(f"\nmedian ms of {rounds} interleaved rounds; speed-up = median at 1 thread / median at N\n")
print("| case | 1 thread ms | " + " | ".join(f"{t}" for t in threads[1:]) + f" | {threads[-1]} threads ms |")
print("|---|---:|" + "---:|" * len(threads))
for case in order:
    one = median.get((case, 1), math.nan)
    cells = [f"{one / median[(case, t)]:.2f}×" if (case, t) in median else "–" for t in threads[1:]]
    last = median.get((case, threads[-1]), math.nan)
    print(f"| {case} | {one:.1f} | " + " | ".join(cells) + f" | {last:.1f} |")
print("\nThe median of the rounds' own speed-ups (a round's 1-thread time over its time at N), with its 95 % interval\n")
print("| case | " + " | ".join(f"{t}" for t in threads[1:]) + " |")
print("|---|" + "---:|" * (len(threads) - 1))
for case in order:
    cells = []
    for t in threads[1:]:
        one, many = rounds_of.get((case, 1), {}), rounds_of.get((case, t), {})
        own = [one[r] / many[r] for r in one if r in many]
        interval = median_interval(own) if own else None
        cells.append(f"{statistics.median(own):.2f}× ({interval[0]:.2f}–{interval[1]:.2f})" if interval
                     else f"{statistics.median(own):.2f}×" if own else "–")
    print(f"| {case} | " + " | ".join(cells) + " |")
anchors = [c for c in order if "-anchor-" in c and c.startswith("bench-jittered16")]
if anchors and any(("bench-jittered16", t) in median for t in threads):
    print("\nThe anchor's bench-jittered16 time over RayLab's (above 1: RayLab is faster)\n")
    print("| anchor | " + " | ".join(f"{t}" for t in threads) + " |")
    print("|---|" + "---:|" * len(threads))
    for a in anchors:
        for raylab in ("bench-jittered16", "bench-jittered16-vector256"):
            cells = [f"{median[(a, t)] / median[(raylab, t)]:.2f}" if (raylab, t) in median and (a, t) in median else "–"
                     for t in threads]
            print(f"| {raylab} against {a.split('-anchor-')[1]} | " + " | ".join(cells) + " |")
