// The tier debug view (GRASS_VIEW_FLAG_DEBUG_CELLS): every planned instance of every tier
// kind as a flat false-colour box on the ground (api/shaders/debug_tiers.*). Same set and
// pipeline layout as the blades; no patch: the vertices of a box (TierDraw::vertex_count)
// from the vertex index, the tier instances as the only vertex input. BladePipeline makes its pipelines
// per feature mask.
#pragma once

#include "vk_functions.hpp"
#include "vk_pipeline.hpp"
#include "vk_spirv.hpp"

#include <cstdint>

namespace grass::vk {

struct DebugViewPipeline {
    // The vertex binding of the tier instances.
    static constexpr uint32_t kInstanceBinding = 0;

    static PipelineShape shape(SpirvVariant variant);
};

} // namespace grass::vk
