// The SPIR-V of the Vulkan backend's graphics shaders, compiled at build time in one scheme
// (backend_vk/CMakeLists.txt): each optional feature is a define, each shader lists the
// features it has, and every usable combination of them is compiled once; spirv() finds a
// shader's module for a feature set in the table CMake writes (spirv/vk_spirv_table.cpp).
// The features (SpirvFeature; a shader without one runs its module without it):
// - multiview: GRASS_MULTIVIEW (stereo, blade_interface.glsl), for every pipeline of a context
//   made with a view mask (grass_vk_multiview_desc.view_mask); mono contexts run the others;
// - depth target: the fragment shaders (blade, volume, image) with GRASS_DEPTH_TARGET, without
//   the colour output, for a depth pass's pipelines (grass_vk_depth_pass_desc: the host's
//   depth-only pass has no colour attachment, which the validation layers would warn of);
// - host shadows: the same fragment shaders with GRASS_HOST_SHADOWS, for a view that receives
//   the host's shadow maps (grass_shadow_receive_desc; the map and its block in set 1);
// - velocity: blade.vert and the same fragment shaders with GRASS_VELOCITY, for a view that
//   writes motion vectors (grass_view_motion_desc; the GrassMotion block in set 1), alone or
//   with host shadows (set 1 is one layout for both, vk_view_extras.hpp);
// - host lights: the fragment shaders with GRASS_HOST_LIGHTS, for a view lit by the host's
//   lights (grass_view_lights_desc; the GrassLights block in set 1), alone or with either or
//   both of the above;
// - G-buffer: the fragment shaders with GRASS_GBUFFER, for a G-buffer view
//   (grass_view_gbuffer_desc; the GrassGBuffer block in set 1), alone or with velocity;
// - responsive: GRASS_RESPONSIVE, for the pipelines of kBladeCurveFeatures (blade.vert,
//   volume.frag and image.frag have it);
// - blade window: GRASS_BLADE_WINDOW, blade.vert of the responsive pipelines of
//   kFeatureBladeWindow, which reads each blade's pose from the blade window (bindings 14 and
//   15, vk_blade_window.hpp) instead of computing it; never without responsive;
// - indexed blocks: GRASS_INDEXED_BLOCKS, the Frame and Field blocks read at an index from a
//   push constant (always 0) instead of the literal 0; the pipeline layout then has a 4-byte
//   push-constant range, which vk_record sets to 0.
// Multiview never combines with depth target, host shadows, velocity or host lights (those
// are mono), nor depth target with any of a view's extras: those combinations are not compiled.
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
constexpr uint32_t kSpirvShaderCount = 8;

// The features' bits, in the order of backend_vk/CMakeLists.txt's GRASS_VK_SPIRV_FEATURES.
enum SpirvFeature : uint32_t {
    kSpirvMultiview = 1u << 0,     // GRASS_MULTIVIEW
    kSpirvDepthTarget = 1u << 1,   // GRASS_DEPTH_TARGET
    kSpirvHostShadows = 1u << 2,   // GRASS_HOST_SHADOWS
    kSpirvVelocity = 1u << 3,      // GRASS_VELOCITY
    kSpirvResponsive = 1u << 4,    // GRASS_RESPONSIVE
    kSpirvIndexedBlocks = 1u << 5, // GRASS_INDEXED_BLOCKS
    kSpirvHostLights = 1u << 6,    // GRASS_HOST_LIGHTS
    kSpirvGBuffer = 1u << 7,       // GRASS_GBUFFER
    kSpirvBladeWindow = 1u << 8,   // GRASS_BLADE_WINDOW
};

struct Spirv {
    const uint32_t* code; // nullptr: no such module
    uint32_t size;        // bytes
};

// Which module of a shader: the defines it was compiled with.
struct SpirvVariant {
    bool responsive = false;     // GRASS_RESPONSIVE
    bool indexed_blocks = false; // GRASS_INDEXED_BLOCKS
    bool multiview = false;      // GRASS_MULTIVIEW
    bool depth_target = false;   // GRASS_DEPTH_TARGET: a depth pass's fragment shaders. Mono only.
    bool host_shadows = false;   // GRASS_HOST_SHADOWS: a receiving view's fragment shaders. Mono only.
    bool velocity = false;       // GRASS_VELOCITY: a motion view's blade.vert and fragment shaders. Mono only.
    bool host_lights = false;    // GRASS_HOST_LIGHTS: a lit view's fragment shaders. Mono only.
    bool gbuffer = false;        // GRASS_GBUFFER: a G-buffer view's fragment shaders. Mono only.
    bool blade_window = false;   // GRASS_BLADE_WINDOW: blade.vert reads the blade window's poses. Responsive only.
    uint32_t features() const {
        return (multiview ? kSpirvMultiview : 0u) | (depth_target ? kSpirvDepthTarget : 0u) |
               (host_shadows ? kSpirvHostShadows : 0u) | (velocity ? kSpirvVelocity : 0u) |
               (responsive ? kSpirvResponsive : 0u) | (indexed_blocks ? kSpirvIndexedBlocks : 0u) |
               (host_lights ? kSpirvHostLights : 0u) | (gbuffer ? kSpirvGBuffer : 0u) |
               (blade_window ? kSpirvBladeWindow : 0u);
    }
};

// One compiled module (the generated table's row).
struct SpirvModule {
    uint32_t shader;   // Shader
    uint32_t features; // SpirvFeature bits it was compiled with
    const uint32_t* code;
    const uint32_t* size; // bytes
};
extern const uint32_t kSpirvShaderFeatures[kSpirvShaderCount]; // the features each shader has
extern const SpirvModule kSpirvModules[];
extern const uint32_t kSpirvModuleCount;

// The module of `shader` compiled with the features of `variant` it has; code nullptr where
// that combination is not compiled (multiview with a mono-only feature, a depth target with
// a view's extras).
Spirv spirv(Shader shader, SpirvVariant variant);

} // namespace grass::vk
