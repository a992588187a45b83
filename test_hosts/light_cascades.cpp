#include "light_cascades.hpp"

#include "matrix4.hpp"

#include <cmath>
#include <cstring>
#include <string>

namespace grass_host {

namespace {

struct V3 {
    double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 unit(V3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }

std::string text(double v) { return std::to_string(v); }

} // namespace

LightCascades fit_light_cascades(const grass_view_desc& main, const HostShadows& shadows, bool vulkan) {
    LightCascades out;
    out.count = shadows.cascades;
    const float* v = main.view;
    const V3 forward = unit({-double(v[2]), -double(v[6]), -double(v[10])});
    const V3 right = unit({double(v[0]), double(v[4]), double(v[8])});
    const V3 up = unit({double(v[1]), double(v[5]), double(v[9])});
    const double tan_x = 1.0 / std::fabs(double(main.projection[0]));
    const double tan_y = 1.0 / std::fabs(double(main.projection[5]));
    const V3 camera = {main.camera_position[0], main.camera_position[1], main.camera_position[2]};
    const V3 to_sun =
        unit({double(main.sun_direction[0]), double(main.sun_direction[1]), double(main.sun_direction[2])});
    const V3 light_forward = to_sun * -1.0;
    const V3 up_hint = std::fabs(light_forward.y) > 0.9999 ? V3{0.0, 0.0, 1.0} : V3{0.0, 1.0, 0.0};
    const V3 light_right = unit(cross(light_forward, up_hint));
    const V3 light_up = cross(light_right, light_forward);

    HostShadowUniforms& u = out.uniforms;
    u.forward[0] = float(forward.x), u.forward[1] = float(forward.y), u.forward[2] = float(forward.z);
    u.forward[3] = shadows.host_receive_bias;
    u.params[0] = float(shadows.cascades);
    u.params[1] = 1.0f / float(shadows.map_size);
    u.params[2] = shadows.filter_radius;

    for (uint32_t i = 0; i < shadows.cascades; ++i) {
        // The slice's corners, camera-relative, and their bounding sphere.
        const double depths[2] = {i == 0 ? 0.0 : double(shadows.splits[i - 1]), double(shadows.splits[i])};
        V3 corners[8];
        V3 centre{0.0, 0.0, 0.0};
        for (int k = 0; k < 8; ++k) {
            const double d = depths[k >> 2], sx = (k & 1) ? 1.0 : -1.0, sy = (k & 2) ? 1.0 : -1.0;
            corners[k] = forward * d + right * (d * tan_x * sx) + up * (d * tan_y * sy);
            centre = centre + corners[k] * 0.125;
        }
        double radius = 0.0;
        for (const V3& c : corners) radius = std::fmax(radius, std::sqrt(dot(c - centre, c - centre)));
        radius = std::fmax(radius * 1.01, 0.01);
        // Snapped to whole texels in the light's plane, in world coordinates: the map does not
        // swim as the camera moves.
        const double texel = 2.0 * radius / double(shadows.map_size);
        V3 world = camera + centre;
        const double a = dot(world, light_right), b = dot(world, light_up);
        world =
            world + light_right * (std::floor(a / texel) * texel - a) + light_up * (std::floor(b / texel) * texel - b);
        const double reach = double(shadows.caster_reach);
        const V3 eye = world + to_sun * (radius + reach);
        const double near_m = 0.0, far_m = 2.0 * radius + reach;

        grass_view_desc& lv = out.light_view[i];
        lv = main;
        lv.next = nullptr;
        lv.flags = 0;
        lv.camera_position[0] = eye.x, lv.camera_position[1] = eye.y, lv.camera_position[2] = eye.z;
        std::memset(lv.view, 0, sizeof lv.view);
        const V3 rows[3] = {light_right, light_up, light_forward * -1.0};
        for (int r = 0; r < 3; ++r) {
            lv.view[0 + r] = float(rows[r].x);
            lv.view[4 + r] = float(rows[r].y);
            lv.view[8 + r] = float(rows[r].z);
        }
        lv.view[15] = 1.0f;
        double p[16] = {};
        p[0] = 1.0 / radius;
        p[5] = (vulkan ? -1.0 : 1.0) / radius;
        p[10] = vulkan ? -1.0 / (far_m - near_m) : -2.0 / (far_m - near_m);
        p[14] = vulkan ? -near_m / (far_m - near_m) : -(far_m + near_m) / (far_m - near_m);
        p[15] = 1.0;
        for (int k = 0; k < 16; ++k) lv.projection[k] = float(p[k]);
        lv.viewport[0] = lv.viewport[1] = 0;
        lv.viewport[2] = lv.viewport[3] = int32_t(shadows.map_size);

        // world -> (u, v, depth): bias * projection * view (with the eye's translation).
        double view_full[16] = {};
        for (int r = 0; r < 3; ++r) {
            view_full[0 + r] = rows[r].x, view_full[4 + r] = rows[r].y, view_full[8 + r] = rows[r].z;
            view_full[12 + r] = -dot(rows[r], eye);
        }
        view_full[15] = 1.0;
        double bias[16] = {};
        bias[0] = bias[5] = 0.5;
        bias[12] = bias[13] = 0.5;
        bias[10] = vulkan ? 1.0 : 0.5;
        bias[14] = vulkan ? 0.0 : 0.5;
        bias[15] = 1.0;
        double pv[16], world_to_shadow[16];
        multiply4(p, view_full, pv);
        multiply4(bias, pv, world_to_shadow);
        // Camera-relative: the translation column takes the camera's position in double.
        double camera_translate[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, camera.x, camera.y, camera.z, 1};
        double relative[16];
        multiply4(world_to_shadow, camera_translate, relative);
        for (int k = 0; k < 16; ++k) {
            out.world_to_shadow[i][k] = float(world_to_shadow[k]);
            u.relative_to_shadow[i][k] = float(relative[k]);
        }
        u.cascade_end[i] = shadows.splits[i];
    }
    return out;
}

void make_shadow_frame_views(const grass_view_desc& main, const LightCascades& cascades, const HostShadows& shadows,
                             uint64_t shadow_map, uint32_t vk_image_layout, bool receive, ShadowFrameViews* out) {
    out->main = main;
    if (receive) {
        grass_shadow_receive_desc& r = out->receive;
        r = grass_default_shadow_receive_desc();
        r.shadow_map = shadow_map;
        r.vk_image_layout = vk_image_layout;
        r.cascade_count = cascades.count;
        for (uint32_t i = 0; i < cascades.count; ++i) {
            std::memcpy(r.world_to_shadow[i], cascades.world_to_shadow[i], sizeof r.world_to_shadow[i]);
            r.cascade_end[i] = shadows.splits[i];
        }
        r.compare = GRASS_SHADOW_COMPARE_LESS_EQUAL;
        r.depth_bias = shadows.grass_receive_bias;
        r.filter_radius = shadows.filter_radius;
        r.next = main.next;
        out->main.next = &r;
    }
    for (uint32_t i = 0; i < cascades.count; ++i) {
        out->pass[i] = grass_default_view_pass_desc();
        out->pass[i].pass = GRASS_PASS_DEPTH;
        out->pass[i].depth_bias_constant = shadows.grass_bias_constant;
        out->pass[i].depth_bias_slope = shadows.grass_bias_slope;
        out->lod_origin[i] = grass_default_lod_origin_desc();
        std::memcpy(out->lod_origin[i].position, main.camera_position, sizeof main.camera_position);
        out->lod_origin[i].next = &out->pass[i];
        out->cascade[i] = cascades.light_view[i];
        out->cascade[i].next = &out->lod_origin[i];
    }
}

grass_result plan_shadow_frame(grass_context* context, const ShadowFrameViews& views, uint32_t cascades,
                               bool grass_casts) {
    grass_result result = grass_begin_frame(context, &views.main);
    uint32_t index = 0;
    for (uint32_t i = 0; grass_casts && i < cascades && result == GRASS_SUCCESS; ++i) {
        result = grass_plan_view(context, &views.cascade[i], &index);
    }
    return result;
}

bool check_host_shadows(const TargetDesc& target, std::string* error) {
    const HostShadows& s = target.host_shadows;
    const auto fail = [&](const std::string& what) {
        if (error) *error = "target.host_shadows." + what;
        return false;
    };
    if (s.cascades == 0) return true;
    if (s.cascades > GRASS_MAX_SHADOW_CASCADES)
        return fail("cascades is " + std::to_string(s.cascades) + "; expected 0 to " +
                    std::to_string(GRASS_MAX_SHADOW_CASCADES));
    if (s.map_size < 16 || s.map_size > 4096)
        return fail("map_size is " + std::to_string(s.map_size) + "; expected 16 to 4096");
    for (uint32_t i = 0; i < s.cascades; ++i) {
        const float previous = i == 0 ? 0.0f : s.splits[i - 1];
        if (!(s.splits[i] > previous) || !std::isfinite(s.splits[i]))
            return fail("splits[" + std::to_string(i) + "] is " + text(s.splits[i]) +
                        "; splits must be finite, > 0 and ascending");
    }
    if (!(s.caster_reach >= 0.0f) || !std::isfinite(s.caster_reach))
        return fail("caster_reach is " + text(s.caster_reach) + "; expected a finite value >= 0");
    if (!(s.grass_receive_bias >= 0.0f && s.grass_receive_bias <= 1.0f))
        return fail("grass_receive_bias is " + text(s.grass_receive_bias) + "; expected 0 to 1");
    if (!(s.filter_radius >= 0.0f && s.filter_radius <= 16.0f))
        return fail("filter_radius is " + text(s.filter_radius) + "; expected 0 to 16");
    if (target.vk_depth_pass)
        return fail("cascades is " + std::to_string(s.cascades) +
                    " with vk_depth_pass: the cascades' pass is grass's depth-only pass");
    if (target.reversed_z || target.gl_clip_zero_to_one)
        return fail("cascades is " + std::to_string(s.cascades) +
                    " with reversed_z or gl_clip_zero_to_one; the host's shadows use standard depth");
    return true;
}

} // namespace grass_host
