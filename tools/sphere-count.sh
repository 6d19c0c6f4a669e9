#!/bin/sh
# The cost-against-sphere-count table of docs/performance.md: random scenes (tools/sphere-scenes.py random N)
# at 320×240, 2 threads, renderMs of one run each (jittered 16, adaptive at its defaults, exact), and the
# same with "acceleration": "none" where it finishes in 60 s. Usage: sh tools/sphere-count.sh [RAYLAB]
R=${1:-samples/RayLab.Console/bin/Release/net10.0/raylab}
T=$(mktemp -d)
ms() { timeout 60 "$R" render "$1" -o "$T/x.png" --threads 2 --stats "$T/s.json" $2 >/dev/null 2>&1 && python3 -c "import json;print(round(json.load(open('$T/s.json'))['renderMs'],1))" || echo "> 60 s"; }
echo "| spheres | jittered 16 | jittered 16, none | adaptive | adaptive, none | exact | exact, none |"
echo "|---:|---:|---:|---:|---:|---:|---:|"
for n in 1 10 100 1000 10000 100000; do
  python3 tools/sphere-scenes.py random $n "$T/on.json"
  python3 tools/sphere-scenes.py random $n "$T/off.json" 1 --no-acceleration
  row="| $n"
  for s in "--sampler jittered --samples 16" "--sampler adaptive" "--sampler exact"; do
    row="$row | $(ms "$T/on.json" "$s") | $(ms "$T/off.json" "$s")"
  done
  echo "$row |"
done
rm -rf "$T"
