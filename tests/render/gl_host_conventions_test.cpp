// The GL state of issue 34 (grass_gl.h): what grass reads as the host's conventions and
// honours (glClipControl's origin and depth mode, glDepthRange, GL_FRAMEBUFFER_SRGB, the
// provoking vertex), what it sets for its draws on draw buffer 0 and viewport 0 alone
// (blend enable and colour mask of buffer 0, viewport 0), and what it sets aside (the colour
// masks of the other draw buffers, off while it draws). A host sets unusual values of each;
// every value must be back after grass_gl_render, the picture right under them, and the
// host's other colour attachments untouched, byte for byte.
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <cmath>
#include <cstring>

namespace grass_test {
namespace {

#define GRASS_TEST_GL(X)                                                 \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                 \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                             \
    X(PFNGLGETBOOLEANI_VPROC, GetBooleani_v)                             \
    X(PFNGLGETFLOATVPROC, GetFloatv)                                     \
    X(PFNGLGETFLOATI_VPROC, GetFloati_v)                                 \
    X(PFNGLISENABLEDPROC, IsEnabled)                                     \
    X(PFNGLISENABLEDIPROC, IsEnabledi)                                   \
    X(PFNGLENABLEPROC, Enable)                                           \
    X(PFNGLDISABLEPROC, Disable)                                         \
    X(PFNGLENABLEIPROC, Enablei)                                         \
    X(PFNGLDISABLEIPROC, Disablei)                                       \
    X(PFNGLCLIPCONTROLPROC, ClipControl)                                 \
    X(PFNGLDEPTHRANGEPROC, DepthRange)                                   \
    X(PFNGLDEPTHRANGEINDEXEDPROC, DepthRangeIndexed)                     \
    X(PFNGLVIEWPORTPROC, Viewport)                                       \
    X(PFNGLVIEWPORTINDEXEDFPROC, ViewportIndexedf)                       \
    X(PFNGLCOLORMASKIPROC, ColorMaski)                                   \
    X(PFNGLBLENDFUNCSEPARATEIPROC, BlendFuncSeparatei)                   \
    X(PFNGLBLENDEQUATIONSEPARATEIPROC, BlendEquationSeparatei)           \
    X(PFNGLPROVOKINGVERTEXPROC, ProvokingVertex)                         \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                 \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                         \
    X(PFNGLCREATEFRAMEBUFFERSPROC, CreateFramebuffers)                   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                   \
    X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, NamedFramebufferTexture)         \
    X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, CheckNamedFramebufferStatus) \
    X(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC, ClearNamedFramebufferfv)         \
    X(PFNGLCREATETEXTURESPROC, CreateTextures)                           \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                           \
    X(PFNGLTEXTURESTORAGE2DPROC, TextureStorage2D)                       \
    X(PFNGLTEXTURESUBIMAGE2DPROC, TextureSubImage2D)                     \
    X(PFNGLGETTEXTUREIMAGEPROC, GetTextureImage)

struct Gl {
#define GRASS_TEST_DECLARE(type, name) type name = nullptr;
    GRASS_TEST_GL(GRASS_TEST_DECLARE)
#undef GRASS_TEST_DECLARE
};

Gl load_gl(const grass_host::Host& host) {
    Gl gl;
#define GRASS_TEST_LOAD(type, name)                                     \
    gl.name = reinterpret_cast<type>(host.gl_proc_address("gl" #name)); \
    EXPECT_NE(reinterpret_cast<void*>(gl.name), nullptr) << "gl" #name;
    GRASS_TEST_GL(GRASS_TEST_LOAD)
#undef GRASS_TEST_LOAD
    return gl;
}

constexpr GLuint kBuffers = 4; // draw buffers the tests look at (GL 4.5 has at least 8)

// Every value of the conventions and the per-buffer state the host sets below.
struct HostState {
    GLint clip_origin, clip_depth_mode, provoking_vertex, draw_buffer[kBuffers];
    GLfloat depth_range[2], depth_range1[2], viewport0[4], viewport1[4];
    GLboolean srgb, blend[kBuffers], color_mask[kBuffers][4];
    GLint blend_src_rgb[kBuffers], blend_dst_rgb[kBuffers], blend_src_alpha[kBuffers], blend_dst_alpha[kBuffers],
        blend_eq_rgb[kBuffers], blend_eq_alpha[kBuffers];
    bool operator==(const HostState& o) const { return std::memcmp(this, &o, sizeof(HostState)) == 0; }
};

HostState host_state(const Gl& gl) {
    HostState s;
    std::memset(&s, 0, sizeof(s)); // padding too: compared with memcmp
    gl.GetIntegerv(GL_CLIP_ORIGIN, &s.clip_origin);
    gl.GetIntegerv(GL_CLIP_DEPTH_MODE, &s.clip_depth_mode);
    gl.GetIntegerv(GL_PROVOKING_VERTEX, &s.provoking_vertex);
    gl.GetFloatv(GL_DEPTH_RANGE, s.depth_range);
    gl.GetFloati_v(GL_DEPTH_RANGE, 1, s.depth_range1);
    gl.GetFloati_v(GL_VIEWPORT, 0, s.viewport0);
    gl.GetFloati_v(GL_VIEWPORT, 1, s.viewport1);
    s.srgb = gl.IsEnabled(GL_FRAMEBUFFER_SRGB);
    for (GLuint i = 0; i < kBuffers; ++i) {
        gl.GetIntegerv(GL_DRAW_BUFFER0 + i, &s.draw_buffer[i]);
        s.blend[i] = gl.IsEnabledi(GL_BLEND, i);
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, i, s.color_mask[i]);
        gl.GetIntegeri_v(GL_BLEND_SRC_RGB, i, &s.blend_src_rgb[i]);
        gl.GetIntegeri_v(GL_BLEND_DST_RGB, i, &s.blend_dst_rgb[i]);
        gl.GetIntegeri_v(GL_BLEND_SRC_ALPHA, i, &s.blend_src_alpha[i]);
        gl.GetIntegeri_v(GL_BLEND_DST_ALPHA, i, &s.blend_dst_alpha[i]);
        gl.GetIntegeri_v(GL_BLEND_EQUATION_RGB, i, &s.blend_eq_rgb[i]);
        gl.GetIntegeri_v(GL_BLEND_EQUATION_ALPHA, i, &s.blend_eq_alpha[i]);
    }
    return s;
}

// Blend on for buffers 1 and 3 with odd functions, off for 0 and 2 with odd functions too.
void set_unusual_blend(const Gl& gl) {
    for (GLuint i = 0; i < kBuffers; ++i) {
        if (i % 2 == 1) {
            gl.Enablei(GL_BLEND, i);
        } else {
            gl.Disablei(GL_BLEND, i);
        }
        gl.BlendFuncSeparatei(i, GL_SRC_COLOR + i, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_ALPHA, GL_ZERO);
        gl.BlendEquationSeparatei(i, i == 0 ? GL_MAX : GL_FUNC_REVERSE_SUBTRACT, GL_MIN);
    }
}

void set_default_blend(const Gl& gl) {
    gl.Disable(GL_BLEND);
    for (GLuint i = 0; i < kBuffers; ++i) {
        gl.BlendFuncSeparatei(i, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
        gl.BlendEquationSeparatei(i, GL_FUNC_ADD, GL_FUNC_ADD);
        gl.ColorMaski(i, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
}

class GlHostConventionsTest : public RenderTest {
protected:
    // A geometry tier near the camera and a volume tier (it writes gl_FragDepth) beyond
    // 1.9 m, seen from 2 m straight above: both tiers draw (gl_state_test.cpp's scene).
    grass_view_desc two_tier_scene() {
        tiers_[0] = {GRASS_TIER_GEOMETRY, 0};
        tiers_[1] = {GRASS_TIER_VOLUME, 2};
        bands_[0] = grass_lod_test{};
        bands_[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        bands_[0].end = 1.9f;
        bands_[1] = bands_[0];
        bands_[1].tier = 1;
        bands_[1].begin = 1.9f;
        bands_[1].end = 100.0f;
        grass_field_desc d = field_desc(8);
        d.tiers = tiers_;
        d.tier_count = 2;
        d.lod_tests = bands_;
        d.lod_test_count = 2;
        make_field(d);
        const double eye[3] = {1.0, 2.0, 1.0}, target[3] = {1.0, 0.0, 1.0001};
        return view(eye, target);
    }
    void expect_both_tiers_drew() {
        grass_frame_stats stats{};
        ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        EXPECT_GT(stats.instances[GRASS_TIER_GEOMETRY], 0u);
        EXPECT_GT(stats.instances[GRASS_TIER_VOLUME], 0u);
    }

private:
    grass_tier_desc tiers_[2] = {};
    grass_lod_test bands_[2] = {};
};

// The host draws upside down in memory (glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE), as
// engines ported from Direct3D do) into depth range 0.2 .. 0.8, with sRGB conversion on,
// the first vertex provoking, three draw buffers (its target has one attachment: the
// others' writes go nowhere), draw buffer 0's alpha masked, blend on for buffer 1 with odd
// functions, viewport 1 and depth range 1 of their own. Grass draws the same picture, upside
// down, and the same depths mapped into 0.2 .. 0.8, and every value is back afterwards.
TEST_P(GlHostConventionsTest, AreHonouredAndThePerBufferAndPerViewportStateKept) {
    grass_host::TargetDesc t;
    t.width = t.height = 128;
    t.gl_clip_zero_to_one = true; // the host's projections have clip z 0..1
    t.read_depth = true;
    start(t);
    const Gl gl = load_gl(*host);
    const grass_view_desc v = two_tier_scene();
    const grass_host::Image clean = render(v);
    expect_both_tiers_drew();

    HostState before{}, after{};
    host->before_grass = [&] {
        gl.ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        gl.DepthRange(0.2, 0.8); // every viewport's
        gl.DepthRangeIndexed(1, 0.3, 0.6);
        gl.ViewportIndexedf(1, 1.5f, 2.25f, 33.0f, 17.5f);
        gl.ProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
        const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        gl.DrawBuffers(3, buffers);
        set_unusual_blend(gl);
        gl.ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
        gl.ColorMaski(1, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        before = host_state(gl);
    };
    host->after_grass = [&] {
        after = host_state(gl);
        gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); // the host's own frame state
        gl.DepthRange(0.0, 1.0);
        gl.ProvokingVertex(GL_LAST_VERTEX_CONVENTION);
        const GLenum buffer = GL_COLOR_ATTACHMENT0;
        gl.DrawBuffers(1, &buffer);
        set_default_blend(gl);
    };
    const grass_host::Image unusual = render(v);
    host->before_grass = nullptr;
    host->after_grass = nullptr;
    expect_both_tiers_drew();
    save(clean, "clean");
    save(unusual, "unusual");

    EXPECT_TRUE(before == after) << "grass_gl_render left the host's conventions or per-buffer state changed";
    EXPECT_EQ(after.clip_origin, GL_UPPER_LEFT);
    EXPECT_EQ(after.clip_depth_mode, GL_ZERO_TO_ONE);
    EXPECT_FLOAT_EQ(after.depth_range[0], 0.2f);
    EXPECT_FLOAT_EQ(after.depth_range1[1], 0.6f);
    EXPECT_FLOAT_EQ(after.viewport1[1], 2.25f);
    EXPECT_EQ(after.srgb, GL_TRUE);
    EXPECT_EQ(after.provoking_vertex, GL_FIRST_VERTEX_CONVENTION);
    EXPECT_EQ(after.draw_buffer[2], GL_COLOR_ATTACHMENT2);
    EXPECT_EQ(after.blend[0], GL_FALSE);
    EXPECT_EQ(after.blend[1], GL_TRUE);
    EXPECT_EQ(after.blend_eq_rgb[0], GL_MAX);
    EXPECT_EQ(after.blend_src_rgb[2], GLint(GL_SRC_COLOR + 2));
    EXPECT_EQ(after.color_mask[0][3], GL_FALSE);
    EXPECT_EQ(after.color_mask[1][1], GL_FALSE);
    EXPECT_EQ(after.color_mask[1][2], GL_TRUE);

    // The picture: the clean one upside down (rows mirror exactly: a pixel centre's window
    // y maps to height - y). The depths: the clean ones mapped into 0.2 .. 0.8.
    ASSERT_EQ(clean.rgba.size(), unusual.rgba.size());
    grass_host::Image flipped = unusual;
    const uint32_t w = unusual.width, h = unusual.height;
    for (uint32_t y = 0; y < h; ++y) {
        std::memcpy(&flipped.rgba[size_t(y) * w * 4], unusual.pixel(0, h - 1 - y), size_t(w) * 4);
        std::memcpy(&flipped.depth[size_t(y) * w], &unusual.depth[size_t(h - 1 - y) * w], size_t(w) * sizeof(float));
    }
    save(flipped, "unusual_flipped");
    expect_grass(clean, host->target(), 0.3, "the clean picture");
    EXPECT_LT(mean_difference(clean, flipped), 0.05) << "grass under the host's conventions";
    size_t grass_depths = 0, wrong_depths = 0;
    for (size_t p = 0; p < clean.depth.size(); ++p) {
        const float expected = clean.depth[p] < 1.0f ? 0.2f + 0.6f * clean.depth[p] : 1.0f; // the clear stays 1
        grass_depths += clean.depth[p] < 1.0f ? 1 : 0;
        wrong_depths += std::fabs(flipped.depth[p] - expected) > 1e-4f ? 1 : 0;
    }
    EXPECT_GT(grass_depths, clean.depth.size() / 4);
    EXPECT_LT(wrong_depths, clean.depth.size() / 1000) << "depths outside the host's depth range mapping";
}

// A G-buffer host: four colour attachments and four draw buffers bound, blend on for
// buffers 1-3, sRGB conversion off. Grass writes draw buffer 0 alone: it holds exactly
// what it holds when draw buffer 0 is the only one, and attachments 1-3 keep the host's
// bytes (GL leaves undefined what a draw buffer gets that the shaders write no output for).
TEST_P(GlHostConventionsTest, GrassWritesDrawBufferZeroAloneAndTheOtherAttachmentsKeepTheirBytes) {
    const Gl gl = load_gl(*host);
    const grass_view_desc v = two_tier_scene();
    render(v); // uploads and first-use compiles: the frames below draw alike
    const uint32_t size = host->target().width;
    ASSERT_EQ(size, host->target().height);
    const GLsizei n = GLsizei(size);
    GLuint fbo = 0, textures[kBuffers + 1] = {};
    gl.CreateFramebuffers(1, &fbo);
    gl.CreateTextures(GL_TEXTURE_2D, kBuffers + 1, textures);
    for (GLuint i = 0; i < kBuffers; ++i) {
        gl.TextureStorage2D(textures[i], 1, GL_RGBA8, n, n);
        gl.NamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + i, textures[i], 0);
    }
    gl.TextureStorage2D(textures[kBuffers], 1, GL_DEPTH_COMPONENT32F, n, n);
    gl.NamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, textures[kBuffers], 0);
    ASSERT_EQ(gl.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    // The host's bytes in attachments 1-3: a pattern no grass draw would write.
    std::vector<uint8_t> pattern[kBuffers];
    for (GLuint i = 1; i < kBuffers; ++i) {
        pattern[i].resize(size_t(size) * size * 4);
        for (size_t k = 0; k < pattern[i].size(); ++k) pattern[i][k] = uint8_t((k * 131 + i * 71) >> 2);
    }
    std::vector<uint8_t> read[kBuffers];
    std::vector<uint8_t> alone; // draw buffer 0's bytes with one draw buffer

    for (const GLsizei draw_buffers : {1, GLsizei(kBuffers)}) {
        SCOPED_TRACE(std::to_string(draw_buffers) + " draw buffers");
        HostState before{}, after{};
        host->before_grass = [&] {
            const float sky[4] = {0.2f, 0.3f, 0.4f, 1.0f}, far = 1.0f;
            gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
            gl.ClearNamedFramebufferfv(fbo, GL_COLOR, 0, sky);
            gl.ClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
            for (GLuint i = 1; i < kBuffers; ++i) {
                gl.TextureSubImage2D(textures[i], 0, 0, 0, n, n, GL_RGBA, GL_UNSIGNED_BYTE, pattern[i].data());
            }
            const GLenum buffers[kBuffers] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                              GL_COLOR_ATTACHMENT3};
            gl.DrawBuffers(draw_buffers, buffers);
            gl.Disable(GL_FRAMEBUFFER_SRGB);
            set_unusual_blend(gl);
            before = host_state(gl);
        };
        host->after_grass = [&] {
            after = host_state(gl);
            for (GLuint i = 0; i < kBuffers; ++i) {
                read[i].assign(size_t(size) * size * 4, 0);
                gl.GetTextureImage(textures[i], 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(read[i].size()), read[i].data());
            }
            const GLenum buffer = GL_COLOR_ATTACHMENT0;
            gl.DrawBuffers(1, &buffer);
            set_default_blend(gl);
            gl.Enable(GL_FRAMEBUFFER_SRGB);
        };
        render(v); // grass draws into the test's framebuffer; the host reads back its own
        host->before_grass = nullptr;
        host->after_grass = nullptr;
        expect_both_tiers_drew();
        EXPECT_TRUE(before == after) << "grass_gl_render left the host's per-buffer state changed";
        EXPECT_EQ(after.srgb, GL_FALSE);
        EXPECT_EQ(after.blend[3], GL_TRUE);
        for (GLuint i = 1; i < kBuffers; ++i) {
            EXPECT_TRUE(read[i] == pattern[i]) << "grass wrote into colour attachment " << i;
        }
        if (draw_buffers == 1) {
            alone = read[0];
            size_t grass = 0;
            for (size_t p = 0; p < alone.size(); p += 4) grass += alone[p + 1] > alone[p + 2] ? 1 : 0;
            EXPECT_GT(grass, alone.size() / 4 / 4) << "a quarter of the pixels are grass";
        } else {
            EXPECT_TRUE(read[0] == alone) << "draw buffer 0 differs with the others bound";
        }
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
    gl.DeleteTextures(kBuffers + 1, textures);
}

INSTANTIATE_TEST_SUITE_P(Backends, GlHostConventionsTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
