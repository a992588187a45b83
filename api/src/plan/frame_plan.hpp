// The frame plan: what the core decided to draw this frame, for a backend to execute.
// Everything here is camera-relative and in float; world positions stayed double until
// they were made relative to the camera. Layouts match api/shaders/blade_interface.glsl.
#pragma once

#include "context/allocator.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// std140 uniform block `Frame` (binding 0).
struct FrameUniforms {
    float view_projection[16]; // projection * view rotation: camera-relative world -> clip
    float sun_direction[4];    // xyz unit, towards the sun
    float sun_color[4];        // rgb
    float ambient_color[4];    // rgb
    float params[4];           // x = time (s), y = flags, z = +1 (depth 0 is near) or -1 (reversed depth),
                               // w = 1 when the target is multisampled: the backend sets it (0 from the core)
    float target[4];           // x = 1 when the host's clip z runs 0..1 (Vulkan; GL with glClipControl's
                               // GL_ZERO_TO_ONE), 0 for GL's default -1..1: the GL backend reads it at each
                               // render (the core sets 1 for Vulkan, 0 for GL); yzw = 0
};
static_assert(sizeof(FrameUniforms) == 144, "std140 Frame block");

// std140 uniform block `Field` (binding 1).
struct FieldUniforms {
    float patch_to_world[16]; // patch units -> world metres (rotation x cell size), no translation
    float map_u[4];           // cell space -> map u: u = x * map_u.x + z * map_u.y + map_u.z (x, z in cells)
    float map_v[4];           // ... and map v (lemme's configTf)
    float map_params[4];      // x = density (uniform, or the maps' multiplier), y = height scale in patch units
                              // (metres / cell size), z = cells_x, w = cells_z of the field
    float blade_params[4];    // x = ao impact, y = ao height (patch units), z = tier kind (grass_tier_kind),
                              // w = height of the baked slices (patch units)
    uint32_t tiling[4];       // x = mirror seed, y = 1 if mirrored tiling is on, z = slices per axis of the tier,
                              // w = the draw's feature mask (maps bound, bit = 1 << MapRole)
    float bands[8][4];        // the field's tiers (GRASS_MAX_TIERS): begin, end, transition in, transition out (m)
    uint32_t tiers[4];        // x = this draw's tier, y = the field's tier count, z = 1 for an overlay tier
                              // (a hilltop tier: draws every blade the density passes, takes no share)
    float transition[4];      // x = crossover window (threshold units; 0 = exact partition)
};
static_assert(sizeof(FieldUniforms) == 304, "std140 Field block");

// One patch instance of any tier: a cell, or a macro-cell of count[0] x count[1] cells.
// Vertex input, per instance: location 5 (vec4), location 6 (uvec4) and location 7 (vec4). The exact integer
// cell coordinates let a shader mirror every cell of a macro-cell as that cell is mirrored
// on its own (mirror_tiling.hpp and lighting.glsl share the hash) and find design-map uvs.
struct TierInstance {
    float origin[3];   // location 5 xyz: the (macro-)cell's (0,0) corner relative to the camera, world metres
    float reserved;    // location 5 w
    uint32_t cell[2];  // location 6 xy: the first cell (field x, z)
    uint32_t count[2]; // location 6 zw: size in cells along field x and z (1, 1 for a cell)
    float terrain[4];  // location 7: x = lowest, y = highest terrain height under the instance, in patch
                       // units (cell edges) along the field's up axis (0, 0 without a height map); zw = 0
};
static_assert(sizeof(TierInstance) == 48, "TierInstance must match the shader's instance layout");

// One instanced draw: the instances one tier of one field draws this frame.
struct TierDraw {
    grass_tier_kind kind; // how to draw: blades (geometry), volume or image
    uint32_t tier;        // index of the tier in its field
    uint32_t slices;      // volume tiers: slices per axis
    uint32_t field_slot;
    uint32_t patch_slot;
    uint32_t first_instance; // into FramePlan::instances
    uint32_t instance_count;
    uint32_t features; // shader variant: the field's maps (bit = 1 << MapRole); equals uniforms.tiling[3]
    FieldUniforms uniforms;
};

// The baked slice set a volume or image draw samples: its slices per axis for a volume
// tier, the horizontal slice (N = 0) for an image tier (SliceSet::slices_per_axis).
inline uint32_t draw_slice_set(const TierDraw& draw) { return draw.kind == GRASS_TIER_VOLUME ? draw.slices : 0; }

struct FramePlan {
    explicit FramePlan(HostAllocator* host)
        : instances(StlAllocator<TierInstance>(host)), draws(StlAllocator<TierDraw>(host)) {}
    FrameUniforms frame{};
    int32_t viewport[4] = {0, 0, 0, 0};
    uint32_t flags = 0;             // grass_view_flags: GRASS_VIEW_FLAG_DEBUG_CELLS draws every
                                    // draw as debug boxes instead of its tier
    Vector<TierInstance> instances; // geometry instances of a draw are ordered front to back
    Vector<TierDraw> draws;         // per field, per tier that draws something
    grass_frame_stats stats{};
    void clear() {
        instances.clear();
        draws.clear();
        stats = grass_frame_stats{};
    }
};

} // namespace grass
