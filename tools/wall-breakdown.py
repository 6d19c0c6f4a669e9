#!/usr/bin/env python3
"""Where the wall time of one native `raylab render` goes, beyond renderMs and encodeMs.

Runs the native build's jittered 16 spp and exact renders of benchmarks/anchors/bench-1080.json (1920×1080, 2 threads),
ROUNDS rounds, each round once plainly (its wall time, as startup-speed.py measures it) and once under
`strace -f --seccomp-bpf -ttt -T` tracing only execve, openat, fsync, rename and exit_group (the other system calls
run untraced, so the render is not slowed), and prints medians of the phases those calls mark:

  start        execve → the scene file's openat (loader, runtime start, command-line parsing)
  to render    scene openat → start of the render (scene load, preparation, image allocation), from the traced
               span scene-open → PNG-open minus renderMs
  commitMs     of "to render", the image's pages first touched on every render thread (--stats' commitMs; only in
               the --warmup run: a plain render pays those page faults inside renderMs)
  encode       PNG temp file openat → its rename returns (PNG encoding, write, fsync, rename = encodeMs)
  after        PNG rename → exit_group (the --stats JSON, the summary line)
  exit         exit_group → the last thread gone (strace's "+++ exited")
  rest         the plain run's wall minus all of the above (medians): what none of them covers — the kernel's
               exec before execve returns, process teardown after the last thread, Python's spawn and wait

With raylab's --warmup in a third run per round (this tool's --warmup), the native build renders the scaled-down warm-up first
and commits the image's pages, so renderMs after a warm-up can be compared with the cold one.

Build first: dotnet publish samples/RayLab.Console -c Release -r linux-x64 -o artifacts/native
With --faults, one more run per sampler under `perf record -e page-faults -c 1 -g` counts every page fault (a few µs
each on the lab's VM: the kernel finds, zeroes and charges a page) by the first RayLab, runtime, zlib or loader
frame on its stack.

Usage: python3 tools/wall-breakdown.py [ROUNDS] [--binary PATH] [--warmup] [--faults]   (needs strace)
"""
import argparse, json, os, re, statistics, subprocess, tempfile, time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "benchmarks", "anchors", "bench-1080.json")
parser = argparse.ArgumentParser()
parser.add_argument("rounds", nargs="?", type=int, default=9)
parser.add_argument("--binary", default=os.path.join(root, "artifacts", "native", "raylab"))
parser.add_argument("--warmup", action="store_true")
parser.add_argument("--faults", action="store_true",
                    help="also count the page faults of one run of each sampler by who took them (needs perf)")
args = parser.parse_args()
if not os.access(args.binary, os.X_OK):
    raise SystemExit(f"wall-breakdown.py: {args.binary} is missing; publish it first (see the docstring)")

tmp = tempfile.mkdtemp()
png, stats, trace = (os.path.join(tmp, n) for n in ("x.png", "s.json", "trace.txt"))
samplers = [("jittered 16", ["--sampler", "jittered", "--samples", "16"]), ("exact", ["--sampler", "exact"])]
line = re.compile(r"^\d+\s+(?P<t>\d+\.\d+) (?P<call>\w+)\((?P<args>.*?)(?:<(?P<dur>\d+\.\d+)>)?$")


def run(options, env=None, traced=False):
    command = [args.binary, "render", scene, *options, "--threads", "2", "-o", png, "--stats", stats]
    if traced:
        command = ["strace", "-f", "--seccomp-bpf", "-ttt", "-T", "-o", trace,
                   "-e", "trace=execve,openat,fsync,rename,exit_group", *command]
    start = time.perf_counter()
    subprocess.run(command, check=True, cwd=tmp, stdout=subprocess.DEVNULL, env=env)
    wall = (time.perf_counter() - start) * 1000
    with open(stats) as f:
        return wall, json.load(f)


def phases(render_ms):
    """Milliseconds between the marks in the trace of one run."""
    marks, last = {}, 0.0
    with open(trace) as f:
        for text in f:
            if "+++ exited" in text:
                last = max(last, float(text.split()[1]))
                continue
            m = line.match(text)
            if not m:
                continue
            t, call, a = float(m["t"]), m["call"], m["args"]
            end = t + float(m["dur"] or 0)
            if call == "execve" and "exec" not in marks:
                marks["exec"] = t
            elif call == "openat" and "bench-1080.json" in a and "scene" not in marks:
                marks["scene"] = t
            elif call == "openat" and ".x.png." in a:
                marks["png"] = t
            elif call == "rename" and ".x.png." in a:
                marks["png done"] = end
            elif call == "exit_group":
                marks["exit"] = t
    ms = lambda a, b: (marks[b] - marks[a]) * 1000
    return {"start": ms("exec", "scene"), "to render": ms("scene", "png") - render_ms, "encode": ms("png", "png done"),
            "after": ms("png done", "exit"), "exit": (last - marks["exit"]) * 1000}


rows = {}
for _ in range(args.rounds):
    for label, options in samplers:
        r = rows.setdefault(label, {})
        wall, s = run(options)
        r.setdefault("wall", []).append(wall)
        r.setdefault("renderMs", []).append(s["renderMs"])
        r.setdefault("encodeMs", []).append(s["encodeMs"])
        r.setdefault("commitMs", []).append(s.get("commitMs", float("nan")))
        _, s = run(options, traced=True)
        for k, v in phases(s["renderMs"]).items():
            r.setdefault(k, []).append(v)
        if args.warmup:
            _, s = run([*options, "--warmup"])
            r.setdefault("renderMs after warm-up", []).append(s["renderMs"])

columns = ["wall", "start", "to render", "commitMs", "renderMs", "encodeMs", "encode", "after", "exit", "rest"]
if args.warmup:
    columns.append("renderMs after warm-up")
print(f"Medians of {args.rounds} rounds (`python3 tools/wall-breakdown.py {args.rounds}"
      + (" --warmup" if args.warmup else "") + f"`), load average at the end {os.getloadavg()[0]:.1f}; ms.\n")
print("| sampler | " + " | ".join(columns) + " |")
print("|---|" + "---:|" * len(columns))
med = statistics.median
for label, r in rows.items():
    r["rest"] = [med(r["wall"]) - sum(med(r[k]) for k in ("start", "to render", "renderMs", "encodeMs", "after", "exit"))]
    print(f"| {label} | " + " | ".join(f"{med(r[c]):.1f}" for c in columns) + " |")

if args.faults:
    import collections
    data = os.path.join(tmp, "faults.perf")
    owners = ("RayLab", "raylab_", "Compression", "System_", "S_P_", "WKS::", "Rhp", "_dl_", "pthread", "deflate")
    for label, options in samplers:
        subprocess.run(["perf", "record", "-q", "-e", "page-faults", "-c", "1", "-g", "-o", data, "--", args.binary,
                        "render", scene, *options, "--threads", "2", "-o", png], check=True, cwd=tmp,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        script = subprocess.run(["perf", "script", "-i", data, "-F", "ip,sym"], check=True, capture_output=True, text=True).stdout
        counts = collections.Counter()
        for stack in script.split("\n\n"):
            frames = [f.strip().split(" ", 1)[-1] for f in stack.strip().splitlines() if f.strip()]
            if frames:
                counts[next((f for f in frames if any(o in f for o in owners)), frames[-1])[:100]] += 1
        print(f"\nPage faults of one {label} run: {sum(counts.values())}, by who took them:\n")
        print("| faults | first RayLab, runtime, zlib or loader frame |")
        print("|---:|---|")
        for owner, n in counts.most_common(8):
            print(f"| {n} | `{owner}` |")
