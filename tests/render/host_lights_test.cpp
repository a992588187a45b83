// The host's lights (grass_view_lights_desc; docs/integration.md "The host's lights"): a field
// of geometry, volume and image tiers (RenderTest::three_tier_field) lit by the host's
// directional, point and spot lights and ambient harmonics, checked against the sun, whose
// lighting every tier has had since lemme2012 6.4.3:
// - a directional light with the sun's direction and colour, the sun off, draws the sun's
//   picture; so do a point light far along the sun's direction with intensity x d^2 and a
//   spot there aimed at the field: the falloff, the window and the cone in every tier;
// - a point light out of range and a spot aimed away light nothing (the sun-off picture);
// - an empty struct, and harmonics holding just the ambient colour, draw the plain picture;
// - Kajiya-Kay specular brightens the blades and the slices alike where it should;
// - refusals name the field and begin no frame; Vulkan refuses the struct for now;
// - GL: a view without it keeps its programs (no GrassLights block) and a lit view leaves the
//   host's uniform binding 4.
// The tiers against the blades under a near point light, a spot, the harmonics and the
// specular, within the seed spread: SliceColourTest's host-light cases.
#include "gl_program_spy.hpp"
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <set>
#include <string>

namespace grass_test {
namespace {

constexpr uint32_t kCells = 48; // 12 m x 12 m
const double kEye[3] = {6.0, 1.7, -1.0}, kTarget[3] = {6.0, 0.0, 6.0};
const float kSun[3] = {0.35f, 0.8f, 0.25f}; // grass_view_desc's default sun

// Largest channel difference of two images, in 8-bit levels, and the share of pixels that
// differ from `other` by more than 6 levels (how much of the picture a light changed).
int max_difference(const grass_host::Image& a, const grass_host::Image& b) {
    int worst = 0;
    for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
        worst = std::max(worst, std::abs(a.rgba[i] - b.rgba[i]));
    return worst;
}
double changed_share(const grass_host::Image& a, const grass_host::Image& b) {
    size_t changed = 0;
    for (size_t p = 0; p + 3 < a.rgba.size() && p + 3 < b.rgba.size(); p += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.rgba[p + c] - b.rgba[p + c]));
        changed += d > 6 ? 1u : 0u;
    }
    return a.rgba.empty() ? 0.0 : double(changed) / double(a.rgba.size() / 4);
}

// The mean gain of green from `a` to `b` over rows [y0, y1), in levels, and how many pixels
// there lost more than a level.
double green_gain(const grass_host::Image& a, const grass_host::Image& b, uint32_t y0, uint32_t y1, int* darker) {
    double gain = 0.0;
    *darker = 0;
    for (uint32_t y = y0; y < y1; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            const int g = int(b.pixel(x, y)[1]) - int(a.pixel(x, y)[1]);
            gain += g;
            *darker += g < -1 ? 1 : 0;
        }
    }
    return gain / double((y1 - y0) * a.width);
}

class HostLightsTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 96;
        if (GetParam() == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_program_spy_filter;
        start(t);
        make_field(three_tier_field(kCells));
    }
    // The camera 1.7 m up looking over the field: blades near, the volume and the image tier
    // beyond. `lights` chained (nullptr: none); `sun`: false turns the sun off.
    grass_view_desc camera(const grass_view_lights_desc* lights, bool sun = true) {
        grass_view_desc v = view(kEye, kTarget, 60.0f);
        std::memcpy(v.sun_direction, kSun, sizeof kSun);
        if (!sun) v.sun_color[0] = v.sun_color[1] = v.sun_color[2] = 0.0f;
        lod_origin_ = grass_default_lod_origin_desc();
        std::memcpy(lod_origin_.position, kEye, sizeof kEye);
        lod_origin_.next = lights;
        v.next = &lod_origin_;
        return v;
    }
    // One light in a struct.
    grass_view_lights_desc one(const grass_light& l) {
        light_ = l;
        grass_view_lights_desc d = grass_default_view_lights_desc();
        d.light_count = 1;
        d.lights = &light_;
        return d;
    }
    // The sun's colour as a light's colour x intensity.
    void sun_colour(grass_light* l, double scale) const {
        const grass_view_desc v = grass_default_view_desc();
        for (int c = 0; c < 3; ++c) l->color[c] = v.sun_color[c];
        l->intensity = static_cast<float>(scale);
    }
    // A point `distance` m from the field's centre along the sun's direction.
    static void along_sun(double distance, double out[3]) {
        const double n = std::sqrt(double(kSun[0]) * kSun[0] + double(kSun[1]) * kSun[1] + double(kSun[2]) * kSun[2]);
        const double centre[3] = {6.0, 0.0, 6.0};
        for (int c = 0; c < 3; ++c) out[c] = centre[c] + distance * kSun[c] / n;
    }
    grass_light light_{};
    grass_lod_origin_desc lod_origin_{};
};

TEST_P(HostLightsTest, ADirectionalLightWithTheSunsDirectionAndColourIsTheSun) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan refuses the struct (RefusalsNameTheField)";
    const grass_host::Image sunlit = render(camera(nullptr));
    const grass_host::Image dark = render(camera(nullptr, false));
    save(sunlit, "sunlit");
    ASSERT_GT(changed_share(sunlit, dark), 0.3) << "the sun lights most of the picture";
    grass_light l = grass_default_light();
    l.kind = GRASS_LIGHT_DIRECTIONAL;
    std::memcpy(l.direction, kSun, sizeof kSun);
    sun_colour(&l, 1.0);
    const grass_view_lights_desc d = one(l);
    const grass_host::Image lit = render(camera(&d, false));
    save(lit, "directional");
    ASSERT_FALSE(lit.rgba.empty()) << log;
    EXPECT_LE(max_difference(lit, sunlit), 2) << "a directional light drew another picture than the sun";
    EXPECT_LT(mean_difference(lit, sunlit), 0.2);
}

TEST_P(HostLightsTest, AFarPointLightAndAWideSpotAreTheSunAndOutOfReachTheyLightNothing) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan refuses the struct (RefusalsNameTheField)";
    const grass_host::Image sunlit = render(camera(nullptr));
    const grass_host::Image dark = render(camera(nullptr, false));
    ASSERT_GT(changed_share(sunlit, dark), 0.3);
    const double distance = 2000.0; // the field's 12 m then spans 0.3 degrees of the light's directions
    grass_light point = grass_default_light();
    along_sun(distance, point.position);
    sun_colour(&point, distance * distance);
    point.range = 1e7f; // the window (1 - (d / range)^4)^2 is 1 to 1e-15
    grass_view_lights_desc d = one(point);
    const grass_host::Image from_point = render(camera(&d, false));
    save(from_point, "point");
    EXPECT_LE(max_difference(from_point, sunlit), 3) << "a far point light, intensity x d^2, is the sun";
    EXPECT_LT(mean_difference(from_point, sunlit), 0.3);

    grass_light spot = point;
    spot.kind = GRASS_LIGHT_SPOT;
    for (int c = 0; c < 3; ++c) spot.direction[c] = -kSun[c]; // aimed at the field
    spot.inner_cone_angle = 0.2f;
    spot.outer_cone_angle = 0.3f;
    d = one(spot);
    const grass_host::Image from_spot = render(camera(&d, false));
    save(from_spot, "spot");
    EXPECT_LE(max_difference(from_spot, sunlit), 3) << "a spot aimed at the field, wide enough, is the sun";

    spot.direction[1] = -spot.direction[1]; // aimed up, away from the field
    d = one(spot);
    EXPECT_LE(max_difference(render(camera(&d, false)), dark), 1) << "a spot aimed away lights nothing";
    point.range = static_cast<float>(distance * 0.9);
    d = one(point);
    EXPECT_LE(max_difference(render(camera(&d, false)), dark), 1) << "a point light out of range lights nothing";
}

TEST_P(HostLightsTest, AnEmptyStructAndHarmonicsOfTheAmbientColourDrawThePlainPicture) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan refuses the struct (RefusalsNameTheField)";
    const grass_host::Image plain = render(camera(nullptr));
    grass_view_lights_desc d = grass_default_view_lights_desc();
    EXPECT_LE(max_difference(render(camera(&d)), plain), 1) << "no lights, no specular, no harmonics";
    const grass_view_desc v = grass_default_view_desc();
    d.ambient_sh_enabled = 1;
    for (int c = 0; c < 3; ++c) d.ambient_sh[0][c] = v.ambient_color[c] / 0.282095f;
    EXPECT_LE(max_difference(render(camera(&d)), plain), 1) << "harmonics of a constant ambient colour";
    // A sky brighter above than below (the order-1 y term) lights the grass more, near
    // (blades) and far (slices): their normals lean up on the side that faces the camera
    // (a blade facing down gets darker).
    d.ambient_sh[1][0] = d.ambient_sh[1][1] = d.ambient_sh[1][2] = 1.0f;
    const grass_host::Image sky = render(camera(&d));
    save(sky, "harmonics");
    const uint32_t h = plain.height;
    for (const auto& rows :
         {std::pair<uint32_t, uint32_t>{h * 3 / 4, h}, std::pair<uint32_t, uint32_t>{h / 2, h * 5 / 8}}) {
        int darker = 0;
        const double gain = green_gain(plain, sky, rows.first, rows.second, &darker);
        std::printf("[ measured ] %s rows %u-%u: an order-1 sky term adds %.1f levels of green, %d pixels darker\n",
                    backend_name(GetParam()).c_str(), rows.first, rows.second, gain, darker);
        EXPECT_GT(gain, 2.0) << "rows " << rows.first << "-" << rows.second; // blades facing down get darker
    }
}

TEST_P(HostLightsTest, SpecularBrightensEveryTier) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan refuses the struct (RefusalsNameTheField)";
    // A low sun ahead of the camera: its half vector with the view is near level, across the
    // blades' tangents, where Kajiya-Kay's highlight is.
    grass_view_lights_desc d = grass_default_view_lights_desc();
    grass_view_desc v = camera(&d);
    const float ahead[3] = {0.0f, 0.3f, 1.0f};
    std::memcpy(v.sun_direction, ahead, sizeof ahead);
    const grass_host::Image matte = render(v);
    d.specular_strength = 0.5f;
    d.specular_exponent = 8.0f;
    const grass_host::Image shiny = render(v);
    save(shiny, "specular");
    // Brighter, never darker, over most of the picture: near (blades) and far (slices) rows.
    const uint32_t h = matte.height;
    for (const auto& rows :
         {std::pair<uint32_t, uint32_t>{h * 3 / 4, h}, std::pair<uint32_t, uint32_t>{h / 2, h * 5 / 8}}) {
        int darker = 0;
        const double gain = green_gain(matte, shiny, rows.first, rows.second, &darker);
        std::printf("[ measured ] %s rows %u-%u: specular adds %.1f levels of green, %d pixels darker\n",
                    backend_name(GetParam()).c_str(), rows.first, rows.second, gain, darker);
        EXPECT_GT(gain, 2.0) << "rows " << rows.first << "-" << rows.second;
        EXPECT_EQ(darker, 0) << "rows " << rows.first << "-" << rows.second;
    }
}

TEST_P(HostLightsTest, RefusalsNameTheFieldAndBeginNoFrame) {
    grass_light l = grass_default_light();
    grass_view_lights_desc d = one(l);
    struct Case {
        const char* field;
        std::function<void(grass_view_lights_desc*, grass_light*)> spoil;
    };
    const Case cases[] = {
        {"light_count", [](grass_view_lights_desc* x, grass_light*) { x->light_count = GRASS_MAX_VIEW_LIGHTS + 1; }},
        {"lights", [](grass_view_lights_desc* x, grass_light*) { x->lights = nullptr; }},
        {"lights[0].kind", [](grass_view_lights_desc*, grass_light* y) { y->kind = static_cast<grass_light_kind>(7); }},
        {"lights[0].position", [](grass_view_lights_desc*, grass_light* y) { y->position[1] = NAN; }},
        {"lights[0].range", [](grass_view_lights_desc*, grass_light* y) { y->range = 0.0f; }},
        {"lights[0].color[2]", [](grass_view_lights_desc*, grass_light* y) { y->color[2] = -1.0f; }},
        {"lights[0].inner_cone_angle",
         [](grass_view_lights_desc*, grass_light* y) {
             y->kind = GRASS_LIGHT_SPOT;
             y->inner_cone_angle = 0.5f;
             y->outer_cone_angle = 0.5f;
         }},
        {"lights[0].direction",
         [](grass_view_lights_desc*, grass_light* y) {
             y->kind = GRASS_LIGHT_DIRECTIONAL;
             y->direction[0] = y->direction[1] = y->direction[2] = 0.0f;
         }},
        {"specular_strength", [](grass_view_lights_desc* x, grass_light*) { x->specular_strength = 2.0f; }},
        {"specular_exponent", [](grass_view_lights_desc* x, grass_light*) { x->specular_exponent = 0.5f; }},
        {"ambient_sh", [](grass_view_lights_desc* x, grass_light*) {
             x->ambient_sh_enabled = 1;
             x->ambient_sh[4][1] = INFINITY;
         }}};
    for (const Case& c : cases) {
        grass_view_lights_desc bad = d;
        grass_light spoiled = l;
        bad.lights = &spoiled;
        c.spoil(&bad, &spoiled);
        log.clear();
        const grass_view_desc v = camera(&bad);
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT) << c.field;
        EXPECT_NE(log.find(std::string("grass_view_lights_desc->") + c.field), std::string::npos)
            << c.field << ": " << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << c.field << ": a frame was begun";
    }
    const grass_view_desc v = camera(&d);
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        log.clear();
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_UNSUPPORTED);
        EXPECT_NE(log.find("grass_view_lights_desc"), std::string::npos) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE);
        return;
    }
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS) << log;
}

TEST_P(HostLightsTest, AViewWithoutItKeepsItsProgramsAndTheHostsBinding) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "GL programs and state";
    auto get_block = reinterpret_cast<PFNGLGETUNIFORMBLOCKINDEXPROC>(host->gl_proc_address("glGetUniformBlockIndex"));
    auto create_buffers = reinterpret_cast<PFNGLCREATEBUFFERSPROC>(host->gl_proc_address("glCreateBuffers"));
    auto buffer_data = reinterpret_cast<PFNGLNAMEDBUFFERDATAPROC>(host->gl_proc_address("glNamedBufferData"));
    auto bind_range = reinterpret_cast<PFNGLBINDBUFFERRANGEPROC>(host->gl_proc_address("glBindBufferRange"));
    auto get_i = reinterpret_cast<PFNGLGETINTEGERI_VPROC>(host->gl_proc_address("glGetIntegeri_v"));
    auto delete_buffers = reinterpret_cast<PFNGLDELETEBUFFERSPROC>(host->gl_proc_address("glDeleteBuffers"));
    ASSERT_TRUE(get_block && create_buffers && buffer_data && bind_range && get_i && delete_buffers);
    gl_program_spy().used.clear();
    const grass_host::Image plain = render(camera(nullptr));
    const std::set<GLuint> plain_programs = gl_program_spy().used;
    ASSERT_GE(plain_programs.size(), 3u) << "a program per tier kind";
    for (const GLuint program : plain_programs) EXPECT_EQ(get_block(program, "GrassLights"), GL_INVALID_INDEX);
    const int64_t plain_created = gl_program_spy().created;

    GLuint host_buffer = 0;
    create_buffers(1, &host_buffer);
    buffer_data(host_buffer, 2048, nullptr, GL_STATIC_DRAW);
    bind_range(GL_UNIFORM_BUFFER, 4, host_buffer, 256, 1024);
    grass_light l = grass_default_light();
    l.position[0] = 6.0;
    l.position[1] = 1.0;
    l.position[2] = 2.0;
    l.intensity = 4.0f;
    const grass_view_lights_desc d = one(l);
    gl_program_spy().used.clear();
    const grass_host::Image lit = render(camera(&d));
    save(lit, "near_point");
    EXPECT_GT(changed_share(lit, plain), 0.05) << "a point light 1 m over the near grass";
    EXPECT_GE(gl_program_spy().created - plain_created, 3) << "a lit view compiles its own variants";
    for (const GLuint program : gl_program_spy().used) {
        EXPECT_EQ(plain_programs.count(program), 0u) << "the lit view drew with a plain view's program";
        EXPECT_NE(get_block(program, "GrassLights"), GL_INVALID_INDEX);
    }
    GLint buffer = 0;
    get_i(GL_UNIFORM_BUFFER_BINDING, 4, &buffer);
    EXPECT_EQ(GLuint(buffer), host_buffer) << "uniform binding 4";

    const int64_t before = gl_program_spy().created;
    gl_program_spy().used.clear();
    const grass_host::Image again = render(camera(nullptr));
    EXPECT_EQ(gl_program_spy().created, before);
    EXPECT_EQ(gl_program_spy().used, plain_programs);
    EXPECT_EQ(again.rgba, plain.rgba);
    delete_buffers(1, &host_buffer);
}

INSTANTIATE_TEST_SUITE_P(Backends, HostLightsTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
