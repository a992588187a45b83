#include "vk_debug_view.hpp"

#include "vk_spirv.hpp"

namespace grass::vk {

// Opaque boxes: no alpha to coverage.
PipelineShape DebugViewPipeline::shape(SpirvVariant variant) {
    variant.responsive = false; // the boxes have no responsive code
    const Spirv vert = spirv(Shader::debug_vert, variant);
    const Spirv frag = spirv(Shader::debug_frag, variant);
    return PipelineShape{vert.code,
                         vert.size,
                         frag.code,
                         frag.size,
                         instance_only_vertex_input(),
                         false,
                         "the tier debug view pipelines"};
}

} // namespace grass::vk
