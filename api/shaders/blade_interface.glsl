// The data every grass shader sees: the uniform blocks of api/src/frame_plan.hpp (std140)
// and the design maps. Shared by the GL and Vulkan backends (Vulkan: descriptor set 0).

// Stereo (grass_stereo_view_desc): the multiview variant, GRASS_MULTIVIEW, compiled only for
// the pipelines of a Vulkan context made with a view mask. gl_ViewIndex picks the eye: its
// view-projection and its position relative to the plan's origin (the Frame block's eyes).
// Every vertex shader makes its instance's origin relative to the eye
// (GRASS_INSTANCE_ORIGIN), so what follows is eye-relative as in a mono frame; what must be
// the same for both eyes measures from the plan's origin again (wind_at, interaction_texel,
// blade_culled add GRASS_EYE back). Without it the preprocessed shaders are those of before.
#ifdef GRASS_MULTIVIEW
#ifndef VULKAN
#error "GRASS_MULTIVIEW is the Vulkan multiview variant; the GL backend has no GL_OVR_multiview path"
#endif
#extension GL_EXT_multiview : require
#endif

// Shader variants: GRASS_FEATURES says which design maps the field has (bit = 1 << MapRole,
// api/src/foundation/shader_interface.hpp), so a field samples only its own maps and one
// without maps runs the code it ran before maps existed. Vulkan: a specialization constant
// (id 0) set per pipeline; GL: the backend defines GRASS_FEATURES before this file. Either
// way the compiler folds the tests below away.
#define GRASS_MAP_DENSITY 1u
#define GRASS_MAP_COLOR 2u
#define GRASS_MAP_AMBIENT 4u
#define GRASS_MAP_DIFFUSE 8u
#define GRASS_MAP_HEIGHT 16u
#define GRASS_WIND 32u        // responsive grass: wind or gravity (wind.glsl)
#define GRASS_INTERACTION 64u // responsive grass: the interaction map is bound (interaction.glsl)
#define GRASS_WIND_MAP 128u   // responsive grass: the field's wind map is bound (wind.glsl; with GRASS_WIND)
#define GRASS_BLADE_CULLING 256u // per-blade culling, geometry draws (blade_culling.glsl)
#define GRASS_DEBUG_VIEW 512u    // the frame draws the tier tint or the threshold view (lighting.glsl)
#define GRASS_DEPTH_PASS 1024u   // a depth-only pass (shadow maps): no lighting, no colour (depth_pass())
#define GRASS_SHADOW_RECEIVE 2048u // the view receives the host's shadow map (host_shadows.glsl, GRASS_HOST_SHADOWS)
#define GRASS_MOTION 4096u         // the view writes motion vectors (motion.glsl, GRASS_VELOCITY)
// Responsive grass's code (and its bindings 10-13) is compiled only where GRASS_RESPONSIVE
// is defined (so is per-blade culling's, which reads the blades' control points too): the
// shaders of still grass are exactly what they were, and declare no binding
// they do not use (a Vulkan pipeline layout must hold every binding a module declares and
// uses, whatever its specialization constants say). GL: defined with GRASS_FEATURES for the
// masks with GRASS_WIND or GRASS_INTERACTION; Vulkan: a second SPIR-V module per shader,
// compiled with -DGRASS_RESPONSIVE, for those pipelines.
#ifdef VULKAN
layout(constant_id = 0) const uint GRASS_FEATURES = 0u;
#elif !defined(GRASS_FEATURES)
#error "the GL backend must define GRASS_FEATURES (the draw's map feature mask)"
#endif
bool has_map(uint role_bit) { return (GRASS_FEATURES & role_bit) != 0u; }
// The depth pass's variant: the fragment shaders keep their coverage test and depth, and
// return before any lighting or colour (a constant: the other variants hold none of it).
bool depth_pass() { return (GRASS_FEATURES & GRASS_DEPTH_PASS) != 0u; }

struct FrameData {
    mat4 view_projection;  // camera-relative world -> clip (the host's projection)
    vec4 sun_direction;    // xyz: unit vector towards the sun
    vec4 sun_color;        // rgb
    vec4 ambient_color;    // rgb
    vec4 params;           // x: time in seconds, y: view flags, z: +1 depth 0 near, -1 reversed depth,
                           // w: the target's samples per pixel (as the backend reports it: write_render_target)
    vec4 target;           // x: 1 when the host's clip z runs 0..1 (Vulkan, GL_ZERO_TO_ONE clip control),
                           // 0 for GL's default -1..1 (as the backend reports it); yzw: an orthographic
                           // view's axis (world, unit, the way it looks), zero for perspective (view_axis())
    vec4 lod_origin;       // xyz: the lod origin relative to the plan's origin (m) (lod_distance())
    vec4 projection_centre; // xyz: where a perspective view's rays start relative to its camera (m): zero
                            // but for an off-centre or warped projection (towards_viewer())
    // Responsive grass (api/src/foundation/frame_plan.hpp FrameUniforms): read only by variants with
    // GRASS_WIND / GRASS_INTERACTION.
    vec4 wind;             // xyz: mean wind velocity (world m/s), w: gust strength
    vec4 wind_shape;       // x: 1 / gust length, y: turbulence, z: source count, w: time step (s)
    vec4 wind_phase;       // xyz: phases (cycles) of the three gust waves at the camera
    vec4 gravity;          // xyz: gravity minus standard gravity (world m/s^2)
    vec4 map_up;           // xyz: the interaction map's up, w: level count (0: no map)
    vec4 map_axis_u;       // xyz: world direction of map texel x
    vec4 map_axis_v;       // xyz: world direction of map texel y, w: camera height above the map's anchor (m)
    vec4 map_levels[2];    // xy: camera's map coordinate (texels, mod N), z: texels per metre, w: N
    vec4 wind_sources[64]; // 16 sources x 4 vec4 (frame_plan.hpp)
    vec4 map_offset;       // xyz: this view's camera relative to the interaction map's (frame_plan.hpp)
#ifdef GRASS_MULTIVIEW
    mat4 eye_view_projection[2]; // per eye: eye-relative world -> clip (StereoUniforms)
    vec4 eye_position[2];        // per eye: xyz relative to the plan's origin (m)
#endif
};

struct FieldData {
    mat4 patch_to_world;   // patch units -> world metres; rotation x cell size, no translation
    vec4 map_u;            // cell space -> map u: dot(map_u.xyz, vec3(x, z, 1)) (lemme's configTf)
    vec4 map_v;            // ... and map v
    vec4 map_params;       // x: density (uniform, or the maps' multiplier), y: height scale in patch units,
                           // z: cells_x, w: cells_z of the field
    vec4 blade_params;     // x: ao impact (B_impact), y: ao height (B_height, patch units), z: tier kind,
                           // w: height of the baked slices (patch units)
    uvec4 tiling;          // x: mirror seed, y: 1 = mirrored tiling on, z: slices per axis of this tier,
                           // w: feature mask (the same as GRASS_FEATURES)
    vec4 bands[8];         // the field's tiers: begin, end, transition in, transition out (metres)
    uvec4 tiers;           // x: this draw's tier, y: the field's tier count, z: 1 = overlay tier (hilltops:
                           // draws every blade the density passes, takes no share of the transitions),
                           // w: the geometry tiers' bits (texel_transition; a blade draw's pass: its
                           // first work item, blade_window.comp)
    vec4 transition;       // x: crossover window (threshold units; 0 = exact)
    vec4 mechanics;        // x: stiffness (m/s^2), y: mass, z: wind response, w: per-blade variation
    vec4 trample;          // x: trample depth, y: recovery time (s), z: 1 = the field reads the interaction map
    vec4 field_up;         // xyz: the field's up (world), w: metres per patch unit
    vec4 wind_map_u;       // xyz: cell space -> wind map u (as map_u), w: m/s for an encoded 1
    vec4 wind_map_v;       // xyz: ... and wind map v
    vec4 culling;          // per-blade culling (blade_culling.glsl): x: orientation limit (2: off),
                           // y: frustum tolerance (< 0: off), z: distance max (m; 0: off), w: levels (0: by threshold)
    vec4 alpha_test_scale[4]; // the horizontal slice's alpha-test scale per mip level, 4 a row (sample_coverage.glsl)
};

// The Frame and Field blocks (uniform buffers, std140), read as `frame` and `field`. Each
// holds its struct as the one element of an array, indexed by the literal 0, or (Vulkan,
// GRASS_INDEXED_BLOCKS) by a push constant that the backend sets to 0. The index
// is for lavapipe (Mesa's Vulkan on llvmpipe; seen in 22.3): it recompiles a shader on every
// draw whose branches read uniform-buffer values at constant offsets, and it loads a storage
// buffer lane by lane; an offset from a push constant is neither (backend_vk/src/vk_spirv.hpp).
layout(std140, binding = 0) uniform Frame { FrameData frame_at[1]; };
layout(std140, binding = 1) uniform Field { FieldData field_at[1]; };
// lavapipe gathers a read at the pushed index lane by lane, each time the code reads it, and
// runs both sides of a branch on what it read: there every shader's main() first copies both
// blocks (load_blocks()), once per invocation.
#ifdef GRASS_INDEXED_BLOCKS
layout(push_constant) uniform BlockIndex { uint block_index; } grass_push;
FrameData g_frame;
FieldData g_field;
#define frame g_frame
#define field g_field
#define load_blocks() g_frame = frame_at[grass_push.block_index], g_field = field_at[grass_push.block_index]
#else
#define frame frame_at[0]
#define field field_at[0]
#define load_blocks()
#endif

// The view-projection of the view drawn (the eye's in the multiview variant), the eye's
// position relative to the plan's origin, and an instance origin made relative to the eye.
#ifdef GRASS_MULTIVIEW
#define GRASS_VIEW_PROJECTION frame.eye_view_projection[gl_ViewIndex]
#define GRASS_EYE frame.eye_position[gl_ViewIndex].xyz
#define GRASS_INSTANCE_ORIGIN(o) ((o) - GRASS_EYE)
#else
#define GRASS_VIEW_PROJECTION frame.view_projection
#define GRASS_INSTANCE_ORIGIN(o) o
#endif

// Orthographic views (a shadow cascade, a top-down map; a warp of one whose rays stay parallel,
// as a light-space perspective shadow map's): the view axis, the world direction the view
// looks along, which every ray of the view is parallel to; zero for a perspective
// view (and the eyes of a stereo frame). The same for every invocation of a draw: code that
// branches on it runs one side, and a perspective view computes what it did before.
vec3 view_axis() {
    return frame.target.yzw;
}
bool orthographic_view() {
    return frame.target.y != 0.0 || frame.target.z != 0.0 || frame.target.w != 0.0;
}
// A perspective view's centre of projection relative to the view's eye (every position in
// the shaders is): the point its rays start from, the eye itself unless the host's projection
// is off-centre or warped (a spot light's frustum placed off camera_position, a light-space
// perspective shadow map's); the planner takes it from the matrix (ViewCulling).
vec3 projection_centre() {
    return frame.projection_centre.xyz;
}
// The direction from a point towards the viewer, not unit: the centre of projection's in a
// perspective view, against the axis in an orthographic one (whose eye point is only where
// its box was put).
vec3 towards_viewer(vec3 p) {
    return orthographic_view() ? -view_axis() : projection_centre() - p;
}
// The distance the tiers and their transitions are chosen by, of a point relative to the
// view's eye: from the lod origin (the camera unless grass_lod_origin_desc moves it; a
// stereo frame's eyes' midpoint, which is the plan's origin there), as the planner measures
// it (api/src/plan/frame_planner.cpp). Metres.
#ifdef GRASS_MULTIVIEW
#define GRASS_LOD_ORIGIN (frame.lod_origin.xyz - GRASS_EYE)
#else
#define GRASS_LOD_ORIGIN frame.lod_origin.xyz
#endif
float lod_distance(vec3 p) {
    return length(p - GRASS_LOD_ORIGIN);
}

// Design maps (lemme 6.4), 16-bit unorm, bilinear, clamped; sample only those in GRASS_FEATURES.
layout(binding = 2) uniform sampler2D density_map;  // r: density multiplier
layout(binding = 6) uniform sampler2D color_map;    // rgb: linear colour, a: its weight (eq. 6.8)
layout(binding = 7) uniform sampler2D ambient_map;  // r: ambient light incl. scene AO (eq. 6.9-6.10)
layout(binding = 8) uniform sampler2D diffuse_map;  // r: diffuse light (shadows of the scenery)
layout(binding = 9) uniform sampler2D height_map;   // r: terrain height / height scale
// The tier's baked slices (api/src/baked_slices.hpp): vertical slices of a volume tier, or
// the horizontal slice (one layer) of the image tier.
layout(binding = 3) uniform sampler2DArray slice_color;     // sRGB albedo + coverage
layout(binding = 4) uniform sampler2DArray slice_normal;    // xyz: normal * 0.5 + 0.5, w: height / slice height
layout(binding = 5) uniform sampler2DArray slice_threshold; // r: density threshold (0 = no blade)

// The design-map uv of a point of the field given in cells.
vec2 map_uv(vec2 cell_point) {
    vec3 p = vec3(cell_point, 1.0);
    return vec2(dot(field.map_u.xyz, p), dot(field.map_v.xyz, p));
}

// The local density at a point of the field given in cells (bilinear density map).
float local_density(vec2 cell_point) {
    float density = field.map_params.x;
    if (has_map(GRASS_MAP_DENSITY)) density *= textureLod(density_map, map_uv(cell_point), 0.0).r;
    return density;
}

// The terrain height at a point of the field given in cells, in patch units above the
// field's plane (lemme eq. 6.13, 6.16); 0 without a height map.
float terrain_height(vec2 cell_point) {
    if (!has_map(GRASS_MAP_HEIGHT)) return 0.0;
    return field.map_params.y * textureLod(height_map, map_uv(cell_point), 0.0).r;
}

// Colour modulation (lemme eq. 6.8): C = A_c C_c + (1 - A_c) C_blade, in linear RGB.
vec3 modulate_color(vec3 blade_color, vec2 cell_point) {
    if (!has_map(GRASS_MAP_COLOR)) return blade_color;
    vec4 c = textureLod(color_map, map_uv(cell_point), 0.0);
    return mix(blade_color, c.rgb, c.a);
}

// The light maps at a point: x scales the ambient light (scene AO included), y the sun.
vec2 light_maps(vec2 cell_point) {
    vec2 l = vec2(1.0);
    if (has_map(GRASS_MAP_AMBIENT)) l.x = textureLod(ambient_map, map_uv(cell_point), 0.0).r;
    if (has_map(GRASS_MAP_DIFFUSE)) l.y = textureLod(diffuse_map, map_uv(cell_point), 0.0).r;
    return l;
}

// GRASS_VIEW_FLAG_ENCODE_SRGB (16 in frame.params.y): the host's target stores what the
// shader writes (UNORM, or GL_FRAMEBUFFER_SRGB off), so the shader encodes to sRGB itself.
bool encode_srgb() {
    return (uint(frame.params.y + 0.5) & 16u) != 0u;
}
// The colour a tier writes: linear RGB, sRGB-encoded when the host asks for it. Alpha is
// coverage and stays linear. Before a multisample resolve, as a UNORM target stores it.
vec4 output_color(vec4 linear) {
    if (!encode_srgb()) return linear;
    vec3 c = clamp(linear.rgb, 0.0, 1.0);
    vec3 encoded = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
    return vec4(encoded, linear.a);
}

// The target's samples per pixel (1 without multisampling; set by the backend).
int sample_count() {
    return max(int(frame.params.w + 0.5), 1);
}


// The window depth of a camera-relative world position, for gl_FragDepth: clip z / w
// mapped as the host's clip convention maps it (frame.target.x: 0..1 or -1..1), then into
// the depth range (GL: the host's glDepthRange; Vulkan: the viewport's 0..1, vk_record).
// Reversed depth needs nothing here: it is in the host's projection.
float window_depth(vec3 position) {
    vec4 clip = GRASS_VIEW_PROJECTION * vec4(position, 1.0);
    float z = clip.z / clip.w;
    if (frame.target.x < 0.5) z = 0.5 * z + 0.5;
#ifdef VULKAN
    return z;
#else
    return gl_DepthRange.near + gl_DepthRange.diff * z;
#endif
}
