#!/usr/bin/env bash
# The main job on the built-in default scene: installs what is missing, builds, then writes the
# shadow-volume mesh (out/default-volume.ply), the same with silhouette refinement
# (out/default-volume-refined.ply) and, with the GPU path, the rendered image (out/default.png)
# and its stencil (out/default-stencil.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target shadowvol
mkdir -p out
./build/apps/shadowvol build --out out/default-volume.ply
./build/apps/shadowvol build --refine 6 --out out/default-volume-refined.ply
if ./build/apps/shadowvol --help | grep -q "^  render"; then
  ./build/apps/shadowvol render --out out/default.png --stencil out/default-stencil.png
fi
