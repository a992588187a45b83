// The adapter's image of a fixed field and camera against the headless host's (the one
// grass-render draws with: test_hosts), on an sRGB target and on OSG's usual RGBA8
// target. The tolerance is what the headless host differs from itself between those two
// targets (the shader's sRGB encoding against the target's).
#include "osg_scene.hpp"

#include <cmath>

namespace grass_osg_test {
namespace {

struct Difference {
    double mean = 0.0;    // mean absolute difference per channel, levels
    double over_2 = 0.0;  // fraction of pixels with a channel more than 2 levels apart
    double over_16 = 0.0; // ... more than 16 levels apart
    size_t grass = 0;     // grass pixels in the first image
};

Difference compare(const grass_host::Image& a, const grass_host::Image& b) {
    Difference d;
    size_t over_2 = 0, over_16 = 0;
    double sum = 0.0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]));
                sum += diff;
                worst = std::max(worst, diff);
            }
            over_2 += worst > 2;
            over_16 += worst > 16;
            d.grass += is_grass(a.pixel(x, y));
        }
    }
    const double n = double(a.width) * a.height;
    d.mean = sum / (3.0 * n);
    d.over_2 = over_2 / n;
    d.over_16 = over_16 / n;
    return d;
}

std::ostream& operator<<(std::ostream& out, const Difference& d) {
    return out << "mean " << d.mean << " levels, " << 100.0 * d.over_2 << "% of pixels > 2 levels, "
               << 100.0 * d.over_16 << "% > 16 levels, " << d.grass << " grass pixels";
}

const double kEye[3] = {2.0, 0.9, -0.5}, kTarget[3] = {2.0, 0.0, 2.0};
constexpr float kFovy = 45.0f;

// The headless host's frame: what `grass-render` writes for this field and camera.
bool headless_frame(bool unorm, grass_host::Image* out, std::string* error) {
    grass_host::TargetDesc t;
    t.width = t.height = 128;
    t.unorm_color = unorm;
    std::unique_ptr<grass_host::Host> host = grass_host::Host::create(GRASS_BACKEND_GL, t, error);
    if (!host) return false;
    grass_context* context = nullptr;
    if (host->create_context(grass_default_context_desc(), &context) != GRASS_SUCCESS) return false;
    const grass_osg::FieldDesc d = field_desc(16);
    grass_field_desc fd = d.field;
    grass_create_patch(context, &d.patch, &fd.patch);
    grass_field_id field{};
    grass_create_field(context, &fd, &field);
    grass_view_desc view = grass_host::make_view(*host, kEye, kTarget, kFovy);
    if (unorm) view.flags |= GRASS_VIEW_FLAG_ENCODE_SRGB;
    const grass_result r = host->render(context, view, nullptr, out, error);
    grass_destroy_context(context);
    return r == GRASS_SUCCESS;
}

grass_host::Image osg_frame(bool srgb_target, uint32_t samples) {
    TargetFormat f;
    f.srgb = srgb_target;
    f.samples = samples;
    std::string error;
    OsgHost host(f, &error);
    EXPECT_TRUE(host.ok()) << error;
    if (!host.ok()) return {};
    host.look(osg::Vec3d(kEye[0], kEye[1], kEye[2]), osg::Vec3d(kTarget[0], kTarget[1], kTarget[2]), kFovy);
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(grass.get());
    auto image = host.frame(geode.get());
    EXPECT_EQ(grass->lastError(), "");
    return image;
}

TEST(MatchesCliTest, TheAdaptersImageIsTheHeadlessHostsImage) {
    grass_host::Image reference, reference_unorm;
    std::string error;
    if (!headless_frame(false, &reference, &error)) GTEST_SKIP() << "no headless GL host: " << error;
    ASSERT_TRUE(headless_frame(true, &reference_unorm, &error)) << error;
    save(reference, "cli_srgb");
    const Difference itself = compare(reference, reference_unorm);
    std::cout << "headless host, sRGB target against RGBA8 + shader encoding: " << itself << "\n";
    ASSERT_GT(itself.grass, 128u * 128u / 4) << "the frame shows a field, not the sky";

    const grass_host::Image srgb = osg_frame(true, 1), unorm = osg_frame(false, 1);
    save(srgb, "osg_srgb");
    save(unorm, "osg_rgba8");
    const Difference same_target = compare(reference, srgb), osg_usual = compare(reference, unorm);
    std::cout << "OSG on an sRGB target against the headless host: " << same_target << "\n"
              << "OSG on RGBA8 (grass encodes) against the headless host: " << osg_usual << "\n";
    // The same target and the same draws: the same image, to the rounding of a matrix.
    EXPECT_LT(same_target.mean, 0.5);
    EXPECT_LT(same_target.over_16, 0.005);
    // OSG's usual target: no further from the reference than the headless host on that
    // target is, plus the same rounding allowance.
    EXPECT_LT(osg_usual.mean, itself.mean + 0.5);
    EXPECT_LT(osg_usual.over_16, itself.over_16 + 0.005);
}

} // namespace
} // namespace grass_osg_test
