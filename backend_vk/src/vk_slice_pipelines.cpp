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
extern const uint32_t volume_frag_grass_responsive[];
extern const uint32_t volume_frag_grass_responsive_size;
extern const uint32_t image_frag_grass_responsive[];
extern const uint32_t image_frag_grass_responsive_size;
} // namespace grass_vk_spirv

namespace grass::vk {

// Both shaders write their coverage as a sample mask (coverage_mask() of
// blade_interface.glsl), not through alpha to coverage. No culling (shared state):
// volume.frag keeps the back faces itself.
PipelineShape SlicePipelines::volume_shape(bool responsive) {
    namespace spv = grass_vk_spirv;
    return PipelineShape{spv::volume_vert,
                         spv::volume_vert_size,
                         responsive ? spv::volume_frag_grass_responsive : spv::volume_frag,
                         responsive ? spv::volume_frag_grass_responsive_size : spv::volume_frag_size,
                         instance_only_vertex_input(),
                         false,
                         "the volume tier pipelines"};
}

PipelineShape SlicePipelines::image_shape(bool responsive) {
    namespace spv = grass_vk_spirv;
    return PipelineShape{spv::image_vert,
                         spv::image_vert_size,
                         responsive ? spv::image_frag_grass_responsive : spv::image_frag,
                         responsive ? spv::image_frag_grass_responsive_size : spv::image_frag_size,
                         instance_only_vertex_input(),
                         false,
                         "the image tier pipelines"};
}

} // namespace grass::vk
