// The slices' colour matches the blades' (issue 12, item 3): the same cells drawn by the
// volume tier alone and by blades have the same mean colour, row band by row band, within
// what another seed of the blades themselves shows, in several lights. The test prints what
// it measures.
#include "coverage_colour.hpp"
#include "render_fixture.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace grass_test {
namespace {

constexpr int kBands = 3;
// The seed-to-seed spread of the blades is measured in every run (two patch and mirror
// seeds). Over the 8 x 8 cells of this view it is small by chance in some bands, so the
// tolerance is the largest spread over all bands and lights, and at least the spread the
// issue measured on the football strip (1.5 levels per channel).
constexpr double kSpreadFloor = 1.5; // levels
// Measured (GL; Vulkan within 0.5 levels), largest channel difference of a band's mean colour
// to the blades', far / middle / near band, against a seed-to-seed spread of 2.4-2.6 levels:
//                   default sun      side sun         facing sun       unlit
//   before the fix  10.7, 8.8, 2.2   7.9, 5.0, 2.2    8.8, 7.1, 2.2    11.7, 8.7, 2.2  (darker)
//   after           1.5, 1.2, 4.7    2.4, 2.5, 4.6    0.6, 0.6, 1.2    0.4, 0.6, 0.9
//   and colour at   0.2, 0.5, 3.7    0.5, 0.9, 3.2    0.2, 0.2, 0.7    0.8, 0.3, 0.7
//   the descent's level (Vulkan: at most 1.6 in the far and middle bands, 3.9 in the near)
// (the fixes: partly covered texels keep their own colour, slice_mips.cpp bleed_colours; the
// colour and coverage are looked up no coarser up a slice than the ray descends between two
// crossings, volume.frag). In every light the far and middle bands match the blades within
// the spread. In the default and side suns the near band, seen steeper, is 3.2-3.9 levels
// lighter than the blades, 1.3 beyond the spread: the sun term of the slices' lobe lighting
// (lighting.glsl), not their colour. Not fixed; a lit light gets this much on top of the
// spread, as a limit against regressions (4.6-5 before the descent's level failed it).
constexpr double kSunTermLimit = 2.0; // levels
// The image tier (one horizontal slice) is one colour over all bands, its colour baked as a
// ray 10 degrees up sees the grass (slice_baker.cpp, apply_grazing), and its normals those
// that ray sees heading along x and along z, weighed by the view's heading. Measured (GL;
// Vulkan within 0.8), far / middle band, levels off the blades:
//                          default sun  side sun     facing sun  unlit
//   before the grazing bake  16.4, 14.9   2.7, 1.5     12.2, 10.1  19.1, 15.5  (darker; side: 23
//                                                                              in the near band)
//   grazing colour           4.4, 3.0     10.9, 12.7   0.1, 1.8    1.4, 2.7
//   and grazing normals      0.5, 2.0     3.3, 5.2     0.3, 1.6    1.4, 2.7
// Unlit, facing the sun and in the default sun it matches the blades within the spread and a
// level. In the low side sun the middle band is still 2.8-3.4 levels beyond the spread
// (lighter): a regression limit there. The near band is not compared: it holds the field's
// near edge, the front blades seen from the side down to their dark bases, which a flat slice
// does not have (blades 87 levels red unlit, the image 118).
constexpr int kImageBands = 2;
constexpr double kImageColourLimit = 1.0; // levels beyond the spread

// The host's lights (grass_view_lights_desc) of a case: none, or one of these, the sun off
// (ambient 0.15) unless the case keeps it.
enum HostLight { kNoHostLight, kPointLight, kSpotLight, kHarmonics, kSpecular };

struct Light {
    const char* name;
    float sun_direction[3];
    bool sun;                         // false: no sun, ambient 1 (the albedo and the ambient occlusion alone)
    double limit_beyond_spread;       // levels (kSunTermLimit where the near band's sun term is off)
    double image_limit_beyond_spread; // levels, the image tier's far and middle bands
    HostLight host = kNoHostLight;
};
// The default sun (from behind the camera's left, 45 degrees up), a low sun from the side, a
// sun facing the camera (the blades' back sides lit), and no sun.
const Light kLights[] = {{"default", {0.0f, 0.0f, 0.0f}, true, kSunTermLimit, kImageColourLimit},
                         {"side", {1.0f, 0.35f, 0.0f}, true, kSunTermLimit, 4.0},
                         {"facing", {0.0f, 0.6f, 1.0f}, true, 0.0, kImageColourLimit},
                         {"unlit", {0.0f, 1.0f, 0.0f}, false, 0.0, kImageColourLimit},
                         // The host's lights (both backends): a point light 2.5 m over the
                         // field's near edge, a spot from above aimed at the field's middle, a
                         // sky brighter above than below as harmonics, and Kajiya-Kay specular
                         // under a low sun ahead. Measured (GL), levels off the blades against a
                         // spread of 3.0, far / middle / near band:
                         //              volume          image (far, middle)
                         //   point      0.2, 0.6, 8.9   1.7, 4.7  (near band 8.4 before the horizontal
                         //                                     slice kept its mean opacity, slice_mips.hpp)
                         //   spot       0.8, 0.3, 1.7   0.8, 7.4
                         //   harmonics  1.0, 0.5, 2.4   2.4, 0.3
                         //   specular   0.9, 2.5, 2.4   7.9, 7.0  (without it 0.1, 0.4, 1.0 and 0.8, 2.9)
                         // The point light's near band is the lobes' known excess in the near band
                         // (kSunTermLimit), here under a light 1.3 times the sun's; the image tier's
                         // one slice at half height reads the spot's cone edge, and under a high
                         // exponent the highlight of the blades bent furthest (the tail of their
                         // tangents), less well. Regression limits, not goals (issue 32: slices that
                         // know the view and the light). Vulkan: the slices within 0.3 level of GL's
                         // in the far and middle bands; specular's image far band 8.9 (GL 7.9): the
                         // blades there 0.8 lighter than GL's (under a sun ahead the backends' blades
                         // differ without the lights too: facing, near band, 2.8), hence 6, not 5.
                         {"point", {0.0f, 1.0f, 0.0f}, false, 6.0, 2.0, kPointLight},
                         {"spot", {0.0f, 1.0f, 0.0f}, false, 0.0, 4.5, kSpotLight},
                         {"harmonics", {0.0f, 1.0f, 0.0f}, false, 0.0, kImageColourLimit, kHarmonics},
                         {"specular", {0.0f, 0.3f, 1.0f}, true, 0.0, 6.0, kSpecular}};

// The case's grass_view_lights_desc in `d` (its light in `l`), chained on `v`.
void add_host_light(HostLight kind, grass_view_desc* v, grass_view_lights_desc* d, grass_light* l) {
    if (kind == kNoHostLight) return;
    *d = grass_default_view_lights_desc();
    *l = grass_default_light();
    if (kind != kSpecular) {
        for (int c = 0; c < 3; ++c) {
            v->sun_color[c] = 0.0f;
            v->ambient_color[c] = 0.15f;
        }
    }
    if (kind == kPointLight || kind == kSpotLight) {
        d->light_count = 1;
        d->lights = l;
        l->position[0] = 1.0;
        l->position[1] = kind == kPointLight ? 2.5 : 4.0;
        l->position[2] = kind == kPointLight ? 0.0 : 1.0;
        l->intensity = kind == kPointLight ? 8.0f : 16.0f;
        l->range = 30.0f;
        if (kind == kSpotLight) {
            l->kind = GRASS_LIGHT_SPOT;
            l->direction[0] = 0.0f;
            l->direction[1] = -1.0f;
            l->direction[2] = 0.0f;
            l->inner_cone_angle = 0.1f;
            l->outer_cone_angle = 0.3f;
        }
    } else if (kind == kHarmonics) {
        d->ambient_sh_enabled = 1;
        for (int c = 0; c < 3; ++c) {
            d->ambient_sh[0][c] = 0.5f / 0.282095f;
            d->ambient_sh[1][c] = 0.6f; // brighter from above
            d->ambient_sh[3][c] = 0.3f; // and from +x
        }
    } else {
        d->specular_strength = 0.4f;
        d->specular_exponent = 16.0f;
    }
    d->next = v->next;
    v->next = d;
}

using grass_host::largest_channel_difference;
using Pair = grass_host::CoveragePair;

struct Bands {
    double colour[kBands][3] = {}; // coverage-weighted mean sRGB of the grass
    double coverage[kBands] = {};  // summed coverage, pixels
};

// The grass rows [first, last) of `p` split into kBands bands of equal height.
Bands measure(const Pair& p, uint32_t first, uint32_t last) {
    Bands b;
    const std::vector<grass_host::BandColour> bands = grass_host::band_colours(p, first, last, kBands);
    for (int k = 0; k < kBands; ++k) {
        b.coverage[k] = bands[size_t(k)].coverage;
        for (int ch = 0; ch < 3; ++ch) b.colour[k][ch] = bands[size_t(k)].colour[ch];
    }
    return b;
}

constexpr int kLightCount = int(sizeof(kLights) / sizeof(kLights[0]));
enum Variant { kBlades, kBladesOtherSeed, kVolume, kImage, kVariants };

class SliceColourTest : public RenderTest {
protected:
    // Every variant in every light, over black and over white, one context per background:
    // the 8 x 8 cells of the default patch drawn by blades, the same with patch seed 2 and
    // mirror seed 1, and the default patch drawn by the volume tier (8 slices) alone and by
    // the image tier alone.
    void render_all(Pair out[kVariants][kLightCount]) {
        const char* names[kVariants] = {"blades", "blades_seed2", "volume", "image"};
        for (int b = 0; b < 2; ++b) {
            start(black_or_white_target(b == 1));
            grass_patch_desc pd = grass_default_patch_desc();
            pd.seed = 2;
            grass_patch_id other{};
            ASSERT_EQ(grass_create_patch(ctx, &pd, &other), GRASS_SUCCESS) << log;
            for (int variant = 0; variant < kVariants; ++variant) {
                for (int l = 0; l < kLightCount; ++l) {
                    const Light& light = kLights[l];
                    grass_field_desc d = variant == kVolume  ? solo_tier_field(8, GRASS_TIER_VOLUME, 8, 1)
                                         : variant == kImage ? solo_tier_field(8, GRASS_TIER_IMAGE, 0, 1)
                                                             : field_desc(8);
                    d.patch = variant == kBladesOtherSeed ? other : patch;
                    d.mirror_seed = variant == kBladesOtherSeed ? 1u : 0u;
                    const grass_field_id f = make_field(d);
                    // TierLightingTest's view: the 2 m x 2 m field about 9 m away, 1.6 m up.
                    const double eye[3] = {1.0, 1.6, -8.0}, target[3] = {1.0, 0.0, 1.0};
                    grass_view_desc v = view(eye, target, 14.0f);
                    if (!light.sun) {
                        for (int c = 0; c < 3; ++c) {
                            v.sun_color[c] = 0.0f;
                            v.ambient_color[c] = 1.0f;
                        }
                    } else if (light.sun_direction[0] != 0.0f || light.sun_direction[1] != 0.0f ||
                               light.sun_direction[2] != 0.0f) {
                        for (int c = 0; c < 3; ++c) v.sun_direction[c] = light.sun_direction[c];
                    }
                    grass_view_lights_desc lights{};
                    grass_light host_light{};
                    add_host_light(light.host, &v, &lights, &host_light);
                    grass_host::Image& image = b == 0 ? out[variant][l].black : out[variant][l].white;
                    image = render(v);
                    save(image, std::string(light.name) + "_" + names[variant] + (b == 0 ? "_black" : "_white"));
                    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
                }
            }
        }
    }
};

TEST_P(SliceColourTest, VolumeAndImageRowBandsMatchTheBladesWithinTheSeedSpread) {
    double spread = kSpreadFloor, worst = 0.0, worst_image = 0.0;
    Bands volume[kLightCount], image[kLightCount], blades[kLightCount];
    Pair images[kVariants][kLightCount];
    render_all(images);
    if (HasFatalFailure()) return;
    int count = 0;
    for (const Light& light : kLights) {
        const std::string name = light.name;
        const Pair& a = images[kBlades][count];
        const Pair& b = images[kBladesOtherSeed][count];
        const Pair& v = images[kVolume][count];
        const Pair& im = images[kImage][count];
        // The rows the blades cover (more than 2 pixels' worth in a row), far to near.
        uint32_t first = 0, last = 0;
        grass_host::covered_rows(a, 2.0, &first, &last);
        ASSERT_GT(last, first + 3 * kBands) << "no grass in the blades' render (" << name << ")";
        blades[count] = measure(a, first, last);
        const Bands other = measure(b, first, last);
        volume[count] = measure(v, first, last);
        image[count] = measure(im, first, last);
        for (int k = 0; k < kBands; ++k) {
            ASSERT_GT(blades[count].coverage[k], 100.0) << name << " band " << k;
            ASSERT_GT(volume[count].coverage[k], 100.0) << name << " band " << k;
            ASSERT_GT(image[count].coverage[k], 100.0) << name << " band " << k;
            const double s = largest_channel_difference(blades[count].colour[k], other.colour[k]);
            const double d = largest_channel_difference(volume[count].colour[k], blades[count].colour[k]);
            const double di = largest_channel_difference(image[count].colour[k], blades[count].colour[k]);
            spread = std::max(spread, s);
            worst = std::max(worst, d);
            if (k < kImageBands) worst_image = std::max(worst_image, di);
            std::printf("[ measured ] %s %-7s band %d: blades (%.1f, %.1f, %.1f), other seed %.1f levels off; volume "
                        "(%.1f, %.1f, %.1f), %.1f levels off; image (%.1f, %.1f, %.1f), %.1f levels off\n",
                        backend_name(GetParam()).c_str(), light.name, k, blades[count].colour[k][0],
                        blades[count].colour[k][1], blades[count].colour[k][2], s, volume[count].colour[k][0],
                        volume[count].colour[k][1], volume[count].colour[k][2], d, image[count].colour[k][0],
                        image[count].colour[k][1], image[count].colour[k][2], di);
        }
        ++count;
    }
    std::printf("[ measured ] %s: seed-to-seed spread %.1f levels (at least %.1f), volume at most %.1f levels off, "
                "image at most %.1f (far and middle bands)\n",
                backend_name(GetParam()).c_str(), spread, kSpreadFloor, worst, worst_image);
    for (int l = 0; l < count; ++l) {
        for (int k = 0; k < kBands; ++k) {
            EXPECT_LE(largest_channel_difference(volume[l].colour[k], blades[l].colour[k]),
                      spread + kLights[l].limit_beyond_spread)
                << kLights[l].name << " light, band " << k << " (0 far): volume's mean colour against the blades'";
            if (k >= kImageBands) continue;
            EXPECT_LE(largest_channel_difference(image[l].colour[k], blades[l].colour[k]),
                      spread + kLights[l].image_limit_beyond_spread)
                << kLights[l].name << " light, band " << k << " (0 far): image's mean colour against the blades'";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, SliceColourTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
