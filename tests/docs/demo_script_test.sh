#!/usr/bin/env bash
# scripts/demo.sh as the README uses it, its commands printed (GRASS_DEMO_DRY_RUN=1), not run:
# it configures build/ as scripts/test.sh does (tests on: the README's later ctest commands
# find the tests), and each backend writes its own image (--backend vk no longer overwrites
# the GL one). And the README's first commands are still demo.sh and test.sh.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
fail() {
  echo "demo_script_test: $*"
  exit 1
}
gl=$(GRASS_DEMO_DRY_RUN=1 bash "$root/scripts/demo.sh" 2>&1)
vk=$(GRASS_DEMO_DRY_RUN=1 bash "$root/scripts/demo.sh" --backend vk 2>&1)
vk2=$(GRASS_DEMO_DRY_RUN=1 bash "$root/scripts/demo.sh" --backend=vulkan --samples 4 2>&1)
configure=$(grep '^cmake -S . -B build ' <<<"$gl") || fail "no configure of build/ in: $gl"
grep -q -- '-DGRASS_BUILD_TESTS=ON' <<<"$configure" || fail "build/ is configured without the tests: $configure"
test_configure=$(grep -o 'cmake -S . -B build -G Ninja [^>]*' "$root/scripts/test.sh" | head -n 1)
[[ ${configure%% >*} == "${test_configure% }" ]] || fail "demo.sh configures build/ as '$configure', test.sh as '$test_configure'"
grep -q -- '--output build/grass-demo-gl.png$' <<<"$gl" || fail "the GL image is not build/grass-demo-gl.png: $gl"
grep -q -- '--output build/grass-demo-vk.png --backend vk$' <<<"$vk" || fail "the Vulkan image is not build/grass-demo-vk.png: $vk"
grep -q -- '--output build/grass-demo-vk.png --backend=vulkan --samples 4$' <<<"$vk2" || fail "--backend=vulkan: $vk2"
if GRASS_DEMO_DRY_RUN=1 bash "$root/scripts/demo.sh" --backend dx12 >/dev/null 2>&1; then
  fail "--backend dx12 was accepted"
fi
# The README's first block of commands is these two, before any other (CI runs scripts/test.sh).
first=$(awk '/^```/ { if (open) exit; open = 1; next } open { sub(/ *#.*/, ""); print }' "$root/README.md")
[[ $first == $'bash scripts/demo.sh\nbash scripts/test.sh' ]] || fail "README.md's first block is not the two commands: $first"
echo "demo_script_test: build/ configured as test.sh does; build/grass-demo-gl.png and build/grass-demo-vk.png;" \
  "the README starts with the two commands"
