// The generated geometry of a grass patch (lemme2012 4.1): blades as quad strips in
// patch units, with per-blade density thresholds. Shared by the core and the backends.
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

// One vertex of a blade. Layout matches api/shaders/blade_interface.glsl, locations 0-4.
struct BladeVertex {
    float position[3];   // location 0: patch units, root on the unit ground square
    float normal[3];     // location 1: unit, orthogonal to the blade's tangent
    float root_shape[4]; // location 2: root x, root z, u across the blade (0..1), v along it (0 root, 1 tip)
    uint8_t color[4];    // location 3: linear RGB modulation of the blade and vertex, unorm8; a = 255
    float threshold;     // location 4: the blade's density threshold in (0, 1]
};
static_assert(sizeof(BladeVertex) == 48, "BladeVertex must match the shader's vertex layout");

// One level of the blades' dynamic tessellation (blade_levels.hpp): its indices in
// PatchData::indices, blade after blade, and how far its outline strays from the full one.
struct BladeLevel {
    uint32_t first_index = 0;       // the level's first index
    uint32_t indices_per_blade = 0; // 6 per quad
    float error = 0.0f;             // patch units: the farthest a full vertex lies from this level's outline
};
constexpr uint32_t kMaxBladeLevels = 6; // 32 subdivisions: 32, 16, 8, 4, 2 and 1 quads

struct PatchData {
    explicit PatchData(HostAllocator* host)
        : vertices(StlAllocator<BladeVertex>(host)), indices(StlAllocator<uint32_t>(host)),
          thresholds(StlAllocator<float>(host)), blade_curves(StlAllocator<float>(host)) {}
    Vector<BladeVertex> vertices; // blade after blade, (subdivisions + 1) * 2 each
    Vector<uint32_t> indices;     // triangle lists: every level (levels), level 0 first (subdivisions * 6 per blade)
    Vector<float> thresholds;     // one per blade
    // Responsive grass (jahrmann2017 4): each blade's rest pose as a quadratic Bezier curve,
    // 8 floats per blade (two vec4 of the std430 buffer BladeCurves, binding 12), patch units
    // relative to the root: v1 - v0 (xyz) and the blade's arc length; v2 - v0 (xyz) and its
    // facing angle (radians; its width runs along (-sin, 0, cos)). The generator's
    // trajectory p(t) = b t + g t^2 is exactly the Bezier curve with v1 = b / 2, v2 = b + g.
    // Uploaded to the GPU only when a draw needs it (kFeatureWind or kFeatureInteraction).
    Vector<float> blade_curves;
    uint32_t blade_count = 0;
    uint32_t vertices_per_blade = 0;
    uint32_t indices_per_blade = 0; // level 0's
    BladeLevel levels[kMaxBladeLevels];
    uint32_t level_count = 0; // 1 for a blade of one quad
    float bounds_min[3] = {0, 0, 0};
    float bounds_max[3] = {0, 0, 0};
    float ao_impact = 0;       // B_impact (lemme eq. 6.11)
    float ao_height = 0;       // B_height, patch units
    uint64_t content_hash = 0; // FNV-1a 64 over vertices then level 0's indices
    // Level 0's indices: the full strip of every blade (the triangles the patch is made of).
    uint32_t full_index_count() const { return blade_count * indices_per_blade; }
};

} // namespace grass
