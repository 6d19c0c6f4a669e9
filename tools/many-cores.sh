#!/usr/bin/env bash
# The every-core table on a machine with more cores than this one, where neither the .NET SDK nor a compiler is at
# hand: everything is built here first, and the run needs only bash.
#
#   tools/many-cores.sh prepare [DIR]        here: the native builds (x86-64-v3 and -v4), raylab-scaling (native,
#                                            both levels), the C++ anchor (both levels) with its input, the field scene
#   tools/many-cores.sh run DIR OUT [ROUNDS] there: ROUNDS (default 5) interleaved rounds of every case at 1, 2, 4, 8,
#                                            16 threads (and every core, if more), with the anchor in the same rounds;
#                                            then raylab-scaling's model, and its in-process speed-ups and wall-time
#                                            breakdown (the row loop's crew against the .NET thread pool), and
#                                            what waking the crew costs (wake.md)
#   tools/many-cores.sh pair DIR BEFORE OUT [ROUNDS] [THREADS]
#                                            there: this build against another's (BEFORE: that checkout's
#                                            artifacts/many-cores, from its own prepare), every method on both
#                                            scenes at THREADS (default 2), the two builds alternating; cases
#                                            whose name (e.g. field-guard) matches PAIR_EXCLUDE (grep -E) are left out
#   python3 tools/many-cores.py OUT          the tables (medians, speed-ups, RayLab against the anchor, or the pair)
#
# DIR defaults to artifacts/many-cores. OUT gets machine.txt, raw.tsv (round, case, build, threads, ms),
# scaling.md and wake.md. The lent machine takes at most 64 MiB and brings back only a few files: carry DIR (and BEFORE) as one
# tar.gz (about 29 MB for both levels and one other build), and tar OUT into one file there. Each render is `raylab render SCENE --width 1920 --height 1080 --threads T --stats S --warmup` plus the
# method's options; its time is the stats file's renderMs (the loop, after a scaled-down warm-up render and with the
# image's memory committed, as the anchor commits its own before its clock).
set -euo pipefail

prepare() {
  local dir=${1:-artifacts/many-cores}
  cd "$(dirname "$0")/.."
  rm -rf "$dir" && mkdir -p "$dir"
  local tmp
  # Only the two levels this needs, not publish-native.sh's four builds: the lent machine takes at most 64 MiB.
  for isa in x86-64-v3 x86-64-v4; do
    tmp=$(mktemp -d)
    dotnet publish samples/RayLab.Console -c Release -r linux-x64 -p:RayLabIsa=$isa -o "$tmp" -v q -nologo
    cp "$tmp/raylab" "$dir/raylab-$isa"
    rm -rf "$tmp" && tmp=$(mktemp -d)
    dotnet publish tools/RayLab.Scaling -c Release -r linux-x64 -p:IlcInstructionSet=$isa \
      -o "$tmp" -v q -nologo
    cp "$tmp/RayLab.Scaling" "$dir/raylab-scaling-$isa"
    rm -rf "$tmp"
    g++ -O3 -march=$isa -ffast-math -fno-finite-math-only -std=c++17 -pthread -static-libstdc++ -static-libgcc \
      benchmarks/anchors/native_ref.cpp -o "$dir/anchor-$isa"
  done
  # The anchor's input: the bench scene reduced to numbers, 4×4 strata (16 spp), THREADS standing for the count.
  python3 benchmarks/anchors/native.py benchmarks/anchors/bench-1080.json 4 999 input | sed '1s/ 999 / THREADS /' \
    > "$dir/anchor-input.txt"
  python3 tools/sphere-scenes.py field 24 40 "$dir/field.json"
  cp benchmarks/anchors/bench-1080.json "$dir/bench.json"
  ls -la "$dir"
}

# The time the hypervisor took the vCPUs from this VM since /proc/stat's cpu line read "$1": its steal ticks as a share
# of the ticks the vCPUs ran or were taken (user, nice, system, irq, softirq, steal), idle left out. A render's wall
# time holds the time its threads' vCPUs were taken, its CPU time does not.
steal_since() {
  head -1 /proc/stat | awk -v before="$1" 'BEGIN { split(before, b, " ") }
    { busy = 0; for (i = 2; i <= 9; i++) if (i != 5 && i != 6) busy += $i - b[i]
      printf "steal %.1f %% of %d busy ticks", busy ? 100 * ($9 - b[9]) / busy : 0, busy }'
}

# One render's milliseconds: raylab's renderMs, or the anchor's seconds × 1000. Prints nothing when it failed.
render_ms() {
  local build=$1 threads=$2; shift 2
  case $build in
    anchor-*)
      sed "1s/THREADS/$threads/" "$dir/anchor-input.txt" | "$dir/anchor-$isa" "${build#anchor-}" \
        | sed -n 's/.*"seconds":\([0-9.]*\).*/\1/p' | awk '{ printf "%.4f", $1 * 1000 }' ;;
    *)
      rm -f "$tmp/s.json"
      "$dir/raylab-$isa" render "$@" -o "$tmp/x.png" --width 1920 --height 1080 --threads "$threads" \
        --stats "$tmp/s.json" --warmup > /dev/null 2>> "$out/errors.txt" || return 0
      sed -n 's/.*"renderMs": *\([0-9.]*\).*/\1/p' "$tmp/s.json" ;;
  esac
}

run() {
  dir=$1 out=$2
  local rounds=${3:-5}
  mkdir -p "$out"
  tmp=$(mktemp -d)
  isa=x86-64-v3
  grep -q avx512f /proc/cpuinfo && isa=x86-64-v4
  local cores
  cores=$(nproc)
  {
    echo "isa $isa; nproc $cores; load $(cat /proc/loadavg)"
    lscpu 2>/dev/null || grep -m1 'model name' /proc/cpuinfo
    echo "avx512: $(grep -o 'avx512[a-z_0-9]*' /proc/cpuinfo | sort -u | tr '\n' ' ')"
    free -g 2>/dev/null || true
  } > "$out/machine.txt"
  local threads=""
  for t in 1 2 4 8 16; do [ "$t" -le "$cores" ] && threads="$threads $t"; done
  [ "$cores" -gt 16 ] && threads="$threads $cores"
  # case name, build, then the render's arguments
  local -a cases=(
    "bench-jittered16|raylab|$dir/bench.json --sampler jittered --samples 16"
    "bench-jittered16-vector256|raylab|$dir/bench.json --sampler jittered --samples 16 --kernel vector256"
    "bench-jittered16-anchor-avx2v|anchor-avx2v|"
    "bench-jittered256|raylab|$dir/bench.json --sampler jittered --samples 256"
    "bench-adaptive|raylab|$dir/bench.json --sampler adaptive"
    "bench-guard|raylab|$dir/bench.json --sampler adaptive --guard"
    "bench-exact|raylab|$dir/bench.json --sampler exact"
    "field-jittered16|raylab|$dir/field.json --sampler jittered --samples 16"
    "field-adaptive|raylab|$dir/field.json --sampler adaptive"
    "field-guard|raylab|$dir/field.json --sampler adaptive --guard"
    "field-exact|raylab|$dir/field.json --sampler exact"
  )
  [ $isa = x86-64-v4 ] && cases+=("bench-jittered16-anchor-avx512|anchor-avx512|")
  echo -e "round\tcase\tbuild\tthreads\tms" > "$out/raw.tsv"
  for ((r = 1; r <= rounds; r++)); do
    stat=$(head -1 /proc/stat)
    for c in "${cases[@]}"; do
      IFS='|' read -r name build rest <<< "$c"
      for t in $threads; do
        # shellcheck disable=SC2086
        ms=$(render_ms "$build" "$t" $rest)
        echo -e "$r\t$name\t$build-$isa\t$t\t${ms:-NaN}" >> "$out/raw.tsv"
      done
    done
    echo "round $r done: $(date -u +%T), load $(cut -d' ' -f1-3 /proc/loadavg), $(steal_since "$stat")" >> "$out/machine.txt"
  done
  cp "$dir/field.json" "${TMPDIR:-/tmp}/raylab-scaling-field-24-40.json"
  "$dir/raylab-scaling-$isa" --rounds 3 --threads "$(echo $threads | tr ' ' ',')" --model "$(echo $threads | tr ' ' ',')" --cuts 2,4,8 \
    > "$out/scaling.md" 2>> "$out/errors.txt" || echo "raylab-scaling failed: $?" >> "$out/errors.txt"
  "$dir/raylab-scaling-$isa" --wake 100 --threads "$(echo $threads | tr ' ' ',')" \
    > "$out/wake.md" 2>> "$out/errors.txt" || echo "raylab-scaling --wake failed: $?" >> "$out/errors.txt"
  rm -rf "$tmp"
}

# This build against another, every method on both scenes, the builds alternating render by render.
pair() {
  dir=$1
  local before=$2
  out=$3
  local rounds=${4:-5} threads=${5:-2}
  mkdir -p "$out"
  tmp=$(mktemp -d)
  isa=x86-64-v3
  grep -q avx512f /proc/cpuinfo && isa=x86-64-v4
  echo "isa $isa; nproc $(nproc); load $(cat /proc/loadavg); pair at $threads threads" > "$out/machine.txt"
  lscpu 2>/dev/null | grep -E 'Model name|Model:|^CPU\(s\)' >> "$out/machine.txt" || true
  local -a methods=()
  for s in regular random jittered cmj multijittered nrooks hammersley sobol pmj02 pmj02bn zsobol; do
    methods+=("$s|--sampler $s --samples 16")
  done
  methods+=("adaptive|--sampler adaptive" "guard|--sampler adaptive --guard" "exact|--sampler exact")
  echo -e "round\tcase\tbuild\tthreads\tms" > "$out/raw.tsv"
  for ((r = 1; r <= rounds; r++)); do
    stat=$(head -1 /proc/stat)
    for scene in bench field; do
      for m in "${methods[@]}"; do
        IFS='|' read -r name rest <<< "$m"
        if [ -n "${PAIR_EXCLUDE:-}" ] && grep -qE -e "$PAIR_EXCLUDE" <<< "$scene-$name"; then continue; fi
        for build in this before; do
          local exe="$dir/raylab-$isa"
          [ $build = before ] && exe="$before/raylab-$isa"
          rm -f "$tmp/s.json"
          # shellcheck disable=SC2086
          "$exe" render "$dir/$scene.json" $rest -o "$tmp/x.png" --width 1920 --height 1080 --threads "$threads" \
            --stats "$tmp/s.json" --warmup > /dev/null 2>> "$out/errors.txt" || true
          ms=$(sed -n 's/.*"renderMs": *\([0-9.]*\).*/\1/p' "$tmp/s.json" 2>/dev/null)
          echo -e "$r\t$scene-$name\t$build\t$threads\t${ms:-NaN}" >> "$out/raw.tsv"
        done
      done
    done
    echo "round $r done: $(date -u +%T), load $(cut -d' ' -f1-3 /proc/loadavg), $(steal_since "$stat")" >> "$out/machine.txt"
  done
  rm -rf "$tmp"
}

usage() {
  echo "usage: tools/many-cores.sh prepare [DIR] | run DIR OUT [ROUNDS] | pair DIR BEFORE OUT [ROUNDS] [THREADS]" >&2
  exit 2
}

case "${1:-}" in
  prepare) shift; prepare "$@" ;;
  run) shift; [ $# -ge 2 ] || usage; run "$@" ;;
  pair) shift; [ $# -ge 3 ] || usage; pair "$@" ;;
  *) usage ;;
esac
