#version 450
// Image tier: the horizontal slice, repeated per cell with the cell's mirroring (lemme eq.
// 6.6), thinned by the density thresholds and the tier transitions, lit per pixel through
// the slice's normal with the lighting of every tier.
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

layout(location = 0) in vec3 v_position;
layout(location = 1) in vec2 v_local;
layout(location = 2) flat in uvec2 v_first_cell;

#ifdef GRASS_DEPTH_TARGET
vec4 out_color; // Vulkan's depth-only target (a depth pass): no colour attachment, no output
#else
layout(location = 0) out vec4 out_color;
#endif
#ifdef GRASS_GBUFFER // G-buffer views' variants only
#include "gbuffer.glsl"
#endif

#ifdef GRASS_RESPONSIVE
// The bend of the grass the quad stands for (its point is at half the grass's height), and
// how far back along it the slice is read there (`back`, patch units): the bend moves the
// grass by x(1/2) along its direction.
ShellBend image_bend(out float back) {
    vec3 up = normalize(field.field_up.xyz);
    float height_m = field.blade_params.w * field.field_up.w;
    ShellBend bend = shell_bend(v_position - up * (0.5 * height_m), up, height_m, vec2(v_first_cell) + v_local);
    float a = 0.5 * bend.angle;
    back = a < 1e-4 ? 0.0 : field.blade_params.w * (1.0 - cos(a)) / bend.angle;
    return bend;
}
#endif

void main() {
    load_blocks();
    note_pixel(v_position); // the dither's pixel, while derivatives are defined
#ifdef GRASS_VELOCITY
    vec3 before = v_position; // where the grass seen here was at the previous frame's time
#endif
    vec2 local = v_local;
    float shade = 1.0;
    float turn = 0.0; // the bent tangent's angle at half height (grass_lighting_lobes_bent)
    vec3 bend_dir = vec3(0.0);
#ifdef GRASS_RESPONSIVE
    if (has_map(GRASS_WIND | GRASS_INTERACTION)) {
        // Responsive grass (shell_bend.glsl): the quad stands for the grass at half its
        // height, which a bend moves by x(1/2) along its direction: the slice is read that
        // far back. Pressed grass darkens.
        float back;
        ShellBend bend = image_bend(back);
        float a = 0.5 * bend.angle;
#ifdef GRASS_VELOCITY
        g_previous_time = true; // the same grass bent as at the previous time (motion.glsl)
        float back_before;
        ShellBend bent_before = image_bend(back_before);
        g_previous_time = false;
        before += (bent_before.dir * back_before - bend.dir * back) * field.field_up.w;
#endif
        vec3 d = transpose(mat3(field.patch_to_world)) * bend.dir / max(field.field_up.w, 1e-30);
        local -= d.xz * back;
        turn = a;
        bend_dir = vec3(d.x, 0.0, d.z);
        local = max(local, -vec2(v_first_cell)); // not before the field's first cell
        shade = bend.shade;
    }
#endif
    vec2 cell = floor(local);
    vec2 s = mirror_signs(uvec2(ivec2(v_first_cell) + ivec2(cell)));
    vec2 f = local - cell;
    vec2 uv = vec2(s.x < 0.0 ? 1.0 - f.x : f.x, s.y < 0.0 ? 1.0 - f.y : f.y); // eq. 6.6
    // Gradients of the continuous coordinate: mirroring and cell seams must not pick mip 0.
    vec2 dx = dFdx(v_local), dy = dFdy(v_local);
    vec3 coord = vec3(uv, 0.0);
    vec4 albedo = textureGrad(slice_color, coord, dx, dy);
    vec2 texels = vec2(textureSize(slice_color, 0).xy);
    albedo.a = horizontal_slice_alpha(albedo.a, log2(max(max(length(dx * texels), length(dy * texels)), 1.0)));
    vec4 normal_height = textureGrad(slice_normal, coord, dx, dy);
    vec4 thresholds = textureGrad(slice_threshold, coord, dx, dy); // r: threshold, gba: coverage curve
    float threshold = thresholds.r;
    if (threshold <= 0.0 || albedo.a <= 0.0) discard;

    vec2 cell_point = vec2(v_first_cell) + local; // where the blade stands in the field
    float density = local_density(cell_point);
    // The threshold view partitions whole texels by their threshold; the picture draws the
    // share of each texel's blades the density and the tier select.
    // Between two texel tiers the quad draws the grass whole and takes its part of the samples.
    bool exact = debug_thresholds();
    float d = lod_distance(v_position);
    bool parts = !exact && texel_transition(d);
    float share = exact ? 1.0 : tier_texel_share(d, thresholds, density, false, parts);
    float opacity = exact ? tier_blade_opacity(d, threshold, density) : 1.0;
    // The horizontal slice holds the coverage of the grass seen from above. Seen at an
    // elevation theta the view crosses the blade layer 1 / sin(theta) times as long, so the
    // layer is more opaque (Beer-Lambert along the slanted path): 1 - (1 - a)^(1 / sin).
    vec3 to_viewer = normalize(towards_viewer(v_position));
    float sin_elevation = max(abs(dot(to_viewer, normalize(mat3(field.patch_to_world)[1]))), 0.05);
    float coverage = 1.0 - pow(max(1.0 - albedo.a * share, 0.0), 1.0 / sin_elevation);
    float alpha = coverage * opacity;
    if (!write_coverage(alpha, parts ? tier_texel_part(d, false) : 1.0, (field.tiers.x & 1u) != 0u)) discard;
    if (depth_pass()) return; // the coverage's depth alone: no lighting, no colour

    // Layers 1 and 2 hold what a grazing ray sees (slice_baker.cpp, apply_grazing): the
    // colour and heights of the blades' upper parts, whose ambient occlusion the height
    // gives, and the normals a ray 10 degrees up sees heading along x and along z (the blades
    // it meets broadside), lit each and weighed by the view's heading, as the volume weighs
    // its two slice families. Steeper views turn to layer 0's colour, heights and normals,
    // seen from above (the tips and, through the gaps, the darker lower parts; the blades'
    // parts that face up), whose normals' up component is scaled by sin(elevation) (from an
    // elevation one sees more of the blades' sides; their spread, the mean's length, kept).
    // The four sign lobes of the two horizontal components light the blades that face the
    // camera from every side (lighting.glsl).
    vec3 to_camera = world_to_patch_direction(to_viewer);
    vec3 sun = world_to_patch_direction(frame.sun_direction.xyz);
    vec4 grazing_normal_height = textureGrad(slice_normal, vec3(uv, 1.0), dx, dy);
    vec3 grazing_albedo = textureGrad(slice_color, vec3(uv, 1.0), dx, dy).rgb;
    const float sin_baked = 0.173648; // sin(10 degrees), the grazing bake's elevation
    float steep = clamp((sin_elevation - sin_baked) / (1.0 - sin_baked), 0.0, 1.0);
    float height = mix(grazing_normal_height.w, normal_height.w, steep) * field.blade_params.w;
    float ao = blade_ambient_occlusion(density, height, field.blade_params.x, field.blade_params.y);
    // The design maps per pixel (lemme 6.4.2-6.4.3): colour modulation, then the light maps.
    vec3 base_grazing = modulate_color(grazing_albedo, cell_point) * shade;
    vec3 base_above = modulate_color(albedo.rgb, cell_point) * shade;
    vec2 light = light_maps(cell_point);
#ifdef GRASS_HOST_SHADOWS
    light.y *= host_sun_visibility(v_position); // the host's shadow at the quad's point
#endif
    const vec3 folded = vec3(1.0, 0.0, 1.0);
    // A slice's light: the sun's and the ambient, and the host's lights at the quad's point.
#ifdef GRASS_HOST_LIGHTS
#define slice_light(a, n, f, v, l, o, m, b, t) \
    (grass_lighting_lobes_bent(a, n, f, v, l, o, m, b, t) + host_lights_lobes(a, n, f, v, v_position, b, t, (m).y))
#else
#define slice_light grass_lighting_lobes_bent
#endif
    vec3 n_above = normal_height.xyz * 2.0 - 1.0;
    {
        float r = length(n_above);
        vec3 u = r > 1e-4 ? n_above / r : vec3(0.0, 1.0, 0.0);
        u.y *= sin_elevation;
        n_above = dot(u, u) > 1e-8 ? normalize(u) * r : vec3(0.0, r, 0.0);
    }
    vec3 n_x = grazing_normal_height.xyz * 2.0 - 1.0;
    vec3 n_z = textureGrad(slice_normal, vec3(uv, 2.0), dx, dy).xyz * 2.0 - 1.0;
    float along_x = abs(to_camera.x) / max(abs(to_camera.x) + abs(to_camera.z), 1e-6);
#ifdef GRASS_GBUFFER // the surface the lighting below weighs, as one normal
    vec3 n_grazing = mix(gbuffer_slice_normal(n_z, folded, to_camera), gbuffer_slice_normal(n_x, folded, to_camera),
                         along_x);
    vec3 n_patch = mix(n_grazing, gbuffer_slice_normal(n_above, folded, to_camera), steep);
    write_gbuffer(mix(base_grazing, base_above, steep), normalize(mat3(field.patch_to_world) * n_patch),
                  ao * light.x);
#ifdef GRASS_VELOCITY
    write_velocity(clip_velocity(clip_now(v_position), clip_before(before)));
#endif
    return;
#endif
    vec3 grazing = mix(slice_light(base_grazing, n_z, folded, to_camera, sun, ao, light, bend_dir, turn),
                       slice_light(base_grazing, n_x, folded, to_camera, sun, ao, light, bend_dir, turn), along_x);
    vec3 color = grazing;
    if (steep > 0.0) {
        color = mix(grazing, slice_light(base_above, n_above, folded, to_camera, sun, ao, light, bend_dir, turn),
                    steep);
    }
    out_color = debug_thresholds() ? threshold_code(threshold) : output_color(vec4(debug_tint(color), alpha));
#ifdef GRASS_VELOCITY
    write_velocity(clip_velocity(clip_now(v_position), clip_before(before)));
#endif
}
