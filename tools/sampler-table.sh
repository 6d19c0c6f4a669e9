#!/usr/bin/env bash
# Rays per pixel of each sampler on the lab's two-sphere scene (samples/scenes/two-spheres.json, 800×600):
# prints a Markdown table from `raylab render --stats`. Usage: bash tools/sampler-table.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scene="$root/samples/scenes/two-spheres.json"
dotnet build "$root/samples/RayLab.Console" -c Release -v q -nologo >/dev/null
raylab=("dotnet" "$root/samples/RayLab.Console/bin/Release/net10.0/raylab.dll")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
row() { # label, args...
  local label=$1; shift
  "${raylab[@]}" render "$scene" -o "$tmp/img.png" --stats "$tmp/s.json" --warmup "$@" >/dev/null
  python3 - "$label" "$tmp/s.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[2]))
print(f"| {sys.argv[1]} | {s['rays']:,} | {s['raysPerPixel']:.2f} |")
PY
}
echo "| sampler (two-spheres.json, perspective, 800×600) | primary rays | rays per pixel |"
echo "|---|---:|---:|"
for camera in perspective; do
  for d in "0 1 0.05" "0 2 0.05" "0 3 0.05" "0 4 0.05" "0 3 0.01" "0 3 0.2" "1 3 0.05"; do
    set -- $d
    row "adaptive, min depth $1, max depth $2, contrast $3" --camera $camera --sampler adaptive --min-depth $1 --max-depth $2 --contrast $3
  done
  quincunx="$tmp/quincunx.json"
  python3 -c "import json,re,sys; t=re.sub(r'(?m)^\s*//.*\n','',open(sys.argv[1]).read()); d=json.loads(t); d['sampler']['quincunx']=True; json.dump(d,open(sys.argv[2],'w'))" "$scene" "$quincunx"
  "${raylab[@]}" render "$quincunx" -o "$tmp/img.png" --stats "$tmp/s.json" --warmup --camera $camera >/dev/null
  python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(f\"| adaptive with the quincunx (every centre), depth 0–3, contrast 0.05 | {s['rays']:,} | {s['raysPerPixel']:.2f} |\")" "$tmp/s.json"
  for s in "regular 16" "random 16" "jittered 16" "cmj 16" "multijittered 16" "nrooks 16" "hammersley 16" "sobol 16" "pmj02 16" "pmj02bn 16" "zsobol 16"; do
    set -- $s
    row "$1, $2 samples" --camera $camera --sampler $1 --samples $2
  done
done
