#!/usr/bin/env bash
# Renders the figures of docs/responsive.md: each responsive sample scene (football-ball,
# park-walker, hills-helicopter) as an animation with both backends (grass-render
# --animation: frames, GIF, MP4 under OUT), then puts into docs/images/responsive/ a still of
# the middle and the last frame of each backend and one small GIF per scene (GL; 320 pixels
# wide, 12 fps, 64 colours, gifsicle --lossy=60: about 200 KB), and prints each run's time per frame.
# Usage: scripts/responsive-figures.sh [build dir, default build] [out dir, default BUILD/responsive-out]
# Environment: FRAMES (default 48), FPS (default 16), BACKENDS (default "gl vk"), SCENES.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
out="${2:-$build/responsive-out}"
render="$build/samples/grass_render/grass-render"
frames="${FRAMES:-48}"
fps="${FPS:-16}"
docs=docs/images/responsive
mkdir -p "$docs" "$out"
for scene in ${SCENES:-football-ball park-walker hills-helicopter}; do
  for backend in ${BACKENDS:-gl vk}; do
    dir="$out/$scene-$backend"
    echo "== $scene ($backend): $frames frames at $fps fps"
    start=$(date +%s.%N)
    "$render" --backend "$backend" --scene "samples/grass_render/scenes/$scene.json" --frames "$frames" --fps "$fps" \
      --animation "$dir" --output "$dir/last.png" | grep -E "wrote|blades|frame|responsive"
    end=$(date +%s.%N)
    python3 -c "print('   %.2f s per frame (wall, incl. writing it)' % (($end - $start) / $frames))"
    middle=$(printf "%04d" $((frames / 2)))
    cp "$dir/frame-$middle.png" "$docs/$scene-middle-$backend.png"
    cp "$dir/last.png" "$docs/$scene-last-$backend.png"
  done
  gl="$out/$scene-gl"
  if [[ -d $gl ]]; then
    ffmpeg -v error -y -framerate "$fps" -i "$gl/frame-%04d.png" -vf \
      "fps=12,scale=320:-1:flags=lanczos,split[a][b];[a]palettegen=max_colors=64:stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=4" \
      -loop 0 "$docs/$scene.gif"
    if command -v gifsicle >/dev/null; then gifsicle -b -O3 --lossy=60 "$docs/$scene.gif"; fi
    ls -l "$docs/$scene.gif" | awk '{print "   " $9 ": " $5 " bytes"}'
  fi
done
