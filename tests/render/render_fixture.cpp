#include "render_fixture.hpp"

#include "image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace grass_test {

std::string backend_name(grass_backend b) {
    return b == GRASS_BACKEND_GL ? "gl" : b == GRASS_BACKEND_VULKAN ? "vk" : "none";
}

std::vector<grass_backend> enabled_backends() {
    std::vector<grass_backend> b;
#ifdef GRASS_HOST_HAS_GL
    b.push_back(GRASS_BACKEND_GL);
#endif
#ifdef GRASS_HOST_HAS_VULKAN
    b.push_back(GRASS_BACKEND_VULKAN);
#endif
    return b;
}

void RenderTest::SetUp() {
    blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    blade_band.tier = 0;
    blade_band.begin = 0.0f;
    blade_band.end = 60.0f;
    grass_host::TargetDesc t;
    t.width = 128;
    t.height = 128;
    start(t);
}

void RenderTest::start(const grass_host::TargetDesc& target, grass_backend backend) {
    if (ctx) grass_destroy_context(ctx);
    ctx = nullptr;
    host.reset();
    std::string error;
    if (backend == GRASS_BACKEND_NONE) backend = GetParam();
    host = grass_host::Host::create(backend, target, &error);
    ASSERT_TRUE(host) << "cannot create the " << backend_name(backend) << " host: " << error;
    grass_context_desc d = grass_default_context_desc();
    d.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char* message) {
        // Errors and warnings carry a stable message id (grass.h), whatever the path.
        if (level != GRASS_LOG_INFO) {
            EXPECT_NE(id, GRASS_MSG_NONE) << message;
        }
        *static_cast<std::string*>(user) += std::to_string(static_cast<int>(id)) + ": " + message + "\n";
    };
    d.log_user_data = &log;
    d.next = context_next;
    d.depth_mode = target.reversed_z ? GRASS_DEPTH_GREATER : GRASS_DEPTH_LESS;
    ASSERT_EQ(host->create_context(d, &ctx), GRASS_SUCCESS) << log;
    grass_patch_desc p = grass_default_patch_desc();
    ASSERT_EQ(grass_create_patch(ctx, &p, &patch), GRASS_SUCCESS) << log;
}

void RenderTest::TearDown() {
    if (ctx) grass_destroy_context(ctx);
    ctx = nullptr;
    if (host) {
        EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    }
    host.reset();
}

grass_field_desc RenderTest::field_desc(uint32_t cells) const {
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = d.cells_z = cells;
    d.tiers = &blade_tier;
    d.tier_count = 1;
    d.lod_tests = &blade_band;
    d.lod_test_count = 1;
    return d;
}

grass_field_desc RenderTest::three_tier_field(uint32_t cells) {
    const float bands[3][4] = {{0.0f, 3.0f, 0.0f, 1.0f}, {2.0f, 7.0f, 1.0f, 1.5f}, {5.5f, INFINITY, 1.5f, 0.0f}};
    for (uint32_t t = 0; t < 3; ++t) {
        grass_lod_test& b = three_tier_bands[t];
        b = grass_lod_test{};
        b.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        b.tier = t;
        b.begin = bands[t][0];
        b.end = bands[t][1];
        b.transition_in = bands[t][2];
        b.transition_out = bands[t][3];
    }
    grass_field_desc d = field_desc(cells);
    d.tiers = three_tiers;
    d.tier_count = 3;
    d.lod_tests = three_tier_bands;
    d.lod_test_count = 3;
    return d;
}

grass_field_desc RenderTest::solo_tier_field(uint32_t cells, grass_tier_kind kind, uint32_t slices,
                                             uint32_t max_macro_cells) {
    solo_tier = grass_tier_desc{kind, slices};
    solo_tests[0] = grass_lod_test{};
    solo_tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    solo_tests[0].end = INFINITY;
    solo_tests[1] = grass_lod_test{};
    solo_tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
    solo_tests[1].max_macro_cells = max_macro_cells;
    grass_field_desc d = field_desc(cells);
    d.tiers = &solo_tier;
    d.tier_count = 1;
    d.lod_tests = solo_tests;
    d.lod_test_count = kind == GRASS_TIER_GEOMETRY ? 1 : 2;
    return d;
}

grass_field_id RenderTest::make_field(grass_field_desc d) {
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << log;
    return f;
}

grass_view_desc RenderTest::view(const double eye[3], const double target[3], float fovy_degrees) const {
    return grass_host::make_view(*host, eye, target, fovy_degrees, 0.05f, 100.0f);
}

grass_host::Image RenderTest::render(const grass_view_desc& v, const grass_host::Occluder* occluder) {
    grass_host::Image image;
    std::string error;
    const grass_result r = host->render(ctx, v, occluder, &image, &error);
    EXPECT_EQ(r, GRASS_SUCCESS) << grass_result_string(r) << " " << error << "\n" << log;
    return image;
}

void RenderTest::save(const grass_host::Image& image, const std::string& tag) const {
    const char* dir = std::getenv("GRASS_TEST_IMAGE_DIR");
    if (!dir || image.rgba.empty()) return;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name() + "." + tag + ".png";
    for (char& c : name) {
        if (c == '/') c = '_';
    }
    grass_host::write_png(std::string(dir) + "/" + name, image, nullptr);
}

RenderTest::CameraSteps RenderTest::step_camera(double ox, double oz, int steps, double step_m, double height,
                                                uint32_t cells) {
    constexpr float kFov = 50.0f;
    CameraSteps out;
    const double half = 0.5 * cells * 0.25; // the default cell size
    grass_field_desc d = field_desc(cells);
    d.base_transform[12] = ox;
    d.base_transform[14] = oz;
    const grass_field_id f = make_field(d);
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    for (int k = 0; k <= steps; ++k) {
        const double x = ox + half + step_m * k;
        const double eye[3] = {x, height, oz + half}, target[3] = {x, 0.0, oz + half + 0.0001};
        out.frames.push_back(render(view(eye, target, kFov)));
        out.shift.push_back(grass_centroid_x(out.frames.back(), sky) - grass_centroid_x(out.frames[0], sky));
    }
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    // A ground point moves step * f_px / depth; blades stand up to ~0.21 m (0.25 allowed), so
    // the depth is between height - 0.25 and height.
    const double f_px = 0.5 * host->target().height / std::tan(kFov * 3.141592653589793 / 360.0);
    out.expected_lo = f_px / height * step_m;
    out.expected_hi = f_px / (height - 0.25) * step_m;
    double sxy = 0.0, sxx = 0.0;
    for (int k = 0; k <= steps; ++k) {
        sxy += k * out.shift[k];
        sxx += double(k) * k;
    }
    out.slope = sxy / sxx;
    out.px_per_step = std::fabs(out.slope);
    return out;
}

double grass_centroid_x(const grass_host::Image& image, const uint8_t sky[3]) {
    double sum_w = 0.0, sum_x = 0.0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = image.pixel(x, y);
            const double w = std::abs(p[0] - sky[0]) + std::abs(p[1] - sky[1]) + std::abs(p[2] - sky[2]);
            sum_w += w;
            sum_x += w * (x + 0.5);
        }
    }
    return sum_w > 0.0 ? sum_x / sum_w : 0.0;
}

grass_result create_blade_field(grass_context* ctx, grass_patch_id patch, uint32_t cells, grass_field_id* out) {
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = cells;
    const grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.end = 60.0f;
    fd.tiers = &tier;
    fd.tier_count = 1;
    fd.lod_tests = &band;
    fd.lod_test_count = 1;
    return grass_create_field(ctx, &fd, out);
}

grass_host::Image render_default_scene(grass_backend backend, const grass_host::TargetDesc& target, uint32_t cells,
                                       const double eye[3], const double look[3], int frames,
                                       const SceneFrame& before_frame, const FieldSetup& field_setup) {
    grass_host::Image image;
    std::string error;
    auto host = grass_host::Host::create(backend, target, &error);
    EXPECT_TRUE(host) << error;
    if (!host) return image;
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    EXPECT_EQ(host->create_context(cd, &ctx), GRASS_SUCCESS);
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    EXPECT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_field_id field{};
    EXPECT_EQ(create_blade_field(ctx, patch, cells, &field), GRASS_SUCCESS);
    if (field_setup) field_setup(ctx, field);
    for (int frame = 0; frame < frames; ++frame) {
        grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f, 0.05f, 100.0f);
        if (before_frame) before_frame(ctx, frame, &v);
        EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error;
    }
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    return image;
}

double mean_difference(const grass_host::Image& a, const grass_host::Image& b) {
    if (a.rgba.size() != b.rgba.size() || a.rgba.empty()) return 1e9;
    double sum = 0.0;
    for (size_t k = 0; k < a.rgba.size(); ++k) {
        if (k % 4 != 3) sum += std::abs(int(a.rgba[k]) - int(b.rgba[k]));
    }
    return sum / double(a.rgba.size() / 4 * 3);
}

double share_apart(const grass_host::Image& a, const grass_host::Image& b, int levels) {
    if (a.rgba.size() != b.rgba.size() || a.rgba.empty()) return 1.0;
    size_t apart = 0;
    for (size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        apart += worst > levels;
    }
    return double(apart) / double(a.rgba.size() / 4);
}

grass_host::TargetDesc black_or_white_target(bool white) {
    grass_host::TargetDesc t;
    t.width = t.height = 128;
    t.samples = 4;
    for (int c = 0; c < 3; ++c) t.clear_color[c] = white ? 1.0f : 0.0f;
    return t;
}

void expected_sky(const grass_host::TargetDesc& t, uint8_t out[3]) {
    for (int c = 0; c < 3; ++c) {
        const double l = t.clear_color[c];
        const double s = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
        out[c] = static_cast<uint8_t>(std::lround(s * 255.0));
    }
}

bool is_grass(const uint8_t* p, const uint8_t sky[3], int tolerance) {
    for (int c = 0; c < 3; ++c) {
        if (std::abs(int(p[c]) - int(sky[c])) > tolerance) return true;
    }
    return false;
}

double grass_share(const grass_host::Image& image, const uint8_t sky[3], uint32_t x0, uint32_t y0, uint32_t x1,
                   uint32_t y1) {
    uint64_t n = 0, g = 0;
    for (uint32_t y = y0; y < y1; ++y) {
        for (uint32_t x = x0; x < x1; ++x) {
            ++n;
            g += is_grass(image.pixel(x, y), sky);
        }
    }
    return n ? double(g) / double(n) : 0.0;
}

double expect_grass(const grass_host::Image& image, const grass_host::TargetDesc& target, double min_share,
                    const char* what) {
    if (image.rgba.empty()) {
        ADD_FAILURE() << what << ": no image";
        return 0.0;
    }
    uint8_t sky[3];
    expected_sky(target, sky);
    const double share = grass_share(image, sky, 0, 0, image.width, image.height);
    EXPECT_GE(share, min_share) << what << ": too little grass for the comparison to mean anything";
    return share;
}

void look_at_basis(const double eye[3], const double target[3], double f[3], double r[3], double u[3]) {
    for (int c = 0; c < 3; ++c) f[c] = target[c] - eye[c];
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int c = 0; c < 3; ++c) f[c] /= fl;
    const double up[3] = {0.0, 1.0, 0.0}, alt_up[3] = {0.0, 0.0, -1.0};
    const double* u0 = std::fabs(f[1]) > 0.9999 ? alt_up : up;
    r[0] = f[1] * u0[2] - f[2] * u0[1];
    r[1] = f[2] * u0[0] - f[0] * u0[2];
    r[2] = f[0] * u0[1] - f[1] * u0[0];
    const double rl = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int c = 0; c < 3; ++c) r[c] /= rl;
    u[0] = r[1] * f[2] - r[2] * f[1];
    u[1] = r[2] * f[0] - r[0] * f[2];
    u[2] = r[0] * f[1] - r[1] * f[0];
}

bool project_point(const double eye[3], const double target[3], float fovy_degrees, uint32_t width, uint32_t height,
                   const double point[3], double* out_x, double* out_y) {
    double f[3], r[3], u[3];
    look_at_basis(eye, target, f, r, u);
    const double d[3] = {point[0] - eye[0], point[1] - eye[1], point[2] - eye[2]};
    const double z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    if (z <= 0.0) return false;
    const double t = std::tan(fovy_degrees * 3.141592653589793 / 360.0);
    const double aspect = double(width) / double(height);
    const double nx = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / (z * t * aspect);
    const double ny = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / (z * t);
    *out_x = (nx + 1.0) * 0.5 * width;
    *out_y = (1.0 - ny) * 0.5 * height;
    return true;
}

grass_patch_id create_turf_patch(grass_context* ctx, uint64_t seed, std::string* log) {
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 1200;
    pd.subdivisions = 3;
    pd.length_min = 0.35f;
    pd.length_max = 0.6f;
    pd.width_min = 0.02f;
    pd.width_max = 0.03f;
    pd.tilt_min = 0.05f;
    pd.tilt_max = 0.45f;
    pd.threshold_mode = GRASS_THRESHOLD_UNIFORM;
    pd.seed = seed;
    grass_patch_id id{};
    EXPECT_EQ(grass_create_patch(ctx, &pd, &id), GRASS_SUCCESS) << *log;
    return id;
}

} // namespace grass_test
