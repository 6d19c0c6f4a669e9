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
#   6. the sphere field (960 spheres, through its hierarchy) jittered 16 spp, and adaptive (max depth 3, plain and
#      guarded) on the bench scene and the field, at 1080p, once on each device with --warmup: renderMs, and whether the
#      PNGs and the heat maps (rays per pixel) are the same bytes; the kernel alone and the whole device call of the same
#      renders, medians of 5 after a warm-up (GpuFigures.FieldAndAdaptiveTimes, in step 3);
#   7. `raylab compare samples/scenes/two-spheres.json` at 1920x1080 with its default settings, --device gpu and then
#      --device cpu: wall time, the stats file's stages (the first launch apart), and whether every picture is the same;
#   8. the anchor once more, last, so a drift of the machine during the sitting shows.
# About 5 to 7 minutes on a 16-core host (the CPU's compare the longest part, at most 240 s).
#
#     RAYLAB_MEASURE_DRY=1 tools/gpu/measure.sh /tmp/dry   # a dry run without a GPU: ILGPU's CPU accelerator, 48x32,
#                                                          # compare at 2 budgets and 2 depths, no anchor, no figures
# Nothing here is timed by a test: the figures go into docs/performance.md with this command.
set -euo pipefail
results=${1:-gpu-results}
mkdir -p "$results"
anchors=../shared/anchors
dry=${RAYLAB_MEASURE_DRY:-0}
if [ "$dry" = 1 ]; then
  gpu=ilgpu-cpu; size=(--width 48 --height 32); compare_extra=(--budgets 1,4 --max-depths 1,2 --repeats 1); config=Debug
else
  gpu=gpu; size=(--width 1920 --height 1080); compare_extra=(); config=Release
  [ -f "$anchors/gpu_anchor.cu" ] || { echo "measure.sh: $anchors/gpu_anchor.cu not found (../shared beside the clone)" >&2; exit 1; }
  command -v nvcc >/dev/null || { echo "measure.sh: nvcc not found (the CUDA toolkit)" >&2; exit 1; }
fi

{ if [ "$dry" = 1 ]; then echo "dry run: ILGPU's CPU accelerator, no GPU"; else nvidia-smi; fi
  lscpu | grep -E 'Model name|^CPU\(s\)'; uptime; dotnet --version; } | tee "$results/machine.txt"

[ "$dry" = 1 ] || nvcc -O3 -arch=native "$anchors/gpu_anchor.cu" -o "$results/gpu_anchor"
input() { # width height n: the anchor's input with its first line replaced
  { echo "$1 $2 $3 16 0"; tail -n +2 "$anchors/bench-1080-n4.txt"; }
}
anchor_all() {
  [ "$dry" = 1 ] && { echo "dry run: no anchor"; return; }
  for anchor_size in "1920 1080 4" "1920 1080 16" "3840 2160 16"; do
    # shellcheck disable=SC2086
    echo "$anchor_size: $(input $anchor_size | "$results/gpu_anchor" 20)"
  done
}
anchor_all | tee "$results/anchor-first.txt"

if [ "$dry" != 1 ]; then
  dotnet build tests/RayLab.Gpu.Tests -c Release
  dotnet test tests/RayLab.Gpu.Tests -c Release --no-build --filter Category=Figures \
    --logger "console;verbosity=detailed" | tee "$results/raylab-kernel.txt"
fi

dotnet build samples/RayLab.Console -c "$config"
raylab=(dotnet "samples/RayLab.Console/bin/$config/net10.0/raylab.dll")
for run in 1 2 3 4 5; do
  for device in "$gpu" cpu; do
    start=$(date +%s.%N)
    "${raylab[@]}" render benchmarks/anchors/bench-1080.json "${size[@]}" --sampler jittered --samples 16 --device "$device" --warmup \
      -o "$results/out-$device.png" --stats "$results/stats-$device-$run.json" >/dev/null
    end=$(date +%s.%N)
    echo "$device run $run: wall $(echo "$end - $start" | bc) s, renderMs $(grep -o '"renderMs": *[0-9.]*' "$results/stats-$device-$run.json" | tr -dc '0-9.')"
  done
done | tee "$results/raylab-command.txt"
cmp "$results/out-$gpu.png" "$results/out-cpu.png" && echo "gpu and cpu PNGs: same bytes" | tee -a "$results/raylab-command.txt"

for sampler in regular jittered random hammersley nrooks multijittered cmj sobol zsobol pmj02 pmj02bn; do
  for device in "$gpu" cpu; do
    "${raylab[@]}" render benchmarks/anchors/bench-1080.json "${size[@]}" --sampler "$sampler" --samples 16 --device "$device" \
      -o "$results/$sampler-$device.png" >/dev/null
  done
  if cmp -s "$results/$sampler-$gpu.png" "$results/$sampler-cpu.png"; then echo "$sampler: same bytes"; else echo "$sampler: bytes differ"; fi
done | tee "$results/samplers.txt"

same() { if cmp -s "$1" "$2"; then echo "same bytes"; else echo "BYTES DIFFER"; fi; }
render_ms() { grep -o '"renderMs": *[0-9.]*' "$1" | tr -dc '0-9.'; }
{
  for device in "$gpu" cpu; do
    "${raylab[@]}" render samples/scenes/sphere-field.json "${size[@]}" --sampler jittered --samples 16 --device "$device" --warmup \
      -o "$results/field-jittered-$device.png" --stats "$results/field-jittered-$device.json" >/dev/null
    echo "field jittered 16 spp on $device: renderMs $(render_ms "$results/field-jittered-$device.json")"
  done
  echo "field jittered: $(same "$results/field-jittered-$gpu.png" "$results/field-jittered-cpu.png")"
  for scene in benchmarks/anchors/bench-1080.json samples/scenes/sphere-field.json; do
    for guard in plain guard; do
      name="$(basename "$scene" .json)-adaptive-$guard"
      flags=(--sampler adaptive --max-depth 3 --contrast 0.1)
      [ "$guard" = guard ] && flags+=(--guard)
      for device in "$gpu" cpu; do
        "${raylab[@]}" render "$scene" "${size[@]}" "${flags[@]}" --device "$device" --warmup -o "$results/$name-$device.png" \
          --heatmap "$results/$name-$device-rays.png" --stats "$results/$name-$device.json" >/dev/null
        echo "$name on $device: renderMs $(render_ms "$results/$name-$device.json")"
      done
      echo "$name: picture $(same "$results/$name-$gpu.png" "$results/$name-cpu.png"), rays per pixel $(same "$results/$name-$gpu-rays.png" "$results/$name-cpu-rays.png")"
    done
  done
} | tee "$results/field-adaptive.txt"

{
  for device in "$gpu" cpu; do
    start=$(date +%s.%N)
    timeout 240 "${raylab[@]}" compare samples/scenes/two-spheres.json --out "$results/compare-$device" "${size[@]}" "${compare_extra[@]}" \
      --device "$device" --stats "$results/compare-$device.json" >"$results/compare-$device.log" 2>&1 || echo "compare on $device: failed or over 240 s"
    end=$(date +%s.%N)
    echo "compare on $device: wall $(echo "$end - $start" | bc) s; $(tail -1 "$results/compare-$device.log")"
    grep -o '"firstLaunchMs": *[0-9.]*' "$results/compare-$device.json" || true
  done
  if diff -rq "$results/compare-$gpu/images" "$results/compare-cpu/images" >/dev/null; then echo "compare: every picture the same bytes"; else echo "compare: PICTURES DIFFER"; fi
} | tee "$results/compare.txt"

anchor_all | tee "$results/anchor-last.txt"
echo "measure.sh: results in $results/"
