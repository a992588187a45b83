#!/usr/bin/env bash
# Renders Lemme's football field (all three tiers, default lod setup) from the four
# benchmark cameras with both backends into docs/images/tiers/, plain and with the tier
# tint (GRASS_VIEW_FLAG_DEBUG_TIERS), and prints each frame's stats.
# Usage: scripts/three-tier-figures.sh [build dir, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
render="${1:-build}/samples/grass_render/grass-render"
scene=samples/grass_render/scenes/football.json
mkdir -p docs/images/tiers
cameras=(
  "high 47.5,60,-40 47.5,0,80"
  "player 47.5,1.7,6 47.5,0,60"
  "ant 47.3,0.05,6 47.3,0.04,20"
  "grazing 47.3,3,-2 47.3,2.9,400"
)
for backend in gl vk; do
  for c in "${cameras[@]}"; do
    read -r name eye target <<<"$c"
    for mode in plain tint; do
      flags=()
      [[ $mode == tint ]] && flags=(--debug-tiers)
      echo "== $name $mode ($backend)"
      "$render" --scene "$scene" --backend "$backend" --size 640x360 --samples 4 --far 2000 "${flags[@]}" \
        --camera "$eye" --target "$target" --output "docs/images/tiers/football-$name-$mode-$backend.png" |
        grep -E "triangles|frame"
    done
  done
done
