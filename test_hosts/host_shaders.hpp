// The hosts' own shaders (shaders/ground.*, shaders/mesh.*), embedded by the build: GLSL
// source text for GL (grass_host_shaders, when GL is built) and SPIR-V words for Vulkan
// (grass_host_spirv, when Vulkan is built).
#pragma once

#include <cstdint>

namespace grass_host_shaders {
extern const char* const ground_vert;
extern const char* const ground_frag;
extern const char* const mesh_vert;
extern const char* const mesh_frag;
} // namespace grass_host_shaders

namespace grass_host_spirv {
extern const uint32_t ground_vert[];
extern const uint32_t ground_vert_size; // bytes
extern const uint32_t ground_frag[];
extern const uint32_t ground_frag_size;
extern const uint32_t mesh_vert[];
extern const uint32_t mesh_vert_size;
extern const uint32_t mesh_frag[];
extern const uint32_t mesh_frag_size;
// TargetDesc::host_shadows: the ground and meshes that sample the host's shadow map.
extern const uint32_t ground_vert_host_shadows[];
extern const uint32_t ground_vert_host_shadows_size;
extern const uint32_t ground_frag_host_shadows[];
extern const uint32_t ground_frag_host_shadows_size;
extern const uint32_t mesh_frag_host_shadows[];
extern const uint32_t mesh_frag_host_shadows_size;
} // namespace grass_host_spirv
