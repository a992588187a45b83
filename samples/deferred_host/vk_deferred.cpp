// grass-deferred's Vulkan half (grass-deferred --backend vk): grass draws a GRASS_PASS_GBUFFER
// view with grass_vk_record into the Vulkan test host's render pass of three RGBA8 UNORM colour
// attachments (albedo: the host's colour; normal; material) and depth, which the context was
// told of with a grass_vk_gbuffer_target_desc (TargetDesc::vk_gbuffer_formats). The host reads
// the G-buffer back and does the rest on the CPU, pixel by pixel, with the GL half's lighting
// (main.cpp's kLightFrag, line for line): where grass wrote no depth its ground (the same
// quad, found along the pixel's ray) or the sky, then every pixel lit by the sun, the ambient
// term and the three lamps. A renderer would do that in a full-screen pass of its own; this
// one keeps the sample to the part grass does.
#include "host_factories.hpp"
#include "matrix4.hpp"
#include "scene.hpp"

#include <grass/grass_vk.h>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace deferred {

namespace {

constexpr uint32_t kRgba8Unorm = 37; // VK_FORMAT_R8G8B8A8_UNORM

// The camera-relative point of clip (x, y, z) through `inverse`.
void unproject(const double inverse[16], double x, double y, double z, double out[3]) {
    double p[4];
    for (int r = 0; r < 4; ++r) p[r] = inverse[r] * x + inverse[4 + r] * y + inverse[8 + r] * z + inverse[12 + r];
    for (int k = 0; k < 3; ++k) out[k] = p[k] / p[3];
}

// What a blade lets through to its front of the light on its back (the material's g).
double diffuse(double n_dot_l, double translucency) {
    return std::max(n_dot_l, 0.0) + translucency * std::max(-n_dot_l, 0.0);
}

uint8_t srgb_byte(double linear) {
    return static_cast<uint8_t>(std::lround(grass_host::linear_to_srgb(float(linear)) * 255.0f));
}

} // namespace

int run_vulkan(const std::string& out_path) {
    grass_host::TargetDesc target;
    target.width = kWidth;
    target.height = kHeight;
    target.unorm_color = true; // the albedo as grass writes it, linear
    target.read_depth = true;
    for (float& c : target.clear_color) c = 0.0f;
    target.vk_gbuffer_formats[0] = kRgba8Unorm; // normal, n * 0.5 + 0.5
    target.vk_gbuffer_formats[1] = kRgba8Unorm; // material: roughness, translucency, ambient occlusion
    std::string error;
    std::unique_ptr<grass_host::Host> host = grass_host::create_vk_host(target, &error);
    if (!host) {
        std::fprintf(stderr, "no Vulkan device: %s\n", error.c_str());
        return 1;
    }
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = nullptr;
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) {
        std::fprintf(stderr, "grass_vk_create_context failed\n");
        return 1;
    }
    grass_patch_id patch{};
    grass_field_id field{};
    grass_patch_desc pd = grass_default_patch_desc();
    grass_field_desc fd = grass_default_field_desc();
    bool ok = grass_create_patch(ctx, &pd, &patch) == GRASS_SUCCESS;
    fd.patch = patch;
    fd.cells_x = fd.cells_z = kCells;
    ok = ok && grass_create_field(ctx, &fd, &field) == GRASS_SUCCESS;

    // grass into the G-buffer: albedo, normal, material (with its ambient occlusion).
    grass_view_desc view = grass_host::make_view(*host, kEye, kAt, kFovy, kNear, kFar);
    view.viewport[2] = kWidth;
    view.viewport[3] = kHeight;
    grass_view_gbuffer_desc layout = gbuffer_layout();
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    view.next = &pass;
    grass_host::Image g;
    ok = ok && host->render(ctx, view, nullptr, &g, &error) == GRASS_SUCCESS && g.gbuffer.size() == 2;
    grass_destroy_context(ctx);
    if (!ok || host->validation_messages() != 0) {
        std::fprintf(stderr, "the G-buffer frame failed: %s\n%s\n", error.c_str(), host->validation_log().c_str());
        return 1;
    }

    // The lighting, on the CPU: Vulkan's clip y runs down the image, its depth 0..1.
    float vp[16];
    view_projection(view, vp);
    double vp_double[16], inverse[16];
    for (int i = 0; i < 16; ++i) vp_double[i] = vp[i];
    if (!grass_host::invert4(vp_double, inverse)) return 1;
    double lamps[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c) lamps[i][c] = kLamps[i][c] - kEye[c];
    }
    const auto light = [&](bool with_lamps) {
        std::vector<uint8_t> out(size_t(kWidth) * kHeight * 4);
        for (uint32_t y = 0; y < kHeight; ++y) {
            for (uint32_t x = 0; x < kWidth; ++x) {
                const size_t p = size_t(y) * kWidth + x;
                const double cx = (x + 0.5) / kWidth * 2.0 - 1.0, cy = (y + 0.5) / kHeight * 2.0 - 1.0;
                double albedo[3], n[3], m[3], position[3], color[3];
                if (g.depth[p] < 1.0f) { // grass
                    for (int k = 0; k < 3; ++k) {
                        albedo[k] = g.rgba[p * 4 + k] / 255.0;
                        n[k] = g.gbuffer[0][p * 4 + k] / 255.0 * 2.0 - 1.0;
                        m[k] = g.gbuffer[1][p * 4 + k] / 255.0;
                    }
                    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                    for (double& c : n) c /= len > 0.0 ? len : 1.0;
                    unproject(inverse, cx, cy, g.depth[p], position);
                } else { // the ground along the pixel's ray, or the sky
                    double a[3], b[3];
                    unproject(inverse, cx, cy, 0.0, a);
                    unproject(inverse, cx, cy, 1.0, b);
                    const double t = b[1] != a[1] ? (-kEye[1] - a[1]) / (b[1] - a[1]) : -1.0;
                    for (int k = 0; k < 3; ++k) position[k] = a[k] + t * (b[k] - a[k]);
                    const double wx = position[0] + kEye[0], wz = position[2] + kEye[2];
                    if (t < 0.0 || t > 1.0 || wx < kGroundMin || wx > kGroundMax || wz < kGroundMin ||
                        wz > kGroundMax) {
                        for (int k = 0; k < 3; ++k) out[p * 4 + k] = srgb_byte(kSky[k]);
                        out[p * 4 + 3] = 255;
                        continue;
                    }
                    for (int k = 0; k < 3; ++k) {
                        albedo[k] = kSoil[k];
                        n[k] = k == 1 ? 1.0 : 0.0;
                    }
                    m[0] = 1.0, m[1] = 0.0, m[2] = 1.0; // rough, opaque, unoccluded
                }
                const double sun =
                    diffuse(n[0] * kSunDirection[0] + n[1] * kSunDirection[1] + n[2] * kSunDirection[2], m[1]);
                for (int k = 0; k < 3; ++k) color[k] = albedo[k] * kAmbient[k] * m[2] + kSunColor[k] * albedo[k] * sun;
                for (int i = 0; i < 3 && with_lamps; ++i) {
                    double to[3], d2 = 0.0;
                    for (int k = 0; k < 3; ++k) {
                        to[k] = lamps[i][k] - position[k];
                        d2 += to[k] * to[k];
                    }
                    const double d = std::sqrt(d2);
                    const double fade = std::clamp(1.0 - std::pow(d / kLampRange, 4.0), 0.0, 1.0);
                    const double lambert = diffuse((n[0] * to[0] + n[1] * to[1] + n[2] * to[2]) / d, m[1]);
                    for (int k = 0; k < 3; ++k)
                        color[k] += kLampColors[i][k] * albedo[k] * lambert * fade * fade / std::max(d2, 1e-4);
                }
                for (int k = 0; k < 3; ++k) out[p * 4 + k] = srgb_byte(color[k]);
                out[p * 4 + 3] = 255;
            }
        }
        return out;
    };
    return holds_lit_grass(light(true), light(false), out_path) ? 0 : 1;
}

} // namespace deferred
