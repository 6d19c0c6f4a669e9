#!/usr/bin/env bash
# RayLab on the GPU against the CUDA anchor (../shared/anchors/gpu_anchor.cu), in one sitting, on a machine with an
# NVIDIA GPU, the CUDA toolkit (nvcc) and the .NET 10 SDK. Run from the repository root:
#
#     tools/gpu/measure.sh [RESULTS_FOLDER]        # default: gpu-results
#
# It prints and keeps (RESULTS_FOLDER/*.txt, *.json):
#   1. the machine: nvidia-smi, the CPU, the load;
#   2. the anchor's kernel and copy-back times (median of 20 after 2 warm-ups, CUDA events) at 1080p 16 spp,
#      1080p 256 spp and 2160p 256 spp, two spheres (bench-1080-n4.txt with its first line changed);
#   3. RayLab's kernel alone and the whole device call (uploads, kernel, bytes back), the same three sizes, medians of
#      20 after 2 warm-ups, the first launch, and the bytes that differ from the CPU renderer's
#      (tests/RayLab.Gpu.Tests/GpuFigures.cs);
#   4. the whole command, `raylab render bench-1080.json --device gpu` (jittered 16 spp) and `--device cpu`,
#      5 runs each, alternating, wall time (start-up, scene, compile, render, PNG) and the stats file's renderMs (--warmup:
#      without the first launch);
#   5. every built-in point sampler at 1080p 16 spp once on each device, and whether the PNGs' bytes are the same (cmj's
#      jitter is the one product a GPU compiler may fuse into a multiply-add: docs/gpu.md);
#   6. the anchor once more, last, so a drift of the machine during the sitting shows.
# Nothing here is timed by a test: the figures go into docs/performance.md with this command.
set -euo pipefail
results=${1:-gpu-results}
mkdir -p "$results"
anchors=../shared/anchors
[ -f "$anchors/gpu_anchor.cu" ] || { echo "measure.sh: $anchors/gpu_anchor.cu not found (../shared beside the clone)" >&2; exit 1; }
command -v nvcc >/dev/null || { echo "measure.sh: nvcc not found (the CUDA toolkit)" >&2; exit 1; }

{ nvidia-smi; lscpu | grep -E 'Model name|^CPU\(s\)'; uptime; dotnet --version; } | tee "$results/machine.txt"

nvcc -O3 -arch=native "$anchors/gpu_anchor.cu" -o "$results/gpu_anchor"
input() { # width height n: the anchor's input with its first line replaced
  { echo "$1 $2 $3 16 0"; tail -n +2 "$anchors/bench-1080-n4.txt"; }
}
anchor_all() {
  for size in "1920 1080 4" "1920 1080 16" "3840 2160 16"; do
    # shellcheck disable=SC2086
    echo "$size: $(input $size | "$results/gpu_anchor" 20)"
  done
}
anchor_all | tee "$results/anchor-first.txt"

dotnet build tests/RayLab.Gpu.Tests -c Release
dotnet test tests/RayLab.Gpu.Tests -c Release --no-build --filter Category=Figures \
  --logger "console;verbosity=detailed" | tee "$results/raylab-kernel.txt"

dotnet build samples/RayLab.Console -c Release
raylab=(dotnet samples/RayLab.Console/bin/Release/net10.0/raylab.dll)
for run in 1 2 3 4 5; do
  for device in gpu cpu; do
    start=$(date +%s.%N)
    "${raylab[@]}" render benchmarks/anchors/bench-1080.json --sampler jittered --samples 16 --device "$device" --warmup \
      -o "$results/out-$device.png" --stats "$results/stats-$device-$run.json" >/dev/null
    end=$(date +%s.%N)
    echo "$device run $run: wall $(echo "$end - $start" | bc) s, renderMs $(grep -o '"renderMs": *[0-9.]*' "$results/stats-$device-$run.json" | tr -dc '0-9.')"
  done
done | tee "$results/raylab-command.txt"
cmp "$results/out-gpu.png" "$results/out-cpu.png" && echo "gpu and cpu PNGs: same bytes" | tee -a "$results/raylab-command.txt"

for sampler in regular jittered random hammersley nrooks multijittered cmj sobol zsobol pmj02 pmj02bn; do
  for device in gpu cpu; do
    "${raylab[@]}" render benchmarks/anchors/bench-1080.json --sampler "$sampler" --samples 16 --device "$device" \
      -o "$results/$sampler-$device.png" >/dev/null
  done
  if cmp -s "$results/$sampler-gpu.png" "$results/$sampler-cpu.png"; then echo "$sampler: same bytes"; else echo "$sampler: bytes differ"; fi
done | tee "$results/samplers.txt"

anchor_all | tee "$results/anchor-last.txt"
echo "measure.sh: results in $results/"
