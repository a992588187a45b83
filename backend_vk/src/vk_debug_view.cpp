#include "vk_debug_view.hpp"

#include "vk_spirv.hpp"

namespace grass::vk {

// Opaque boxes: no alpha to coverage.
PipelineShape DebugViewPipeline::shape(bool indexed_blocks) {
    const Spirv vert = spirv(Shader::debug_vert, false, indexed_blocks);
    const Spirv frag = spirv(Shader::debug_frag, false, indexed_blocks);
    return PipelineShape{vert.code,
                         vert.size,
                         frag.code,
                         frag.size,
                         instance_only_vertex_input(),
                         false,
                         "the tier debug view pipelines"};
}

} // namespace grass::vk
