// The tier debug view (GRASS_VIEW_FLAG_DEBUG_CELLS): every planned instance of every tier
// kind as a flat false-colour box on the ground (api/shaders/debug_tiers.*). Same set and
// pipeline layout as the blades; no patch: six vertices per instance from the vertex
// index, the tier instances as the only vertex input.
#pragma once

#include "vk_functions.hpp"
#include "vk_pipeline.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

class DebugViewPipeline {
public:
    // The vertex binding of the tier instances, and the vertices each instance draws.
    static constexpr uint32_t kInstanceBinding = 0;
    static constexpr uint32_t kVerticesPerBox = 6;

    DebugViewPipeline(const Functions& functions, VkDevice device) : fn_(functions), device_(device) {}
    ~DebugViewPipeline() { destroy(); }
    DebugViewPipeline(const DebugViewPipeline&) = delete;
    DebugViewPipeline& operator=(const DebugViewPipeline&) = delete;

    // `layout`: the blade pipeline layout. *what names the object being made when it fails.
    bool create(const PipelineTarget& target, VkPipelineLayout layout, VkFailure* failure, const char** what);
    void destroy();

    VkPipeline pipeline(bool depth_test) const { return depth_test ? depth_tested_ : depth_off_; }

private:
    const Functions& fn_;
    VkDevice device_;
    VkPipeline depth_tested_ = VK_NULL_HANDLE;
    VkPipeline depth_off_ = VK_NULL_HANDLE;
};

} // namespace grass::vk
