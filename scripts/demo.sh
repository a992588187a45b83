#!/usr/bin/env bash
# Installs what is needed, builds, and renders the demo scene headless: build/grass-demo.png.
# Usage: scripts/demo.sh [grass-render options], e.g. --backend vk
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRASS_BUILD_TESTS=OFF >/dev/null
cmake --build build --target grass-render
./build/samples/grass_render/grass-render --output build/grass-demo.png "$@"
