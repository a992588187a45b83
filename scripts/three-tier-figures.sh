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
source scripts/football-cameras.sh
for backend in gl vk; do
  for c in "${football_cameras[@]}"; do
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
