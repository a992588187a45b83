// grass_gl_render restores every piece of GL state it changes (the list in grass_gl.h):
// the host sets unusual values, grass draws, and every value must be back.
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <cstring>

namespace grass_test {
namespace {

struct Gl {
    PFNGLGETINTEGERVPROC GetIntegerv;
    PFNGLGETINTEGERI_VPROC GetIntegeri_v;
    PFNGLGETBOOLEANVPROC GetBooleanv;
    PFNGLISENABLEDPROC IsEnabled;
    PFNGLENABLEPROC Enable;
    PFNGLDISABLEPROC Disable;
    PFNGLVIEWPORTPROC Viewport;
    PFNGLDEPTHFUNCPROC DepthFunc;
    PFNGLDEPTHMASKPROC DepthMask;
    PFNGLACTIVETEXTUREPROC ActiveTexture;
    PFNGLCREATEVERTEXARRAYSPROC CreateVertexArrays;
    PFNGLBINDVERTEXARRAYPROC BindVertexArray;
    PFNGLDELETEVERTEXARRAYSPROC DeleteVertexArrays;
    PFNGLCREATEBUFFERSPROC CreateBuffers;
    PFNGLBINDBUFFERPROC BindBuffer;
    PFNGLBINDBUFFERBASEPROC BindBufferBase;
    PFNGLDELETEBUFFERSPROC DeleteBuffers;
    PFNGLGETERRORPROC GetError;
    PFNGLCREATETEXTURESPROC CreateTextures;
    PFNGLTEXTURESTORAGE2DPROC TextureStorage2D;
    PFNGLTEXTURESTORAGE3DPROC TextureStorage3D;
    PFNGLBINDTEXTUREPROC BindTexture;
    PFNGLDELETETEXTURESPROC DeleteTextures;
    PFNGLCREATESAMPLERSPROC CreateSamplers;
    PFNGLBINDSAMPLERPROC BindSampler;
    PFNGLDELETESAMPLERSPROC DeleteSamplers;
};

// The texture units grass samples from: 0 (density map, 2D), 3-5 (baked slices, 2D
// arrays) and 6-9 (colour, ambient, diffuse and height maps, 2D).
constexpr GLuint kUnits[] = {0, 3, 4, 5, 6, 7, 8, 9};
constexpr int kUnitCount = 8;
GLenum unit_target(GLuint unit) { return unit >= 3 && unit <= 5 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D; }
GLenum unit_binding(GLuint unit) {
    return unit >= 3 && unit <= 5 ? GL_TEXTURE_BINDING_2D_ARRAY : GL_TEXTURE_BINDING_2D;
}

template <class T>
void load(const grass_host::Host& host, T* fn, const char* name) {
    *fn = reinterpret_cast<T>(host.gl_proc_address(name));
    ASSERT_NE(*fn, nullptr) << name;
}

struct Snapshot {
    GLint program, vao, array_buffer, ubo0, ubo1, active_texture, viewport[4], depth_func, polygon_mode[2];
    GLboolean depth_mask, depth_test, cull, blend, multisample, a2c;
    GLint unit_texture[kUnitCount], unit_sampler[kUnitCount];
    bool operator==(const Snapshot& o) const {
        for (int i = 0; i < kUnitCount; ++i) {
            if (unit_texture[i] != o.unit_texture[i] || unit_sampler[i] != o.unit_sampler[i]) return false;
        }
        return program == o.program && vao == o.vao && array_buffer == o.array_buffer && ubo0 == o.ubo0 &&
               ubo1 == o.ubo1 && active_texture == o.active_texture && viewport[0] == o.viewport[0] &&
               viewport[1] == o.viewport[1] && viewport[2] == o.viewport[2] && viewport[3] == o.viewport[3] &&
               depth_func == o.depth_func && polygon_mode[0] == o.polygon_mode[0] && depth_mask == o.depth_mask &&
               depth_test == o.depth_test && cull == o.cull && blend == o.blend && multisample == o.multisample &&
               a2c == o.a2c;
    }
};

Snapshot snapshot(const Gl& gl) {
    Snapshot s{};
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vao);
    gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &s.array_buffer);
    gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &s.ubo0);
    gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 1, &s.ubo1);
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &s.active_texture);
    gl.GetIntegerv(GL_VIEWPORT, s.viewport);
    gl.GetIntegerv(GL_DEPTH_FUNC, &s.depth_func);
    gl.GetIntegerv(GL_POLYGON_MODE, s.polygon_mode);
    gl.GetBooleanv(GL_DEPTH_WRITEMASK, &s.depth_mask);
    s.depth_test = gl.IsEnabled(GL_DEPTH_TEST);
    s.cull = gl.IsEnabled(GL_CULL_FACE);
    s.blend = gl.IsEnabled(GL_BLEND);
    s.multisample = gl.IsEnabled(GL_MULTISAMPLE);
    s.a2c = gl.IsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    for (int i = 0; i < kUnitCount; ++i) {
        gl.ActiveTexture(GL_TEXTURE0 + kUnits[i]);
        gl.GetIntegerv(unit_binding(kUnits[i]), &s.unit_texture[i]);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &s.unit_sampler[i]);
    }
    gl.ActiveTexture(static_cast<GLenum>(s.active_texture));
    return s;
}

class GlStateTest : public RenderTest {};

TEST_P(GlStateTest, RenderRestoresTheHostsGlState) {
    Gl gl{};
    load(*host, &gl.GetIntegerv, "glGetIntegerv");
    load(*host, &gl.GetIntegeri_v, "glGetIntegeri_v");
    load(*host, &gl.GetBooleanv, "glGetBooleanv");
    load(*host, &gl.IsEnabled, "glIsEnabled");
    load(*host, &gl.Enable, "glEnable");
    load(*host, &gl.Disable, "glDisable");
    load(*host, &gl.Viewport, "glViewport");
    load(*host, &gl.DepthFunc, "glDepthFunc");
    load(*host, &gl.DepthMask, "glDepthMask");
    load(*host, &gl.ActiveTexture, "glActiveTexture");
    load(*host, &gl.CreateVertexArrays, "glCreateVertexArrays");
    load(*host, &gl.BindVertexArray, "glBindVertexArray");
    load(*host, &gl.DeleteVertexArrays, "glDeleteVertexArrays");
    load(*host, &gl.CreateBuffers, "glCreateBuffers");
    load(*host, &gl.BindBuffer, "glBindBuffer");
    load(*host, &gl.BindBufferBase, "glBindBufferBase");
    load(*host, &gl.DeleteBuffers, "glDeleteBuffers");
    load(*host, &gl.CreateTextures, "glCreateTextures");
    load(*host, &gl.TextureStorage2D, "glTextureStorage2D");
    load(*host, &gl.TextureStorage3D, "glTextureStorage3D");
    load(*host, &gl.BindTexture, "glBindTexture");
    load(*host, &gl.DeleteTextures, "glDeleteTextures");
    load(*host, &gl.CreateSamplers, "glCreateSamplers");
    load(*host, &gl.BindSampler, "glBindSampler");
    load(*host, &gl.DeleteSamplers, "glDeleteSamplers");

    // A field with every design map, and a volume tier beside the blades, so that grass
    // binds every unit it has: 0, 3-5 and 6-9.
    const uint8_t grey[4 * 4] = {200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200};
    grass_map_desc m = grass_default_map_desc();
    m.pixels = grey;
    m.width = m.height = 2;
    grass_field_desc d = field_desc(4);
    grass_map_id* single[] = {&d.maps.density, &d.maps.ambient, &d.maps.diffuse, &d.maps.height};
    for (grass_map_id* id : single) ASSERT_EQ(grass_create_map(ctx, &m, id), GRASS_SUCCESS) << log;
    m.format = GRASS_MAP_FORMAT_RGBA8_UNORM;
    ASSERT_EQ(grass_create_map(ctx, &m, &d.maps.color), GRASS_SUCCESS) << log;
    d.maps.height_scale = 0.1f;
    grass_tier_desc tiers[2] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 2}};
    grass_lod_test bands[2] = {};
    bands[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    bands[0].end = 1.9f;
    bands[1].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    bands[1].tier = 1;
    bands[1].begin = 1.9f;
    bands[1].end = 100.0f;
    d.tiers = tiers;
    d.tier_count = 2;
    d.lod_tests = bands;
    d.lod_test_count = 2;
    make_field(d);
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    const grass_view_desc v = view(eye, target);
    // A first frame through the host (its FBO stays bound afterwards).
    render(v);

    // The host's unusual state.
    GLuint vao = 0, buffers[3] = {0, 0, 0};
    gl.CreateVertexArrays(1, &vao);
    gl.CreateBuffers(3, buffers);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, 0, buffers[1]);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, 1, buffers[2]);
    gl.ActiveTexture(GL_TEXTURE3);
    gl.Viewport(3, 5, 17, 19);
    gl.DepthFunc(GL_GREATER);
    gl.DepthMask(GL_FALSE);
    gl.Disable(GL_DEPTH_TEST);
    gl.Enable(GL_CULL_FACE);
    gl.Enable(GL_BLEND);
    GLuint textures[kUnitCount] = {}, samplers[kUnitCount] = {};
    gl.CreateSamplers(kUnitCount, samplers);
    for (int i = 0; i < kUnitCount; ++i) {
        const GLenum target_kind = unit_target(kUnits[i]);
        gl.CreateTextures(target_kind, 1, &textures[i]);
        if (target_kind == GL_TEXTURE_2D_ARRAY) {
            gl.TextureStorage3D(textures[i], 1, GL_RGBA8, 2, 2, 2);
        } else {
            gl.TextureStorage2D(textures[i], 1, GL_RGBA8, 2, 2);
        }
        gl.ActiveTexture(GL_TEXTURE0 + kUnits[i]);
        gl.BindTexture(target_kind, textures[i]);
        gl.BindSampler(kUnits[i], samplers[i]);
    }
    gl.ActiveTexture(GL_TEXTURE3);
    const Snapshot before = snapshot(gl);

    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_gl_render(ctx), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    const Snapshot after = snapshot(gl);
    EXPECT_TRUE(before == after);
    EXPECT_EQ(after.vao, static_cast<GLint>(vao));
    EXPECT_EQ(after.viewport[2], 17);
    EXPECT_EQ(after.depth_func, GL_GREATER);
    EXPECT_EQ(after.blend, GL_TRUE);
    EXPECT_EQ(after.active_texture, GL_TEXTURE3);
    EXPECT_EQ(after.ubo1, static_cast<GLint>(buffers[2]));
    for (int i = 0; i < kUnitCount; ++i) {
        EXPECT_EQ(after.unit_texture[i], static_cast<GLint>(textures[i])) << "texture unit " << kUnits[i];
        EXPECT_EQ(after.unit_sampler[i], static_cast<GLint>(samplers[i])) << "sampler of unit " << kUnits[i];
    }
    grass_frame_stats stats{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    EXPECT_GT(stats.instances[GRASS_TIER_GEOMETRY], 0u);
    EXPECT_GT(stats.instances[GRASS_TIER_VOLUME], 0u);

    for (int i = 0; i < kUnitCount; ++i) {
        gl.ActiveTexture(GL_TEXTURE0 + kUnits[i]);
        gl.BindTexture(unit_target(kUnits[i]), 0);
        gl.BindSampler(kUnits[i], 0);
    }
    gl.DeleteTextures(kUnitCount, textures);
    gl.DeleteSamplers(kUnitCount, samplers);

    gl.BindVertexArray(0);
    gl.DeleteVertexArrays(1, &vao);
    gl.DeleteBuffers(3, buffers);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
    gl.ActiveTexture(GL_TEXTURE0);
}

// The host's draw state that grass does not bind but depends on (issue 16). grass_gl.h
// sorts it: state grass sets for its draws and restores (colour mask of draw buffer 0,
// stencil, scissor, polygon offset, clip distances, rasterizer discard, sample mask, sample
// shading, sample coverage and alpha-to-one, depth clamp, primitive restart, logic op) and
// state it reads as the host's choice (sRGB conversion, clip control, depth range, dither;
// front face does not matter: grass culls no faces). A host that leaves each in an unusual
// state gets the same picture as one with GL's defaults, and every value back.
struct DrawState {
    GLboolean color_mask[4], stencil, scissor, offset_fill, discard, sample_mask_on, sample_shading, sample_coverage,
        alpha_to_one, depth_clamp, restart, restart_fixed, logic_op, dither, srgb;
    GLboolean clip[8];
    GLint sample_mask, stencil_func, scissor_box[4], restart_index, logic_op_mode, front_face;
    GLfloat offset_factor, offset_units, min_sample_shading;
    bool operator==(const DrawState& o) const { return std::memcmp(this, &o, sizeof(DrawState)) == 0; }
};

struct StateGl {
    PFNGLGETINTEGERVPROC GetIntegerv;
    PFNGLGETINTEGERI_VPROC GetIntegeri_v;
    PFNGLGETBOOLEANI_VPROC GetBooleani_v;
    PFNGLGETFLOATVPROC GetFloatv;
    PFNGLISENABLEDPROC IsEnabled;
    PFNGLENABLEPROC Enable;
    PFNGLDISABLEPROC Disable;
    PFNGLCOLORMASKPROC ColorMask;
    PFNGLSTENCILFUNCPROC StencilFunc;
    PFNGLSCISSORPROC Scissor;
    PFNGLPOLYGONOFFSETPROC PolygonOffset;
    PFNGLSAMPLEMASKIPROC SampleMaski;
    PFNGLMINSAMPLESHADINGPROC MinSampleShading;
    PFNGLSAMPLECOVERAGEPROC SampleCoverage;
    PFNGLPRIMITIVERESTARTINDEXPROC PrimitiveRestartIndex;
    PFNGLLOGICOPPROC LogicOp;
    PFNGLFRONTFACEPROC FrontFace;
};

DrawState draw_state(const StateGl& gl) {
    DrawState s;
    std::memset(&s, 0, sizeof(s)); // padding too: compared with memcmp
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, 0, s.color_mask);
    s.stencil = gl.IsEnabled(GL_STENCIL_TEST);
    s.scissor = gl.IsEnabled(GL_SCISSOR_TEST);
    s.offset_fill = gl.IsEnabled(GL_POLYGON_OFFSET_FILL);
    s.discard = gl.IsEnabled(GL_RASTERIZER_DISCARD);
    s.sample_mask_on = gl.IsEnabled(GL_SAMPLE_MASK);
    s.sample_shading = gl.IsEnabled(GL_SAMPLE_SHADING);
    s.sample_coverage = gl.IsEnabled(GL_SAMPLE_COVERAGE);
    s.alpha_to_one = gl.IsEnabled(GL_SAMPLE_ALPHA_TO_ONE);
    s.depth_clamp = gl.IsEnabled(GL_DEPTH_CLAMP);
    s.restart = gl.IsEnabled(GL_PRIMITIVE_RESTART);
    s.restart_fixed = gl.IsEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    s.logic_op = gl.IsEnabled(GL_COLOR_LOGIC_OP);
    s.dither = gl.IsEnabled(GL_DITHER);
    s.srgb = gl.IsEnabled(GL_FRAMEBUFFER_SRGB);
    for (int i = 0; i < 8; ++i) s.clip[i] = gl.IsEnabled(GL_CLIP_DISTANCE0 + i);
    gl.GetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &s.sample_mask);
    gl.GetIntegerv(GL_STENCIL_FUNC, &s.stencil_func);
    gl.GetIntegerv(GL_SCISSOR_BOX, s.scissor_box);
    gl.GetIntegerv(GL_PRIMITIVE_RESTART_INDEX, &s.restart_index);
    gl.GetIntegerv(GL_LOGIC_OP_MODE, &s.logic_op_mode);
    gl.GetIntegerv(GL_FRONT_FACE, &s.front_face);
    gl.GetFloatv(GL_POLYGON_OFFSET_FACTOR, &s.offset_factor);
    gl.GetFloatv(GL_POLYGON_OFFSET_UNITS, &s.offset_units);
    gl.GetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &s.min_sample_shading);
    return s;
}

void set_unusual_state(const StateGl& gl) {
    gl.ColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
    gl.Enable(GL_STENCIL_TEST);
    gl.StencilFunc(GL_NEVER, 1, 0xff);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(0, 0, 8, 8);
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(0.0f, 1e7f);
    for (int i = 0; i < 8; ++i) gl.Enable(GL_CLIP_DISTANCE0 + i);
    gl.Enable(GL_RASTERIZER_DISCARD);
    gl.Enable(GL_SAMPLE_MASK);
    gl.SampleMaski(0, 0x1);
    gl.Enable(GL_SAMPLE_SHADING);
    gl.MinSampleShading(1.0f);
    gl.Enable(GL_SAMPLE_COVERAGE);
    gl.SampleCoverage(0.25f, GL_FALSE);
    gl.Enable(GL_SAMPLE_ALPHA_TO_ONE);
    gl.Enable(GL_DEPTH_CLAMP);
    gl.Enable(GL_PRIMITIVE_RESTART);
    gl.PrimitiveRestartIndex(0);
    gl.Enable(GL_COLOR_LOGIC_OP);
    gl.LogicOp(GL_XOR);
    gl.Disable(GL_DITHER);
    gl.FrontFace(GL_CW);
}

void set_default_state(const StateGl& gl) {
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Disable(GL_STENCIL_TEST);
    gl.StencilFunc(GL_ALWAYS, 0, 0xff);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(0.0f, 0.0f);
    for (int i = 0; i < 8; ++i) gl.Disable(GL_CLIP_DISTANCE0 + i);
    gl.Disable(GL_RASTERIZER_DISCARD);
    gl.Disable(GL_SAMPLE_MASK);
    gl.SampleMaski(0, ~0u);
    gl.Disable(GL_SAMPLE_SHADING);
    gl.MinSampleShading(0.0f);
    gl.Disable(GL_SAMPLE_COVERAGE);
    gl.SampleCoverage(1.0f, GL_FALSE);
    gl.Disable(GL_SAMPLE_ALPHA_TO_ONE);
    gl.Disable(GL_DEPTH_CLAMP);
    gl.Disable(GL_PRIMITIVE_RESTART);
    gl.PrimitiveRestartIndex(0);
    gl.Disable(GL_COLOR_LOGIC_OP);
    gl.LogicOp(GL_COPY);
    gl.Enable(GL_DITHER);
    gl.FrontFace(GL_CCW);
}

TEST_P(GlStateTest, AHostsUnusualDrawStateChangesNeitherTheGrassNorItself) {
    StateGl gl{};
    load(*host, &gl.GetIntegerv, "glGetIntegerv");
    load(*host, &gl.GetIntegeri_v, "glGetIntegeri_v");
    load(*host, &gl.GetBooleani_v, "glGetBooleani_v");
    load(*host, &gl.GetFloatv, "glGetFloatv");
    load(*host, &gl.IsEnabled, "glIsEnabled");
    load(*host, &gl.Enable, "glEnable");
    load(*host, &gl.Disable, "glDisable");
    load(*host, &gl.ColorMask, "glColorMask");
    load(*host, &gl.StencilFunc, "glStencilFunc");
    load(*host, &gl.Scissor, "glScissor");
    load(*host, &gl.PolygonOffset, "glPolygonOffset");
    load(*host, &gl.SampleMaski, "glSampleMaski");
    load(*host, &gl.MinSampleShading, "glMinSampleShading");
    load(*host, &gl.SampleCoverage, "glSampleCoverage");
    load(*host, &gl.PrimitiveRestartIndex, "glPrimitiveRestartIndex");
    load(*host, &gl.LogicOp, "glLogicOp");
    load(*host, &gl.FrontFace, "glFrontFace");

    for (const uint32_t samples : {1u, 4u}) {
        SCOPED_TRACE(std::to_string(samples) + " samples");
        grass_host::TargetDesc t;
        t.width = t.height = 128;
        t.samples = samples;
        start(t);
        // Every tier (Lemme's setup over a large field) and a host wall the near grass hides.
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 1024;
        make_field(d);
        const double eye[3] = {128.0, 1.7, 1.0}, target[3] = {128.0, 0.0, 12.0};
        const grass_view_desc v = view(eye, target, 60.0f);
        grass_host::Occluder wall;
        wall.x0 = 32;
        wall.x1 = 96;
        wall.y0 = 48;
        wall.y1 = 128;
        wall.distance = 6.0f;
        const grass_host::Image clean = render(v, &wall);

        DrawState before{}, after{};
        host->before_grass = [&] {
            set_unusual_state(gl);
            before = draw_state(gl);
        };
        host->after_grass = [&] {
            after = draw_state(gl);
            set_default_state(gl); // the host's own read-back (a blit) obeys the scissor
        };
        const grass_host::Image unusual = render(v, &wall);
        host->before_grass = nullptr;
        host->after_grass = nullptr;
        save(clean, std::to_string(samples) + "x_clean");
        save(unusual, std::to_string(samples) + "x_unusual");

        EXPECT_TRUE(before == after) << "grass_gl_render left the host's draw state changed";
        EXPECT_EQ(after.scissor_box[2], 8);
        EXPECT_EQ(after.front_face, GL_CW);
        EXPECT_EQ(after.sample_mask, 1);
        // Grass sees its own draw state either way: the same picture (the occluder's clear is
        // the host's, before its state changed).
        EXPECT_LT(mean_difference(clean, unusual), 0.05) << "the host's draw state changed the grass";
    }
}

// A depth pass (grass_view_pass_desc) masks every colour off and sets its polygon offset:
// the host's masks and offset (enabled with its values, or disabled at 0) are back after it.
TEST_P(GlStateTest, ADepthPassRestoresTheHostsColourMasksAndPolygonOffset) {
    StateGl gl{};
    load(*host, &gl.GetIntegerv, "glGetIntegerv");
    load(*host, &gl.GetIntegeri_v, "glGetIntegeri_v");
    load(*host, &gl.GetBooleani_v, "glGetBooleani_v");
    load(*host, &gl.GetFloatv, "glGetFloatv");
    load(*host, &gl.IsEnabled, "glIsEnabled");
    load(*host, &gl.Enable, "glEnable");
    load(*host, &gl.Disable, "glDisable");
    load(*host, &gl.ColorMask, "glColorMask");
    load(*host, &gl.StencilFunc, "glStencilFunc");
    load(*host, &gl.Scissor, "glScissor");
    load(*host, &gl.PolygonOffset, "glPolygonOffset");
    load(*host, &gl.SampleMaski, "glSampleMaski");
    load(*host, &gl.MinSampleShading, "glMinSampleShading");
    load(*host, &gl.SampleCoverage, "glSampleCoverage");
    load(*host, &gl.PrimitiveRestartIndex, "glPrimitiveRestartIndex");
    load(*host, &gl.LogicOp, "glLogicOp");
    load(*host, &gl.FrontFace, "glFrontFace");
    make_field(field_desc(16));
    const double eye[3] = {2.0, 1.5, -1.0}, target[3] = {2.0, 0.0, 2.0};
    grass_view_desc v = view(eye, target);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.depth_bias_constant = 4.0f;
    pass.depth_bias_slope = 1.5f;
    v.next = &pass;
    for (const bool unusual : {false, true}) {
        SCOPED_TRACE(unusual ? "the host's unusual state" : "the default state");
        DrawState before{}, after{};
        host->before_grass = [&] {
            if (unusual) set_unusual_state(gl);
            before = draw_state(gl);
        };
        host->after_grass = [&] {
            after = draw_state(gl);
            set_default_state(gl);
        };
        render(v);
        host->before_grass = nullptr;
        host->after_grass = nullptr;
        EXPECT_TRUE(before == after) << "the depth pass left the host's draw state changed";
        EXPECT_EQ(after.offset_fill, unusual ? GL_TRUE : GL_FALSE);
        EXPECT_EQ(after.offset_units, unusual ? 1e7f : 0.0f);
        EXPECT_EQ(after.color_mask[1], GL_TRUE);
    }
}

// Responsive grass touches more (grass_gl.h): shader storage bindings 0-7 and the generic
// one, uniform buffer binding 2, image unit 0, texture units 10-11 and their samplers. With
// wind and a collider (the interaction pass runs, the blade window pass steps and poses the
// blades, and the draws read the map and the window), every one of them is back as the host
// left it. Seen failing with the state guard's restore of storage bindings 4-7 left out.
TEST_P(GlStateTest, ResponsiveRenderRestoresItsExtraState) {
    PFNGLGETINTEGERI_VPROC get_i = nullptr;
    PFNGLGETINTEGERVPROC get = nullptr;
    PFNGLCREATEBUFFERSPROC create_buffers = nullptr;
    PFNGLBINDBUFFERBASEPROC bind_base = nullptr;
    PFNGLBINDBUFFERRANGEPROC bind_range = nullptr;
    PFNGLBINDBUFFERPROC bind = nullptr;
    PFNGLCREATETEXTURESPROC create_textures = nullptr;
    PFNGLTEXTURESTORAGE2DPROC storage = nullptr;
    PFNGLBINDIMAGETEXTUREPROC bind_image = nullptr;
    PFNGLACTIVETEXTUREPROC active = nullptr;
    PFNGLBINDTEXTUREPROC bind_texture = nullptr;
    PFNGLCREATESAMPLERSPROC create_samplers = nullptr;
    PFNGLBINDSAMPLERPROC bind_sampler = nullptr;
    load(*host, &get_i, "glGetIntegeri_v");
    load(*host, &get, "glGetIntegerv");
    load(*host, &create_buffers, "glCreateBuffers");
    load(*host, &bind_base, "glBindBufferBase");
    load(*host, &bind_range, "glBindBufferRange");
    load(*host, &bind, "glBindBuffer");
    load(*host, &create_textures, "glCreateTextures");
    load(*host, &storage, "glTextureStorage2D");
    load(*host, &bind_image, "glBindImageTexture");
    load(*host, &active, "glActiveTexture");
    load(*host, &bind_texture, "glBindTexture");
    load(*host, &create_samplers, "glCreateSamplers");
    load(*host, &bind_sampler, "glBindSampler");

    make_field(field_desc(4));
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 5.0f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    grass_collider c{};
    c.shape = GRASS_COLLIDER_SPHERE;
    c.radius = 0.3f;
    c.center[0] = c.center[2] = 0.5;
    c.center[1] = 0.3;
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    grass_view_desc v = view(eye, target);
    render(v);

    GLuint buffers[10] = {}, textures[3] = {}, samplers[2] = {};
    PFNGLNAMEDBUFFERDATAPROC buffer_data = nullptr;
    load(*host, &buffer_data, "glNamedBufferData");
    create_buffers(10, buffers);
    for (GLuint i = 0; i < 8; ++i) bind_base(GL_SHADER_STORAGE_BUFFER, i, buffers[i]);
    bind(GL_SHADER_STORAGE_BUFFER, buffers[8]);
    buffer_data(buffers[9], 1024, nullptr, GL_STATIC_DRAW);
    bind_range(GL_UNIFORM_BUFFER, 2, buffers[9], 256, 512); // a range, so its offset and size are checked too
    create_textures(GL_TEXTURE_2D, 3, textures);
    for (GLuint t : textures) storage(t, 1, GL_RGBA8, 2, 2);
    bind_image(0, textures[0], 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
    create_samplers(2, samplers);
    for (int i = 0; i < 2; ++i) {
        active(GL_TEXTURE10 + i);
        bind_texture(GL_TEXTURE_2D, textures[1 + i]);
        bind_sampler(10 + i, samplers[i]);
    }
    active(GL_TEXTURE2);
    struct Extra {
        GLint storage[8], generic, uniform2, uniform2_start, uniform2_size, image, image_access, image_format,
            unit_texture[2], unit_sampler[2], active;
    };
    const auto extra = [&] {
        Extra e{};
        for (GLuint i = 0; i < 8; ++i) get_i(GL_SHADER_STORAGE_BUFFER_BINDING, i, &e.storage[i]);
        get(GL_SHADER_STORAGE_BUFFER_BINDING, &e.generic);
        get_i(GL_UNIFORM_BUFFER_BINDING, 2, &e.uniform2);
        get_i(GL_UNIFORM_BUFFER_START, 2, &e.uniform2_start);
        get_i(GL_UNIFORM_BUFFER_SIZE, 2, &e.uniform2_size);
        get_i(GL_IMAGE_BINDING_NAME, 0, &e.image);
        get_i(GL_IMAGE_BINDING_ACCESS, 0, &e.image_access);
        get_i(GL_IMAGE_BINDING_FORMAT, 0, &e.image_format);
        get(GL_ACTIVE_TEXTURE, &e.active);
        for (int i = 0; i < 2; ++i) {
            active(GL_TEXTURE10 + i);
            get(GL_TEXTURE_BINDING_2D, &e.unit_texture[i]);
            get(GL_SAMPLER_BINDING, &e.unit_sampler[i]);
        }
        active(static_cast<GLenum>(e.active));
        return e;
    };
    const Extra before = extra();
    v.time = 0.5;
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_gl_render(ctx), GRASS_SUCCESS) << log;
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    grass_frame_stats stats{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    EXPECT_GT(stats.interaction_texels, 0u) << "the interaction pass must have run";
    const Extra after = extra();
    EXPECT_EQ(std::memcmp(&before, &after, sizeof before), 0);
    for (GLuint i = 0; i < 8; ++i) EXPECT_EQ(after.storage[i], GLint(buffers[i])) << "storage binding " << i;
    EXPECT_EQ(after.generic, GLint(buffers[8]));
    EXPECT_EQ(after.uniform2, GLint(buffers[9]));
    EXPECT_EQ(after.uniform2_start, 256);
    EXPECT_EQ(after.uniform2_size, 512);
    EXPECT_EQ(after.image, GLint(textures[0]));
    EXPECT_EQ(after.image_access, GL_READ_ONLY);
    EXPECT_EQ(after.unit_texture[1], GLint(textures[2]));
    EXPECT_EQ(after.unit_sampler[0], GLint(samplers[0]));
    EXPECT_EQ(after.active, GL_TEXTURE2);

    // The blade window pass ran (else bindings 4-7 and uniform 2 were never touched): beyond
    // the interaction map's levels and the blade curves, the 16 cells hold their blades'
    // records (kBladeWindowRecordBytes = 96 a blade).
    grass_memory_stats memory{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &memory), GRASS_SUCCESS);
    grass_patch_info info{};
    ASSERT_EQ(grass_get_patch_info(ctx, patch, &info), GRASS_SUCCESS);
    const grass_interaction_desc map = grass_default_interaction_desc();
    const uint64_t map_bytes = uint64_t(map.level_count) * map.resolution * map.resolution * 16u;
    const uint64_t curve_bytes = uint64_t(info.blade_count) * 32u;
    EXPECT_GE(memory.dynamics_gpu_bytes, map_bytes + curve_bytes + 16u * info.blade_count * 96u)
        << "the blade window pass did not run";
}

INSTANTIATE_TEST_SUITE_P(Backends, GlStateTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
