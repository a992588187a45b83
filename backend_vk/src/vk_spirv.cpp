#include "vk_spirv.hpp"

namespace grass_vk_spirv {
extern const uint32_t blade_vert[];
extern const uint32_t blade_vert_size; // bytes
extern const uint32_t blade_vert_grass_indexed_blocks[];
extern const uint32_t blade_vert_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_vert_grass_responsive[];
extern const uint32_t blade_vert_grass_responsive_size; // bytes
extern const uint32_t blade_vert_grass_responsive_grass_indexed_blocks[];
extern const uint32_t blade_vert_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_vert_grass_multiview[];
extern const uint32_t blade_vert_grass_multiview_size; // bytes
extern const uint32_t blade_vert_grass_multiview_grass_indexed_blocks[];
extern const uint32_t blade_vert_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_vert_grass_multiview_grass_responsive[];
extern const uint32_t blade_vert_grass_multiview_grass_responsive_size; // bytes
extern const uint32_t blade_vert_grass_multiview_grass_responsive_grass_indexed_blocks[];
extern const uint32_t blade_vert_grass_multiview_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_frag[];
extern const uint32_t blade_frag_size; // bytes
extern const uint32_t blade_frag_grass_indexed_blocks[];
extern const uint32_t blade_frag_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_frag_grass_multiview[];
extern const uint32_t blade_frag_grass_multiview_size; // bytes
extern const uint32_t blade_frag_grass_multiview_grass_indexed_blocks[];
extern const uint32_t blade_frag_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_vert[];
extern const uint32_t volume_vert_size; // bytes
extern const uint32_t volume_vert_grass_indexed_blocks[];
extern const uint32_t volume_vert_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_vert_grass_multiview[];
extern const uint32_t volume_vert_grass_multiview_size; // bytes
extern const uint32_t volume_vert_grass_multiview_grass_indexed_blocks[];
extern const uint32_t volume_vert_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag[];
extern const uint32_t volume_frag_size; // bytes
extern const uint32_t volume_frag_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_responsive[];
extern const uint32_t volume_frag_grass_responsive_size; // bytes
extern const uint32_t volume_frag_grass_responsive_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_multiview[];
extern const uint32_t volume_frag_grass_multiview_size; // bytes
extern const uint32_t volume_frag_grass_multiview_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_multiview_grass_responsive[];
extern const uint32_t volume_frag_grass_multiview_grass_responsive_size; // bytes
extern const uint32_t volume_frag_grass_multiview_grass_responsive_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_multiview_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t image_vert[];
extern const uint32_t image_vert_size; // bytes
extern const uint32_t image_vert_grass_indexed_blocks[];
extern const uint32_t image_vert_grass_indexed_blocks_size; // bytes
extern const uint32_t image_vert_grass_multiview[];
extern const uint32_t image_vert_grass_multiview_size; // bytes
extern const uint32_t image_vert_grass_multiview_grass_indexed_blocks[];
extern const uint32_t image_vert_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag[];
extern const uint32_t image_frag_size; // bytes
extern const uint32_t image_frag_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_responsive[];
extern const uint32_t image_frag_grass_responsive_size; // bytes
extern const uint32_t image_frag_grass_responsive_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_multiview[];
extern const uint32_t image_frag_grass_multiview_size; // bytes
extern const uint32_t image_frag_grass_multiview_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_multiview_grass_responsive[];
extern const uint32_t image_frag_grass_multiview_grass_responsive_size; // bytes
extern const uint32_t image_frag_grass_multiview_grass_responsive_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_multiview_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t debug_tiers_vert[];
extern const uint32_t debug_tiers_vert_size; // bytes
extern const uint32_t debug_tiers_vert_grass_indexed_blocks[];
extern const uint32_t debug_tiers_vert_grass_indexed_blocks_size; // bytes
extern const uint32_t debug_tiers_vert_grass_multiview[];
extern const uint32_t debug_tiers_vert_grass_multiview_size; // bytes
extern const uint32_t debug_tiers_vert_grass_multiview_grass_indexed_blocks[];
extern const uint32_t debug_tiers_vert_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t debug_tiers_frag[];
extern const uint32_t debug_tiers_frag_size; // bytes
extern const uint32_t debug_tiers_frag_grass_indexed_blocks[];
extern const uint32_t debug_tiers_frag_grass_indexed_blocks_size; // bytes
extern const uint32_t debug_tiers_frag_grass_multiview[];
extern const uint32_t debug_tiers_frag_grass_multiview_size; // bytes
extern const uint32_t debug_tiers_frag_grass_multiview_grass_indexed_blocks[];
extern const uint32_t debug_tiers_frag_grass_multiview_grass_indexed_blocks_size; // bytes
extern const uint32_t blade_frag_grass_depth_target[];
extern const uint32_t blade_frag_grass_depth_target_size; // bytes
extern const uint32_t blade_frag_grass_depth_target_grass_indexed_blocks[];
extern const uint32_t blade_frag_grass_depth_target_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_depth_target[];
extern const uint32_t volume_frag_grass_depth_target_size; // bytes
extern const uint32_t volume_frag_grass_depth_target_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_depth_target_grass_indexed_blocks_size; // bytes
extern const uint32_t volume_frag_grass_depth_target_grass_responsive[];
extern const uint32_t volume_frag_grass_depth_target_grass_responsive_size; // bytes
extern const uint32_t volume_frag_grass_depth_target_grass_responsive_grass_indexed_blocks[];
extern const uint32_t volume_frag_grass_depth_target_grass_responsive_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_depth_target[];
extern const uint32_t image_frag_grass_depth_target_size; // bytes
extern const uint32_t image_frag_grass_depth_target_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_depth_target_grass_indexed_blocks_size; // bytes
extern const uint32_t image_frag_grass_depth_target_grass_responsive[];
extern const uint32_t image_frag_grass_depth_target_grass_responsive_size; // bytes
extern const uint32_t image_frag_grass_depth_target_grass_responsive_grass_indexed_blocks[];
extern const uint32_t image_frag_grass_depth_target_grass_responsive_grass_indexed_blocks_size; // bytes
} // namespace grass_vk_spirv

namespace grass::vk {

namespace {
using namespace grass_vk_spirv;
// [shader][multiview][responsive][indexed blocks], in the order of Shader.
const Spirv kModules[][2][2][2] = {
    {{{{blade_vert, blade_vert_size}, {blade_vert_grass_indexed_blocks, blade_vert_grass_indexed_blocks_size}},
      {{blade_vert_grass_responsive, blade_vert_grass_responsive_size},
       {blade_vert_grass_responsive_grass_indexed_blocks, blade_vert_grass_responsive_grass_indexed_blocks_size}}},
     {{{blade_vert_grass_multiview, blade_vert_grass_multiview_size},
       {blade_vert_grass_multiview_grass_indexed_blocks, blade_vert_grass_multiview_grass_indexed_blocks_size}},
      {{blade_vert_grass_multiview_grass_responsive, blade_vert_grass_multiview_grass_responsive_size},
       {blade_vert_grass_multiview_grass_responsive_grass_indexed_blocks,
        blade_vert_grass_multiview_grass_responsive_grass_indexed_blocks_size}}}},
    {{{{blade_frag, blade_frag_size}, {blade_frag_grass_indexed_blocks, blade_frag_grass_indexed_blocks_size}},
      {{blade_frag, blade_frag_size}, {blade_frag_grass_indexed_blocks, blade_frag_grass_indexed_blocks_size}}},
     {{{blade_frag_grass_multiview, blade_frag_grass_multiview_size},
       {blade_frag_grass_multiview_grass_indexed_blocks, blade_frag_grass_multiview_grass_indexed_blocks_size}},
      {{blade_frag_grass_multiview, blade_frag_grass_multiview_size},
       {blade_frag_grass_multiview_grass_indexed_blocks, blade_frag_grass_multiview_grass_indexed_blocks_size}}}},
    {{{{volume_vert, volume_vert_size}, {volume_vert_grass_indexed_blocks, volume_vert_grass_indexed_blocks_size}},
      {{volume_vert, volume_vert_size}, {volume_vert_grass_indexed_blocks, volume_vert_grass_indexed_blocks_size}}},
     {{{volume_vert_grass_multiview, volume_vert_grass_multiview_size},
       {volume_vert_grass_multiview_grass_indexed_blocks, volume_vert_grass_multiview_grass_indexed_blocks_size}},
      {{volume_vert_grass_multiview, volume_vert_grass_multiview_size},
       {volume_vert_grass_multiview_grass_indexed_blocks, volume_vert_grass_multiview_grass_indexed_blocks_size}}}},
    {{{{volume_frag, volume_frag_size}, {volume_frag_grass_indexed_blocks, volume_frag_grass_indexed_blocks_size}},
      {{volume_frag_grass_responsive, volume_frag_grass_responsive_size},
       {volume_frag_grass_responsive_grass_indexed_blocks, volume_frag_grass_responsive_grass_indexed_blocks_size}}},
     {{{volume_frag_grass_multiview, volume_frag_grass_multiview_size},
       {volume_frag_grass_multiview_grass_indexed_blocks, volume_frag_grass_multiview_grass_indexed_blocks_size}},
      {{volume_frag_grass_multiview_grass_responsive, volume_frag_grass_multiview_grass_responsive_size},
       {volume_frag_grass_multiview_grass_responsive_grass_indexed_blocks,
        volume_frag_grass_multiview_grass_responsive_grass_indexed_blocks_size}}}},
    {{{{image_vert, image_vert_size}, {image_vert_grass_indexed_blocks, image_vert_grass_indexed_blocks_size}},
      {{image_vert, image_vert_size}, {image_vert_grass_indexed_blocks, image_vert_grass_indexed_blocks_size}}},
     {{{image_vert_grass_multiview, image_vert_grass_multiview_size},
       {image_vert_grass_multiview_grass_indexed_blocks, image_vert_grass_multiview_grass_indexed_blocks_size}},
      {{image_vert_grass_multiview, image_vert_grass_multiview_size},
       {image_vert_grass_multiview_grass_indexed_blocks, image_vert_grass_multiview_grass_indexed_blocks_size}}}},
    {{{{image_frag, image_frag_size}, {image_frag_grass_indexed_blocks, image_frag_grass_indexed_blocks_size}},
      {{image_frag_grass_responsive, image_frag_grass_responsive_size},
       {image_frag_grass_responsive_grass_indexed_blocks, image_frag_grass_responsive_grass_indexed_blocks_size}}},
     {{{image_frag_grass_multiview, image_frag_grass_multiview_size},
       {image_frag_grass_multiview_grass_indexed_blocks, image_frag_grass_multiview_grass_indexed_blocks_size}},
      {{image_frag_grass_multiview_grass_responsive, image_frag_grass_multiview_grass_responsive_size},
       {image_frag_grass_multiview_grass_responsive_grass_indexed_blocks,
        image_frag_grass_multiview_grass_responsive_grass_indexed_blocks_size}}}},
    {{{{debug_tiers_vert, debug_tiers_vert_size},
       {debug_tiers_vert_grass_indexed_blocks, debug_tiers_vert_grass_indexed_blocks_size}},
      {{debug_tiers_vert, debug_tiers_vert_size},
       {debug_tiers_vert_grass_indexed_blocks, debug_tiers_vert_grass_indexed_blocks_size}}},
     {{{debug_tiers_vert_grass_multiview, debug_tiers_vert_grass_multiview_size},
       {debug_tiers_vert_grass_multiview_grass_indexed_blocks,
        debug_tiers_vert_grass_multiview_grass_indexed_blocks_size}},
      {{debug_tiers_vert_grass_multiview, debug_tiers_vert_grass_multiview_size},
       {debug_tiers_vert_grass_multiview_grass_indexed_blocks,
        debug_tiers_vert_grass_multiview_grass_indexed_blocks_size}}}},
    {{{{debug_tiers_frag, debug_tiers_frag_size},
       {debug_tiers_frag_grass_indexed_blocks, debug_tiers_frag_grass_indexed_blocks_size}},
      {{debug_tiers_frag, debug_tiers_frag_size},
       {debug_tiers_frag_grass_indexed_blocks, debug_tiers_frag_grass_indexed_blocks_size}}},
     {{{debug_tiers_frag_grass_multiview, debug_tiers_frag_grass_multiview_size},
       {debug_tiers_frag_grass_multiview_grass_indexed_blocks,
        debug_tiers_frag_grass_multiview_grass_indexed_blocks_size}},
      {{debug_tiers_frag_grass_multiview, debug_tiers_frag_grass_multiview_size},
       {debug_tiers_frag_grass_multiview_grass_indexed_blocks,
        debug_tiers_frag_grass_multiview_grass_indexed_blocks_size}}}},
};

// The depth-only target's fragment shaders (GRASS_DEPTH_TARGET): [blade, volume, image][responsive]
// [indexed blocks] (blade.frag has no responsive variant).
const Spirv kDepthTargetModules[3][2][2] = {
    {{{blade_frag_grass_depth_target, blade_frag_grass_depth_target_size},
      {blade_frag_grass_depth_target_grass_indexed_blocks, blade_frag_grass_depth_target_grass_indexed_blocks_size}},
     {{blade_frag_grass_depth_target, blade_frag_grass_depth_target_size},
      {blade_frag_grass_depth_target_grass_indexed_blocks, blade_frag_grass_depth_target_grass_indexed_blocks_size}}},
    {{{volume_frag_grass_depth_target, volume_frag_grass_depth_target_size},
      {volume_frag_grass_depth_target_grass_indexed_blocks, volume_frag_grass_depth_target_grass_indexed_blocks_size}},
     {{volume_frag_grass_depth_target_grass_responsive, volume_frag_grass_depth_target_grass_responsive_size},
      {volume_frag_grass_depth_target_grass_responsive_grass_indexed_blocks,
       volume_frag_grass_depth_target_grass_responsive_grass_indexed_blocks_size}}},
    {{{image_frag_grass_depth_target, image_frag_grass_depth_target_size},
      {image_frag_grass_depth_target_grass_indexed_blocks, image_frag_grass_depth_target_grass_indexed_blocks_size}},
     {{image_frag_grass_depth_target_grass_responsive, image_frag_grass_depth_target_grass_responsive_size},
      {image_frag_grass_depth_target_grass_responsive_grass_indexed_blocks,
       image_frag_grass_depth_target_grass_responsive_grass_indexed_blocks_size}}},
};
} // namespace

Spirv spirv(Shader shader, SpirvVariant variant) {
    if (variant.host_shadows &&
        (shader == Shader::blade_frag || shader == Shader::volume_frag || shader == Shader::image_frag)) {
        return host_shadow_spirv(shader, variant);
    }
    if (variant.depth_target) {
        const int program = shader == Shader::blade_frag ? 0 : shader == Shader::volume_frag ? 1 : 2;
        if (shader == Shader::blade_frag || shader == Shader::volume_frag || shader == Shader::image_frag) {
            return kDepthTargetModules[program][variant.responsive ? 1 : 0][variant.indexed_blocks ? 1 : 0];
        }
    }
    return kModules[static_cast<int>(shader)][variant.multiview ? 1 : 0][variant.responsive ? 1 : 0]
                   [variant.indexed_blocks ? 1 : 0];
}

} // namespace grass::vk
