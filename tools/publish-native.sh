#!/usr/bin/env bash
# One folder of native raylab builds that runs on any x86-64 CPU and takes the widest SIMD it has:
#   DIR/raylab            x86-64-v2 (SSE4.2: the vector128 kernel), the one to start
#   DIR/raylab-x86-64-v3  AVX2 + FMA (vector256)
#   DIR/raylab-x86-64-v4  AVX-512 (vector512)
# DIR/raylab asks the CPU at start-up and execs the widest sibling it runs (samples/RayLab.Console/NativeDispatch.cs);
# RAYLAB_NO_DISPATCH=1 keeps it in the binary started. Native AOT cannot make that choice inside one binary: it
# compiles AVX2/AVX-512 checks to constants (docs/performance.md, "The native build").
# Usage: tools/publish-native.sh [DIR]   (default artifacts/native-all; linux-x64)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-artifacts/native-all}
mkdir -p "$out"
for isa in x86-64-v2 x86-64-v3 x86-64-v4; do
  tmp=$(mktemp -d)
  dotnet publish samples/RayLab.Console -c Release -r linux-x64 -p:RayLabIsa=$isa -o "$tmp"
  if [ $isa = x86-64-v2 ]; then
    cp "$tmp/raylab" "$out/raylab"
    rm -rf "$out/scenes" && cp -r "$tmp/scenes" "$out/scenes"
  else
    cp "$tmp/raylab" "$out/raylab-$isa"
  fi
  rm -rf "$tmp"
done
echo "$out: raylab (x86-64-v2), raylab-x86-64-v3, raylab-x86-64-v4, scenes/"
