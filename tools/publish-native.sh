#!/usr/bin/env bash
# One folder of native raylab builds that runs on any x86-64 CPU and takes the widest SIMD it has:
#   DIR/raylab            the launcher (samples/RayLab.Launcher), the one to start
#   DIR/raylab-x86-64-v2  the console for SSE4.2 (the vector128 kernel)
#   DIR/raylab-x86-64-v3  AVX2 + FMA (vector256)
#   DIR/raylab-x86-64-v4  AVX-512 (vector512)
# DIR/raylab asks the CPU its level at start-up and execs the widest build beside it that the CPU runs;
# RAYLAB_NO_DISPATCH=1 makes it exec raylab-x86-64-v2. Native AOT cannot make that choice inside one binary: it
# compiles AVX2/AVX-512 checks to constants (docs/native.md, "Instruction sets on x64").
# Usage: tools/publish-native.sh [DIR]   (default artifacts/native-all; linux-x64)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-artifacts/native-all}
mkdir -p "$out"
for isa in x86-64-v2 x86-64-v3 x86-64-v4; do
  tmp=$(mktemp -d)
  dotnet publish samples/RayLab.Console -c Release -r linux-x64 -p:RayLabIsa=$isa -o "$tmp"
  cp "$tmp/raylab" "$out/raylab-$isa"
  if [ $isa = x86-64-v2 ]; then
    rm -rf "$out/scenes" && cp -r "$tmp/scenes" "$out/scenes"
  fi
  rm -rf "$tmp"
done
tmp=$(mktemp -d)
dotnet publish samples/RayLab.Launcher -c Release -r linux-x64 -o "$tmp"
cp "$tmp/raylab-launcher" "$out/raylab"
rm -rf "$tmp"
echo "$out: raylab (the launcher), raylab-x86-64-v2, raylab-x86-64-v3, raylab-x86-64-v4, scenes/"
