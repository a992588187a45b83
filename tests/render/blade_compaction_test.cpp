// Culled blades compacted (docs/responsive.md "Culled blades compacted", jahrmann2017
// 6.1-6.2): on a backend that compacts (GL), a window draw runs the vertex shader for the
// blades its view draws only, and draws what it drew before. The triangles the vertex stage
// emits are counted with a GL_PRIMITIVES_GENERATED query around grass_gl_render.
#include "gl_test_functions.hpp"
#include "render_fixture.hpp"

#include <cstring>

namespace grass_test {
namespace {

// A GL 4.5 driver without GL_ARB_shader_draw_parameters, made by hiding it from glGetStringi.
PFNGLGETSTRINGIPROC g_real_get_stringi = nullptr;
const GLubyte* APIENTRY get_stringi_without_draw_parameters(GLenum name, GLuint index) {
    const GLubyte* s = g_real_get_stringi(name, index);
    if (name == GL_EXTENSIONS && s != nullptr &&
        std::strcmp(reinterpret_cast<const char*>(s), "GL_ARB_shader_draw_parameters") == 0)
        return reinterpret_cast<const GLubyte*>("GL_GRASS_TEST_hidden_extension");
    return s;
}
void (*hide_draw_parameters(const char* name, void (*real)(void)))(void) {
    if (std::strcmp(name, "glGetStringi") != 0) return real;
    g_real_get_stringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(real);
    return reinterpret_cast<void (*)(void)>(&get_stringi_without_draw_parameters);
}

class BladeCompactionTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND; // field_desc's geometry tier, out to 60 m
        blade_band.end = 60.0f;
        start(target());
    }

    static grass_host::TargetDesc target() {
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 120;
        return t;
    }

    // The triangles the grass draws of a frame of `v` emit, with wind (`wind`) or still.
    uint64_t triangles(const grass_view_desc& v, bool wind, grass_host::Image* image) {
        GlTestFunctions gl;
        load_gl_test_functions(*host, &gl);
        GLuint query = 0;
        gl.CreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
        grass_wind_desc w = grass_default_wind_desc();
        w.speed = 6.0f;
        EXPECT_EQ(grass_set_wind(ctx, wind ? &w : nullptr), GRASS_SUCCESS) << log;
        host->draw_grass = [&](grass_context* c, void*) {
            gl.BeginQuery(GL_PRIMITIVES_GENERATED, query);
            const grass_result r = grass_gl_render(c);
            gl.EndQuery(GL_PRIMITIVES_GENERATED);
            return r;
        };
        *image = render(v);
        host->draw_grass = nullptr;
        GLuint64 count = 0;
        gl.GetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
        gl.DeleteQueries(1, &query);
        return count;
    }
};

// A 2 m x 2 m field seen whole, at full density and at half: still grass emits every
// blade's triangles at both (the blades the density drops are degenerate); with wind the
// window variant emits those of the blades that pass their threshold only: all of them at
// full density (the same count as still grass), about half at half density (0.500). Seen
// failing with blade_compaction.comp's opacity test dropped (every blade kept): 1.000 at
// half density; and with it dropping every odd blade: 0.255, and half the count at full.
TEST_P(BladeCompactionTest, EmitsOnlyTheBladesThatPassTheirThreshold) {
    const double eye[3] = {1.0, 1.6, -0.4}, look[3] = {1.0, 0.0, 1.1};
    const grass_view_desc v = view(eye, look);
    uint64_t counts[2][2] = {}; // [density full, half][still, wind]
    for (int half = 0; half < 2; ++half) {
        grass_field_desc fd = field_desc(8);
        fd.density = half ? 0.5f : 1.0f;
        const grass_field_id field = make_field(fd);
        grass_host::Image image;
        counts[half][0] = triangles(v, false, &image);
        expect_grass(image, host->target(), 0.2, half ? "still grass, half density" : "still grass");
        counts[half][1] = triangles(v, true, &image);
        expect_grass(image, host->target(), 0.2, half ? "wind, half density" : "wind");
        EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS) << log;
    }
    const double half_share = double(counts[1][1]) / double(counts[1][0]);
    std::printf("triangles: full density still %llu, wind %llu; half density still %llu, wind %llu (%.3f)\n",
                static_cast<unsigned long long>(counts[0][0]), static_cast<unsigned long long>(counts[0][1]),
                static_cast<unsigned long long>(counts[1][0]), static_cast<unsigned long long>(counts[1][1]),
                half_share);
    EXPECT_GT(counts[0][0], 0u);
    EXPECT_EQ(counts[1][0], counts[0][0]) << "still grass emits every blade at any density";
    EXPECT_EQ(counts[0][1], counts[0][0]) << "at full density every blade passes its threshold";
    EXPECT_GT(half_share, 0.44);
    EXPECT_LT(half_share, 0.56);
}

// A GL 4.5 driver without GL_ARB_shader_draw_parameters (the compacted variant's base
// instance) draws the window variant uncompacted: every blade's triangles at half density,
// and the same picture as the compacting driver's. Seen failing while the window variant's
// programs were compiled compacted whatever the driver: the uncompacted draws drew no grass
// (the picture 63 levels from the compacting driver's).
TEST_P(BladeCompactionTest, ADriverWithoutDrawParametersDrawsEveryBlade) {
    const double eye[3] = {1.0, 1.6, -0.4}, look[3] = {1.0, 0.0, 1.1};
    grass_host::Image images[2];
    uint64_t counts[2][2] = {}; // [compacting, hidden][still, wind]
    for (int hidden = 0; hidden < 2; ++hidden) {
        grass_host::TargetDesc t = target();
        if (hidden) t.gl_proc_filter = &hide_draw_parameters;
        start(t);
        ASSERT_FALSE(HasFatalFailure());
        grass_field_desc fd = field_desc(8);
        fd.density = 0.5f;
        make_field(fd);
        const grass_view_desc v = view(eye, look);
        grass_host::Image still;
        counts[hidden][0] = triangles(v, false, &still);
        expect_grass(still, host->target(), 0.2, hidden ? "still, no draw parameters" : "still");
        counts[hidden][1] = triangles(v, true, &images[hidden]);
        expect_grass(images[hidden], host->target(), 0.2, hidden ? "wind, no draw parameters" : "wind");
    }
    EXPECT_LT(counts[0][1], counts[0][0]) << "the compacting driver should draw fewer blades with wind";
    EXPECT_EQ(counts[1][1], counts[1][0]) << "without the extension every blade is drawn, as still grass draws them";
    EXPECT_LT(mean_difference(images[0], images[1]), 0.01) << "the uncompacted window variant draws another picture";
}

// GL: a query counts the triangles (Vulkan does not compact: Backend::compacts_blade_window).
INSTANTIATE_TEST_SUITE_P(Backends, BladeCompactionTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const ::testing::TestParamInfo<grass_backend>& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
