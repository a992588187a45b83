#include "vk_debug_view.hpp"

namespace grass_vk_spirv {
extern const uint32_t debug_tiers_vert[];
extern const uint32_t debug_tiers_vert_size; // bytes
extern const uint32_t debug_tiers_frag[];
extern const uint32_t debug_tiers_frag_size;
} // namespace grass_vk_spirv

namespace grass::vk {

// Opaque boxes: no alpha to coverage.
PipelineShape DebugViewPipeline::shape() {
    return PipelineShape{grass_vk_spirv::debug_tiers_vert, grass_vk_spirv::debug_tiers_vert_size,
                         grass_vk_spirv::debug_tiers_frag, grass_vk_spirv::debug_tiers_frag_size,
                         instance_only_vertex_input(),     false,
                         "the tier debug view pipelines"};
}

} // namespace grass::vk
