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

namespace {

// Locations 5 and 6 of debug_tiers.vert, as in blade.vert.
constexpr VkVertexInputBindingDescription kBinding = {DebugViewPipeline::kInstanceBinding, sizeof(TierInstance),
                                                      VK_VERTEX_INPUT_RATE_INSTANCE};
constexpr VkVertexInputAttributeDescription kAttributes[] = {
    {5, DebugViewPipeline::kInstanceBinding, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(TierInstance, origin)},
    {6, DebugViewPipeline::kInstanceBinding, VK_FORMAT_R32G32B32A32_UINT, offsetof(TierInstance, cell)},
};
static_assert(offsetof(TierInstance, cell) == 16, "instance layout of debug_tiers.vert");

} // namespace

bool DebugViewPipeline::create(const PipelineTarget& target, VkPipelineLayout layout, VkFailure* failure,
                               const char** what) {
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &kBinding;
    vertex_input.vertexAttributeDescriptionCount = 2;
    vertex_input.pVertexAttributeDescriptions = kAttributes;
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
