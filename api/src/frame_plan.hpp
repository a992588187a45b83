// The frame plan: what the core decided to draw this frame, for a backend to execute.
// Everything here is camera-relative and in float; world positions stayed double until
// they were made relative to the camera. Layouts match api/shaders/blade_interface.glsl.
#pragma once

#include "allocator.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// std140 uniform block `Frame` (binding 0).
struct FrameUniforms {
    float view_projection[16]; // projection * view rotation: camera-relative world -> clip
    float sun_direction[4];    // xyz unit, towards the sun
    float sun_color[4];        // rgb
    float ambient_color[4];    // rgb
    float params[4];           // x = time (s), y = flags, zw unused
};
static_assert(sizeof(FrameUniforms) == 128, "std140 Frame block");

// std140 uniform block `Field` (binding 1).
struct FieldUniforms {
    float patch_to_world[16]; // patch units -> world metres (rotation x cell size), no translation
    float map_params[4];      // x = map u per cell, y = map v per cell, z = density (uniform or map multiplier), w = 1 if a density map is bound
    float blade_params[4];    // x = ao impact, y = ao height (patch units), zw unused
};
static_assert(sizeof(FieldUniforms) == 96, "std140 Field block");

// One patch instance of the blade tier. Vertex input, per instance (locations 5-6).
struct BladeInstance {
    float origin[3];  // location 5 xyz: the cell's (0,0) corner relative to the camera, world metres
    float mirror;     // location 5 w: bit 0 mirrors x, bit 1 mirrors z (as a float 0..3)
    float map_uv[2];  // location 6 xy: the cell's (0,0) corner in density-map uv
    float reserved[2];
};
static_assert(sizeof(BladeInstance) == 32, "BladeInstance must match the shader's instance layout");

// One instanced draw: a field's planned cells, all with the same patch.
struct BladeDraw {
    uint32_t field_slot;
    uint32_t patch_slot;
    uint32_t first_instance; // into FramePlan::blade_instances
    uint32_t instance_count;
    FieldUniforms uniforms;
};

struct FramePlan {
    explicit FramePlan(HostAllocator* host) : blade_instances(StlAllocator<BladeInstance>(host)),
                                              blade_draws(StlAllocator<BladeDraw>(host)) {}
    FrameUniforms frame{};
    int32_t viewport[4] = {0, 0, 0, 0};
    uint32_t flags = 0;                  // grass_view_flags
    Vector<BladeInstance> blade_instances;
    Vector<BladeDraw> blade_draws;
    grass_frame_stats stats{};
    void clear() {
        blade_instances.clear();
        blade_draws.clear();
        stats = grass_frame_stats{};
    }
};

} // namespace grass
