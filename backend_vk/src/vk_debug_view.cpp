#include "vk_debug_view.hpp"

#include "frame_plan.hpp"

#include <cstddef>

namespace grass_vk_spirv {
extern const uint32_t debug_tiers_vert[];
extern const uint32_t debug_tiers_vert_size; // bytes
extern const uint32_t debug_tiers_frag[];
extern const uint32_t debug_tiers_frag_size;
} // namespace grass_vk_spirv

namespace grass::vk {


bool DebugViewPipeline::create(const PipelineTarget& target, VkPipelineLayout layout, VkFailure* failure,
                               const char** what) {
    const VkPipelineVertexInputStateCreateInfo vertex_input = instance_only_vertex_input();
    // Opaque boxes: no alpha to coverage.
    const PipelineShape shape{grass_vk_spirv::debug_tiers_vert, grass_vk_spirv::debug_tiers_vert_size,
                              grass_vk_spirv::debug_tiers_frag, grass_vk_spirv::debug_tiers_frag_size,
                              &vertex_input,                    false,
                              "the tier debug view pipelines"};
    VkPipeline pipelines[2];
    if (!create_pipeline_pair(fn_, device_, target, layout, shape, pipelines, failure, what)) return false;
    depth_tested_ = pipelines[0];
    depth_off_ = pipelines[1];
    return true;
}

void DebugViewPipeline::destroy() {
    if (depth_tested_) fn_.vkDestroyPipeline(device_, depth_tested_, nullptr);
    if (depth_off_) fn_.vkDestroyPipeline(device_, depth_off_, nullptr);
    depth_tested_ = depth_off_ = VK_NULL_HANDLE;
}

} // namespace grass::vk
