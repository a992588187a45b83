#!/usr/bin/env bash
# Renders the park (density, colour, ambient and diffuse maps) and the hills (height map,
# unplanarity and hilltop lod tests) from several cameras with both backends into
# docs/images/maps/, and prints each frame's stats. The maps are PNG files that
# scripts/make-scene-maps.py writes.
# Usage: scripts/design-map-figures.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
render="${1:-build}/samples/grass_render/grass-render"
mkdir -p docs/images/maps
# name, scene, eye, target
views=(
  "park-overview park 20,16,-6 20,0,22"
  "park-flower-bed park 14,1.7,14 9,0.3,30"
  "park-shadow park 22,2.2,18 32,0,31"
  "park-pond park 20,1.7,4 29,0,11"
  "hills-valley hills 100,3,5 100,6,120"
  "hills-above hills 40,40,-30 110,0,110"
)
for backend in gl vk; do
  for v in "${views[@]}"; do
    read -r name scene eye target <<<"$v"
    echo "== $name ($backend)"
    "$render" --scene "samples/grass_render/scenes/$scene.json" --backend "$backend" --size 640x360 --samples 4 \
      --camera "$eye" --target "$target" --output "docs/images/maps/$name-$backend.png" |
      grep -E "quadtree|geometry|volume|image |frame"
  done
done
