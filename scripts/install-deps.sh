#!/usr/bin/env bash
# Installs the Debian 12 packages grass needs to build, render headless and run its tests.
# Idempotent: runs apt-get only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  libgl-dev libegl-dev libgl1-mesa-dri libegl-mesa0 libosmesa6-dev   # GL 4.5 via llvmpipe: EGL surfaceless + OSMesa
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers          # Vulkan loader, lavapipe, validation layers
  glslc                                                              # GLSL -> SPIR-V at build time
  libpng-dev nlohmann-json3-dev                                      # image I/O, JSON scenes
  libtinygltf-dev                                                    # glTF scenes (header; images decoded by libpng)
  libcli11-dev                                                       # the tools' command lines
  libgtest-dev libbenchmark-dev                                      # tests, benchmarks
  python3-pytest python3-numpy python3-pip python3-setuptools        # the Python binding: tests, maps from arrays, pip install
  clang-format-15 python3                                            # the style check, the docs' link check
  clang-15                                                           # the fuzz build: libFuzzer, ASan, UBSan (scripts/fuzz.sh)
  libglfw3-dev libimgui-dev libglm-dev libstb-dev                    # the windowed viewers: window, overlay, camera maths
  xvfb xauth                                                         # the viewers' window test (xvfb-run)
  ffmpeg gifsicle                                                    # grass-render --animation: GIF and MP4 (gifsicle shrinks the GIF)
  # The Qt Quick 3D adapter (integration/qtquick3d) and its tests under a virtual X server
  qt6-base-dev qt6-base-dev-tools qt6-declarative-dev qt6-qpa-plugins
  qml6-module-qtquick qml6-module-qtquick-window qml6-module-qtqml-workerscript
  qml6-module-quick3d qml6-module-quick3d-helpers
  libopenscenegraph-dev openscenegraph                               # the OSG adapter (integration/osg): its library, osgconv
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
