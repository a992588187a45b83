#!/usr/bin/env bash
# Renders the glTF sample scene (samples/grass_render/scenes/hill.glb, written by
# scripts/make-gltf-scene.py) with both backends into docs/images/gltf/: from the file's
# camera and from above, and prints what grass-render reports about the scene.
# Usage: scripts/gltf-figures.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
render="${1:-build}/samples/grass_render/grass-render"
mkdir -p docs/images/gltf
scene=samples/grass_render/scenes/hill.glb
for backend in gl vk; do
  echo "== file camera ($backend)"
  "$render" --scene "$scene" --backend "$backend" --size 640x360 --samples 4 \
    --output "docs/images/gltf/hill-$backend.png" | grep -E "quadtree|geometry|volume|frame|glTF"
  echo "== above ($backend)"
  "$render" --scene "$scene" --backend "$backend" --size 360x360 --samples 4 --camera 0,38,-0.01 --target 0,0,0 \
    --output "docs/images/gltf/hill-above-$backend.png" | grep -E "quadtree|frame"
done
