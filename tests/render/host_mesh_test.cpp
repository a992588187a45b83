// The hosts' mesh drawers (test_hosts/mesh_drawer_*.hpp) share depth with grass under
// every depth convention, with 1 and 4 samples: a wall across a lawn hides the grass behind
// it and the grass in front of it hides its foot. And the glTF sample scene renders with
// grass on its terrain and its shed drawn by the host, in both backends.
#include "gltf_scene.hpp"
#include "render_fixture.hpp"

#include <algorithm>

namespace grass_test {
namespace {

// Wall-coloured: strongly red, as the wall's albedo (0.8, 0.05, 0.05) lit.
bool is_wall(const uint8_t* p) { return p[0] > 2 * p[1] + 20 && p[0] > 2 * p[2] + 20; }
// Grass-coloured: greener than red.
bool is_green(const uint8_t* p) { return p[1] > p[0] + 4 && p[1] > p[2]; }

// A vertical quad from (-1.5, 0, z) to (1.5, 0.6, z), facing -z.
grass_host::HostMesh wall(double z) {
    grass_host::HostMesh m;
    m.name = "wall";
    m.origin[2] = z;
    m.vertices = {-1.5f, 0.0f, 0.0f, 0, 0, -1, 1.5f, 0.0f, 0.0f, 0, 0, -1,
                  -1.5f, 0.6f, 0.0f, 0, 0, -1, 1.5f, 0.6f, 0.0f, 0, 0, -1};
    m.indices = {0, 1, 2, 2, 1, 3};
    m.color[0] = 0.8f, m.color[1] = 0.05f, m.color[2] = 0.05f;
    return m;
}

class HostMeshTest : public RenderTest {};

// A lawn 6 m x 6 m of blades, the wall across it 2 m ahead of a camera 0.6 m up (level with
// the wall's top). The lawn behind the wall projects onto the wall: a mesh that did not
// write depth, or wrote the wrong depth, lets that grass over it; the blades (up to 0.2 m)
// in front of the wall cover its foot.
TEST_P(HostMeshTest, AWallHidesTheGrassBehindItAndTheGrassInFrontHidesItsFoot) {
    struct Convention {
        bool clip_zero_to_one, reversed;
    };
    const bool gl = GetParam() == GRASS_BACKEND_GL;
    const Convention gl_conventions[] = {{false, false}, {false, true}, {true, false}, {true, true}};
    const Convention vk_conventions[] = {{false, false}, {false, true}};
    const double eye[3] = {0.0, 0.6, -2.0}, look[3] = {0.0, 0.3, 1.0};
    for (int c = 0; c < (gl ? 4 : 2); ++c) {
        for (uint32_t samples : {1u, 4u}) {
            const Convention conv = gl ? gl_conventions[c] : vk_conventions[c];
            SCOPED_TRACE(std::string(conv.reversed ? "reversed" : "classic") + " depth, clip z " +
                         (conv.clip_zero_to_one || !gl ? "0..1" : "-1..1") + ", " + std::to_string(samples) +
                         " samples" + (gl || samples == 1 ? "" : ", dynamic rendering"));
            grass_host::TargetDesc t;
            t.width = t.height = 96;
            t.samples = samples;
            t.reversed_z = conv.reversed;
            t.gl_clip_zero_to_one = conv.clip_zero_to_one;
            t.vk_dynamic_rendering = !gl && samples == 4; // the mesh pipeline for both Vulkan pass kinds
            t.meshes = {wall(0.0)};
            start(t);
            grass_field_desc d = field_desc(24);
            d.base_transform[12] = -3.0;
            d.base_transform[14] = -2.5;
            const grass_field_id field = make_field(d);
            const grass_host::Image image = render(view(eye, look));
            double x0, y_top, x1, y_foot, unused;
            const double top_left[3] = {-1.5, 0.58, 0.0}, foot_right[3] = {1.5, 0.0, 0.0};
            ASSERT_TRUE(project_point(eye, look, 50.0f, 96, 96, top_left, &x0, &y_top));
            ASSERT_TRUE(project_point(eye, look, 50.0f, 96, 96, foot_right, &x1, &y_foot));
            const double lawn_top[3] = {0.0, 0.25, 0.0}, lawn_foot[3] = {0.0, 0.08, 0.0}; // blades: 0.11..0.21 m
            double y_lawn, y_low;
            ASSERT_TRUE(project_point(eye, look, 50.0f, 96, 96, lawn_top, &unused, &y_lawn));
            ASSERT_TRUE(project_point(eye, look, 50.0f, 96, 96, lawn_foot, &unused, &y_low));
            // Across the width the wall spans (+x is to the left: the camera looks along +z).
            auto clamp = [](double v) { return uint32_t(std::min(std::max(v, 0.0), 96.0)); };
            const uint32_t left = clamp(std::min(x0, x1) + 1), right = clamp(std::max(x0, x1) - 1);
            int wall_pixels = 0, pixels = 0, green_at_foot = 0, foot_pixels = 0;
            for (uint32_t y = clamp(y_top + 1); y < clamp(y_lawn); ++y) {
                for (uint32_t x = left; x < right; ++x, ++pixels) wall_pixels += is_wall(image.pixel(x, y));
            }
            for (uint32_t y = clamp(y_low); y < clamp(y_foot); ++y) {
                for (uint32_t x = left; x < right; ++x, ++foot_pixels) green_at_foot += is_green(image.pixel(x, y));
            }
            ASSERT_GT(pixels, 200);
            ASSERT_GT(foot_pixels, 150);
            EXPECT_GT(wall_pixels, pixels * 97 / 100) << "the wall hides the lawn behind it";
            EXPECT_GT(green_at_foot, foot_pixels / 2) << "the blades in front of the wall cover its foot";
            if (HasFailure()) save(image, "host-mesh");
            EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
        }
    }
}

// hill.glb at 160 x 90: grass on the terrain (the lower half mostly green), the shed drawn
// by the host where its node puts it, the sky above the hill.
TEST_P(HostMeshTest, TheGltfSampleSceneRendersWithGrassOnItsTerrain) {
    grass_sample::Scene scene;
    grass_sample::GltfInfo info;
    std::string error;
    ASSERT_TRUE(grass_sample::load_gltf_scene(GRASS_GLTF_SAMPLE, &scene, &info, &error)) << error;
    grass_host::TargetDesc t;
    t.width = 160;
    t.height = 90;
    t.meshes = scene.meshes;
    start(t);
    grass_field_desc d = scene.field;
    d.patch = patch;
    for (grass_sample::MapRole role : {grass_sample::MapRole::height, grass_sample::MapRole::density}) {
        const grass_sample::Scene::MapImage& m = scene.map(role);
        grass_map_desc md = grass_default_map_desc();
        md.pixels = m.pixels.data();
        md.width = m.width;
        md.height = m.height;
        md.format = m.format;
        ASSERT_EQ(grass_create_map(ctx, &md, role == grass_sample::MapRole::height ? &d.maps.height : &d.maps.density),
                  GRASS_SUCCESS)
            << log;
    }
    d.maps.height_scale = scene.height_scale;
    const grass_field_id field = make_field(d);
    grass_view_desc v =
        grass_host::make_view(*host, scene.eye, scene.target, scene.fov_degrees, scene.near_m, scene.far_m);
    const grass_host::Image image = render(v);
    int green = 0;
    for (uint32_t y = 60; y < 90; ++y)
        for (uint32_t x = 0; x < 160; ++x) green += is_green(image.pixel(x, y));
    EXPECT_GT(green, 160 * 30 * 9 / 10) << "grass covers the terrain in front of the camera";
    // Points up the shed's axis (its node stands at (-7, 1.2, 7), 2.6 m tall).
    double sx, sy;
    int shed_pixels = 0;
    for (double h = -0.8; h < 1.2; h += 0.25) {
        const double p[3] = {-7.0, 1.2 + h, 7.0};
        ASSERT_TRUE(project_point(scene.eye, scene.target, scene.fov_degrees, 160, 90, p, &sx, &sy));
        if (sx < 0 || sy < 0 || sx >= 160 || sy >= 90) continue;
        const uint8_t* q = image.pixel(uint32_t(sx), uint32_t(sy));
        shed_pixels += q[0] > q[1] + 25 && q[0] > q[2] + 25; // red paint, in the shade or the sun
    }
    EXPECT_GE(shed_pixels, 6) << "the host draws the shed";
    if (HasFailure()) save(image, "gltf-hill");
    EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
}

INSTANTIATE_TEST_SUITE_P(Backends, HostMeshTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
