// The SPIR-V of the Vulkan backend's graphics shaders, compiled at build time
// (backend_vk/CMakeLists.txt) in up to eight variants each:
// - multiview: compiled with GRASS_MULTIVIEW (stereo, blade_interface.glsl), for every
//   pipeline of a context made with a view mask (grass_vk_multiview_desc.view_mask); mono contexts
//   run the other variants, exactly the modules of before;
// - responsive: compiled with GRASS_RESPONSIVE, for the pipelines of kBladeCurveFeatures
//   (blade.vert, volume.frag and image.frag have it; the other shaders are the same);
// - indexed blocks: compiled with GRASS_INDEXED_BLOCKS, the Frame and Field blocks read
//   at an index from a push constant (always 0) instead of the literal 0; the pipeline
//   layout then has a 4-byte push-constant range, which vk_record sets to 0.
// - depth target: the fragment shaders (blade, volume, image) compiled with GRASS_DEPTH_TARGET,
//   without the colour output, for a depth pass's pipelines (grass_vk_depth_pass_desc: the
//   host's depth-only pass has no colour attachment, which the validation layers would warn
//   of); mono, plain or responsive, indexed or not.
// - host shadows: the same fragment shaders compiled with GRASS_HOST_SHADOWS, for the pipelines
//   of a view that receives the host's shadow maps (grass_shadow_receive_desc); mono, plain or
//   responsive, indexed or not.
//
// Why indexed blocks: lavapipe (Mesa's Vulkan on llvmpipe; seen in 22.3) specialises a
// shader whose branches or loop bounds read uniform-buffer values at constant offsets on
// those values: on every draw after a pipeline or descriptor set bind it copies the shader,
// substitutes them and compiles it again, with no cache, and keeps the copies with the
// pipeline. grass binds a set with dynamic offsets for every draw, so each volume and blade
// draw cost a compile (about 50 ms) and several megabytes kept until the context went
// (docs/records/testing.md, "Soak"). Storage buffers avoided that, but lavapipe loads a
// storage-buffer value lane by lane (a loop over the 8 lanes with a bounds check per lane):
// those loops took about 60% of the volume tier's fragment time. A uniform-buffer offset
// computed from a push constant is neither inlined (not a constant) nor loaded lane by lane
// (a push constant is uniform by definition, so one scalar load serves every lane).
// Other drivers get the plain variants: no push constants, constant offsets.
#pragma once

#include <cstdint>

namespace grass::vk {

enum class Shader { blade_vert, blade_frag, volume_vert, volume_frag, image_vert, image_frag, debug_vert, debug_frag };

struct Spirv {
    const uint32_t* code;
    uint32_t size; // bytes
};

// Which module of a shader: the defines it was compiled with.
struct SpirvVariant {
    bool responsive = false;     // GRASS_RESPONSIVE (shaders without it: the plain module)
    bool indexed_blocks = false; // GRASS_INDEXED_BLOCKS
    bool multiview = false;      // GRASS_MULTIVIEW
    // GRASS_DEPTH_TARGET: the fragment shaders of a depth pass's pipelines (blade, volume and
    // image), made for the host's depth-only target: no colour output. Mono only.
    bool depth_target = false;
    // GRASS_HOST_SHADOWS: the fragment shaders (blade, volume and image) of a view that receives
    // the host's shadow maps (the map and its block in set 1). Mono only.
    bool host_shadows = false;
};

Spirv spirv(Shader shader, SpirvVariant variant);
// The GRASS_HOST_SHADOWS module of blade.frag, volume.frag or image.frag (vk_spirv_shadows.cpp).
Spirv host_shadow_spirv(Shader shader, SpirvVariant variant);

} // namespace grass::vk
