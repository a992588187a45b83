// The pipelines of the baked-slice tiers (lemme2012 5.2, 5.3): the volume tier (a cuboid
// carrier per instance, 36 vertices, ray-cast through the implicit vertical slices,
// api/shaders/volume.*) and the image tier (a horizontal quad per instance, 6 vertices,
// api/shaders/image.*). Same set and pipeline layout as the blades; no patch vertices: the
// vertices come from the vertex index, the tier instances are the only vertex input.
// Alpha to coverage on multisampled targets. BladePipeline makes them per feature mask.
#pragma once

#include "vk_functions.hpp"
#include "vk_pipeline.hpp"

#include <cstdint>

namespace grass::vk {

struct SlicePipelines {
    // The vertex binding of the tier instances, and the vertices each instance draws.
    static constexpr uint32_t kInstanceBinding = 0;
    static constexpr uint32_t kVerticesPerVolume = 36;          // 6 faces x 2 triangles
    static constexpr uint32_t kVerticesPerImage = 6;            // 2 triangles
    static constexpr uint32_t kVerticesPerImageWithSkirts = 30; // on a height map: the quad and 4 skirts (image.vert)

    // `responsive`: the fragment shaders compiled with GRASS_RESPONSIVE (wind, trails).
    static PipelineShape volume_shape(bool responsive, bool indexed_blocks);
    static PipelineShape image_shape(bool responsive, bool indexed_blocks);
};

} // namespace grass::vk
