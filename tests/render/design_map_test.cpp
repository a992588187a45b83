// Design maps (lemme2012 6.4) on the blade tier, in both backends, seen from straight
// above: the density map removes grass, the colour map tints it (eq. 6.8), the ambient and
// diffuse light maps darken it (eq. 6.9-6.10), and grass_update_map changes the picture
// only where the updated texels are.
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace grass_test {
namespace {

// Straight down onto an 8 x 8 cell field (2 m x 2 m): image x follows world x, image y
// world z; 30 degrees from 4 m see 2.14 m across.
const double kEye[3] = {1.0, 4.0, 1.0};
const double kTarget[3] = {1.0, 0.0, 1.0001};
constexpr float kFov = 30.0f;
constexpr uint32_t kCells = 8;
constexpr double kFieldMetres = kCells * 0.25;
// How far a blade of the default patch reaches sideways from its root: at most its length,
// 0.85 cells (0.21 m).
constexpr double kReach = 0.22;

struct Rect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0; // pixels, x1/y1 exclusive
};

struct Mean {
    double rgb[3] = {0.0, 0.0, 0.0};
    uint64_t count = 0;
    double luminance() const { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }
};

class DesignMapTest : public RenderTest {
protected:
    // A single-channel 8-bit map of w x h texels, texel(x, y) each.
    grass_map_id make_r8_map(uint32_t w, uint32_t h, const std::function<uint8_t(uint32_t, uint32_t)>& texel) {
        std::vector<uint8_t> pixels(size_t(w) * h);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) pixels[size_t(y) * w + x] = texel(x, y);
        }
        grass_map_desc m = grass_default_map_desc();
        m.pixels = pixels.data();
        m.width = w;
        m.height = h;
        m.format = GRASS_MAP_FORMAT_R8_UNORM;
        grass_map_id id{};
        EXPECT_EQ(grass_create_map(ctx, &m, &id), GRASS_SUCCESS) << log;
        return id;
    }

    // The pixels where the ground square [x0, x1] x [z0, z1] (metres) and the same square
    // `lift` metres up appear, grown by `border` pixels and clamped to the image.
    Rect pixels_of(double x0, double z0, double x1, double z1, double lift, int border) const {
        double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
        const uint32_t w = host->target().width, h = host->target().height;
        for (int k = 0; k < 8; ++k) {
            const double p[3] = {(k & 1) ? x1 : x0, (k & 4) ? lift : 0.0, (k & 2) ? z1 : z0};
            double px = 0.0, py = 0.0;
            EXPECT_TRUE(project_point(kEye, kTarget, kFov, w, h, p, &px, &py));
            lo[0] = std::min(lo[0], px);
            lo[1] = std::min(lo[1], py);
            hi[0] = std::max(hi[0], px);
            hi[1] = std::max(hi[1], py);
        }
        const auto clamp_to = [](double v, uint32_t n) { return uint32_t(std::clamp(v, 0.0, double(n))); };
        Rect r;
        r.x0 = clamp_to(std::floor(lo[0]) - border, w);
        r.y0 = clamp_to(std::floor(lo[1]) - border, h);
        r.x1 = clamp_to(std::ceil(hi[0]) + border, w);
        r.y1 = clamp_to(std::ceil(hi[1]) + border, h);
        return r;
    }

    // The pixels that certainly show only ground points inside [x0, x1] x [z0, z1] (metres).
    Rect inside(double x0, double z0, double x1, double z1) const {
        // From 4 m straight down, the ground square's image lies inside the lifted square's.
        return pixels_of(x0, z0, x1, z1, 0.0, -1);
    }

    Mean mean_grass(const grass_host::Image& image, const Rect& r) const {
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        Mean m;
        for (uint32_t y = r.y0; y < r.y1; ++y) {
            for (uint32_t x = r.x0; x < r.x1; ++x) {
                const uint8_t* p = image.pixel(x, y);
                if (!is_grass(p, sky)) continue;
                for (int c = 0; c < 3; ++c) m.rgb[c] += p[c];
                ++m.count;
            }
        }
        for (double& c : m.rgb) c /= double(std::max<uint64_t>(m.count, 1));
        return m;
    }

    double share(const grass_host::Image& image, const Rect& r) const {
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        return grass_share(image, sky, r.x0, r.y0, r.x1, r.y1);
    }

    grass_host::Image render_top() { return render(view(kEye, kTarget, kFov)); }

    // Mean luminance of the grass in the left (x < 0.8 m) and right (x > 1.2 m) parts of the
    // field, without a map and then with `map` as the field's ambient (or diffuse) map.
    void light_map_ratios(bool ambient, double* ratio_without, double* ratio_with) {
        const Rect left = inside(0.1, 0.1, 0.8, 1.9), right = inside(1.2, 0.1, 1.9, 1.9);
        const grass_field_id plain = make_field(field_desc(kCells));
        const auto image_plain = render_top();
        EXPECT_EQ(grass_destroy_field(ctx, plain), GRASS_SUCCESS);
        // 0 on the left half, 1 on the right (32 texels: the bilinear ramp is 1/32 wide).
        const grass_map_id map = make_r8_map(32, 2, [](uint32_t x, uint32_t) { return x < 16 ? 0 : 255; });
        grass_field_desc d = field_desc(kCells);
        (ambient ? d.maps.ambient : d.maps.diffuse) = map;
        make_field(d);
        const auto image_map = render_top();
        save(image_plain, backend_name(GetParam()) + ".plain");
        save(image_map, backend_name(GetParam()) + ".map");
        const Mean pl = mean_grass(image_plain, left), pr = mean_grass(image_plain, right);
        const Mean ml = mean_grass(image_map, left), mr = mean_grass(image_map, right);
        EXPECT_GT(std::min(std::min(pl.count, pr.count), std::min(ml.count, mr.count)), 500u) << "grass to measure";
        *ratio_without = pl.luminance() / pr.luminance();
        *ratio_with = ml.luminance() / mr.luminance();
        std::printf("[ measured ] %s %s map: left/right luminance %.3f without, %.3f with (right %.1f vs %.1f)\n",
                    backend_name(GetParam()).c_str(), ambient ? "ambient" : "diffuse", *ratio_without, *ratio_with,
                    pr.luminance(), mr.luminance());
    }
};

TEST_P(DesignMapTest, TheZeroRegionOfADensityMapShowsNoGrassAndTheRestDoes) {
    // Zero in texels 8..23 of 32 both ways: no density between their centres, 0.53..1.47 m.
    const grass_map_id map =
        make_r8_map(32, 32, [](uint32_t x, uint32_t y) { return (x >= 8 && x < 24 && y >= 8 && y < 24) ? 0 : 255; });
    grass_field_desc d = field_desc(kCells);
    d.maps.density = map;
    make_field(d);
    const auto image = render_top();
    save(image, backend_name(GetParam()));
    // No blade stands in the zero square; blades rooted outside it lean in by kReach at most.
    const double lo = 8.5 / 32.0 * kFieldMetres + kReach, hi = 23.5 / 32.0 * kFieldMetres - kReach;
    const Rect hole = pixels_of(lo, lo, hi, hi, 0.25, 0);
    ASSERT_GT((hole.x1 - hole.x0) * (hole.y1 - hole.y0), 300u);
    EXPECT_EQ(share(image, hole), 0.0) << "no grass where the density map is 0";
    // The full-density border all around.
    EXPECT_GT(share(image, inside(0.05, 0.05, 0.4, 1.95)), 0.5);
    EXPECT_GT(share(image, inside(1.6, 0.05, 1.95, 1.95)), 0.5);
    EXPECT_GT(share(image, inside(0.5, 0.05, 1.5, 0.4)), 0.5);
    EXPECT_GT(share(image, inside(0.5, 1.6, 1.5, 1.95)), 0.5);
}

TEST_P(DesignMapTest, AColourMapTintsTheGrassByItsAlpha) {
    // Three strips along x: opaque red, no modulation (alpha 0), and red at alpha 0.06.
    std::vector<uint8_t> rgba(48 * 2 * 4);
    for (uint32_t y = 0; y < 2; ++y) {
        for (uint32_t x = 0; x < 48; ++x) {
            uint8_t* t = &rgba[(size_t(y) * 48 + x) * 4];
            const int strip = x / 16;
            t[0] = 255;
            t[1] = 0;
            t[2] = 0;
            t[3] = strip == 0 ? 255 : strip == 1 ? 0 : 15;
        }
    }
    grass_map_desc m = grass_default_map_desc();
    m.pixels = rgba.data();
    m.width = 48;
    m.height = 2;
    m.format = GRASS_MAP_FORMAT_RGBA8_UNORM;
    grass_map_id map{};
    ASSERT_EQ(grass_create_map(ctx, &m, &map), GRASS_SUCCESS) << log;
    grass_field_desc d = field_desc(kCells);
    d.maps.color = map;
    make_field(d);
    const auto image = render_top();
    save(image, backend_name(GetParam()));
    // Strip edges at 0.67 m and 1.33 m; a blade has its root's colour and leans kReach.
    const Mean red = mean_grass(image, inside(0.05, 0.05, 0.67 - kReach - 0.03, 1.95));
    const Mean plain = mean_grass(image, inside(0.67 + kReach + 0.03, 0.05, 1.33 - kReach - 0.03, 1.95));
    const Mean subtle = mean_grass(image, inside(1.33 + kReach + 0.03, 0.05, 1.95, 1.95));
    std::printf("[ measured ] %s: mean rgb red strip %.0f %.0f %.0f, plain %.0f %.0f %.0f, alpha 0.06 %.0f %.0f %.0f\n",
                backend_name(GetParam()).c_str(), red.rgb[0], red.rgb[1], red.rgb[2], plain.rgb[0], plain.rgb[1],
                plain.rgb[2], subtle.rgb[0], subtle.rgb[1], subtle.rgb[2]);
    ASSERT_GT(std::min(std::min(red.count, plain.count), subtle.count), 300u);
    EXPECT_GT(red.rgb[0], 2.0 * red.rgb[1]) << "opaque red paints the grass red";
    EXPECT_GT(red.rgb[0], 2.0 * red.rgb[2]);
    EXPECT_GT(plain.rgb[1], 1.15 * plain.rgb[0]) << "alpha 0 leaves the grass green";
    EXPECT_GT(subtle.rgb[1], subtle.rgb[0]) << "a low alpha keeps the grass green...";
    const double plain_ratio = plain.rgb[0] / plain.rgb[1], subtle_ratio = subtle.rgb[0] / subtle.rgb[1];
    EXPECT_GT(subtle_ratio, plain_ratio + 0.03) << "...but shifts its hue towards the map's colour";
    EXPECT_LT(subtle_ratio, plain_ratio + 0.3) << "only slightly";
}

TEST_P(DesignMapTest, AZeroAmbientMapDarkensTheGrassThere) {
    double without = 0.0, with = 0.0;
    light_map_ratios(true, &without, &with);
    EXPECT_NEAR(without, 1.0, 0.08) << "both halves alike without the map";
    EXPECT_LT(with, 0.93 * without) << "no ambient light on the left";
    EXPECT_GT(with, 0.3 * without) << "the sun still lights it";
}

TEST_P(DesignMapTest, AZeroDiffuseMapDarkensTheGrassThere) {
    double without = 0.0, with = 0.0;
    light_map_ratios(false, &without, &with);
    EXPECT_NEAR(without, 1.0, 0.08) << "both halves alike without the map";
    EXPECT_LT(with, 0.85 * without) << "the left half is in the scenery's shadow";
    EXPECT_GT(with, 0.1 * without) << "the ambient light still lights it";
}

TEST_P(DesignMapTest, UpdatingARegionOfTheDensityMapChangesOnlyThatRegion) {
    std::vector<uint16_t> full(32 * 32, 65535);
    grass_map_desc m = grass_default_map_desc();
    m.pixels = full.data();
    m.width = m.height = 32;
    m.format = GRASS_MAP_FORMAT_R16_UNORM;
    grass_map_id map{};
    ASSERT_EQ(grass_create_map(ctx, &m, &map), GRASS_SUCCESS) << log;
    grass_field_desc d = field_desc(kCells);
    d.maps.density = map;
    make_field(d);
    const auto before = render_top();

    // Mow texels 4..19 both ways, passed as rows of 16 in a wider buffer (row pitch).
    const uint32_t x0 = 4, y0 = 4, n = 16, pitch_texels = 20;
    std::vector<uint16_t> zeros(size_t(pitch_texels) * n, 0);
    grass_map_desc region = grass_default_map_desc();
    region.pixels = zeros.data();
    region.width = region.height = n;
    region.row_pitch = pitch_texels * sizeof(uint16_t);
    region.format = GRASS_MAP_FORMAT_R16_UNORM;
    ASSERT_EQ(grass_update_map(ctx, map, x0, y0, &region), GRASS_SUCCESS) << log;
    const auto after = render_top();
    save(before, backend_name(GetParam()) + ".before");
    save(after, backend_name(GetParam()) + ".after");

    // The density changes between the centres of texels 3 and 20 (bilinear), and the blades
    // rooted there reach kReach further.
    const double lo = 3.5 / 32.0 * kFieldMetres - kReach, hi = 20.5 / 32.0 * kFieldMetres + kReach;
    const Rect changed = pixels_of(lo, lo, hi, hi, 0.25, 2);
    uint64_t outside_changes = 0;
    for (uint32_t y = 0; y < after.height; ++y) {
        for (uint32_t x = 0; x < after.width; ++x) {
            if (x >= changed.x0 && x < changed.x1 && y >= changed.y0 && y < changed.y1) continue;
            const uint8_t *a = before.pixel(x, y), *b = after.pixel(x, y);
            if (std::abs(a[0] - b[0]) > 2 || std::abs(a[1] - b[1]) > 2 || std::abs(a[2] - b[2]) > 2) ++outside_changes;
        }
    }
    EXPECT_EQ(outside_changes, 0u) << "pixels changed outside the updated region";
    // Inside, where the density is 0 now, the grass is gone.
    const double ilo = 4.5 / 32.0 * kFieldMetres + kReach, ihi = 19.5 / 32.0 * kFieldMetres - kReach;
    const Rect mown = pixels_of(ilo, ilo, ihi, ihi, 0.25, 0);
    EXPECT_GT(share(before, mown), 0.5);
    EXPECT_EQ(share(after, mown), 0.0);
    // And the rest is still there.
    EXPECT_GT(share(after, inside(1.6, 0.05, 1.95, 1.95)), 0.5);
}

INSTANTIATE_TEST_SUITE_P(Backends, DesignMapTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
