#version 450
// Volume tier (lemme2012 5.2, eq. 5.3-5.21): the view ray is cast through the grid of
// implicit vertical slices of the (macro-)cell, each cell's slices mirrored as the cell is
// (eq. 6.6), composited front to back until opaque; the fragment takes the depth of the hit.
// On a height map (lemme 6.4.4, eq. 6.14-6.18) the carrier spans the terrain's height range
// and every hit looks its slice up at its height above the terrain under it.
#include "blade_interface.glsl"
#ifdef GRASS_HOST_LIGHTS // the host's lights' variants only
#include "host_lights.glsl"
#endif
#include "lighting.glsl"
#ifdef GRASS_HOST_SHADOWS
#include "host_shadows.glsl"
#endif
#include "tier_transitions.glsl"
#include "sample_coverage.glsl"
#ifdef GRASS_VELOCITY // motion vectors' variants only
#define GRASS_MOTION_FRAGMENT
#include "motion.glsl"
#endif
#ifdef GRASS_RESPONSIVE // responsive grass variants only (blade_interface.glsl)
#include "wind.glsl"
#include "interaction.glsl"
#include "shell_bend.glsl"
#endif

layout(location = 0) in vec3 v_local;
layout(location = 1) flat in vec3 v_camera_local;
layout(location = 2) flat in vec3 v_face_normal;
layout(location = 3) flat in uvec4 v_cell;
layout(location = 4) flat in vec2 v_terrain; // lowest, highest terrain under the instance (patch units)
layout(location = 5) flat in float v_field_edge; // 1: a field-edge instance (tier_interval)

#ifdef GRASS_DEPTH_TARGET
vec4 out_color; // Vulkan's depth-only target (a depth pass): no colour attachment, no output
#else
layout(location = 0) out vec4 out_color;
#endif
#ifdef GRASS_GBUFFER // G-buffer views' variants only
#include "gbuffer.glsl"
// The surface the ray composites, front to back as g_color: albedo, world normal (summed,
// normalised at the end), ambient occlusion.
vec3 g_albedo = vec3(0.0);
vec3 g_normal = vec3(0.0);
float g_ao = 0.0;
#endif

const float kHuge = 1e30;

// The ray and what it has gathered, shared by main() and composite().
vec3 g_dir;
vec2 g_abs_dir;    // |dir.x|, |dir.z|: the weights of the two slice families
vec3 g_sun;        // the direction towards the sun in patch space
vec3 g_size;
mat3 g_to_world;
vec3 g_origin;     // the instance corner relative to the camera
vec2 g_field_cells;
float g_n;         // slices per axis
float g_pixel_angle;
float g_pixel_size;   // orthographic views: a pixel's footprint across the rays (cells), the same at every t
vec3 g_eye;           // where the ray starts, cuboid cells (main())
float g_descent_lod = 0.0; // the level of the height the ray descends between two crossings (composite())
float g_taps = 1.0;     // taps down a slab's share (main(): steep rays through sparse slices)
float g_tap_span = 0.0; // the share's height span, in slice heights
vec2 g_texels;
vec3 g_color = vec3(0.0);
float g_alpha = 0.0;
// The fragment's depth: where the ray gathered half of its alpha, or 1/2 of it when it ends
// more opaque than that. A partial ray (a tier's share in a transition zone, thin grass)
// takes the depth of its own blades: where its coverage of the two tiers' samples overlaps
// (sample_coverage.glsl), the nearer blades win, not whichever carrier's back face is nearer.
vec3 g_depth_at[5];            // the first hit, then where g_alpha first reached 1/16, 1/8, 1/4, 1/2
int g_depth_reached = 0;       // how many of them are set
vec2 g_plane_depth = vec2(0.0); // x: the window depth of the field's plane on the ray, y: its spread
                                // over the pixel (0: a height map, or no plane below the ray)
float g_depth_threshold = 0.0; // the threshold of the blade where the ray turns opaque
#ifdef GRASS_VELOCITY
// Motion vectors: how far the grass at the hit being composited was moved by the bend since
// the previous frame's time (world metres, this frame minus that), and its value at each of
// g_depth_at: the written depth's point moves by it.
vec3 g_shift = vec3(0.0);
vec3 g_shift_at[5];
#endif

// The opacity of a slice texel of coverage `alpha` drawn by this draw's tier: alpha
// times what the density keeps of it (full = curve(density)), and in a transition zone the
// tier's share f = tier_texel_share / full of that as transmittance, 1 - (1 - alpha full)^f.
// The tiers' rays together let through what the whole grass would, and a texel the whole
// grass makes opaque stays opaque in each: drawn as alpha x share, a thinned ray saw past
// the tips to darker grass (a darker line where the volume hands over to the image tier).
// Between two texel tiers (g_parts, texel_transition) the ray gathers the grass whole and the
// tier takes its part of the samples (main()).
bool g_parts = false;
float tier_texel_alpha(float d, vec4 t, float density, bool field_edge, float alpha) {
    if (!(density > 0.0) || t.r <= 0.0) return 0.0;
    float full = coverage_curve(t, density);
    if (field.tiers.z != 0u || g_parts) return alpha * full;
    vec2 interval = tier_interval(d, field_edge);
    if (interval.x > interval.y) return 0.0;
    if (interval.x <= 0.0 && interval.y >= 1.0) return alpha * full; // the whole tier: no share
    float below = interval.x > 0.0 ? coverage_curve(t, interval.x * density) : 0.0;
    float share = max(coverage_curve(t, interval.y * density) - below, 0.0);
    // (pow(0, 0) is undefined: a tier that draws none of an opaque texel must not reach it.)
    if (!(share > 0.0)) return 0.0;
    if (!(full > 0.0) || share >= full) return alpha * share;
    return 1.0 - pow(max(1.0 - alpha * full, 0.0), share / full);
}

// Gathers the opacity `a` of the hit at `hit` into the ray's alpha and notes the depths
// where it reaches each level (g_depth_at).
void gather(float a, vec3 hit, float threshold) {
    g_alpha += (1.0 - g_alpha) * a;
    while (g_depth_reached < 5 && g_alpha >= (g_depth_reached == 0 ? 0.0 : 0.03125 * float(1 << g_depth_reached))) {
        g_depth_at[g_depth_reached] = hit;
#ifdef GRASS_VELOCITY
        g_shift_at[g_depth_reached] = g_shift;
#endif
        if (g_depth_reached == 4) g_depth_threshold = threshold;
        ++g_depth_reached;
    }
}

// Composites the hit of the ray at `hit` (cuboid cells, distance t) with a slice: across x
// (kind 0), across z (kind 1), or the horizontal slice near the ground (kind 2, the set's
// last layer). Front to back (eq. 5.19-5.20). `h` is the hit in the slices' frame: its y is
// the height above the terrain under it (eq. 6.18; the hit itself without a height map).
// `slab`: the share of the slice's slab (the 1/n around it that its texels stand for) that
// the ray crosses above the ground; 1 but at the last crossings.
void composite(vec3 h, vec3 hit, float t, int kind, float slab) {
    // Responsive grass (shell_bend.glsl): the bent grass seen at h is the rest grass of the
    // column whose root lies back along the bend, at its rest height; it darkens where
    // pressed. Bent grass only gets lower, so the carrier still contains it; where it leans
    // out of its cell it is drawn by the rays that cross the neighbouring cells (they reach
    // 4 cells past their carrier), and it is cut off at the field's edge (accepted).
    float shade = 1.0;
    float turn = 0.0;   // the bent tangent's angle at this height (grass_lighting_lobes_bent)
    vec3 bend_dir = vec3(0.0);
#ifdef GRASS_RESPONSIVE
    if (has_map(GRASS_WIND | GRASS_INTERACTION)) {
        vec3 up = normalize(field.field_up.xyz);
        float ground_y = has_map(GRASS_MAP_HEIGHT) ? hit.y - h.y : 0.0;
        ShellBend bend = shell_bend(g_to_world * vec3(h.x, ground_y, h.z) + g_origin, up, g_size.y * field.field_up.w,
                                    vec2(v_cell.xy) + h.xz);
        float rest_y, back;
        if (!shell_unbend(bend.angle, h.y, g_size.y, rest_y, back)) return;
        vec3 d = transpose(g_to_world) * bend.dir / max(field.field_up.w, 1e-30); // unit, patch frame
#ifdef GRASS_VELOCITY
        // The same grass (its column's root, its rest height) bent as at the previous time.
        g_previous_time = true;
        ShellBend before = shell_bend(g_to_world * vec3(h.x, ground_y, h.z) + g_origin, up,
                                      g_size.y * field.field_up.w, vec2(v_cell.xy) + h.xz);
        g_previous_time = false;
        vec3 d_before = transpose(g_to_world) * before.dir / max(field.field_up.w, 1e-30);
        float a_u = before.angle * rest_y / g_size.y;
        vec2 xy = before.angle < 1e-4 ? vec2(0.0, rest_y)
                                      : g_size.y * vec2(1.0 - cos(a_u), sin(a_u)) / before.angle;
        vec3 then = vec3(h.x - d.x * back + d_before.x * xy.x, xy.y, h.z - d.z * back + d_before.z * xy.x);
        g_shift = g_to_world * (h - then);
#endif
        h = vec3(h.x - d.x * back, rest_y, h.z - d.z * back);
        shade = bend.shade;
        turn = bend.angle * rest_y / g_size.y;
        bend_dir = vec3(d.x, 0.0, d.z);
    }
#endif
    vec2 cell = floor(h.xz);
    vec2 global = vec2(v_cell.xy) + cell;
    if (any(lessThan(global, vec2(0.0))) || any(greaterThanEqual(global, g_field_cells - 0.5))) return;
    vec2 s = mirror_signs(uvec2(global));
    vec2 f = h.xz - cell;
    vec2 m = vec2(s.x < 0.0 ? 1.0 - f.x : f.x, s.y < 0.0 ? 1.0 - f.y : f.y); // eq. 6.6
    // The slice (layer) and the point on it, in the mirrored patch.
    vec3 coord;
    if (kind == 0) coord = vec3(m.y, h.y / g_size.y, clamp(floor(m.x * g_n), 0.0, g_n - 1.0));
    else if (kind == 1) coord = vec3(m.x, h.y / g_size.y, g_n + clamp(floor(m.y * g_n), 0.0, g_n - 1.0));
    else coord = vec3(m.x, m.y, 2.0 * g_n);
    // Texels are 3-4x denser across a slice than up it (256 x 64 over 1 x ~0.85 cells);
    // the level follows the coarser, vertical density so blades keep their height.
    float footprint = orthographic_view() ? g_pixel_size : t * g_pixel_angle; // cells; t: distance in cells
    float lod = log2(max(footprint * g_texels.y / g_size.y, 1.0));
    // What the ray sees (colour, coverage, normal), though, need be no coarser up a vertical
    // slice than the height the ray descends from one crossing to the next (g_descent_lod,
    // main()): the crossings composited in turn gather the heights the ray passes. At the
    // footprint's level a texel averages its column down to the dense roots, which a grazing
    // ray never reaches under the tips in front of them: the far field came out 7-10 sRGB
    // levels darker than the blades (docs/records/three-tiers.md). At most 2 levels finer
    // than the footprint, so that the slices do not alias across (their texels are denser
    // across than up). The thresholds and coverage curves stay at the footprint's level: the
    // curves (tier_transitions.glsl) model a texel of many blades, and a fine one holds few.
    float color_lod = kind == 2 ? lod : max(min(lod, g_descent_lod), lod - 2.0);
    vec4 thresholds = textureLod(slice_threshold, coord, lod); // r: threshold, gba: coverage curve
    float threshold = thresholds.r;
    vec4 albedo;
    if (kind == 2 || g_taps <= 1.0) {
        albedo = textureLod(slice_color, coord, color_lod);
        if (kind == 2) albedo.a = horizontal_slice_alpha(albedo.a, color_lod);
    } else {
        // The share's colour and coverage: taps from its top down, each for 1/taps of it,
        // looked up no coarser than the height it stands for. The slices a grazing ray runs
        // nearly along are crossed once in a long slab and take taps; at the footprint's level
        // each tap averaged the column down to the dark roots the ray never reaches (the real
        // football's far rows, docs/records/three-tiers.md). At most 1 level finer than the
        // footprint: 2 thinned thin grass seen from above (TierDensityTest).
        vec3 c = vec3(0.0);
        float tr = 1.0;
        float tap_lod = max(min(lod, log2(max(g_tap_span / g_taps * g_texels.y, 1.0))), lod - 1.0);
        for (float q = 0.5; q < g_taps; q += 1.0) {
            vec3 at = vec3(coord.x, coord.y + (0.5 - q / g_taps) * g_tap_span, coord.z);
            vec4 tap = textureLod(slice_color, at, tap_lod);
            float a_q = 1.0 - pow(max(1.0 - tap.a, 0.0), 1.0 / g_taps);
            c += tr * a_q * tap.rgb;
            tr *= 1.0 - a_q;
        }
        albedo = vec4(tr < 1.0 ? c / (1.0 - tr) : vec3(0.0), 1.0 - tr); // no taps covered: alpha 0, returns below
        if (threshold <= 0.0) threshold = thresholds.r = 1.0 / 65535.0;
    }
    if (threshold <= 0.0) return;
    if (albedo.a <= 0.0) return;

    vec3 world = g_to_world * hit + g_origin;
    vec2 cell_point = vec2(v_cell.xy) + h.xz;
    float density = local_density(cell_point);
    // The threshold view partitions whole texels by their threshold (each is one tier's);
    // the picture draws the share of each texel's blades the density and the tier select.
    bool field_edge = v_field_edge > 0.5;
    float a = debug_thresholds() ? albedo.a * tier_blade_opacity(lod_distance(world), threshold, density, field_edge)
                                 : tier_texel_alpha(lod_distance(world), thresholds, density, field_edge, albedo.a);
    if (a <= 0.0) return;
    // Every blade is baked into one slice of each family (across x and across z), so a ray
    // that crosses both would meet it twice and cover about 1 - (1 - c)^2 where the blades
    // cover c. Each family alone represents all the blades along the ray; their
    // transmittances are weighted by the share of the family's crossings, (1 - a)^w_x and
    // (1 - a)^w_z with w_x + w_z = 1, so the ray meets every blade once in expectation. A
    // ray parallel to one family crosses only the other, which gets the full weight.
    // The horizontal slice holds the same blades seen from above: a steep ray that crosses
    // few vertical slices needs it, a grazing one has met the blades in them already. It
    // adds only the optical depth beyond what the ray has gathered (transmittance
    // min(1, T_h / T_gathered)): a tilted blade seen from above and from the side counts
    // once, by the larger of its two projections.
    if (kind == 2) {
        a = 1.0 - min(1.0, (1.0 - a) / max(1.0 - g_alpha, 1e-4));
    } else {
        float w = slab * (kind == 0 ? g_abs_dir.x : g_abs_dir.y) / (g_abs_dir.x + g_abs_dir.y);
        a = a >= 1.0 ? 1.0 : 1.0 - pow(1.0 - a, w);
    }
    if (a <= 0.0) return;
    if (depth_pass()) { // the depth pass gathers coverage alone
        gather(a, hit, threshold);
        return;
    }
    // The design maps at the hit (lemme 6.4.2-6.4.3).
    vec3 color = modulate_color(albedo.rgb, cell_point) * shade;
    vec2 light = light_maps(cell_point);
#ifdef GRASS_HOST_SHADOWS
    light.y *= host_sun_visibility(world); // the host's shadow at each point the ray composites
#endif
    vec4 normal_height = textureLod(slice_normal, coord, color_lod);
    vec3 nrm = normal_height.xyz * 2.0 - 1.0;
    nrm.xz *= s;
    // The horizontal slice's heights are its blades' tips; a vertical slice's hit is at h.y.
    float ao = blade_ambient_occlusion(density, kind == 2 ? normal_height.w * g_size.y : h.y, field.blade_params.x,
                                       field.blade_params.y);
    vec3 folded = kind == 0 ? vec3(0.0, 1.0, 1.0) : kind == 1 ? vec3(1.0, 1.0, 0.0) : vec3(1.0, 0.0, 1.0);
#ifdef GRASS_GBUFFER // the surface instead of its light
    float weight = (1.0 - g_alpha) * a;
    g_albedo += weight * color;
    g_normal += weight * normalize(g_to_world * gbuffer_slice_normal(nrm, folded, -g_dir));
    g_ao += weight * ao * light.x;
#else
    vec3 lit = grass_lighting_lobes_bent(color, nrm, folded, -g_dir, g_sun, ao, light, bend_dir, turn);
#ifdef GRASS_HOST_LIGHTS
    lit += host_lights_lobes(color, nrm, folded, -g_dir, world, bend_dir, turn, light.y);
#endif
    g_color += (1.0 - g_alpha) * a * lit;
#endif
    gather(a, hit, threshold);
}

// The depth pass (depth_pass()) of a single-sampled target stops where the ray has gathered
// half its alpha: its coverage test passes from there on and its depth is fixed (main()), so
// what lies behind changes nothing it writes. Multisampled, it marches on: its sample mask
// is the colour pass's.
bool depth_pass_done() { return depth_pass() && sample_count() <= 1 && g_alpha >= 0.5; }

// The horizontal slice near the ground of a flat field, met at t (kind 2 above).
void composite_flat_ground(float t) {
    vec3 g = g_eye + g_dir * t;
    composite(g, g, t, 2, 1.0);
}

// The host's ground under a flat field. The ray's depth may lie at the horizontal slice, a
// few centimetres above the field's plane, or on the plane itself (a view from above through
// sparse vertical slices crosses them down to it), where the host drew its ground. With one
// sample the ground tied with the grass at the pixel's centre, and the depth buffer's
// rounding picked the winner (from 60 m up GL and Vulkan 9 levels apart); with several, the
// ground has a depth per sample and the volume one per fragment, and the samples whose ground
// lies nearer than the centre won (rows of ground through the grass, 3-28 levels darker than
// one sample from 20 and 60 m up: MultisampleGroundTest). Half the plane's depth step to the
// neighbouring pixels bounds how much nearer than at the centre it lies at a sample; the
// written depth stays in front of that (in_front_of_plane). Derivatives: main() calls this
// before the march, where they are defined; `on` keeps its lanes uniform.
vec2 plane_depth(vec3 eye, vec3 dir, float plane_y, bool on) {
    float t = dir.y < 0.0 ? (plane_y - eye.y) / dir.y : -1.0;
    vec3 p = mat3(field.patch_to_world) * (eye + dir * max(t, 0.0) - v_camera_local);
    float depth = window_depth(p);
    float spread = 0.5 * (abs(dFdx(depth)) + abs(dFdy(depth)));
    return on && t > 0.0 ? vec2(depth, spread) : vec2(0.0);
}
float in_front_of_plane(float depth) {
    if (g_plane_depth.y <= 0.0) return depth;
    float nearest = g_plane_depth.x - frame.params.z * g_plane_depth.y; // params.z: -1 reversed depth
    return frame.params.z > 0.0 ? min(depth, nearest) : max(depth, nearest);
}

void main() {
    load_blocks();
    note_pixel(mat3(field.patch_to_world) * (v_local - v_camera_local)); // the dither's pixel
    vec3 size = vec3(float(v_cell.z), field.blade_params.w, float(v_cell.w));
    // The carrier: the slices' height over a flat field; on a height map from the lowest
    // terrain under the instance to the slices' height above the highest (eq. 6.14).
    bool displaced = has_map(GRASS_MAP_HEIGHT);
    vec3 box_min = vec3(0.0), box_max = size;
    if (displaced) {
        box_min.y = v_terrain.x;
        box_max.y = v_terrain.y + size.y;
    }
    // The ray through the fragment, in the cuboid's frame. Perspective: from the centre of
    // projection, the camera unless the host's projection is off-centre or warped (the same
    // for every invocation of a draw: an ordinary view skips the inverse).
    // Orthographic (a shadow cascade, a top-down map): every ray is parallel to the view axis;
    // this one is the line through the fragment along it, started outside the cuboid (a cell
    // before the sphere around it), and t counts from there. Only the fragment's position
    // across the axis counts: a face seen almost edge-on (exactly edge-on is a front face) is
    // shaded at positions extrapolated along it, which may lie far from the cuboid.
    // What depends on the distance to the viewer does not use t: the lod distances measure
    // the hit from the lod origin, the mip levels take the pixel's footprint (below), the
    // depth the hit's position.
    vec3 eye = v_camera_local;
    if (projection_centre() != vec3(0.0)) eye += inverse(mat3(field.patch_to_world)) * projection_centre();
    vec3 ray;
    if (orthographic_view()) {
        vec3 axis = world_to_patch_direction(view_axis());
        float reach = 0.5 * length(box_max - box_min) + 1.0;
        float along = dot(v_local - 0.5 * (box_min + box_max), axis);
        eye = v_local - axis * (along + reach);
        ray = axis * (clamp(along, 1.0 - reach, reach - 1.0) + reach); // to the fragment, within the sphere
    } else {
        ray = v_local - eye;
    }
    // The back face ends the ray; a front face leaves the work to the back face behind it.
    // (Decided geometrically: no dependence on the host's winding or clip conventions.)
    // A discarded front face also gets an empty march and no ground hit below: on lavapipe
    // its lanes go on through the code after `discard` (masked), and marched every ray a
    // second time (docs/records/tier-cost.md).
    bool front = dot(v_face_normal, ray) <= 0.0;
    if (front) discard;
    float t_out = length(ray);
    vec3 dir = ray / t_out;

    // Where the ray enters the cuboid (slab test), or the camera if it is inside.
    vec3 inv = vec3(dir.x != 0.0 ? 1.0 / dir.x : kHuge, dir.y != 0.0 ? 1.0 / dir.y : kHuge,
                    dir.z != 0.0 ? 1.0 / dir.z : kHuge);
    vec3 t0 = (box_min - eye) * inv, t1 = (box_max - eye) * inv;
    vec3 t_near = min(t0, t1);
    float t_in = max(max(max(t_near.x, t_near.y), t_near.z), 0.0);
    // Orthographic: from where the ray enters the blade layer (the carrier's height range),
    // at most the cuboid's diameter and 4 cells before the fragment, as it goes on up to 4
    // cells past it (below). A fragment is shaded at the pixel's centre, which for a pixel
    // that the face covers only in part (multisampling) may lie off the face, beside the
    // carrier: a ray parallel to its sides from there misses it, and left those samples empty
    // (a line of the clear colour along the carriers' edges, seen from straight above). Both
    // carriers of such a pixel now composite the same ray, whole, as the nearest carrier of
    // a ray does.
    if (orthographic_view()) {
        float before = 2.0 * length(box_max - box_min) + 4.0 / max(length(dir.xz), 1e-3);
        t_in = max(max(t_near.y, t_out - before), 0.0);
    }

    // Mip level per hit from the pixel's angular size times the hit's distance: the slices
    // are seen at every angle, so the carrier's own footprint (stretched at grazing angles)
    // would blur them. Derivatives outside the loop: they need uniform control flow.
    float n = float(field.tiling.z);
    vec2 texels = vec2(textureSize(slice_color, 0).xy);
    float pixel_angle = max(length(dFdx(dir)), length(dFdy(dir)));  // radians per pixel
    // Orthographic: the rays do not spread; a pixel's footprint is the fragment's step to its
    // neighbours across the rays, the same at every distance (cells).
    vec3 step_dx = dFdx(v_local), step_dy = dFdy(v_local);
    float pixel_size = max(length(step_dx - dir * dot(step_dx, dir)), length(step_dy - dir * dot(step_dy, dir)));
    g_plane_depth = plane_depth(eye, dir, box_min.y, !displaced);

    // The slices across x sit at x = (j + 0.5) / n for every integer j (each cell repeats
    // its n slices), likewise across z. Walk both families in order (a 2D DDA).
    float step_x = dir.x != 0.0 ? 1.0 / (n * abs(dir.x)) : kHuge;
    float step_z = dir.z != 0.0 ? 1.0 / (n * abs(dir.z)) : kHuge;
    // A downward ray over a flat field that enters through the carrier's top: each family
    // starts half its slab before the entry, so that a crossing just above the blades, whose
    // slab reaches into them, counts in part (below).
    float t_top = !displaced && dir.y < 0.0 ? (box_max.y - eye.y) / dir.y : -kHuge;
    bool from_top = t_in > 0.0 && t_in <= t_top * (1.0 + 1e-5);
    vec3 start_x = eye + dir * (from_top ? max(t_in - 0.5 * step_x, 0.0) : t_in);
    vec3 start_z = eye + dir * (from_top ? max(t_in - 0.5 * step_z, 0.0) : t_in);
    vec3 start = eye + dir * t_in;
    float jx = dir.x > 0.0 ? floor(start_x.x * n - 0.5) + 1.0 : ceil(start_x.x * n - 0.5) - 1.0;
    float jz = dir.z > 0.0 ? floor(start_z.z * n - 0.5) + 1.0 : ceil(start_z.z * n - 0.5) - 1.0;
    float tx = dir.x != 0.0 ? ((jx + 0.5) / n - eye.x) / dir.x : kHuge;
    float tz = dir.z != 0.0 ? ((jz + 0.5) / n - eye.z) / dir.z : kHuge;

    g_dir = dir;
    g_abs_dir = abs(dir.xz);
    g_sun = world_to_patch_direction(frame.sun_direction.xyz);
    g_size = size;
    g_to_world = mat3(field.patch_to_world);
    g_origin = g_to_world * (-v_camera_local); // the instance's corner relative to the camera, in either view
    g_n = n;
    g_texels = texels;
    g_pixel_angle = pixel_angle;
    g_pixel_size = pixel_size;
    g_eye = eye;
    g_descent_lod = log2(max(abs(dir.y) / (n * (g_abs_dir.x + g_abs_dir.y)) * texels.y / size.y, 1.0));
    g_depth_at[0] = v_local;
    g_parts = !debug_thresholds() && texel_transition(lod_distance(g_to_world * start + g_origin));
    // The ray goes on past this carrier into the neighbouring cells (the same patch, mirrored
    // by their own cells' bits) until it leaves the blade layer: a ray that crosses several
    // carriers is then composited whole by the nearest of them, and no seam shows where each
    // carrier alone would see too little grass. It stops at the field's edges.
    g_field_cells = field.map_params.zw;
    float t_layer = dir.y < 0.0 ? (box_min.y - eye.y) / dir.y
                  : dir.y > 0.0 ? (box_max.y - eye.y) / dir.y : kHuge;
    float t_reach = t_out + 4.0 / max(length(dir.xz), 1e-3);
    // On a height map the neighbours' terrain may lie below or above this carrier's box: the
    // ray goes on over them by the 4 cells and stops where it meets the ground (below).
    float t_end = displaced ? t_reach : max(t_out, min(t_layer, t_reach));
    // The horizontal slice lies near the ground (boulanger 3.3: seen only from above, it fills
    // what the vertical slices leave open there); a downward ray meets it once. Flat field:
    // a plane, met at t_ground. On a height map it follows the terrain at `layer_y` above it:
    // met where the ray's height above the layer turns negative between two slice
    // crossings (`above`, sampled at each crossing), found by the secant.
    float layer_y = 0.1 * size.y;
    float t_ground = !displaced && dir.y < 0.0 ? (layer_y - eye.y) / dir.y : kHuge;
    float t_floor = !displaced && dir.y < 0.0 ? (box_min.y - eye.y) / dir.y : kHuge; // the ground
    bool ground_pending = !front && (displaced || (t_ground >= t_in && t_ground <= t_end));
    float prev_t = t_in, prev_above = -1.0;
    if (displaced) prev_above = start.y - terrain_height(vec2(v_cell.xy) + start.xz) - layer_y;
    // Every slice plane the ray crosses in the cuboid and the 4 cells beyond it is crossed
    // once: a fixed bound from the slice count and the macro-cell size, so a grazing ray
    // cannot loop for ever.
    int max_steps = front ? 0 : int(n) * int(v_cell.z + v_cell.w + 8u) + 4;
    for (int i = 0; i < max_steps; ++i) {
        bool across_x = tx < tz;
        float t = across_x ? tx : tz;
        float half_slab = 0.5 * (across_x ? step_x : step_z); // in t
        if (t > t_end + (displaced ? 0.0 : half_slab)) break;
        if (across_x) tx += step_x; else tz += step_z;
        vec3 h = eye + dir * t;
        float ground = terrain_height(vec2(v_cell.xy) + h.xz); // eq. 6.16 (0 on a flat field)
        // On a flat field each crossing stands for its slab (the 1/n around it), of which a
        // downward ray crosses the share [lo, hi] in the blades: below their tips (when it came
        // in through the carrier's top) and above the ground. Counted whole or not at all,
        // the crossings at the tips and at the dense roots came and went with the slices'
        // phase along the ray: moire over the field from above, rows a cell apart with one or
        // two slices a cell.
        float lo = t - half_slab, hi = t + half_slab;
        if (!displaced && dir.y < 0.0) {
            lo = max(lo, from_top ? t_top : lo);
            hi = min(hi, t_floor);
        }
        float slab = clamp((hi - lo) / (2.0 * half_slab), 0.0, 1.0);
        // A steep ray through sparse slices (one or two a cell) descends across that share by
        // much of the blades' height: one lookup would show the blades at one height of it,
        // the tips or the roots by the slices' phase. Where it descends more than an eighth of
        // the height, the share is met at its middle and its colour and coverage gathered in
        // up to 4 taps down the span (composite()). Taps around the texture lookups only: a
        // loop around composite() made every march twice as dear on llvmpipe.
        float steps = displaced || slab <= 0.0 || n > 2.0
                          ? 1.0
                          : clamp(ceil(-dir.y * (hi - lo) / (0.125 * size.y)), 1.0, 4.0);
        float tq = steps > 1.0 ? 0.5 * (lo + hi) : t; // where the crossing is looked up
        if (displaced) {
            float above = h.y - ground - layer_y;
            if (ground_pending && prev_above >= 0.0 && above < 0.0) {
                float tg = mix(prev_t, t, prev_above / (prev_above - above));
                vec3 g = eye + dir * tg;
                composite(vec3(g.x, layer_y, g.z), g, tg, 2, 1.0);
                ground_pending = false;
                if (g_alpha >= kOpaqueAlpha || depth_pass_done()) break;
            }
            prev_t = t;
            prev_above = above;
        } else if (ground_pending && t_ground <= tq) {
            composite_flat_ground(t_ground);
            ground_pending = false;
            if (g_alpha >= kOpaqueAlpha || depth_pass_done()) break;
        }
        // The slice is looked up at the hit's height above the terrain (eq. 6.17-6.18); a
        // hit below the terrain or above the blades there meets nothing. On a flat field a
        // crossing below the ground or above the tips that counts in part is looked up there.
        float y = h.y - ground;
        if (displaced && y < 0.0 && t > t_out) break; // under a neighbour's ground: hidden by it
        if (!displaced) y = clamp(y, 0.0, from_top ? size.y : y);
        if ((t < t_in && !from_top) || y < 0.0 || y > size.y || slab <= 0.0) continue;
        vec3 hq = eye + dir * tq;
        g_taps = steps;
        g_tap_span = -dir.y * (hi - lo) / size.y;
        composite(steps > 1.0 ? (across_x ? vec3(h.x, hq.y, hq.z) : vec3(hq.x, hq.y, h.z)) : vec3(h.x, y, h.z),
                  hq, tq, across_x ? 0 : 1, slab);
        g_taps = 1.0;
        if (g_alpha >= kOpaqueAlpha || depth_pass_done()) break;
    }
    if (ground_pending && g_alpha < kOpaqueAlpha && !depth_pass_done()) {
        if (displaced) {
            vec3 e = eye + dir * t_end;
            float above = e.y - terrain_height(vec2(v_cell.xy) + e.xz) - layer_y;
            if (prev_above >= 0.0 && above < 0.0) {
                float tg = mix(prev_t, t_end, prev_above / (prev_above - above));
                vec3 g = eye + dir * tg;
                composite(vec3(g.x, layer_y, g.z), g, tg, 2, 1.0);
            }
        } else {
            composite_flat_ground(t_ground);
        }
    }
    // Between two texel tiers: the part of the samples at the point the depth is written at
    // (below). A field-edge instance stands in for the tiers after its own: their end of the
    // samples.
    int level = 0; // the last level at or below half the ray's alpha (1/2 for an opaque ray)
    for (int i = 1; i < g_depth_reached; ++i) {
        if (0.03125 * float(1 << i) <= (g_alpha >= 0.5 ? 0.5 : 0.5 * g_alpha)) level = i;
    }
    vec3 depth_point = g_to_world * g_depth_at[level] + g_origin;
    bool from_last = ((field.tiers.x & 1u) != 0u) != (g_parts && v_field_edge > 0.5);
    if (!write_coverage(g_alpha, g_parts ? tier_texel_part(lod_distance(depth_point), v_field_edge > 0.5) : 1.0,
                        from_last)) {
        discard;
    }
#ifdef GRASS_GBUFFER
    vec3 facing = dot(g_normal, g_normal) > 1e-12 ? normalize(g_normal) : normalize(g_to_world * -g_dir);
    write_gbuffer(g_albedo / g_alpha, facing, g_ao / g_alpha);
#else
    if (!depth_pass()) { // the depth pass writes the depth alone
        out_color = debug_thresholds() ? threshold_code(g_depth_threshold)
                                       : output_color(vec4(debug_tint(g_color / g_alpha), g_alpha));
    }
#endif
    float depth = in_front_of_plane(window_depth(depth_point));
#ifdef GRASS_VELOCITY
    vec3 now = depth_point;
    write_velocity(clip_velocity(clip_now(now), clip_before(now - g_shift_at[level])));
#endif
    // The depth pass's bias (glPolygonOffset, Vulkan's depth bias) moves the rasterised depth,
    // which gl_FragDepth replaces: the carrier's biased depth minus its own is added instead
    // (the slope term is the carrier face's, not the blades').
    if (depth_pass()) depth += gl_FragCoord.z - window_depth(g_to_world * v_local + g_origin);
    gl_FragDepth = depth;
}
