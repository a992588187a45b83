// The host's ground (private to the headless hosts): uniforms of shaders/ground.vert/.frag.
#pragma once

#include "headless_host.hpp"

namespace grass_host {

// The ground is drawn as kGroundTiles x kGroundTiles squares of 6 vertices (shaders/ground.vert):
// draw kGroundVertexCount vertices, no vertex buffer.
constexpr int kGroundTiles = 32;
constexpr unsigned kGroundVertexCount = 6u * kGroundTiles * kGroundTiles;

// std140 block `Ground`.
struct GroundUniforms {
    float view_projection[16]; // projection * view rotation: camera-relative
    float plane[4];            // x: ground height - camera height (m), y: half size (m)
    float color[4];
    float sun_direction[4];
    float sun_color[4];
    float ambient_color[4];
};
static_assert(sizeof(GroundUniforms) == 144, "std140 Ground block");

GroundUniforms make_ground_uniforms(const grass_view_desc& view, const TargetDesc& target);

} // namespace grass_host
