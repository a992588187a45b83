// The SPIR-V of the Vulkan backend's graphics shaders, compiled at build time
// (backend_vk/CMakeLists.txt) in up to four variants each:
// - responsive: compiled with GRASS_RESPONSIVE, for the pipelines of kBladeCurveFeatures
//   (blade.vert, volume.frag and image.frag have it; the other shaders are the same);
// - storage blocks: compiled with GRASS_STORAGE_BLOCKS, the Frame and Field blocks as
//   read-only storage buffers of the same std140 layout instead of uniform buffers.
//
// Why storage blocks: lavapipe (Mesa's Vulkan on llvmpipe; seen in 22.3) specialises a
// shader whose branches or loop bounds read uniform-buffer values on those values: on every
// draw after a pipeline or descriptor set bind it copies the shader, substitutes them and
// compiles it again, with no cache, and keeps the copies with the pipeline. grass binds a
// set with dynamic offsets for every draw, so each volume and blade draw cost a compile
// (about 50 ms) and several megabytes kept until the context went (docs/records/testing.md,
// "Soak"). Its inliner reads uniform-buffer loads only. Other drivers keep the uniform
// buffers, which are what constant caches serve best.
#pragma once

#include <cstdint>

namespace grass::vk {

enum class Shader { blade_vert, blade_frag, volume_vert, volume_frag, image_vert, image_frag, debug_vert, debug_frag };

struct Spirv {
    const uint32_t* code;
    uint32_t size; // bytes
};

Spirv spirv(Shader shader, bool responsive, bool storage_blocks);

} // namespace grass::vk
