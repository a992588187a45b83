#!/usr/bin/env bash
# Renders the debug view of Lemme's football field from the four benchmark cameras with
# both backends into docs/images/terrain/ and prints each frame's plan stats.
# Usage: scripts/terrain-figures.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
render="${1:-build}/samples/grass_render/grass-render"
scene=samples/grass_render/scenes/football.json
source scripts/football-cameras.sh
for backend in gl vk; do
  for c in "${football_cameras[@]}"; do
    read -r name eye target <<<"$c"
    echo "== $name ($backend)"
    "$render" --scene "$scene" --backend "$backend" --debug-cells --size 640x360 --far 2000 \
      --camera "$eye" --target "$target" --output "docs/images/terrain/football-$name-$backend.png" |
      grep -E "quadtree|geometry|volume|image|plan"
  done
done
