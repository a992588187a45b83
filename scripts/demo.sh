#!/usr/bin/env bash
# Installs what is needed, builds grass-render, and renders the demo scene headless:
# build/grass-demo-gl.png (build/grass-demo-vk.png with --backend vk), then prints its stats.
# build/ is configured as scripts/test.sh configures it (tests on), so the README's later
# commands (cmake --build build, ctest --test-dir build, the viewers) use the same tree.
# Usage: scripts/demo.sh [grass-render options], e.g. --backend vk
set -euo pipefail
cd "$(dirname "$0")/.."

backend=gl
output_given=0
previous=
for arg in "$@"; do
  case $arg in
  --backend=*) backend=${arg#--backend=} ;;
  --output | --output=*) output_given=1 ;;
  esac
  if [[ $previous == --backend ]]; then backend=$arg; fi
  previous=$arg
done
case $backend in
gl | vk) ;;
vulkan) backend=vk ;;
*)
  echo "demo.sh: --backend is \"$backend\"; it must be gl or vk" >&2
  exit 2
  ;;
esac

# GRASS_DEMO_DRY_RUN=1: print the commands (to stderr) instead (tests/docs/demo_script_test.sh).
run() {
  if [[ ${GRASS_DEMO_DRY_RUN:-0} == 1 ]]; then
    echo "$*" >&2
  else
    "$@"
  fi
}
run bash scripts/install-deps.sh
run cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRASS_BUILD_TESTS=ON >/dev/null
run cmake --build build --target grass-render
if [[ $output_given == 1 ]]; then
  run ./build/samples/grass_render/grass-render "$@"
else
  run ./build/samples/grass_render/grass-render --output "build/grass-demo-$backend.png" "$@"
  echo "demo.sh: the $backend image is build/grass-demo-$backend.png"
fi
