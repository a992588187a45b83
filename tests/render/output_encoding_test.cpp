// Linear output and targets without sRGB conversion (issue 16): grass writes linear colour,
// which an sRGB target (or GL_FRAMEBUFFER_SRGB) encodes. A host whose target stores what the
// shader writes (a UNORM target) sets GRASS_VIEW_FLAG_ENCODE_SRGB and gets the same picture.
#include "render_fixture.hpp"

#include <cstdlib>

namespace grass_test {
namespace {

class OutputEncodingTest : public RenderTest {
protected:
    // Every tier at once: Lemme's default setup over a large field, seen from 1.7 m high
    // across it, so blades, volumes and the image tier are all in the picture.
    grass_host::Image scene(bool unorm, uint32_t samples, uint32_t flags) {
        grass_host::TargetDesc t;
        t.width = t.height = 128;
        t.samples = samples;
        t.unorm_color = unorm;
        start(t);
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = 1024;
        make_field(d);
        const double eye[3] = {128.0, 1.7, 1.0}, target[3] = {128.0, 0.0, 12.0};
        grass_view_desc v = view(eye, target, 60.0f);
        v.flags = flags;
        grass_frame_stats stats{};
        grass_host::Image image = render(v);
        EXPECT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) EXPECT_GT(stats.instances[k], 0u) << "tier kind " << k;
        return image;
    }
};

double mean_rgb(const grass_host::Image& image, uint32_t y0) {
    double sum = 0.0;
    size_t n = 0;
    for (uint32_t y = y0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) sum += image.pixel(x, y)[c];
            n += 3;
        }
    }
    return n ? sum / double(n) : 0.0;
}

int max_difference(const grass_host::Image& a, const grass_host::Image& b) {
    int worst = 0;
    for (size_t k = 0; k < a.rgba.size() && k < b.rgba.size(); ++k) {
        if (k % 4 != 3) worst = std::max(worst, std::abs(int(a.rgba[k]) - int(b.rgba[k])));
    }
    return worst;
}

TEST_P(OutputEncodingTest, AUnormTargetWithEncodeSrgbMatchesAnSrgbTarget) {
    for (const uint32_t samples : {1u, 4u}) {
        SCOPED_TRACE(std::to_string(samples) + " samples");
        const grass_host::Image srgb = scene(false, samples, 0);
        const grass_host::Image encoded = scene(true, samples, GRASS_VIEW_FLAG_ENCODE_SRGB);
        const grass_host::Image linear = scene(true, samples, 0);
        const std::string tag = std::to_string(samples) + "x";
        save(srgb, tag + "_srgb_target");
        save(encoded, tag + "_unorm_encoded");
        save(linear, tag + "_unorm_linear");
        // Single-sampled, the shader's encoding and the target's agree to rounding. With 4x
        // MSAA a UNORM target averages encoded samples and an sRGB one linear samples: blade
        // edges differ a little (the mean of encoded values is darker), the picture does not
        // (measured: 1.1 levels mean over the image, GL and Vulkan alike).
        EXPECT_LT(mean_difference(srgb, encoded), samples == 1 ? 0.25 : 2.0);
        if (samples == 1) {
            EXPECT_LE(max_difference(srgb, encoded), 2);
        }
        // Without the flag the linear values land unencoded: the grass (the lower half) is
        // several times darker. The check above can fail.
        const double lit = mean_rgb(srgb, 64), dark = mean_rgb(linear, 64);
        EXPECT_GT(lit, 2.0 * dark) << "sRGB target " << lit << ", UNORM target without the flag " << dark;
    }
}

// The threshold view's bytes are exact on either target: an sRGB target without the flag,
// a UNORM target with it.
TEST_P(OutputEncodingTest, DebugThresholdBytesAreTheSameOnAUnormTargetWithEncodeSrgb) {
    const grass_host::Image srgb = scene(false, 1, GRASS_VIEW_FLAG_DEBUG_THRESHOLDS);
    const grass_host::Image encoded = scene(true, 1, GRASS_VIEW_FLAG_DEBUG_THRESHOLDS | GRASS_VIEW_FLAG_ENCODE_SRGB);
    save(srgb, "srgb_target");
    save(encoded, "unorm_encoded");
    EXPECT_EQ(max_difference(srgb, encoded), 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, OutputEncodingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
