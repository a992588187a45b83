#!/usr/bin/env bash
# Renders the debug view of Lemme's football field from the four benchmark cameras with
# both backends into docs/images/terrain/ and prints each frame's plan stats.
# Usage: scripts/terrain-figures.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
render="${1:-build}/samples/grass_render/grass-render"
scene=samples/grass_render/scenes/football.json
cameras=(
  "high 47.5,60,-40 47.5,0,80"
  "player 47.5,1.7,6 47.5,0,60"
  "ant 47.3,0.05,6 47.3,0.04,20"
  "grazing 47.3,3,-2 47.3,2.9,400"
)
for backend in gl vk; do
  for c in "${cameras[@]}"; do
    read -r name eye target <<<"$c"
    echo "== $name ($backend)"
    "$render" --scene "$scene" --backend "$backend" --debug-cells --size 640x360 --far 2000 \
      --camera "$eye" --target "$target" --output "docs/images/terrain/football-$name-$backend.png" |
      grep -E "quadtree|geometry|volume|image|plan"
  done
done
