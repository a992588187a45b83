#version 450
// Volume tier (lemme2012 5.2, eq. 5.3-5.21): the view ray is cast through the grid of
// implicit vertical slices of the (macro-)cell, each cell's slices mirrored as the cell is
// (eq. 6.6), composited front to back until opaque; the fragment takes the depth of the hit.
#include "blade_interface.glsl"
#include "lighting.glsl"
#include "tier_transitions.glsl"

layout(location = 0) in vec3 v_local;
layout(location = 1) flat in vec3 v_camera_local;
layout(location = 2) flat in vec3 v_face_normal;
layout(location = 3) flat in uvec4 v_cell;

layout(location = 0) out vec4 out_color;

const float kHuge = 1e30;

void main() {
    vec3 ray = v_local - v_camera_local;
    // The back face ends the ray; a front face leaves the work to the back face behind it.
    // (Decided geometrically: no dependence on the host's winding or clip conventions.)
    if (dot(v_face_normal, ray) <= 0.0) discard;
    float t_out = length(ray);
    vec3 dir = ray / t_out;
    vec3 size = vec3(float(v_cell.z), field.blade_params.w, float(v_cell.w));

    // Where the ray enters the cuboid (slab test), or the camera if it is inside.
    vec3 inv = vec3(dir.x != 0.0 ? 1.0 / dir.x : kHuge, dir.y != 0.0 ? 1.0 / dir.y : kHuge,
                    dir.z != 0.0 ? 1.0 / dir.z : kHuge);
    vec3 t0 = (vec3(0.0) - v_camera_local) * inv, t1 = (size - v_camera_local) * inv;
    vec3 t_near = min(t0, t1);
    float t_in = max(max(max(t_near.x, t_near.y), t_near.z), 0.0);

    // Mip level per hit from the pixel's angular size times the hit's distance: the slices
    // are seen at every angle, so the carrier's own footprint (stretched at grazing angles)
    // would blur them. Derivatives outside the loop: they need uniform control flow.
    float n = float(field.tiling.z);
    vec2 texels = vec2(textureSize(slice_color, 0).xy);
    float pixel_angle = max(length(dFdx(dir)), length(dFdy(dir)));  // radians per pixel

    // The slices across x sit at x = (j + 0.5) / n for every integer j (each cell repeats
    // its n slices), likewise across z. Walk both families in order (a 2D DDA).
    float step_x = dir.x != 0.0 ? 1.0 / (n * abs(dir.x)) : kHuge;
    float step_z = dir.z != 0.0 ? 1.0 / (n * abs(dir.z)) : kHuge;
    vec3 start = v_camera_local + dir * t_in;
    float jx = dir.x > 0.0 ? floor(start.x * n - 0.5) + 1.0 : ceil(start.x * n - 0.5) - 1.0;
    float jz = dir.z > 0.0 ? floor(start.z * n - 0.5) + 1.0 : ceil(start.z * n - 0.5) - 1.0;
    float tx = dir.x != 0.0 ? ((jx + 0.5) / n - v_camera_local.x) / dir.x : kHuge;
    float tz = dir.z != 0.0 ? ((jz + 0.5) / n - v_camera_local.z) / dir.z : kHuge;

    mat3 to_world = mat3(field.patch_to_world);
    vec3 origin = to_world * (-v_camera_local); // the instance corner relative to the camera
    // The ray goes on past this carrier into the neighbouring cells (the same patch, mirrored
    // by their own cells' bits) until it leaves the blade layer: a ray that crosses several
    // carriers is then composited whole by the nearest of them, and no seam shows where each
    // carrier alone would see too little grass. It stops at the field's edges.
    vec2 field_cells = 1.0 / field.map_params.xy;
    float t_layer = dir.y < 0.0 ? (0.0 - v_camera_local.y) / dir.y : dir.y > 0.0 ? (size.y - v_camera_local.y) / dir.y : kHuge;
    float t_end = max(t_out, min(t_layer, t_out + 4.0 / max(length(dir.xz), 1e-3)));
    vec3 color = vec3(0.0);
    float alpha = 0.0;
    vec3 depth_point = v_local;
    bool depth_set = false;
    float depth_threshold = 0.0; // the threshold of the blade where the ray turns opaque
    // Every slice plane the ray crosses in the cuboid and the 4 cells beyond it is crossed
    // once: a fixed bound from the slice count and the macro-cell size, so a grazing ray
    // cannot loop for ever.
    int max_steps = int(n) * int(v_cell.z + v_cell.w + 8u) + 2;
    for (int i = 0; i < max_steps; ++i) {
        bool across_x = tx < tz;
        float t = across_x ? tx : tz;
        if (t > t_end) break;
        if (across_x) tx += step_x; else tz += step_z;
        vec3 h = v_camera_local + dir * t;
        if (t < t_in || h.y < 0.0 || h.y > size.y) continue;

        vec2 cell = floor(h.xz);
        vec2 global = vec2(v_cell.xy) + cell;
        if (any(lessThan(global, vec2(0.0))) || any(greaterThanEqual(global, field_cells - 0.5))) continue;
        vec2 s = mirror_signs(uvec2(global));
        vec2 f = h.xz - cell;
        vec2 m = vec2(s.x < 0.0 ? 1.0 - f.x : f.x, s.y < 0.0 ? 1.0 - f.y : f.y); // eq. 6.6
        // The slice (layer) and the point on it, in the mirrored patch.
        float layer = across_x ? clamp(floor(m.x * n), 0.0, n - 1.0) : n + clamp(floor(m.y * n), 0.0, n - 1.0);
        vec3 coord = vec3(across_x ? m.y : m.x, h.y / size.y, layer);
        // Texels are 3-4x denser across a slice than up it (256 x 64 over 1 x ~0.85 cells);
        // the level follows the coarser, vertical density so blades keep their height.
        float lod = log2(max(t * pixel_angle * texels.y / size.y, 1.0)); // t: distance in cells
        float threshold = textureLod(slice_threshold, coord, lod).r;
        if (threshold <= 0.0) continue;
        vec4 albedo = textureLod(slice_color, coord, lod);
        if (albedo.a <= 0.0) continue;

        vec3 world = to_world * h + origin;
        float density = local_density(vec2(v_cell.xy) + h.xz);
        float a = albedo.a * tier_blade_opacity(length(world), threshold, density);
        if (a <= 0.0) continue;
        vec4 normal_height = textureLod(slice_normal, coord, lod);
        vec3 nrm = normal_height.xyz * 2.0 - 1.0;
        nrm.xz *= s;
        if (dot(nrm.xz, -dir.xz) < 0.0) nrm.xz = -nrm.xz; // the side facing the camera
        vec3 n_up = normalize(to_world * nrm);
        vec3 n_down = normalize(to_world * vec3(nrm.x, -nrm.y, nrm.z));
        float ao = blade_ambient_occlusion(density, h.y, field.blade_params.x, field.blade_params.y);
        vec3 lit = grass_lighting_two_lobes(albedo.rgb, n_up, n_down, ao);
        // Front to back (eq. 5.19-5.20).
        color += (1.0 - alpha) * a * lit;
        alpha += (1.0 - alpha) * a;
        if (!depth_set && alpha >= 0.5) {
            depth_point = h;
            depth_threshold = threshold;
            depth_set = true;
        }
        if (alpha >= 0.99) break;
    }
    if (alpha < alpha_cut()) discard;
    out_color = debug_thresholds() ? threshold_code(depth_threshold) : vec4(debug_tint(color / alpha), alpha);
    gl_FragDepth = window_depth(to_world * depth_point + origin);
}
