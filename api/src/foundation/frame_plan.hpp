// The frame plan: what the core decided to draw this frame, for a backend to execute.
// Everything here is camera-relative and in float; world positions stayed double until
// they were made relative to the camera. Layouts match api/shaders/blade_interface.glsl.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/shader_interface.hpp"

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
                               // w = the target's samples per pixel (RenderTarget, write_render_target)
    float target[4];           // x = 1 when the host's clip z runs 0..1 (Vulkan; GL with glClipControl's
                               // GL_ZERO_TO_ONE), 0 for GL's default -1..1 (RenderTarget); yzw = the view
                               // axis of an orthographic view (world, unit, the direction it looks along:
                               // its rays are parallel to it), zero for a perspective view (and stereo)
    float lod_origin[4];       // xyz = the lod origin relative to the plan's origin (m; zero unless
                               // grass_lod_origin_desc moves it off the camera), w = 0: the tiers'
                               // distances are measured from it (lod_distance(), blade_interface.glsl)
    // xyz = the centre of projection relative to the plan's origin (m) of a view whose rays start
    // elsewhere than at the camera (an off-centre or warped perspective: ViewCulling::apex()), zero
    // otherwise (the camera; parallel rays, whose axis is target.yzw; stereo); w = 0. The volume
    // tier's rays start there (projection_centre(), towards_viewer(), blade_interface.glsl).
    float projection_centre[4];
    // Responsive grass (docs/responsive.md, api/shaders/wind.glsl, interaction.glsl). Read only by
    // shader variants with kFeatureWind / kFeatureInteraction; zero otherwise.
    float wind[4];          // xyz: mean wind velocity, world m/s (zero: none); w: gust strength (fraction of speed)
    float wind_shape[4];    // x: 1 / gust length (1/m), y: turbulence 0..1, z: wind source count, w: time step (s)
    float wind_phase[4];    // xyz: phase (cycles, in [0, 1)) at the camera of the three gust waves (wind.glsl),
                            // w: unused
    float gravity[4];       // xyz: gravity minus standard gravity (0, -9.81, 0), world m/s^2; w: unused
    float map_up[4];        // xyz: the interaction map's up (world, unit); w: its level count (0: no map)
    float map_axis_u[4];    // xyz: world direction of the map's texel x (unit, across map_up); w: unused
    float map_axis_v[4];    // xyz: world direction of the map's texel y; w: the camera's height along map_up
                            // above the map's height anchor (m): heights in the map are above that anchor
    float map_levels[2][4]; // per level: xy: the camera's map coordinate in texels, modulo the resolution
                            // (in [0, N)); z: texels per metre; w: the resolution N (texels per side)
    float wind_sources[16][4][4]; // GRASS_MAX_WIND_SOURCES, the first wind_shape.z used:
                                  // [0] xyz: position relative to the camera (m), w: kind (grass_wind_source_kind)
                                  // [1] xyz: unit direction (CONE), w: cos(cone angle)
                                  // [2] x: speed (m/s), y: radius (m), z: seconds since start_time (BLAST),
                                  //     w: duration (s)
                                  // [3] x: front speed (m/s), yzw: unused
    // xyz: this view's camera relative to the camera the interaction map's window follows (view 0
    // of the frame, grass.h "Frames and views"): interaction.glsl adds it to a camera-relative point
    // to read the map of view 0's uniforms above. Zero in view 0. w: unused.
    float map_offset[4];
};
static_assert(sizeof(FrameUniforms) == 1360, "std140 Frame block");

// The host's render target as the shaders must know it, which only a backend knows
// (Backend::render_target): its samples per pixel (sample_count() of blade_interface.glsl)
// and its clip convention, the clip z range the volume tier maps its gl_FragDepth with
// (window_depth()).
struct RenderTarget {
    uint32_t samples = 1;          // 1: not multisampled
    bool clip_zero_to_one = false; // clip z runs 0..1 (Vulkan, GL_ZERO_TO_ONE), else -1..1 (GL's default)
    uint32_t views = 1;            // 2: a multiview pass of two eyes (grass_vk_multiview_desc.view_mask 0x3); a frame
                                   // must then be stereo (grass_stereo_view_desc), and only then
    // Depth views (grass_view_pass_desc, GRASS_PASS_DEPTH): whether the backend has a target to
    // draw them in (Vulkan: grass_vk_depth_pass_desc was chained; GL: the bound framebuffer),
    // and that target's samples per pixel (0: `samples`), which a depth view's Frame block gets.
    bool depth_pass = true;
    uint32_t depth_pass_samples = 0;
    // Motion views (grass_view_motion_desc) on Vulkan: the index of the velocity attachment
    // the backend's motion pipelines write (grass_vk_velocity_target_desc), 0 where it has
    // none and refuses them. GL: 0 (it routes the bound framebuffer's draw buffers per view).
    uint32_t velocity_attachment = 0;
    // G-buffer views (GRASS_PASS_GBUFFER) on Vulkan: the colour attachments of the pass the
    // backend's G-buffer pipelines draw in (grass_vk_gbuffer_target_desc), 0 where it has none
    // and refuses them. GL: 0 (it checks the bound framebuffer's draw buffers per view).
    uint32_t gbuffer_attachments = 0;
    bool operator==(const RenderTarget& o) const {
        return samples == o.samples && clip_zero_to_one == o.clip_zero_to_one && views == o.views;
    }
    bool operator!=(const RenderTarget& o) const { return !(*this == o); }
};

// The one place the Frame block's target fields are written: the planner with what the
// backend reports, and a backend again where the host draws one frame into another target.
inline void write_render_target(FrameUniforms* frame, const RenderTarget& target) {
    frame->params[3] = static_cast<float>(target.samples);
    frame->target[0] = target.clip_zero_to_one ? 1.0f : 0.0f;
}

// Stereo frames only (grass_stereo_view_desc): the eyes, as the multiview shader variant
// (GRASS_MULTIVIEW, blade_interface.glsl) reads them at the end of its Frame block, right
// after FrameUniforms (std140; a mono context's Frame block has none of it). Positions are
// relative to the plan's origin, the point the instances are relative to (the eyes' midpoint
// or the grass_lod_origin_desc).
struct StereoUniforms {
    float eye_view_projection[2][16]; // per eye: projection * view rotation: eye-relative world -> clip
    float eye_position[2][4];         // per eye: xyz: the eye relative to the plan's origin (m); w = 0
};
static_assert(sizeof(StereoUniforms) == 160, "std140 Frame block's eyes");

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
                              // (a hilltop tier: draws every blade the density passes, takes no share),
                              // w = the geometry tiers' bits (texel tiers between them take parts of samples)
    float transition[4];      // x = crossover window (threshold units; 0 = exact partition)
    // Responsive grass: the draw's patch's grass_blade_mechanics and the field's up.
    float mechanics[4]; // x = stiffness (m/s^2), y = mass, z = wind response (m/s^2 per m/s), w = variation
    float trample[4];   // x = trample depth (0..1), y = recovery time (s), z = 1 if this field reads the
                        // interaction map (its up within 60 degrees of the map's up), w = the patch's vertices
                        // per blade in the responsive variants (kBladeCurveFeatures: blade.vert finds a
                        // vertex's blade from it), else 0
    float field_up[4];  // xyz = the field's up, world, unit; w = metres per patch unit (the cell size)
    // The field's wind map (dynamics/wind_map.hpp; read only by variants with kFeatureWindMap):
    // cell space -> its map u (xyz, as map_u), w = m/s for an encoded 1; and its map v (xyz).
    float wind_map_u[4];
    float wind_map_v[4];
    // Per-blade culling (geometry draws with kFeatureBladeCulling; plan/blade_culling.hpp):
    // x = orientation limit (|cos|; 2 = off), y = frustum tolerance (relative to w; < 0 = off),
    // z = distance max (m; 0 = off), w = distance levels (0 = thinning by threshold)
    float culling[4];
    // Volume and image draws: the horizontal slice's alpha-test scale per mip level (SliceSet::
    // alpha_test_scale, 4 levels a row), which single-sampled targets apply; 1 elsewhere.
    float alpha_test_scale[4][4];
};
static_assert(sizeof(FieldUniforms) == 464, "std140 Field block");

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
                       // units (cell edges) along the field's up axis (0, 0 without a height map); z = 1 for a
                       // field-edge instance (a volume tier standing in for the image tiers after it at the
                       // field's border: frame_planner.cpp), else 0; w = 0
};
static_assert(sizeof(TierInstance) == 48, "TierInstance must match the shader's instance layout");

// One instanced draw: the instances one tier of one field draws this frame, with everything
// the backend needs to bind and draw it: the core decided it all once, for every backend.
struct TierDraw {
    grass_tier_kind kind; // how to draw: blades (geometry), volume or image
    uint32_t tier;        // index of the tier in its field
    uint32_t slices;      // volume tiers: slices per axis
    uint32_t field_slot;
    uint32_t patch_slot;
    uint32_t first_instance; // into FramePlan::instances
    uint32_t instance_count;
    uint32_t vertex_count;    // per instance: the patch's indices (geometry, an indexed draw; 0 for an empty
                              // patch), the volume's cuboid or the image's quad, with skirts on a height map
                              // (slice_tier_vertices); a debug box under GRASS_VIEW_FLAG_DEBUG_CELLS
    uint32_t first_index = 0; // geometry: the first index of the blades' level (patch/blade_levels.hpp), else 0
    uint32_t blade_level = 0; // geometry: that level (0: the patch's full blades; vertex_count is its indices)
    uint32_t features;        // shader variant: the field's maps (bit = 1 << MapRole), then the responsive and
                              // culling bits (foundation/shader_interface.hpp); equals uniforms.tiling[3]
    FieldUniforms uniforms;   // complete: a backend uploads it as it is
};

// The baked slice set a volume or image draw samples: its slices per axis for a volume
// tier, the horizontal slice (N = 0) for an image tier (SliceSet::slices_per_axis).
inline uint32_t draw_slice_set(const TierDraw& draw) { return draw.kind == GRASS_TIER_VOLUME ? draw.slices : 0; }

// One collider as the interaction pass reads it (std430, api/shaders/interaction.comp), in
// the map's frame: u, v along map_axis_u/v in metres relative to the camera, h along
// map_up in metres above the map's height anchor.
struct GpuCollider {
    float a[4];        // u, v, h of the centre (sphere) or one axis end (capsule); w = radius (m)
    float b[4];        // u, v, h of the capsule's other end (= a for a sphere); w = shape (grass_collider_shape)
    float velocity[4]; // u, v, h components, m/s; w = 1: the collider continues its passage (colliders.hpp), 0: new
};
static_assert(sizeof(GpuCollider) == 48, "GpuCollider must match interaction.comp");

// What the interaction pass does to one level of the map this frame (std140 block
// `Interaction` of interaction.comp).
struct InteractionLevelUniforms {
    int32_t window[4];     // xy: the window's first texel modulo N (where world texel W lands in the
                           // toroidal texture); zw: W - W_prev per axis clamped to [-N, N] (texels that left the
                           // window are cleared; N or -N: all)
    float origin[4];       // xy: texel W's lower corner relative to the camera along u, v (m); z: texel size (m);
                           // w: time step (s)
    uint32_t counts[4];    // x: resolution N, y: tile size in texels, z: tiles per side, w: 1 = clear everything
    float least_radius[4]; // x: a collider's footprint narrower than this (m) is widened to it: half a texel's
                           // diagonal on the coarse level, 0 on the fine one (kCoarseLeastRadius); yzw unused
};
static_assert(sizeof(InteractionLevelUniforms) == 64, "std140 Interaction block");

// The interaction pass of one frame: run when map_levels > 0 (and the map exists or colliders
// ask for it). tile_offsets[level] has tiles^2 + 1 entries into tile_colliders[level]: the
// colliders whose swept footprint reaches each tile (indices into colliders).
struct InteractionPlan {
    explicit InteractionPlan(HostAllocator* host)
        : colliders(StlAllocator<GpuCollider>(host)), tile_offsets{Vector<uint32_t>(StlAllocator<uint32_t>(host)),
                                                                   Vector<uint32_t>(StlAllocator<uint32_t>(host))},
          tile_colliders{Vector<uint32_t>(StlAllocator<uint32_t>(host)),
                         Vector<uint32_t>(StlAllocator<uint32_t>(host))} {}
    uint32_t levels = 0; // 0: no pass this frame and no map bound; the core holds no map then
                         // (never made, or dropped by grass_set_interaction): a backend may
                         // release its textures. While the map exists every frame runs the pass.
    uint32_t resolution = 0;
    // The frame's pass is this plan's (view 0's, grass.h "Frames and views"): its colliders and
    // tile lists are here. A later view of the frame copies levels, resolution and level (it
    // reads the map) and has no pass.
    bool pass = false;
    bool map_is_new = false; // the backend makes (or remakes, at a new resolution) the map's textures
    InteractionLevelUniforms level[2]{};
    Vector<GpuCollider> colliders;
    Vector<uint32_t> tile_offsets[2];
    Vector<uint32_t> tile_colliders[2];
    void clear() {
        levels = 0;
        pass = false;
        map_is_new = false;
        colliders.clear();
        for (int l = 0; l < 2; ++l) {
            tile_offsets[l].clear();
            tile_colliders[l].clear();
        }
    }
};

// The blade window of a frame (plan/blade_window.hpp, api/shaders/blade_window.glsl):
// view 0's plan holds it; empty dispatches: no pass and no buffers (still grass).
// Per blade and slot, one record of six vec4 (kBladeWindowRecordBytes): the pose the draws
// read, (v1, shade) and (v2, 0); the pose of the previous frame, likewise (motion vectors);
// and the blade's state (dynamics/blade_state.hpp GpuBladeState, kBladeStateBytes).
constexpr uint64_t kBladeWindowPoseBytes = 32;   // two vec4: (v1, shade), (v2, 0)
constexpr uint64_t kBladeWindowRecordBytes = 96; // pose, previous pose, state
constexpr uint32_t kNoWindowEntry = 0xffffffffu;
constexpr uint32_t kWindowSlotEntered = 0x80000000u; // a work item's slot bit: the cell took the slot this frame
// One dispatch of the pass: a geometry draw of view 0 (index into its draws) and its work
// items first_item .. first_item + items - 1, one per instance the window holds.
struct BladeWindowDispatch {
    uint32_t draw;
    uint32_t first_item;
    uint32_t items;
};

// A field's table in the frame: its slot in the context, its side and first entry.
struct BladeWindowField {
    uint32_t field_slot;
    uint32_t side;
    uint32_t first_entry;
};

struct BladeWindowPlan {
    explicit BladeWindowPlan(HostAllocator* host)
        : table(StlAllocator<uint32_t>(host)), fields(StlAllocator<BladeWindowField>(host)),
          dispatches(StlAllocator<BladeWindowDispatch>(host)), work(StlAllocator<uint32_t>(host)) {}
    Vector<uint32_t> table; // four words an entry: cell x, cell z, slot, stride (kNoWindowEntry: empty)
    Vector<BladeWindowField> fields;
    Vector<BladeWindowDispatch> dispatches; // none: no pass, no buffers
    // Two words a work item: the slot (| kWindowSlotEntered where the cell took it this frame:
    // its blades start at the equilibrium pose), the instance (index into view 0's instances).
    Vector<uint32_t> work;
    uint32_t stride = 0;     // blades a slot holds: the most blades of the window's patches
    uint32_t slots = 0;      // slots 0 .. slots - 1 (a slot keeps its cell while the cell stays)
    uint64_t pose_bytes = 0; // the window's buffer: slots x stride x kBladeWindowRecordBytes
    void clear() {
        table.clear();
        fields.clear();
        dispatches.clear();
        work.clear();
        stride = 0;
        slots = 0;
        pose_bytes = 0;
    }
};

// std140 uniform block `GrassShadow` (host_shadows.glsl; GL binding 2): the host's shadow
// map of a receiving view (grass_shadow_receive_desc), only in such a view's upload.
struct ShadowUniforms {
    float world_to_shadow[4][16]; // per cascade: camera-relative world -> (u, v, stored depth), column-major
    float cascade_end[4];         // metres along the camera's view axis (unused cascades: 0)
    float axis[4];                // xyz: the camera's view axis (world, unit), w: cascade count
    float params[4];              // x: +1 lit where depth <= stored, -1 >=; y: depth bias; z: filter radius (texels)
};
static_assert(sizeof(ShadowUniforms) == 304, "std140 GrassShadow block");

// std140 uniform block `GrassMotion` (motion.glsl; GL binding 3): a view's motion vectors
// (grass_view_motion_desc), only in such a view's upload.
struct MotionUniforms {
    float view_projection[16]; // this view's camera-relative world -> clip, without its jitter
    // This view's camera-relative world -> the previous frame's clip, without its jitter:
    // previous projection x previous view rotation x translation by (camera - previous camera).
    float previous_view_projection[16];
    float previous_wind_phase[4]; // FrameUniforms::wind_phase at the previous time, at this camera
    // x: this frame's time minus the previous time (s): the interaction map's trails were that
    // much younger then (interaction.glsl); yzw: 0.
    float times[4];
};
static_assert(sizeof(MotionUniforms) == 160, "std140 GrassMotion block");

// std140 uniform block `GrassLights` (host_lights.glsl; GL binding 4): a view's host lights
// (grass_view_lights_desc), only in such a view's upload.
struct LightUniforms {
    float counts[4];        // x: lights, y: specular strength, z: specular exponent, w: 1 = ambient harmonics
    float ambient_sh[9][4]; // rgb per coefficient
    struct Light {
        float position_kind
            [4];       // xyz: camera-relative position, or the unit direction towards a directional light; w: kind
        float axis[4]; // xyz: a spot's unit axis (the way it shines)
        float color_range[4]; // rgb: colour x intensity; w: range (m)
        float cone[4];        // x: cos(inner angle), y: cos(outer angle)
    } light[8];
};
static_assert(sizeof(LightUniforms) == 672, "std140 GrassLights block");

// std140 uniform block `GrassGBuffer` (gbuffer.glsl; GL binding 5): how a G-buffer view
// encodes its normal, only in such a view's upload.
struct GBufferUniforms {
    float normal_encode[4]; // x: scale, y: bias (n * x + y: 0.5, 0.5 for UNORM; 1, 0 otherwise)
};
static_assert(sizeof(GBufferUniforms) == 16, "std140 GrassGBuffer block");

// The blades one patch of a mesh field draws this frame (plan/mesh_plan.hpp): the first
// `blade_count` of the patch's blades, its prefix (a prefix is spread over the whole patch).
struct MeshPatchDraw {
    uint32_t field_slot;
    uint32_t first_blade; // into the field's blades (MeshField)
    uint32_t blade_count;
};

struct FramePlan {
    explicit FramePlan(HostAllocator* host)
        : instances(StlAllocator<TierInstance>(host)), draws(StlAllocator<TierDraw>(host)),
          mesh_draws(StlAllocator<MeshPatchDraw>(host)), interaction(host), blade_window(host) {}
    FrameUniforms frame{};
    double origin[3] = {0, 0, 0}; // world position every position of the plan is relative to (the camera)
    bool stereo = false;          // a stereo frame: `eyes` follows `frame` in the Frame block (RenderTarget::views 2)
    StereoUniforms eyes{};        // stereo frames only
    int32_t viewport[4] = {0, 0, 0, 0};
    uint32_t flags = 0; // grass_view_flags: GRASS_VIEW_FLAG_DEBUG_CELLS draws every
                        // draw as debug boxes instead of its tier
    // A depth pass (grass_view_pass_desc, GRASS_PASS_DEPTH): every draw has kFeatureDepthPass;
    // the backend writes no colour and biases the depth by (constant, slope).
    bool depth_pass = false;
    float depth_bias[2] = {0.0f, 0.0f}; // constant, slope (glPolygonOffset's units, factor)
    // A view that receives the host's shadows (grass_shadow_receive_desc): every draw has
    // kFeatureShadowReceive; the backend binds `shadow_map` with `shadow` (compare in params.x).
    bool shadow_receive = false;
    uint64_t shadow_map = 0;    // GL: texture name
    uint32_t shadow_layout = 0; // Vulkan: VkImageLayout
    ShadowUniforms shadow{};
    // A view with motion vectors (grass_view_motion_desc): every draw has kFeatureMotion; the
    // backend binds `motion` and routes the velocity output to the host's draw buffer
    // `velocity_attachment`.
    bool motion = false;
    uint32_t velocity_attachment = 0;
    MotionUniforms motion_uniforms{};
    // A view lit by the host's lights (grass_view_lights_desc): every draw has
    // kFeatureHostLights; the backend binds `lights`.
    bool host_lights = false;
    LightUniforms lights{};
    // A G-buffer view (GRASS_PASS_GBUFFER): every draw has kFeatureGBuffer; the backend binds
    // `gbuffer_uniforms`, routes output location i (kGBufferOutput) to the host's attachment
    // gbuffer_attachment[i] (kNoGBufferOutput: none) with the colour mask gbuffer_mask[i]
    // (bit 1 r, 2 g, 4 b, 8 a), blends nothing and writes no other draw buffer.
    bool gbuffer = false;
    uint32_t gbuffer_attachment[kGBufferOutputs] = {kNoGBufferOutput, kNoGBufferOutput, kNoGBufferOutput,
                                                    kNoGBufferOutput};
    uint32_t gbuffer_mask[kGBufferOutputs] = {0, 0, 0, 0};
    GBufferUniforms gbuffer_uniforms{};
    Vector<TierInstance> instances;   // geometry instances of a draw are ordered front to back
    Vector<TierDraw> draws;           // per field, per tier that draws something
    Vector<MeshPatchDraw> mesh_draws; // mesh fields: per patch in view, field after field
    grass_frame_stats stats{};
    InteractionPlan interaction;  // responsive grass: the interaction pass (levels = 0: none)
    BladeWindowPlan blade_window; // responsive grass: the poses once per frame (view 0's plan)
    // The backend compacts the culled blades of this plan's window draws (kFeatureBladeWindow)
    // and draws the rest indirectly (Backend::compacts_blade_window).
    bool compact_blade_window = false;
    void clear() {
        instances.clear();
        draws.clear();
        mesh_draws.clear();
        interaction.clear();
        blade_window.clear();
        stats = grass_frame_stats{};
    }
};

} // namespace grass
