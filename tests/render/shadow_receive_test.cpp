// Receiving the host's shadows (grass_shadow_receive_desc; docs/integration.md "Receiving the
// host's shadows"): a field of geometry, volume and image tiers seen by an orthographic
// camera 45 degrees down, and a shadow map the test makes itself (a GL_TEXTURE_2D_ARRAY of
// depth, top-down: u = x / 12 m, v = z / 12 m). Each grass pixel's world point comes back
// from the depth buffer. Where the map shadows a point, the picture is the one drawn with
// the sun off (the sun term gone, the ambient kept); where it lights it, the one drawn
// without receiving; in every tier:
// - a half-plane occluder (x < 6 m), in both comparison conventions; with a filter radius
//   the edge has intermediate values;
// - two cascades, chosen by cascade_end along the view axis (the second shadows all);
// - refusals (bad count, NaN matrix, descending ends, zero map) begin no frame; Vulkan
//   refuses the struct (GRASS_ERROR_UNSUPPORTED);
// - a view without it draws with programs that declare no GrassShadow block, and a
//   receiving view compiles its own and leaves the host's unit 14 and uniform binding 2.
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

namespace grass_test {
namespace {

constexpr uint32_t kSize = 128;         // the target, pixels
constexpr uint32_t kCells = 48;         // 12 m x 12 m
const double kEye[3] = {6.0, 1.0, 2.0}; // the lod origin: the tiers by distance from it
constexpr double kHalf = 7.0;           // the camera's half extent, metres
constexpr double kNear = 1.0, kFar = 40.0;
const double kCamera[3] = {6.0, 10.0, -4.0}, kAt[3] = {6.0, 0.0, 6.0}; // 45 degrees down, looking +z
constexpr int kMapTexels = 64; // the shadow map's layers, texels a side (0.1875 m each)

// The programs grass binds (glUseProgram) and creates, through the host's GL loader.
struct GlSeen {
    std::set<GLuint> used;
    int64_t created = 0;
    PFNGLUSEPROGRAMPROC use_program = nullptr;
    PFNGLCREATEPROGRAMPROC create_program = nullptr;
} gl_seen;

void APIENTRY seen_use_program(GLuint program) {
    if (program != 0) gl_seen.used.insert(program);
    gl_seen.use_program(program);
}
GLuint APIENTRY seen_create_program() {
    gl_seen.created += 1;
    return gl_seen.create_program();
}
void (*gl_filter(const char* name, void (*real)(void)))(void) {
    if (std::strcmp(name, "glUseProgram") == 0) {
        gl_seen.use_program = reinterpret_cast<PFNGLUSEPROGRAMPROC>(real);
        return reinterpret_cast<void (*)(void)>(&seen_use_program);
    }
    if (std::strcmp(name, "glCreateProgram") == 0) {
        gl_seen.create_program = reinterpret_cast<PFNGLCREATEPROGRAMPROC>(real);
        return reinterpret_cast<void (*)(void)>(&seen_create_program);
    }
    return real;
}

struct Gl {
    PFNGLCREATETEXTURESPROC CreateTextures;
    PFNGLTEXTURESTORAGE3DPROC TextureStorage3D;
    PFNGLTEXTURESUBIMAGE3DPROC TextureSubImage3D;
    PFNGLDELETETEXTURESPROC DeleteTextures;
    PFNGLACTIVETEXTUREPROC ActiveTexture;
    PFNGLBINDTEXTUREPROC BindTexture;
    PFNGLGETINTEGERVPROC GetIntegerv;
    PFNGLGETINTEGERI_VPROC GetIntegeri_v;
    PFNGLCREATEBUFFERSPROC CreateBuffers;
    PFNGLNAMEDBUFFERDATAPROC NamedBufferData;
    PFNGLBINDBUFFERRANGEPROC BindBufferRange;
    PFNGLDELETEBUFFERSPROC DeleteBuffers;
    PFNGLGETUNIFORMBLOCKINDEXPROC GetUniformBlockIndex;
};

template <class T>
void load(const grass_host::Host& host, T* fn, const char* name) {
    *fn = reinterpret_cast<T>(host.gl_proc_address(name));
    ASSERT_NE(*fn, nullptr) << name;
}

// Which tier draws a point: well inside one band of make_tiered_field (no transition).
enum Region { kGeometry, kVolume, kImage, kNone };
Region tier_region(const double p[3]) {
    const double d = std::sqrt((p[0] - kEye[0]) * (p[0] - kEye[0]) + (p[1] - kEye[1]) * (p[1] - kEye[1]) +
                               (p[2] - kEye[2]) * (p[2] - kEye[2]));
    return d < 1.9 ? kGeometry : d > 3.2 && d < 4.8 ? kVolume : d > 7.5 ? kImage : kNone;
}
const char* const kRegionNames[3] = {"geometry", "volume", "image"};

class ShadowReceiveTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.read_depth = true;
        if (GetParam() == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_filter;
        start(t);
        if (GetParam() == GRASS_BACKEND_GL) {
            load(*host, &gl.CreateTextures, "glCreateTextures");
            load(*host, &gl.TextureStorage3D, "glTextureStorage3D");
            load(*host, &gl.TextureSubImage3D, "glTextureSubImage3D");
            load(*host, &gl.DeleteTextures, "glDeleteTextures");
            load(*host, &gl.ActiveTexture, "glActiveTexture");
            load(*host, &gl.BindTexture, "glBindTexture");
            load(*host, &gl.GetIntegerv, "glGetIntegerv");
            load(*host, &gl.GetIntegeri_v, "glGetIntegeri_v");
            load(*host, &gl.CreateBuffers, "glCreateBuffers");
            load(*host, &gl.NamedBufferData, "glNamedBufferData");
            load(*host, &gl.BindBufferRange, "glBindBufferRange");
            load(*host, &gl.DeleteBuffers, "glDeleteBuffers");
            load(*host, &gl.GetUniformBlockIndex, "glGetUniformBlockIndex");
        }
    }
    void TearDown() override {
        if (map_ != 0) gl.DeleteTextures(1, &map_);
        RenderTest::TearDown();
    }

    // Geometry near the lod origin, a volume of 2 slices, the horizontal slice far.
    void make_tiered_field() { make_field(three_tier_field(kCells)); }

    // The orthographic camera (GL's clip convention), its lod origin kEye; `shadow` chained
    // when given.
    grass_view_desc camera(const grass_shadow_receive_desc* shadow) {
        grass_view_desc v = view(kCamera, kAt);
        std::memset(v.projection, 0, sizeof v.projection);
        v.projection[0] = float(1.0 / kHalf);
        v.projection[5] = float(1.0 / kHalf);
        v.projection[10] = float(-2.0 / (kFar - kNear));
        v.projection[14] = float(-(kFar + kNear) / (kFar - kNear));
        v.projection[15] = 1.0f;
        lod_origin_ = grass_default_lod_origin_desc();
        std::memcpy(lod_origin_.position, kEye, sizeof kEye);
        lod_origin_.next = shadow;
        v.next = &lod_origin_;
        return v;
    }

    // The world point of pixel (x, y) (top row first) at its window depth, and its distance
    // along the view axis from the camera.
    void world_point(uint32_t x, uint32_t y, float depth, double out[3], double* along) const {
        double f[3], r[3], u[3];
        look_at_basis(kCamera, kAt, f, r, u);
        const double nx = (x + 0.5) / kSize * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / kSize * 2.0;
        const double nz = 2.0 * depth - 1.0;
        const double ze = (nz + (kFar + kNear) / (kFar - kNear)) / (-2.0 / (kFar - kNear)); // eye z (negative)
        *along = -ze;
        for (int c = 0; c < 3; ++c) out[c] = kCamera[c] + r[c] * nx * kHalf + u[c] * ny * kHalf + f[c] * *along;
    }

    // The map: `layers` layers of kMapTexels^2 depths, value(layer, u, v).
    template <class Value>
    void make_map(int layers, Value value) {
        if (map_ != 0) gl.DeleteTextures(1, &map_);
        gl.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, &map_);
        gl.TextureStorage3D(map_, 1, GL_DEPTH_COMPONENT32F, kMapTexels, kMapTexels, layers);
        std::vector<float> texels(size_t(kMapTexels) * kMapTexels * layers);
        for (int l = 0; l < layers; ++l) {
            for (int j = 0; j < kMapTexels; ++j) {
                for (int i = 0; i < kMapTexels; ++i) {
                    texels[(size_t(l) * kMapTexels + j) * kMapTexels + i] =
                        value(l, (i + 0.5) / kMapTexels, (j + 0.5) / kMapTexels);
                }
            }
        }
        gl.TextureSubImage3D(map_, 0, 0, 0, 0, kMapTexels, kMapTexels, layers, GL_DEPTH_COMPONENT, GL_FLOAT,
                             texels.data());
    }

    // A receiving desc over map_: every cascade top-down (u = x / 12, v = z / 12), the
    // point's depth 0.5 -+ 0.01 y (nearer the light higher up).
    grass_shadow_receive_desc receive(grass_shadow_compare compare, uint32_t cascades) const {
        grass_shadow_receive_desc d = grass_default_shadow_receive_desc();
        d.shadow_map = map_;
        d.cascade_count = cascades;
        d.compare = compare;
        d.depth_bias = 0.0f;
        d.filter_radius = 0.0f;
        for (uint32_t i = 0; i < cascades; ++i) {
            float* m = d.world_to_shadow[i];
            std::memset(m, 0, sizeof(float) * 16);
            m[0] = 1.0f / 12.0f;                                                // u from x
            m[9] = 1.0f / 12.0f;                                                // v from z
            m[6] = compare == GRASS_SHADOW_COMPARE_LESS_EQUAL ? -0.01f : 0.01f; // depth from y
            m[14] = 0.5f;
            m[15] = 1.0f;
        }
        return d;
    }

    // The pixels of `image` classified against `lit` (drawn without receiving) and `dark`
    // (the sun off): per tier region, how many grass pixels `shadowed(point, along)` says
    // are shadowed / lit, and how many of those differ from what they should equal by more
    // than 1 level.
    struct Tally {
        size_t shadowed[3] = {}, lit[3] = {}, wrong_shadowed[3] = {}, wrong_lit[3] = {};
        size_t points = 0, off_ground = 0;
    };
    template <class Shadowed>
    Tally tally(const grass_host::Image& image, const grass_host::Image& lit, const grass_host::Image& dark,
                Shadowed shadowed) const {
        Tally t;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                const float depth = lit.depth[size_t(y) * kSize + x];
                if (depth >= 1.0f - 1e-6f) continue; // no grass
                double p[3], along = 0.0;
                world_point(x, y, depth, p, &along);
                ++t.points;
                t.off_ground += p[1] < -0.1 || p[1] > 1.0;
                const Region region = tier_region(p);
                const int s = shadowed(p, along);
                if (region == kNone || s < 0) continue;
                const grass_host::Image& expected = s ? dark : lit;
                int worst = 0;
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(int(image.pixel(x, y)[c]) - int(expected.pixel(x, y)[c])));
                (s ? t.shadowed : t.lit)[region] += 1;
                (s ? t.wrong_shadowed : t.wrong_lit)[region] += worst > 1;
            }
        }
        return t;
    }

    void expect_tally(const Tally& t, const std::string& what) const {
        EXPECT_LT(t.off_ground, t.points / 50 + 1) << what << ": world points off the ground (the reconstruction)";
        for (int r = 0; r < 3; ++r) {
            EXPECT_GT(t.shadowed[r], 30u) << what << ": shadowed " << kRegionNames[r] << " pixels";
            EXPECT_GT(t.lit[r], 30u) << what << ": lit " << kRegionNames[r] << " pixels";
            EXPECT_LE(t.wrong_shadowed[r], t.shadowed[r] / 50)
                << what << ": shadowed " << kRegionNames[r] << " pixels unlike the sun-off picture";
            EXPECT_LE(t.wrong_lit[r], t.lit[r] / 50)
                << what << ": lit " << kRegionNames[r] << " pixels unlike the picture without receiving";
        }
    }

    // The frame drawn with the sun off: what a fully shadowed point looks like.
    grass_host::Image sun_off() {
        grass_view_desc v = camera(nullptr);
        for (float& c : v.sun_color) c = 0.0f;
        return render(v);
    }

    Gl gl{};
    GLuint map_ = 0;
    grass_lod_origin_desc lod_origin_{};
};

TEST_P(ShadowReceiveTest, AHalfPlaneShadowsEveryTierInBothConventions) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan does not receive shadows yet";
    make_tiered_field();
    const grass_host::Image lit = render(camera(nullptr));
    grass_frame_stats stats{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) EXPECT_GT(stats.instances[k], 0u) << "tier kind " << k;
    const grass_host::Image dark = sun_off();
    const auto west = [](const double p[3], double) { return p[0] < 5.7 ? 1 : p[0] > 6.3 ? 0 : -1; };
    for (const grass_shadow_compare compare : {GRASS_SHADOW_COMPARE_LESS_EQUAL, GRASS_SHADOW_COMPARE_GREATER_EQUAL}) {
        const bool less = compare == GRASS_SHADOW_COMPARE_LESS_EQUAL;
        // The occluder over u < 0.5 at the light's side of the depth range, clear elsewhere.
        make_map(1, [&](int, double u, double) { return u < 0.5 ? (less ? 0.0f : 1.0f) : (less ? 1.0f : 0.0f); });
        const grass_shadow_receive_desc d = receive(compare, 1);
        const grass_host::Image image = render(camera(&d));
        save(image, less ? "shadow_receive_less" : "shadow_receive_greater");
        expect_tally(tally(image, lit, dark, west), less ? "LESS_EQUAL" : "GREATER_EQUAL");
    }

    // Filtered: radius 2 texels (0.375 m) leaves intermediate values at the edge, between the
    // sun-off and the lit picture; radius 0 (2x2 hardware taps) hardly any.
    make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
    size_t between[2] = {}, edge[2] = {};
    for (int k = 0; k < 2; ++k) {
        grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
        d.filter_radius = k == 0 ? 0.0f : 2.0f;
        const grass_host::Image image = render(camera(&d));
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                const float depth = lit.depth[size_t(y) * kSize + x];
                if (depth >= 1.0f - 1e-6f) continue;
                double p[3], along = 0.0;
                world_point(x, y, depth, p, &along);
                // Beyond the 2x2 filter's reach (0.09 m), within radius 2's (0.47 m).
                if (std::fabs(p[0] - 6.0) < 0.2 || std::fabs(p[0] - 6.0) > 0.4) continue;
                const int l = lit.pixel(x, y)[1], s = dark.pixel(x, y)[1], v = image.pixel(x, y)[1];
                if (l - s < 12) continue; // too little sun here to tell
                ++edge[k];
                between[k] += v > s + 2 && v < l - 2;
            }
        }
    }
    ASSERT_GT(edge[1], 40u) << "edge pixels";
    EXPECT_GT(between[1], edge[1] / 2) << "intermediate edge pixels with filter_radius 2";
    EXPECT_LT(between[0] * 5, edge[0]) << "intermediate pixels with radius 0 (2x2 taps) this far from the edge";
}

TEST_P(ShadowReceiveTest, TheCascadeIsChosenByItsEnd) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan does not receive shadows yet";
    make_tiered_field();
    const grass_host::Image lit = render(camera(nullptr));
    const grass_host::Image dark = sun_off();
    // Cascade 0 lights everything, cascade 1 shadows everything; cascade 0 ends at the field's
    // centre along the view axis.
    make_map(2, [](int layer, double, double) { return layer == 0 ? 1.0f : 0.0f; });
    grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 2);
    const double end = 10.0 * std::sqrt(2.0);
    d.cascade_end[0] = float(end);
    d.cascade_end[1] = 1000.0f;
    const grass_host::Image image = render(camera(&d));
    save(image, "shadow_receive_cascades");
    const auto beyond = [end](const double*, double along) {
        return along > end + 0.3 ? 1 : along < end - 0.3 ? 0 : -1;
    };
    const Tally t = tally(image, lit, dark, beyond);
    // The geometry tier lies before the end, the image tier beyond it: the volume has both.
    EXPECT_GT(t.lit[kGeometry], 30u);
    EXPECT_LE(t.wrong_lit[kGeometry], t.lit[kGeometry] / 50);
    EXPECT_GT(t.shadowed[kImage], 30u);
    EXPECT_LE(t.wrong_shadowed[kImage], t.shadowed[kImage] / 50);
    for (const Region r : {kVolume}) {
        EXPECT_GT(t.lit[r] + t.shadowed[r], 30u);
        EXPECT_LE(t.wrong_lit[r], t.lit[r] / 50);
        EXPECT_LE(t.wrong_shadowed[r], t.shadowed[r] / 50);
    }
    size_t lit_total = 0, shadowed_total = 0;
    for (int r = 0; r < 3; ++r) lit_total += t.lit[r], shadowed_total += t.shadowed[r];
    EXPECT_GT(lit_total, 200u);
    EXPECT_GT(shadowed_total, 200u);
}

TEST_P(ShadowReceiveTest, BadDescsAreRefusedAndVulkanRefusesIt) {
    make_tiered_field();
    grass_shadow_receive_desc d = grass_default_shadow_receive_desc();
    EXPECT_EQ(d.type, GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC);
    EXPECT_EQ(d.cascade_count, 1u);
    EXPECT_EQ(d.compare, GRASS_SHADOW_COMPARE_LESS_EQUAL);
    d.shadow_map = 7; // never drawn: every view below is refused
    const auto refused = [&](const grass_shadow_receive_desc& s, grass_result expected, const std::string& message) {
        log.clear();
        const grass_view_desc v = camera(&s);
        EXPECT_EQ(grass_begin_frame(ctx, &v), expected) << message;
        EXPECT_NE(log.find(message), std::string::npos) << log;
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
    };
    grass_shadow_receive_desc bad = d;
    bad.cascade_count = 0;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->cascade_count is 0");
    bad.cascade_count = 5;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->cascade_count is 5");
    bad = d;
    bad.cascade_count = 2;
    bad.world_to_shadow[1][5] = NAN;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->world_to_shadow[1]");
    bad = d;
    bad.cascade_count = 2;
    bad.cascade_end[0] = 20.0f;
    bad.cascade_end[1] = 10.0f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->cascade_end[1] is 10");
    bad = d;
    bad.cascade_end[0] = 0.0f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->cascade_end[0] is 0");
    bad = d;
    bad.shadow_map = 0;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->shadow_map is 0");
    bad = d;
    bad.compare = static_cast<grass_shadow_compare>(3);
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->compare is 3");
    bad = d;
    bad.filter_radius = 17.0f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->filter_radius");
    bad = d;
    bad.depth_bias = -1.0f;
    refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->depth_bias");
    grass_shadow_receive_desc second = d;
    bad = d;
    bad.next = &second;
    refused(bad, GRASS_ERROR_WRONG_STRUCT_TYPE, "GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC");
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        refused(d, GRASS_ERROR_UNSUPPORTED, "the Vulkan backend does not receive the host's shadow maps yet");
    }
    // A refused later view of a frame leaves the frame and its first view as they were.
    grass_frame_desc frame = grass_default_frame_desc();
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS);
    const grass_view_desc plain = camera(nullptr);
    uint32_t index = 99;
    ASSERT_EQ(grass_plan_view(ctx, &plain, &index), GRASS_SUCCESS) << log;
    EXPECT_EQ(index, 0u);
    bad = d;
    bad.cascade_count = 0;
    const grass_view_desc refused_view = camera(&bad);
    uint32_t untouched = 99;
    EXPECT_EQ(grass_plan_view(ctx, &refused_view, &untouched), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(untouched, 99u);
    const grass_view_desc plain_again = camera(nullptr); // the lod origin desc is shared
    ASSERT_EQ(grass_plan_view(ctx, &plain_again, &index), GRASS_SUCCESS);
    EXPECT_EQ(index, 1u) << "the refused view took no index";
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

TEST_P(ShadowReceiveTest, AViewWithoutItKeepsItsProgramsAndTheHostsBindings) {
    if (GetParam() == GRASS_BACKEND_VULKAN) GTEST_SKIP() << "GL programs and state";
    make_tiered_field();
    gl_seen.used.clear();
    gl_seen.created = 0;
    const grass_host::Image lit = render(camera(nullptr));
    const std::set<GLuint> plain_programs = gl_seen.used;
    ASSERT_GE(plain_programs.size(), 3u) << "a program per tier kind";
    for (const GLuint program : plain_programs) {
        EXPECT_EQ(gl.GetUniformBlockIndex(program, "GrassShadow"), GL_INVALID_INDEX)
            << "program " << program << " of a view without receiving declares the GrassShadow block";
    }
    const int64_t plain_created = gl_seen.created;

    // The host's own unit 14 and uniform binding 2, which grass must give back.
    GLuint host_texture = 0, host_buffer = 0;
    gl.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, &host_texture);
    gl.CreateBuffers(1, &host_buffer);
    gl.NamedBufferData(host_buffer, 1024, nullptr, GL_STATIC_DRAW);
    gl.ActiveTexture(GL_TEXTURE14);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, host_texture);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindBufferRange(GL_UNIFORM_BUFFER, 2, host_buffer, 256, 512);

    make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
    const grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
    gl_seen.used.clear();
    const grass_host::Image image = render(camera(&d));
    EXPECT_NE(image.rgba, lit.rgba) << "the receiving view drew the same picture";
    EXPECT_GE(gl_seen.created - plain_created, 3) << "a receiving view compiles its own variants";
    for (const GLuint program : gl_seen.used) {
        EXPECT_EQ(plain_programs.count(program), 0u) << "the receiving view drew with a plain view's program";
        EXPECT_NE(gl.GetUniformBlockIndex(program, "GrassShadow"), GL_INVALID_INDEX);
    }
    GLint texture = 0, buffer = 0, active = 0;
    gl.ActiveTexture(GL_TEXTURE14);
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &texture);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 2, &buffer);
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    EXPECT_EQ(GLuint(texture), host_texture) << "unit 14's 2D array texture";
    EXPECT_EQ(GLuint(buffer), host_buffer) << "uniform binding 2";

    // And a view without it afterwards: no program made, the plain ones drawn, the same picture.
    const int64_t before = gl_seen.created;
    gl_seen.used.clear();
    const grass_host::Image again = render(camera(nullptr));
    EXPECT_EQ(gl_seen.created, before);
    EXPECT_EQ(gl_seen.used, plain_programs);
    EXPECT_EQ(again.rgba, lit.rgba);
    gl.DeleteTextures(1, &host_texture);
    gl.DeleteBuffers(1, &host_buffer);
}

INSTANTIATE_TEST_SUITE_P(Backends, ShadowReceiveTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
