#include "vk_slice_pipelines.hpp"

#include "vk_spirv.hpp"

namespace grass::vk {

// Both shaders write their coverage as a sample mask (coverage_mask() of
// blade_interface.glsl), not through alpha to coverage. No culling (shared state):
// volume.frag keeps the back faces itself.
namespace {
PipelineShape slice_shape(Shader vert, Shader frag, SpirvVariant variant, const char* name) {
    const Spirv v = spirv(vert, variant), f = spirv(frag, variant);
    return PipelineShape{v.code, v.size, f.code, f.size, instance_only_vertex_input(), false, name};
}
} // namespace

PipelineShape SlicePipelines::volume_shape(SpirvVariant variant) {
    return slice_shape(Shader::volume_vert, Shader::volume_frag, variant, "the volume tier pipelines");
}

PipelineShape SlicePipelines::image_shape(SpirvVariant variant) {
    return slice_shape(Shader::image_vert, Shader::image_frag, variant, "the image tier pipelines");
}

} // namespace grass::vk
