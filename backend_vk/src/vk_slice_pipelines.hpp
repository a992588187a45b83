// The pipelines of the baked-slice tiers (lemme2012 5.2, 5.3): the volume tier (a cuboid
// carrier per instance, ray-cast through the implicit vertical slices, api/shaders/volume.*)
// and the image tier (a horizontal quad per instance, with skirts on a height map,
// api/shaders/image.*). Same set and pipeline layout as the blades; no patch vertices: the
// vertices come from the vertex index (how many: TierDraw::vertex_count, decided by the
// core), the tier instances are the only vertex input.
// Alpha to coverage on multisampled targets. BladePipeline makes them per feature mask.
#pragma once

#include "vk_functions.hpp"
#include "vk_pipeline.hpp"
#include "vk_spirv.hpp"

#include <cstdint>

namespace grass::vk {

struct SlicePipelines {
    // The vertex binding of the tier instances.
    static constexpr uint32_t kInstanceBinding = 0;

    // `responsive`: the fragment shaders compiled with GRASS_RESPONSIVE (wind, trails).
    static PipelineShape volume_shape(SpirvVariant variant);
    static PipelineShape image_shape(SpirvVariant variant);
};

} // namespace grass::vk
