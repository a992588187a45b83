// The fragment shaders of the pipelines of views that receive the host's shadow maps
// (GRASS_HOST_SHADOWS, backend_vk/CMakeLists.txt): blade.frag, volume.frag and image.frag,
// plain or responsive (blade.frag has no responsive variant), indexed blocks or not.
#include "vk_spirv.hpp"

namespace grass_vk_spirv {
extern const uint32_t blade_frag_grass_host_shadows[];
extern const uint32_t blade_frag_grass_host_shadows_size; // bytes
extern const uint32_t blade_frag_grass_host_shadows_grass_indexed_blocks[];
extern const uint32_t blade_frag_grass_host_shadows_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_host_shadows[];
extern const uint32_t volume_frag_grass_host_shadows_size; // bytes
extern const uint32_t volume_frag_grass_host_shadows_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_host_shadows_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_host_shadows_grass_responsive[];
extern const uint32_t volume_frag_grass_host_shadows_grass_responsive_size; // bytes
extern const uint32_t volume_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_host_shadows[];
extern const uint32_t image_frag_grass_host_shadows_size; // bytes
extern const uint32_t image_frag_grass_host_shadows_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_host_shadows_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_host_shadows_grass_responsive[];
extern const uint32_t image_frag_grass_host_shadows_grass_responsive_size; // bytes
extern const uint32_t image_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks_size; // bytes
} // namespace grass_vk_spirv

namespace grass::vk {

namespace {
using namespace grass_vk_spirv;
// [blade, volume, image][responsive][indexed blocks].
const Spirv kHostShadowModules[3][2][2] = {
    {{{blade_frag_grass_host_shadows, blade_frag_grass_host_shadows_size},
      {blade_frag_grass_host_shadows_grass_indexed_blocks, blade_frag_grass_host_shadows_grass_indexed_blocks_size}},
     {{blade_frag_grass_host_shadows, blade_frag_grass_host_shadows_size},
      {blade_frag_grass_host_shadows_grass_indexed_blocks, blade_frag_grass_host_shadows_grass_indexed_blocks_size}}},
    {{{volume_frag_grass_host_shadows, volume_frag_grass_host_shadows_size},
      {volume_frag_grass_host_shadows_grass_indexed_blocks, volume_frag_grass_host_shadows_grass_indexed_blocks_size}},
     {{volume_frag_grass_host_shadows_grass_responsive, volume_frag_grass_host_shadows_grass_responsive_size},
      {volume_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks,
       volume_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks_size}}},
    {{{image_frag_grass_host_shadows, image_frag_grass_host_shadows_size},
      {image_frag_grass_host_shadows_grass_indexed_blocks, image_frag_grass_host_shadows_grass_indexed_blocks_size}},
     {{image_frag_grass_host_shadows_grass_responsive, image_frag_grass_host_shadows_grass_responsive_size},
      {image_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks,
       image_frag_grass_host_shadows_grass_responsive_grass_indexed_blocks_size}}},
};
} // namespace

Spirv host_shadow_spirv(Shader shader, SpirvVariant variant) {
    const int program = shader == Shader::blade_frag ? 0 : shader == Shader::volume_frag ? 1 : 2;
    return kHostShadowModules[program][variant.responsive ? 1 : 0][variant.indexed_blocks ? 1 : 0];
}

} // namespace grass::vk
