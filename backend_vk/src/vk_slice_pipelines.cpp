#include "vk_slice_pipelines.hpp"

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

// Both shaders write their coverage as a sample mask (coverage_mask() of
// blade_interface.glsl), not through alpha to coverage. No culling (shared state):
// volume.frag keeps the back faces itself.
PipelineShape SlicePipelines::volume_shape() {
    return PipelineShape{grass_vk_spirv::volume_vert,  grass_vk_spirv::volume_vert_size,
                         grass_vk_spirv::volume_frag,  grass_vk_spirv::volume_frag_size,
                         instance_only_vertex_input(), false,
                         "the volume tier pipelines"};
}

PipelineShape SlicePipelines::image_shape() {
    return PipelineShape{grass_vk_spirv::image_vert,      grass_vk_spirv::image_vert_size, grass_vk_spirv::image_frag,
                         grass_vk_spirv::image_frag_size, instance_only_vertex_input(),    false,
                         "the image tier pipelines"};
}

} // namespace grass::vk
