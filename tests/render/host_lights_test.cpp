// The host's lights (grass_view_lights_desc; docs/engine-frames.md "The host's lights"): a field
// of geometry, volume and image tiers (RenderTest::three_tier_field) lit by the host's
// directional, point and spot lights and ambient harmonics, checked against the sun, whose
// lighting every tier has had since lemme2012 6.4.3:
// - a directional light with the sun's direction and colour, the sun off, draws the sun's
//   picture; so do a point light far along the sun's direction with intensity x d^2 and a
//   spot there aimed at the field: the falloff, the window and the cone in every tier;
// - a point light out of range and a spot aimed away light nothing (the sun-off picture);
// - an empty struct, and harmonics holding just the ambient colour, draw the plain picture;
// - Kajiya-Kay specular brightens the blades and the slices alike where it should;
// - refusals name the field and begin no frame;
// - GL: a view without it keeps its programs (no GrassLights block) and a lit view leaves the
//   host's uniform binding 4; Vulkan: a view without it makes nothing for it;
// - GL and Vulkan draw the same picture under a point light, a spot, specular and harmonics.
// The same thresholds on both backends.
// The tiers against the blades under a near point light, a spot, the harmonics and the
// specular, within the seed spread: SliceColourTest's host-light cases.
#include "gl_program_spy.hpp"
#include "render_fixture.hpp"
#ifdef GRASS_HOST_HAS_VULKAN
#    include "vk_intercept.hpp"
#endif

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
        start_on(GetParam());
    }
    // The host and context of `backend` (the test's, or GL for the agreement test) and the field.
    void start_on(grass_backend backend) {
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 96;
        if (backend == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_program_spy_filter;
#ifdef GRASS_HOST_HAS_VULKAN
        if (backend == GRASS_BACKEND_VULKAN) t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr();
#endif
        start(t, backend);
        make_field(three_tier_field(kCells));
    }
    // The camera 1.7 m up looking over the field: blades near, the volume and the image tier
    // beyond. `lights` chained (nullptr: none); `sun`: false turns the sun off.
    // `eye`: another camera position.
    grass_view_desc camera(const grass_view_lights_desc* lights, bool sun = true, const double* eye = kEye) {
        grass_view_desc v = view(eye, kTarget, 60.0f);
        std::memcpy(v.sun_direction, kSun, sizeof kSun);
        if (!sun) v.sun_color[0] = v.sun_color[1] = v.sun_color[2] = 0.0f;
        lod_origin_ = grass_default_lod_origin_desc();
        std::memcpy(lod_origin_.position, eye, sizeof kEye);
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

// A point light 1 m over the near grass, a spot from above the middle distance, specular and
// a sky brighter above than below: every term of the lights' shading at once.
struct ManyLights {
    grass_light lights[2];
    grass_view_lights_desc desc;
    ManyLights() : lights{grass_default_light(), grass_default_light()}, desc(grass_default_view_lights_desc()) {
        const double near[3] = {6.0, 1.0, 2.0}, above[3] = {5.0, 4.0, 7.0};
        std::memcpy(lights[0].position, near, sizeof near);
        lights[0].intensity = 4.0f;
        grass_light& spot = lights[1];
        spot.kind = GRASS_LIGHT_SPOT;
        std::memcpy(spot.position, above, sizeof above);
        const float down[3] = {0.2f, -1.0f, 0.1f};
        std::memcpy(spot.direction, down, sizeof down);
        spot.color[0] = 1.0f;
        spot.color[1] = 0.8f;
        spot.color[2] = 0.6f;
        spot.intensity = 40.0f;
        spot.inner_cone_angle = 0.3f;
        spot.outer_cone_angle = 0.6f;
        desc.light_count = 2;
        desc.lights = lights;
        desc.specular_strength = 0.4f;
        desc.specular_exponent = 12.0f;
        desc.ambient_sh_enabled = 1;
        const grass_view_desc v = grass_default_view_desc();
        for (int c = 0; c < 3; ++c) {
            desc.ambient_sh[0][c] = v.ambient_color[c] / 0.282095f;
            desc.ambient_sh[1][c] = 0.6f;
        }
    }
};

#if defined(GRASS_HOST_HAS_VULKAN) && defined(GRASS_HOST_HAS_GL)
// GL and Vulkan draw the same lit picture (ManyLights), within the single-sampled tolerance of
// BackendAgreement (0.05 levels a pixel on average, 0.05% of pixels more than 32 levels apart),
// from 4 m up (from the other tests' 1.7 m the plain pictures alone are 0.064 levels apart:
// the near blades' edges at a grazing angle).
TEST_P(HostLightsTest, GlAndVulkanDrawTheSameLitPicture) {
    const double kHigh[3] = {6.0, 4.0, -1.0};
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "runs once, from the Vulkan instance";
    const ManyLights many;
    grass_host::Image images[2];
    const grass_host::Image plain = render(camera(nullptr, true, kHigh));
    const grass_backend backends[2] = {GRASS_BACKEND_VULKAN, GRASS_BACKEND_GL};
    for (int b = 0; b < 2; ++b) {
        if (b == 1) start_on(GRASS_BACKEND_GL);
        images[b] = render(camera(&many.desc, true, kHigh));
        save(images[b], std::string("agreement_") + backend_name(backends[b]));
        ASSERT_EQ(images[b].rgba.size(), size_t(160) * 96 * 4) << log;
        EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log(); // the Vulkan host goes next
    }
    // Not a comparison of two skies: the lights change much of the grass.
    EXPECT_GT(changed_share(images[0], plain), 0.2) << "the lights change the Vulkan picture";
    const double mean = mean_difference(images[0], images[1]), share = share_apart(images[0], images[1], 32);
    std::printf("[ measured ] lit: mean |gl - vk| %.4f levels, %.4f%% of pixels > 32 apart\n", mean, 100.0 * share);
    EXPECT_LE(mean, 0.05);
    EXPECT_LE(share, 0.0005);
}
#endif

#ifdef GRASS_HOST_HAS_VULKAN
// Vulkan: a context whose views use no lights makes and holds nothing for them (no lit
// pipeline, no GrassLights block, none of the view extras' layouts or pool); the first lit
// view makes its blade, volume and image pipelines, its block, set 1's and set 2's layouts,
// the extras' pipeline layout and pool, and nothing for shadows or motion; a plain view
// afterwards makes nothing and draws the picture it drew.
TEST_P(HostLightsTest, AVulkanViewWithoutItMakesNothingForIt) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan objects";
    namespace vi = vk_intercept;
    vi::clear_debug_records();      // what earlier tests of the process made
    start_on(GRASS_BACKEND_VULKAN); // a context made since
    // The objects grass made and named since the context began whose name says `what` and `kind`.
    const auto named = [](const char* what, const char* kind) {
        size_t n = 0;
        for (const auto& name : vi::names())
            n += name.second.find(what) != std::string::npos && name.second.find(kind) != std::string::npos;
        return n;
    };
    grass_host::Image plain;
    for (int frame = 0; frame < 3; ++frame) plain = render(camera(nullptr)); // every frame slot's objects made
    const vi::Live plain_live = vi::live();
    EXPECT_EQ(named(" lit ", ""), 0u) << "lit pipelines before any lit view";
    EXPECT_EQ(named("lights", ""), 0u) << "a lights block before any lit view";
    EXPECT_EQ(named("view extras", ""), 0u) << "the view extras' objects before any lit view";

    const ManyLights many;
    const grass_host::Image lit = render(camera(&many.desc));
    EXPECT_GT(changed_share(lit, plain), 0.2) << "the lit view drew the plain picture";
    const vi::Live lit_live = vi::live();
    EXPECT_GE(lit_live.pipelines_made - plain_live.pipelines_made, 3) << "the lit pipelines";
    EXPECT_EQ(named(" lit ", "pipelines"), 3u) << "the blade, volume and image tier lit pipelines";
    EXPECT_EQ(named("lights", "block"), 1u) << "the GrassLights block of the view slot";
    EXPECT_EQ(named("view extras", "pool"), 1u) << "the view extras' descriptor pool";
    EXPECT_EQ(named("view extras", "layout"), 3u) << "the view extras' two set layouts and pipeline layout";
    EXPECT_EQ(named("shadow", ""), 0u) << "a lit view made objects for receiving shadows";
    EXPECT_EQ(named("motion", ""), 0u) << "a lit view made objects for motion vectors";

    const grass_host::Image again = render(camera(nullptr));
    EXPECT_EQ(vi::live().pipelines_made, lit_live.pipelines_made) << "a plain view after a lit one";
    EXPECT_EQ(again.rgba, plain.rgba);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
}
#endif

INSTANTIATE_TEST_SUITE_P(Backends, HostLightsTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
