// Views under any projection matrix (issue 33, items 1 and 3): a depth view whose projection
// is warped (a light-space perspective shadow map's, LiSPSM: an orthographic light view with
// a perspective along its image's y, as osgShadow's ViewDependentShadowMap draws by default)
// or an off-centre perspective (a spot light's asymmetric frustum). The view's
// camera_position is the main camera (also the lod origin) and the projection carries the
// light's place, so the centre of projection lies off camera_position. A field of geometry,
// volume and image tiers (RenderTest::three_tier_field) drawn as a depth pass: every depth
// grass writes, unprojected through the view's own matrix at its pixel, must lie in the
// blade layer of the flat field (0 to the tallest blade, 0.21 m), and grass must cover the
// pixels where the field is. An orthographic view is the control. Measured
// (docs/records/warped-views.md), share of the grass depths off the layer, GL / Vulkan:
//   before (the volume's rays and the culling cone from camera_position): warped 0.18 / 0.40
//     (heights up to 0.9 / 1.8 m: bands), off-centre culled away (no grass at all)
//   now (from the matrix's centre of projection): 0 in every view, heights 0 .. 0.19 m
#include "matrix4.hpp"
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace grass_test {
namespace {

constexpr uint32_t kSize = 128;                  // the light view's target, pixels
constexpr uint32_t kCells = 48;                  // 12 m x 12 m of 0.25 m cells
const double kMainCamera[3] = {6.0, 1.5, -1.0};  // the lod origin
const double kAt[3] = {6.0, 0.0, 6.0};           // the field's centre
constexpr double kLayerTop = 0.85 * 0.25 + 0.02; // the tallest blade (length_max x the cell) and a margin, m
constexpr double kLayerBottom = -0.02;

enum class Kind { orthographic, warped, off_centre };
const char* name(Kind k) {
    return k == Kind::orthographic ? "orthographic" : k == Kind::warped ? "warped" : "off_centre";
}

class WarpedViewTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        grass_host::TargetDesc t;
        t.width = t.height = kSize;
        t.read_depth = true;
        t.vk_depth_pass = true;
        start(t);
    }

    bool vulkan() const { return GetParam() == GRASS_BACKEND_VULKAN; }

    // The light's view of kind `k`, a depth pass with the main camera as lod origin.
    grass_view_desc light_view(Kind k) {
        const bool vk = vulkan();
        double proj[16] = {0};
        // The light's eye: a spot light 9 m up, 6.5 m back, or the sun's box 50 degrees up.
        const double spot[3] = {4.0, 9.0, -0.5}, sun[3] = {6.0 + 10.0, 16.0, 6.0 - 8.0};
        const double* light = k == Kind::off_centre ? spot : sun;
        grass_view_desc v = view(light, kAt);
        if (k == Kind::off_centre) {
            // An asymmetric frustum.
            const double l = -0.55, r = 0.75, b = -0.6, t = 0.7, n = 1.0, f = 40.0;
            proj[0] = 2.0 * n / (r - l);
            proj[8] = (r + l) / (r - l);
            proj[5] = (vk ? -2.0 : 2.0) * n / (t - b);
            proj[9] = (vk ? -1.0 : 1.0) * (t + b) / (t - b);
            proj[10] = vk ? -f / (f - n) : -(f + n) / (f - n);
            proj[14] = vk ? -f * n / (f - n) : -2.0 * f * n / (f - n);
            proj[11] = -1.0;
        } else {
            // An orthographic box over the field.
            const double half = 7.0, n = 1.0, f = 40.0;
            proj[0] = 1.0 / half;
            proj[5] = (vk ? -1.0 : 1.0) / half;
            proj[10] = vk ? -1.0 / (f - n) : -2.0 / (f - n);
            proj[14] = vk ? -n / (f - n) : -(f + n) / (f - n);
            proj[15] = 1.0;
            if (k == Kind::warped) {
                // LiSPSM's perspective along the light image's y: y' = 1.5 y + 0.5 w,
                // w' = 0.5 y + 1.5 w (w' from 1 to 2 across the image); x and z kept. The rays
                // stay parallel to the light, the depth is warped.
                const double warp[16] = {1, 0, 0, 0, 0, 1.5, 0, 0.5, 0, 0, 1, 0, 0, 0.5, 0, 1.5};
                double full[16];
                grass_host::multiply4(warp, proj, full);
                std::memcpy(proj, full, sizeof full);
            }
        }
        // The view's camera_position is the main camera (as the lod origin): the projection
        // carries the light's place (a translation by R (camera - light) in its eye space).
        double shift[3] = {0, 0, 0};
        for (int row = 0; row < 3; ++row) {
            for (int c = 0; c < 3; ++c) shift[row] += v.view[4 * c + row] * (kMainCamera[c] - light[c]);
        }
        const double translate[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, shift[0], shift[1], shift[2], 1};
        double full[16];
        grass_host::multiply4(proj, translate, full);
        std::memcpy(proj, full, sizeof full);
        std::memcpy(v.camera_position, kMainCamera, sizeof kMainCamera);
        for (int i = 0; i < 16; ++i) v.projection[i] = float(proj[i]);
        lod_origin_ = grass_default_lod_origin_desc();
        std::memcpy(lod_origin_.position, kMainCamera, sizeof kMainCamera);
        pass_ = grass_default_view_pass_desc();
        pass_.pass = GRASS_PASS_DEPTH;
        lod_origin_.next = &pass_;
        v.next = &lod_origin_;
        return v;
    }

    // What the depth pass writes under view `v`: the share of pixels with grass depth, and of
    // those the share whose depth, unprojected at the pixel, lies outside the blade layer.
    struct Measure {
        double covered = 0.0, outside = 0.0;
        double lowest = 1e9, highest = -1e9; // heights of the unprojected depths, m
    };
    Measure measure(const grass_view_desc& v, const std::string& tag) {
        host->depth_only = true;
        const grass_host::Image image = render(v);
        host->depth_only = false;
        grass_frame_stats stats{};
        EXPECT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        EXPECT_GT(stats.instances[GRASS_TIER_VOLUME], 0u) << tag;
        EXPECT_EQ(image.depth.size(), size_t(kSize) * kSize) << tag;
        double rotation[16] = {0}, projection[16], vp[16], inv[16];
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) rotation[4 * c + r] = v.view[4 * c + r];
        }
        rotation[15] = 1.0;
        for (int i = 0; i < 16; ++i) projection[i] = v.projection[i];
        grass_host::multiply4(projection, rotation, vp);
        EXPECT_TRUE(grass_host::invert4(vp, inv));
        Measure m;
        size_t grass = 0, outside = 0;
        for (uint32_t y = 0; y < kSize && image.depth.size() == size_t(kSize) * kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                const float d = image.depth[size_t(y) * kSize + x];
                if (d >= 1.0f - 1e-6f) continue; // cleared: no grass
                ++grass;
                const double row = (y + 0.5) / kSize * 2.0 - 1.0; // top row first
                const double ndc[4] = {(x + 0.5) / kSize * 2.0 - 1.0, vulkan() ? row : -row,
                                       vulkan() ? double(d) : 2.0 * d - 1.0, 1.0};
                double p[4] = {0, 0, 0, 0};
                for (int r = 0; r < 4; ++r) {
                    for (int k = 0; k < 4; ++k) p[r] += inv[4 * k + r] * ndc[k];
                }
                const double height = v.camera_position[1] + p[1] / p[3];
                m.lowest = std::min(m.lowest, height);
                m.highest = std::max(m.highest, height);
                outside += height < kLayerBottom || height > kLayerTop;
            }
        }
        m.covered = double(grass) / (double(kSize) * kSize);
        m.outside = grass ? double(outside) / double(grass) : 0.0;
        std::printf("[ %s ] %s: grass depth in %.3f of the pixels, %.4f of them outside the blade layer "
                    "(heights %.3f .. %.3f m)\n",
                    backend_name(GetParam()).c_str(), tag.c_str(), m.covered, m.outside, m.lowest, m.highest);
        return m;
    }

    grass_lod_origin_desc lod_origin_{};
    grass_view_pass_desc pass_{};
};

TEST_P(WarpedViewTest, GrassDepthLiesInTheBladeLayerUnderEveryProjection) {
    make_field(three_tier_field(kCells));
    for (Kind k : {Kind::orthographic, Kind::warped, Kind::off_centre}) {
        const Measure m = measure(light_view(k), name(k));
        EXPECT_GT(m.covered, 0.3) << name(k) << ": too little grass to compare";
        EXPECT_LE(m.outside, 0.002) << name(k) << ": grass depths off the blade layer (heights " << m.lowest << " .. "
                                    << m.highest << " m)";
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, WarpedViewTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
