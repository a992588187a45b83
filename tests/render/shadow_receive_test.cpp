// Receiving the host's shadows (grass_shadow_receive_desc; docs/engine-frames.md "Receiving the
// host's shadows"): a field of geometry, volume and image tiers seen by an orthographic
// camera 45 degrees down, and a shadow map the test makes itself (GL: a GL_TEXTURE_2D_ARRAY of
// depth; Vulkan: a D32_SFLOAT 2D array the host fills and leaves in a read-only layout,
// Host::make_vk_shadow_map; top-down: u = x / 12 m, v = z / 12 m). Each grass pixel's world point comes back
// from the depth buffer. Where the map shadows a point, the picture is the one drawn with
// the sun off (the sun term gone, the ambient kept); where it lights it, the one drawn
// without receiving; in every tier:
// - a half-plane occluder (x < 6 m), in both comparison conventions; with a filter radius
//   the edge has intermediate values;
// - two cascades, chosen by cascade_end along the view axis (the second shadows all);
// - refusals (bad count, NaN matrix, descending ends, zero map; Vulkan: a layout grass does
//   not sample a depth map in) begin no frame;
// - GL: a view without it draws with programs that declare no GrassShadow block, and a
//   receiving view compiles its own and leaves the host's unit 14 and uniform binding 2
//   (Vulkan's pipelines: vk_shadow_receive_test.cpp).
#include "gl_program_spy.hpp"
#include "render_fixture.hpp"
#ifdef GRASS_HOST_HAS_VULKAN
#    include "vk_intercept.hpp"
#endif

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
// VkImageLayout values (the render tests include no Vulkan header).
constexpr uint32_t kVkDepthStencilReadOnly = 4; // VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
constexpr uint32_t kVkShaderReadOnly = 5;       // VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
constexpr uint32_t kVkTransferDst = 7;          // VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL: refused

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
        // Vulkan: the synchronization validation too (the host's map, written by a copy, read
        // by grass's fragment shaders; read when the host makes its instance).
        setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 1);
        RenderTest::SetUp();
        start_on(GetParam());
    }
    // The host and context of `backend` (the test's, or GL for the agreement test); `samples`
    // above 1 or `dynamic_rendering` (Vulkan) read back no depth.
    // `velocity_attachment` (Vulkan): the pass's velocity target there (TargetDesc).
    void start_on(grass_backend backend, uint32_t samples = 1, bool dynamic_rendering = false,
                  uint32_t velocity_attachment = 0) {
        backend_ = backend;
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.vk_velocity_attachment = velocity_attachment;
        t.samples = samples;
        t.vk_dynamic_rendering = dynamic_rendering;
        t.read_depth = samples == 1 && !dynamic_rendering;
        if (backend == GRASS_BACKEND_GL) t.gl_proc_filter = &gl_program_spy_filter;
#ifdef GRASS_HOST_HAS_VULKAN
        if (backend == GRASS_BACKEND_VULKAN) t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr();
#endif
        map_ = 0;
        vk_map_ = 0;
        start(t, backend);
        if (backend == GRASS_BACKEND_GL) {
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
        if (map_ != 0 && gl.DeleteTextures) gl.DeleteTextures(1, &map_);
        RenderTest::TearDown();
    }

    // Geometry near the lod origin, a volume of 2 slices, the horizontal slice far.
    void make_tiered_field() { make_field(three_tier_field(kCells)); }

    // The orthographic camera (the host's clip convention: GL y up and z -1..1, Vulkan y down
    // and z 0..1), its lod origin kEye; `shadow` chained when given.
    grass_view_desc camera(const grass_shadow_receive_desc* shadow) {
        grass_view_desc v = view(kCamera, kAt);
        const bool vulkan = backend_ == GRASS_BACKEND_VULKAN;
        std::memset(v.projection, 0, sizeof v.projection);
        v.projection[0] = float(1.0 / kHalf);
        v.projection[5] = float((vulkan ? -1.0 : 1.0) / kHalf);
        v.projection[10] = float(vulkan ? -1.0 / (kFar - kNear) : -2.0 / (kFar - kNear));
        v.projection[14] = float(vulkan ? -kNear / (kFar - kNear) : -(kFar + kNear) / (kFar - kNear));
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
        const double ze = backend_ == GRASS_BACKEND_VULKAN // eye z (negative)
                              ? -(depth * (kFar - kNear) + kNear)
                              : (2.0 * depth - 1.0 + (kFar + kNear) / (kFar - kNear)) / (-2.0 / (kFar - kNear));
        *along = -ze;
        for (int c = 0; c < 3; ++c) out[c] = kCamera[c] + r[c] * nx * kHalf + u[c] * ny * kHalf + f[c] * *along;
    }

    // The map: `layers` layers of kMapTexels^2 depths, value(layer, u, v).
    // Vulkan: the host's image in vk_layout_, its view in vk_map_.
    template <class Value>
    void make_map(int layers, Value value) {
        std::vector<float> texels(size_t(kMapTexels) * kMapTexels * layers);
        for (int l = 0; l < layers; ++l) {
            for (int j = 0; j < kMapTexels; ++j) {
                for (int i = 0; i < kMapTexels; ++i) {
                    texels[(size_t(l) * kMapTexels + j) * kMapTexels + i] =
                        value(l, (i + 0.5) / kMapTexels, (j + 0.5) / kMapTexels);
                }
            }
        }
        if (backend_ == GRASS_BACKEND_VULKAN) {
            std::string error;
            vk_map_ = host->make_vk_shadow_map(kMapTexels, uint32_t(layers), texels.data(), vk_layout_, &error);
            ASSERT_NE(vk_map_, 0u) << error;
            return;
        }
        if (map_ != 0) gl.DeleteTextures(1, &map_);
        gl.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, &map_);
        gl.TextureStorage3D(map_, 1, GL_DEPTH_COMPONENT32F, kMapTexels, kMapTexels, layers);
        gl.TextureSubImage3D(map_, 0, 0, 0, 0, kMapTexels, kMapTexels, layers, GL_DEPTH_COMPONENT, GL_FLOAT,
                             texels.data());
    }

    // A receiving desc over map_: every cascade top-down (u = x / 12, v = z / 12), the
    // point's depth 0.5 -+ 0.01 y (nearer the light higher up).
    grass_shadow_receive_desc receive(grass_shadow_compare compare, uint32_t cascades) const {
        grass_shadow_receive_desc d = grass_default_shadow_receive_desc();
        d.shadow_map = backend_ == GRASS_BACKEND_VULKAN ? vk_map_ : map_;
        d.vk_image_layout = vk_layout_;
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

    void receive_and_move(const grass_view_lights_desc* lights); // Vulkan's view extras at once

    grass_backend backend_ = GRASS_BACKEND_NONE; // the host's (start_on)
    Gl gl{};
    GLuint map_ = 0;
    uint64_t vk_map_ = 0;                          // Vulkan: the host's VkImageView
    uint32_t vk_layout_ = kVkDepthStencilReadOnly; // Vulkan: the layout the host leaves it in
    grass_lod_origin_desc lod_origin_{};
};

TEST_P(ShadowReceiveTest, AHalfPlaneShadowsEveryTierInBothConventions) {
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
    vk_layout_ = kVkShaderReadOnly; // Vulkan: another layout a host may sample its map in
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

TEST_P(ShadowReceiveTest, BadDescsAreRefused) {
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
    if (GetParam() == GRASS_BACKEND_VULKAN) { // GL ignores the layout
        bad = d;
        bad.vk_image_layout = kVkTransferDst;
        refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->vk_image_layout is 7");
        bad.vk_image_layout = 0; // the default: VK_IMAGE_LAYOUT_UNDEFINED
        refused(bad, GRASS_ERROR_INVALID_ARGUMENT, "grass_shadow_receive_desc->vk_image_layout is 0");
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
    if (GetParam() == GRASS_BACKEND_VULKAN) {
        bad = d;
        bad.vk_image_layout = kVkTransferDst;
        const grass_view_desc bad_layout = camera(&bad);
        EXPECT_EQ(grass_plan_view(ctx, &bad_layout, &untouched), GRASS_ERROR_INVALID_ARGUMENT);
        EXPECT_EQ(untouched, 99u);
    }
    const grass_view_desc plain_again = camera(nullptr); // the lod origin desc is shared
    ASSERT_EQ(grass_plan_view(ctx, &plain_again, &index), GRASS_SUCCESS);
    EXPECT_EQ(index, 1u) << "the refused view took no index";
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

TEST_P(ShadowReceiveTest, AViewWithoutItKeepsItsProgramsAndTheHostsBindings) {
    if (GetParam() == GRASS_BACKEND_VULKAN)
        GTEST_SKIP() << "GL programs and state (Vulkan: AVulkanViewWithoutItKeepsItsPipelines)";
    make_tiered_field();
    gl_program_spy().used.clear();
    gl_program_spy().created = 0;
    const grass_host::Image lit = render(camera(nullptr));
    const std::set<GLuint> plain_programs = gl_program_spy().used;
    ASSERT_GE(plain_programs.size(), 3u) << "a program per tier kind";
    for (const GLuint program : plain_programs) {
        EXPECT_EQ(gl.GetUniformBlockIndex(program, "GrassShadow"), GL_INVALID_INDEX)
            << "program " << program << " of a view without receiving declares the GrassShadow block";
    }
    const int64_t plain_created = gl_program_spy().created;

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
    gl_program_spy().used.clear();
    const grass_host::Image image = render(camera(&d));
    EXPECT_NE(image.rgba, lit.rgba) << "the receiving view drew the same picture";
    EXPECT_GE(gl_program_spy().created - plain_created, 3) << "a receiving view compiles its own variants";
    for (const GLuint program : gl_program_spy().used) {
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
    const int64_t before = gl_program_spy().created;
    gl_program_spy().used.clear();
    const grass_host::Image again = render(camera(nullptr));
    EXPECT_EQ(gl_program_spy().created, before);
    EXPECT_EQ(gl_program_spy().used, plain_programs);
    EXPECT_EQ(again.rgba, lit.rgba);
    gl.DeleteTextures(1, &host_texture);
    gl.DeleteBuffers(1, &host_buffer);
}

// Vulkan: the receiving pipelines of a multisampled target drawn with dynamic rendering (the
// tests above draw single-sampled in a render pass): the map darkens the picture, and the
// validation layers stay silent (TearDown).
TEST_P(ShadowReceiveTest, AMultisampledDynamicRenderingTargetReceives) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan targets";
    start_on(GRASS_BACKEND_VULKAN, 4, true);
    make_tiered_field();
    const grass_host::Image lit = render(camera(nullptr));
    make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
    const grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
    const grass_host::Image image = render(camera(&d));
    save(image, "shadow_receive_msaa_dynamic");
    // The camera's right is world -x: the shadowed half (x < 6 m) is the image's right half,
    // darker; the left half as lit. Green levels lost per pixel, the edge's band left out.
    double darker[2] = {0.0, 0.0}; // left, right
    for (uint32_t y = kSize / 4; y < kSize * 3 / 4; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (x + 8 > kSize / 2 && x < kSize / 2 + 8) continue;
            darker[x < kSize / 2 ? 0 : 1] += double(lit.pixel(x, y)[1]) - double(image.pixel(x, y)[1]);
        }
    }
    const double per_half = double(kSize / 2 - 8) * (kSize / 2);
    EXPECT_GT(darker[1] / per_half, 3.0) << "the shadowed half darkens";
    EXPECT_LT(std::fabs(darker[0] / per_half), 0.5) << "the lit half stays";
}

#if defined(GRASS_HOST_HAS_VULKAN) && defined(GRASS_HOST_HAS_GL)
// GL and Vulkan draw the same receiving picture (a filtered half-plane edge over every tier),
// within the single-sampled tolerance of BackendAgreement (0.05 levels a pixel on average,
// 0.05% of pixels more than 32 levels apart).
TEST_P(ShadowReceiveTest, GlAndVulkanDrawTheSameReceivingPicture) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "runs once, from the Vulkan instance";
    grass_host::Image images[2], lit;
    const grass_backend backends[2] = {GRASS_BACKEND_VULKAN, GRASS_BACKEND_GL};
    for (int b = 0; b < 2; ++b) {
        if (b == 1) start_on(GRASS_BACKEND_GL);
        make_tiered_field();
        if (b == 0) lit = render(camera(nullptr));
        make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
        const grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
        images[b] = render(camera(&d));
        save(images[b], std::string("shadow_receive_agreement_") + backend_name(backends[b]));
        ASSERT_EQ(images[b].rgba.size(), size_t(kSize) * kSize * 4);
        EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log(); // the Vulkan host goes next
    }
    // Not a comparison of two skies: grass covers the image and the map darkens it.
    size_t grass = 0;
    for (const float depth : lit.depth) grass += depth < 1.0f - 1e-6f;
    EXPECT_GT(grass, size_t(kSize) * kSize / 4) << "grass pixels";
    EXPECT_GT(mean_difference(lit, images[0]), 2.0) << "the map shadows the Vulkan picture";
    const double mean = mean_difference(images[0], images[1]), share = share_apart(images[0], images[1], 32);
    std::printf("[ measured ] receiving: mean |gl - vk| %.4f levels, %.4f%% of pixels > 32 apart\n", mean,
                100.0 * share);
    EXPECT_LE(mean, 0.05);
    EXPECT_LE(share, 0.0005);
}
#endif

#ifdef GRASS_HOST_HAS_VULKAN
// Vulkan: a view without it makes and holds nothing for it (no pipeline, layout, sampler or
// descriptor pool); the first receiving view makes its own pipelines (blades, volume, image),
// one pipeline layout (sets 0 and 1), one set layout and two compare samplers; a plain view
// afterwards makes nothing and draws the same picture as before.
TEST_P(ShadowReceiveTest, AVulkanViewWithoutItKeepsItsPipelines) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan pipelines";
    namespace vi = vk_intercept;
    const auto count = [](int32_t type) {
        int n = 0;
        for (const vi::Handle& h : vi::made()) n += h.type == type;
        return n;
    };
    constexpr int32_t kPipelineLayout = 17, kSetLayout = 20, kSampler = 21, kPool = 22; // VkObjectType
    make_tiered_field();
    grass_host::Image lit;
    for (int frame = 0; frame < 3; ++frame) lit = render(camera(nullptr)); // every frame slot's objects made
    const vi::Live plain = vi::live();
    vi::clear_debug_records();
    const grass_host::Image lit_again = render(camera(nullptr));
    EXPECT_EQ(vi::live().pipelines_made, plain.pipelines_made) << "a second plain frame made pipelines";
    EXPECT_TRUE(vi::made().empty()) << vi::made().size() << " objects made by a second plain frame";
    EXPECT_EQ(lit_again.rgba, lit.rgba);

    make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
    const grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
    const grass_host::Image image = render(camera(&d));
    EXPECT_NE(image.rgba, lit.rgba) << "the receiving view drew the same picture";
    const vi::Live receiving = vi::live();
    EXPECT_GE(receiving.pipelines_made - plain.pipelines_made, 3) << "its own blade, volume and image pipelines";
    EXPECT_EQ(count(kPipelineLayout), 1) << "the view extras' pipeline layout";
    EXPECT_EQ(count(kSetLayout), 2) << "set 1's and set 2's layouts";
    EXPECT_EQ(count(kSampler), 2) << "the LESS_OR_EQUAL and GREATER_OR_EQUAL compare samplers";
    EXPECT_EQ(count(kPool), 1) << "the pool of the views' shadow sets";

    vi::clear_debug_records();
    const grass_host::Image plain_after = render(camera(nullptr));
    EXPECT_EQ(vi::live().pipelines_made, receiving.pipelines_made) << "a plain view after a receiving one";
    EXPECT_TRUE(vi::made().empty());
    EXPECT_EQ(plain_after.rgba, lit.rgba);
}
#endif

// The main view of a host with shadows and temporal anti-aliasing: a Vulkan view that receives
// the host's shadow map and writes motion vectors at once (one set 1 of both blocks and the
// map, its own pipelines) draws the receiving view's colour and the motion view's velocity;
// with `lights` (the host's lights chained too: all three extras) the colour is that of the
// view that receives and is lit, and the lights change it.
void ShadowReceiveTest::receive_and_move(const grass_view_lights_desc* lights) {
    start_on(GRASS_BACKEND_VULKAN, 1, false, 2); // velocity at colour attachment 2
    make_tiered_field();
    make_map(1, [](int, double u, double) { return u < 0.5 ? 0.0f : 1.0f; });
    const grass_view_desc unshadowed = camera(nullptr);
    lod_origin_.next = lights;
    const grass_host::Image lit = render(unshadowed); // lit by the sun (and the lights): nothing shadowed
    grass_shadow_receive_desc d = receive(GRASS_SHADOW_COMPARE_LESS_EQUAL, 1);
    const grass_host::Image received_plain = render(camera(&d));
    d.next = lights;
    const grass_host::Image received = render(camera(&d));

    // The previous frame's camera 0.3 m west and 0.2 m lower: every grass pixel moved.
    const grass_view_desc before = camera(nullptr);
    grass_view_motion_desc m = grass_default_view_motion_desc();
    std::memcpy(m.previous_camera_position, before.camera_position, sizeof m.previous_camera_position);
    m.previous_camera_position[0] -= 0.3;
    m.previous_camera_position[1] -= 0.2;
    std::memcpy(m.previous_view, before.view, sizeof m.previous_view);
    std::memcpy(m.previous_projection, before.projection, sizeof m.previous_projection);
    m.previous_time = before.time;
    m.velocity_attachment = 2;
    // All first: no earlier motion view's block can stand in for its own.
    grass_view_lights_desc chained = lights ? *lights : grass_view_lights_desc{};
    chained.next = &m;
    d.next = lights ? static_cast<const void*>(&chained) : &m;
    const grass_host::Image both = render(camera(&d));
    save(both, lights ? "lit_receiving_with_motion" : "shadow_receive_with_motion");
    grass_view_desc moving = camera(nullptr);
    lod_origin_.next = &m;
    const grass_host::Image moved = render(moving);

    size_t grass = 0, shadowed = 0, moving_pixels = 0, colour_off = 0, velocity_off = 0, lights_changed = 0;
    for (size_t i = 0; i < size_t(kSize) * kSize; ++i) {
        if (received.depth[i] >= 1.0f - 1e-6f) continue;
        ++grass;
        int worst = 0, dark = 0, by_lights = 0;
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(int(both.rgba[4 * i + c]) - int(received.rgba[4 * i + c])));
            dark = std::max(dark, int(lit.rgba[4 * i + c]) - int(received.rgba[4 * i + c]));
            by_lights =
                std::max(by_lights, std::abs(int(received.rgba[4 * i + c]) - int(received_plain.rgba[4 * i + c])));
        }
        colour_off += worst > 1;
        shadowed += dark > 8;
        lights_changed += by_lights > 6;
        const float* v = &moved.velocity[4 * i];
        const float* w = &both.velocity[4 * i];
        moving_pixels += std::fabs(v[0]) + std::fabs(v[1]) > 1e-3f;
        velocity_off += !(std::fabs(v[0] - w[0]) + std::fabs(v[1] - w[1]) <= 1e-5f); // NaN: off
    }
    EXPECT_GT(grass, size_t(kSize) * kSize / 4) << "grass pixels";
    EXPECT_GT(shadowed, grass / 5) << "pixels the map shadows";
    if (lights) {
        EXPECT_GT(lights_changed, grass / 5) << "pixels the lights change";
    } else {
        EXPECT_EQ(lights_changed, 0u);
    }
    EXPECT_GT(moving_pixels, grass * 9 / 10) << "grass pixels with a velocity";
    EXPECT_EQ(colour_off, 0u) << "pixels whose colour is not the receiving view's (over 1 level)";
    EXPECT_EQ(velocity_off, 0u) << "pixels whose velocity is not the motion view's (over 1e-5)";
    EXPECT_EQ(both.depth, received.depth);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
}

TEST_P(ShadowReceiveTest, AVulkanViewReceivesAndWritesMotionVectorsAtOnce) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan's view extras";
    receive_and_move(nullptr);
}

// All three of Vulkan's view extras in one view: receiving, motion vectors and the host's
// lights (a point light over the field's middle and specular).
TEST_P(ShadowReceiveTest, AVulkanViewIsLitReceivesAndWritesMotionVectorsAtOnce) {
    if (GetParam() != GRASS_BACKEND_VULKAN) GTEST_SKIP() << "Vulkan's view extras";
    grass_light point = grass_default_light();
    const double above[3] = {6.0, 1.5, 6.0};
    std::memcpy(point.position, above, sizeof above);
    point.intensity = 8.0f;
    grass_view_lights_desc lights = grass_default_view_lights_desc();
    lights.light_count = 1;
    lights.lights = &point;
    lights.specular_strength = 0.3f;
    receive_and_move(&lights);
}

INSTANTIATE_TEST_SUITE_P(Backends, ShadowReceiveTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
