#include "vk_slice_pipelines.hpp"

#include "frame_plan.hpp"

#include <cstddef>

namespace grass_vk_spirv {
extern const uint32_t volume_vert[];
extern const uint32_t volume_vert_size; // bytes
extern const uint32_t volume_frag[];
extern const uint32_t volume_frag_size;
extern const uint32_t image_vert[];
extern const uint32_t image_vert_size;
extern const uint32_t image_frag[];
extern const uint32_t image_frag_size;
} // namespace grass_vk_spirv

namespace grass::vk {


bool SlicePipelines::create(const PipelineTarget& target, VkPipelineLayout layout, VkFailure* failure,
                            const char** what) {
    const VkPipelineVertexInputStateCreateInfo vertex_input = instance_only_vertex_input();
    // Both shaders output coverage as alpha: alpha to coverage with multisampling. No
    // culling (shared state): volume.frag keeps the back faces itself.
    const PipelineShape volume{grass_vk_spirv::volume_vert, grass_vk_spirv::volume_vert_size,
                               grass_vk_spirv::volume_frag, grass_vk_spirv::volume_frag_size,
                               &vertex_input,               true,
                               "the volume tier pipelines"};
    const PipelineShape image{grass_vk_spirv::image_vert, grass_vk_spirv::image_vert_size,
                              grass_vk_spirv::image_frag, grass_vk_spirv::image_frag_size,
                              &vertex_input,              true,
                              "the image tier pipelines"};
    if (!create_pipeline_pair(fn_, device_, target, layout, volume, volume_, failure, what) ||
        !create_pipeline_pair(fn_, device_, target, layout, image, image_, failure, what)) {
        destroy();
        return false;
    }
    return true;
}

void SlicePipelines::destroy() {
    for (VkPipeline* p : {&volume_[0], &volume_[1], &image_[0], &image_[1]}) {
        if (*p) fn_.vkDestroyPipeline(device_, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
}

} // namespace grass::vk
