#include "ground.hpp"
#include "headless_host.hpp"
#include "host_factories.hpp"
#include "mesh_draw.hpp"

#include <cmath>

namespace grass_host {

std::unique_ptr<Host> Host::create(grass_backend backend, const TargetDesc& target, std::string* error) {
    (void)target; // unused in a build without either backend (the fuzz build of scripts/test.sh)
    switch (backend) {
    case GRASS_BACKEND_GL:
#ifdef GRASS_HOST_HAS_GL
        return create_gl_host(target, error);
#else
        break;
#endif
    case GRASS_BACKEND_VULKAN:
#ifdef GRASS_HOST_HAS_VULKAN
        return create_vk_host(target, error);
#else
        break;
#endif
    case GRASS_BACKEND_NONE:
        break;
    }
    if (error) *error = "this build has no headless host for that backend";
    return nullptr;
}

grass_view_desc make_view(const Host& host, const double eye[3], const double target[3], float fovy_degrees,
                          float near_m, float far_m) {
    grass_view_desc v = grass_default_view_desc();
    for (int c = 0; c < 3; ++c) v.camera_position[c] = eye[c];
    double f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    // Looking straight up or down: take -z as "up" for the image.
    const double up[3] = {0.0, 1.0, 0.0}, alt_up[3] = {0.0, 0.0, -1.0};
    const double* u0 = std::fabs(f[1]) > 0.9999 ? alt_up : up;
    double r[3] = {f[1] * u0[2] - f[2] * u0[1], f[2] * u0[0] - f[0] * u0[2], f[0] * u0[1] - f[1] * u0[0]};
    const double rl = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (double& x : r) x /= rl;
    const double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    float* m = v.view;
    for (int k = 0; k < 16; ++k) m[k] = 0.0f;
    for (int c = 0; c < 3; ++c) {
        m[4 * c + 0] = static_cast<float>(r[c]);
        m[4 * c + 1] = static_cast<float>(u[c]);
        m[4 * c + 2] = static_cast<float>(-f[c]);
    }
    m[15] = 1.0f;
    const TargetDesc& t = host.target();
    host.projection(fovy_degrees * 3.14159265358979f / 180.0f,
                    static_cast<float>(t.width) / static_cast<float>(t.height), near_m, far_m, v.projection);
    v.viewport[0] = 0;
    v.viewport[1] = 0;
    v.viewport[2] = static_cast<int32_t>(t.width);
    v.viewport[3] = static_cast<int32_t>(t.height);
    return v;
}

float linear_to_srgb(float v) {
    v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; // NaN fails v > 0: 0
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void vk_projection(float fovy_radians, float aspect, float near_m, float far_m, bool reversed_z, float out[16]) {
    const float f = 1.0f / std::tan(0.5f * fovy_radians);
    for (int i = 0; i < 16; ++i) out[i] = 0.0f;
    out[0] = f / aspect;
    out[5] = -f;
    out[10] = far_m / (near_m - far_m);
    out[11] = -1.0f;
    out[14] = far_m * near_m / (near_m - far_m);
    if (reversed_z) { // z' = w - z: depth 1 - d
        out[10] = -1.0f - out[10];
        out[14] = -out[14];
    }
}

void stored_clear_color(const TargetDesc& target, float out[4]) {
    for (int c = 0; c < 4; ++c)
        out[c] = c < 3 && target.unorm_color ? linear_to_srgb(target.clear_color[c]) : target.clear_color[c];
}

void encode_float_image(Image* image) {
    const size_t n = image->rgba_f32.size();
    image->rgba.resize(n);
    for (size_t k = 0; k < n; ++k) {
        float v = image->rgba_f32[k];
        v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; // NaN fails v > 0: 0
        if (k % 4 != 3) v = linear_to_srgb(v);
        image->rgba[k] = static_cast<uint8_t>(std::lround(v * 255.0f));
    }
}

void camera_relative_view_projection(const grass_view_desc& view, float out[16]) {
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double s = 0.0;
            for (int k = 0; k < 3; ++k)
                s += double(view.projection[4 * k + row]) * (col < 3 ? view.view[4 * col + k] : 0.0);
            if (col == 3) s = view.projection[12 + row];
            out[4 * col + row] = static_cast<float>(s);
        }
    }
}

namespace {
void unit_sun(const grass_view_desc& view, float out[3]) {
    const double sun_len = std::sqrt(double(view.sun_direction[0]) * view.sun_direction[0] +
                                     double(view.sun_direction[1]) * view.sun_direction[1] +
                                     double(view.sun_direction[2]) * view.sun_direction[2]);
    for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(view.sun_direction[c] / sun_len);
}
} // namespace

GroundUniforms make_ground_uniforms(const grass_view_desc& view, const TargetDesc& target) {
    GroundUniforms g{};
    camera_relative_view_projection(view, g.view_projection);
    g.plane[0] = static_cast<float>(0.0 - view.camera_position[1]);
    g.plane[1] = 2000.0f;
    unit_sun(view, g.sun_direction);
    for (int c = 0; c < 3; ++c) {
        g.color[c] = target.ground_color[c];
        g.sun_color[c] = view.sun_color[c];
        g.ambient_color[c] = view.ambient_color[c];
    }
    return g;
}

MeshDraw make_mesh_draw(const grass_view_desc& view, const HostMesh& mesh, bool encode_srgb) {
    MeshDraw d{};
    camera_relative_view_projection(view, d.view_projection);
    unit_sun(view, d.sun_direction);
    for (int c = 0; c < 3; ++c) {
        d.offset[c] = static_cast<float>(mesh.origin[c] - view.camera_position[c]);
        d.albedo[c] = mesh.color[c];
        d.sun_color[c] = view.sun_color[c];
    }
    d.offset[3] = view.ambient_color[0];
    d.albedo[3] = view.ambient_color[1];
    d.sun_direction[3] = view.ambient_color[2];
    d.sun_color[3] = encode_srgb ? 1.0f : 0.0f;
    return d;
}

} // namespace grass_host
