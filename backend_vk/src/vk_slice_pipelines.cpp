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
namespace {
PipelineShape slice_shape(const uint32_t* vert, uint32_t vert_size, const uint32_t* frag, uint32_t frag_size,
                          const char* name) {
    return PipelineShape{vert, vert_size, frag, frag_size, instance_only_vertex_input(), false, name};
}
} // namespace

PipelineShape SlicePipelines::volume_shape(bool responsive) {
    namespace spv = grass_vk_spirv;
    return responsive ? slice_shape(spv::volume_vert, spv::volume_vert_size, spv::volume_frag_grass_responsive,
                                    spv::volume_frag_grass_responsive_size, "the volume tier pipelines")
                      : slice_shape(spv::volume_vert, spv::volume_vert_size, spv::volume_frag, spv::volume_frag_size,
                                    "the volume tier pipelines");
}

PipelineShape SlicePipelines::image_shape(bool responsive) {
    namespace spv = grass_vk_spirv;
    return responsive ? slice_shape(spv::image_vert, spv::image_vert_size, spv::image_frag_grass_responsive,
                                    spv::image_frag_grass_responsive_size, "the image tier pipelines")
                      : slice_shape(spv::image_vert, spv::image_vert_size, spv::image_frag, spv::image_frag_size,
                                    "the image tier pipelines");
}

} // namespace grass::vk
