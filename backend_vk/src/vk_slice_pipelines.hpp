// The pipelines of the baked-slice tiers (lemme2012 5.2, 5.3): the volume tier (a cuboid
// carrier per instance, 36 vertices, ray-cast through the implicit vertical slices,
// api/shaders/volume.*) and the image tier (a horizontal quad per instance, 6 vertices,
// api/shaders/image.*). Same set and pipeline layout as the blades; no patch vertices: the
// vertices come from the vertex index, the tier instances are the only vertex input. Each
// with and without the depth test; alpha to coverage on multisampled targets.
#pragma once

#include "vk_functions.hpp"
#include "vk_pipeline.hpp"
#include "vk_result.hpp"

#include <cstdint>

namespace grass::vk {

class SlicePipelines {
public:
    // The vertex binding of the tier instances, and the vertices each instance draws.
    static constexpr uint32_t kInstanceBinding = 0;
    static constexpr uint32_t kVerticesPerVolume = 36; // 6 faces x 2 triangles
    static constexpr uint32_t kVerticesPerImage = 6;   // 2 triangles

    SlicePipelines(const Functions& functions, VkDevice device) : fn_(functions), device_(device) {}
    ~SlicePipelines() { destroy(); }
    SlicePipelines(const SlicePipelines&) = delete;
    SlicePipelines& operator=(const SlicePipelines&) = delete;

    // `layout`: the blade pipeline layout. *what names the object being made when it fails.
    bool create(const PipelineTarget& target, VkPipelineLayout layout, VkFailure* failure, const char** what);
    void destroy();

    VkPipeline volume(bool depth_test) const { return volume_[depth_test ? 0 : 1]; }
    VkPipeline image(bool depth_test) const { return image_[depth_test ? 0 : 1]; }

private:
    const Functions& fn_;
    VkDevice device_;
    VkPipeline volume_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE}; // depth tested, depth off
    VkPipeline image_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
};

} // namespace grass::vk
