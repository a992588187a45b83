// Shared depth under every depth convention a host may have: GL's default clip z -1..1 and
// clip control's 0..1 (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), Vulkan's only one),
// each with classic (GRASS_DEPTH_LESS) and reversed (GRASS_DEPTH_GREATER) depth, for every
// tier. The volume tier writes gl_FragDepth itself: it must map clip z/w as the host's
// convention does, or grass lands at the wrong depth (issue 16: under clip control the
// volume tier's depths won everywhere in a reversed-Z host).
#include "render_fixture.hpp"

#include <cstdlib>

namespace grass_test {
namespace {

struct Convention {
    const char* name;
    bool clip_zero_to_one; // GL only; Vulkan always has it
    bool reversed;
};

constexpr Convention kGlConventions[] = {
    {"gl -1..1 classic", false, false},
    {"gl -1..1 reversed", false, true},
    {"gl 0..1 classic", true, false},
    {"gl 0..1 reversed", true, true},
};
constexpr Convention kVkConventions[] = {
    {"vk 0..1 classic", false, false},
    {"vk 0..1 reversed", false, true},
};

bool near_color(const uint8_t* p, const uint8_t c[3], int tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (std::abs(int(p[k]) - int(c[k])) > tolerance) return false;
    }
    return true;
}

class DepthConventionTest : public RenderTest {};

// Looking straight down from 1.5 m on a field of one tier: the grass lies 1.3 .. 1.5 m
// from the camera. The host draws a box 1.0 m away over the right half of the middle rows
// (in front of every blade: it hides the grass) and a wall 2.2 m away over their left half
// (behind the grass and its ground: the grass hides it wherever a blade is). A depth mapped
// for the wrong convention moves grass to about twice its distance (behind the wall) or
// to a depth of 1/2 or more (in front of the box for reversed depth).
TEST_P(DepthConventionTest, HostObjectsInFrontHideGrassAndGrassHidesWhatIsBehindIt) {
    const bool gl = GetParam() == GRASS_BACKEND_GL;
    const Convention* conventions = gl ? kGlConventions : kVkConventions;
    const int convention_count = gl ? 4 : 2;
    const grass_tier_kind kinds[3] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
    const char* kind_names[3] = {"geometry", "volume", "image"};
    for (int c = 0; c < convention_count; ++c) {
        grass_host::TargetDesc t;
        t.width = t.height = 128;
        t.gl_clip_zero_to_one = conventions[c].clip_zero_to_one;
        t.reversed_z = conventions[c].reversed;
        start(t);
        for (int k = 0; k < 3; ++k) {
            SCOPED_TRACE(std::string(conventions[c].name) + ", " + kind_names[k] + " tier");
            const uint32_t slices = kinds[k] == GRASS_TIER_VOLUME ? 8 : 0;
            const grass_field_id field = make_field(solo_tier_field(16, kinds[k], slices, 4));
            const double eye[3] = {2.0, 1.5, 2.0}, target[3] = {2.0, 0.0, 2.0001};
            const grass_view_desc v = view(eye, target);
            const grass_host::Image open = render(v);
            grass_host::Occluder box;
            box.x0 = 64;
            box.x1 = 128;
            box.y0 = 32;
            box.y1 = 96;
            box.distance = 1.0f;
            box.color[0] = 0.8f, box.color[1] = 0.1f, box.color[2] = 0.1f; // about (231, 89, 89) in sRGB
            grass_host::Occluder wall = box;
            wall.x0 = 0;
            wall.x1 = 64;
            wall.distance = 2.2f;
            wall.color[0] = 0.1f, wall.color[1] = 0.1f, wall.color[2] = 0.8f; // about (89, 89, 231)
            // The host draws one occluder per frame: the box in one frame, the wall in another.
            const grass_host::Image boxed = render(v, &box);
            const grass_host::Image walled = render(v, &wall);
            std::string tag = std::string(conventions[c].name) + "_" + kind_names[k];
            for (char& ch : tag) ch = ch == ' ' ? '_' : ch;
            save(open, tag + "_open");
            save(boxed, tag + "_box");
            save(walled, tag + "_wall");

            uint8_t sky[3];
            expected_sky(host->target(), sky);
            const uint8_t red[3] = {231, 89, 89};
            int grass = 0, box_shown = 0, grass_over_wall = 0, grass_pixels_left = 0;
            for (uint32_t y = 32; y < 96; ++y) {
                for (uint32_t x = 0; x < 128; ++x) {
                    const bool is_blade = is_grass(open.pixel(x, y), sky);
                    grass += is_blade ? 1 : 0;
                    if (x >= 64) {
                        box_shown += near_color(boxed.pixel(x, y), red, 3) ? 1 : 0;
                    } else if (is_blade) {
                        ++grass_pixels_left;
                        grass_over_wall += near_color(walled.pixel(x, y), open.pixel(x, y), 4) ? 1 : 0;
                    }
                }
            }
            EXPECT_GT(grass, 128 * 64 / 4) << "the tier draws grass under the camera";
            EXPECT_EQ(box_shown, 64 * 64) << "the box in front hides the grass";
            EXPECT_GT(grass_over_wall, grass_pixels_left * 95 / 100)
                << "grass in front of the wall hides it: " << grass_over_wall << " of " << grass_pixels_left;
            EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, DepthConventionTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
