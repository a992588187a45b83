#!/usr/bin/env bash
# Renders a fixed set of views with grass-render on both backends into OUT_DIR: one PNG and one
# stats table (its timings removed) per view. Two sets are compared pixel for pixel by
# scripts/compare-render-sets.py; a change that must not alter what grass draws (a refactor, a
# move of files) keeps them identical:
#   bash scripts/render-set.sh build /tmp/before    # on the old tree
#   bash scripts/render-set.sh build /tmp/after     # on the new tree
#   python3 scripts/compare-render-sets.py /tmp/before /tmp/after
# The views cover the cameras a game uses (eye height, third person, 20 m and 100 m up,
# top-down), 1 and 4 samples, with and without a ground, wind, colliders over frames, the
# design maps, a glTF terrain and the tier tints. About two minutes on llvmpipe and lavapipe.
set -euo pipefail
if (($# != 2)); then
  echo "usage: $0 BUILD_DIR OUT_DIR" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
out=$2
render=$(find "$build" -type f -name grass-render -perm -u+x | head -n 1)
if [[ -z $render ]]; then
  echo "$0: no grass-render under $build (build it with GRASS_BUILD_SAMPLES=ON)" >&2
  exit 1
fi
scenes=$(dirname "$(find "$root" \( -path "$root/build*" -o -path "$root/tests" \) -prune -o -name hills-helicopter.json -print | head -n 1)")
mkdir -p "$out"
views=(
  "eye|"
  "eye-1sample-noground|--samples 1 --no-ground"
  "wind|--wind 1,0.3,6,0.5 --time 2.5"
  "football|--scene $scenes/football.json"
  "third-person|--scene $scenes/football.json --camera 47.5,4,10 --target 47.5,0.5,22"
  "up20m|--scene $scenes/football.json --camera 47.5,20,-10 --target 47.5,0,40"
  "up100m|--scene $scenes/football.json --camera 47.5,100,-60 --target 47.5,0,60"
  "top-down|--scene $scenes/football.json --camera 47.5,40,66.01 --target 47.5,0,66"
  "tiers|--scene $scenes/football.json --debug-tiers --camera 47.5,20,-10 --target 47.5,0,40"
  "football-ball|--scene $scenes/football-ball.json --frames 4 --fps 12"
  "park-walker|--scene $scenes/park-walker.json --frames 3 --fps 12"
  "meadow-windmap|--scene $scenes/meadow-windmap.json --time 1"
  "hills-helicopter|--scene $scenes/hills-helicopter.json"
  "hill-gltf|--scene $scenes/hill.glb"
)
for backend in gl vk; do
  for view in "${views[@]}"; do
    name=${view%%|*}
    args=${view#*|}
    # shellcheck disable=SC2086  # args are whitespace-separated options
    "$render" --backend "$backend" --size 320x180 --output "$out/$name-$backend.png" $args \
      >"$out/$name-$backend.raw.txt" 2>&1 || { cat "$out/$name-$backend.raw.txt" >&2; exit 1; }
    # The table without what varies from run to run: times, the device's name, the file path.
    sed -E -e 's/[0-9]+(\.[0-9]+)? ms/_ ms/g' -e '/^grass-render: wrote/d' -e 's/\(llvmpipe.*\)/(device)/' \
      "$out/$name-$backend.raw.txt" >"$out/$name-$backend.txt"
    rm "$out/$name-$backend.raw.txt"
    echo "render-set: $name-$backend"
  done
done
