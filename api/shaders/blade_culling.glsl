// Per-blade culling (jahrmann2017 6.2): the orientation, view-frustum and distance tests of
// grass_blade_culling_desc (field.culling, api/src/plan/blade_culling.hpp). Every input is
// the blade's own (its root, control points, width direction, index, threshold), so all the
// vertices of a blade decide alike. Included by blade.vert after blade_dynamics.glsl; used
// only by variants with GRASS_BLADE_CULLING (geometry draws).

// Whether any of the three points lies inside the frustum widened by `tolerance` (eq. 18):
// x and y within +-w (1 + tolerance), in front of the camera. Depth is left to the clipper
// (its convention is the host's).
bool blade_in_frustum(vec3 v0, vec3 m, vec3 v2, float tolerance) {
    vec3 points[3] = vec3[3](v0, m, v2);
#ifdef GRASS_MULTIVIEW
    // Points relative to the plan's origin: in either eye's frustum, so both eyes keep it.
    for (int e = 0; e < 2; ++e) {
        for (int k = 0; k < 3; ++k) {
            vec4 p = frame.eye_view_projection[e] * vec4(points[k] - frame.eye_position[e].xyz, 1.0);
            float h = p.w * (1.0 + tolerance);
            if (p.w > 0.0 && abs(p.x) <= h && abs(p.y) <= h) return true;
        }
    }
#else
    for (int k = 0; k < 3; ++k) {
        vec4 p = frame.view_projection * vec4(points[k], 1.0);
        float h = p.w * (1.0 + tolerance);
        if (p.w > 0.0 && abs(p.x) <= h && abs(p.y) <= h) return true;
    }
#endif
    return false;
}

// Whether the blade `blade` of the patch is culled. v0: its root, camera-relative world
// metres (the camera is the origin); v1, v2: its control points relative to the root, world
// metres, as drawn; side: its width direction (world); up: the field's up; r: its density
// threshold over the local density (lemme 3.3: drawn at full density while r <= 1).
bool blade_culled(uint blade, vec3 v0, vec3 v1, vec3 v2, vec3 side, vec3 up, float r) {
#ifdef GRASS_MULTIVIEW
    v0 += GRASS_EYE; // from the plan's origin: both eyes cull the same blades
#endif
    vec4 c = field.culling;
    // Orientation (eq. 17): seen nearly edge-on, the blade is thinner than a pixel and aliases.
    // An orthographic view sees every blade along its axis.
    if (c.x <= 1.0 && abs(dot(normalize(towards_viewer(v0)), normalize(side))) > c.x) return true;
    // View frustum (eq. 18): root, the curve's midpoint (eq. 14) and tip all outside.
    if (c.y >= 0.0 && !blade_in_frustum(v0, v0 + 0.5 * v1 + 0.25 * v2, v0 + v2, c.y)) return true;
    // Distance (eq. 19-20): thinning with the distance across the field's up, from the lod
    // origin (the plan's origin in a stereo frame, where v0 now measures from).
    if (c.z > 0.0) {
        vec3 d = v0 - frame.lod_origin.xyz;
        float keep = 1.0 - length(d - up * dot(d, up)) / c.z; // share of the blades kept
        if (c.w >= 1.0) {
            uint n = uint(c.w + 0.5);
            if (float(blade % n) >= ceil(float(n) * keep)) return true; // eq. 20, by index
        } else if (r > keep) {
            return true; // by threshold: the density falls to zero at distance_max
        }
    }
    return false;
}
