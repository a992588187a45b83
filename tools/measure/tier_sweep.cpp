// grass-measure tier-sweep: each tier alone against the blades, from every elevation and under
// every sun (issue 32, item 1; the record is docs/records/tier-sweep.md). A dense patch (the
// default patch over 8 x 8 cells of 0.25 m) is seen from --distance metres, the view axis
// through the field's centre, at elevations 0 to 90 degrees below the horizon in steps of 10,
// under four suns 35 degrees up: ahead of the camera (the grass lit from behind), behind it, to
// its side, and at the zenith. Each frame is drawn by the blades (the truth), by the blades of
// another patch and mirror seed (the seed spread), by the volume tier alone with 8, 2 and 1
// slices a cell, and by the image tier alone (both in single cells), each over a black and a
// white sky (coverage_colour.hpp: grass's own colour and coverage). The rows the blades cover
// are split into 3 bands; per tier the band and channel whose mean colour is furthest from the
// blades' (signed: negative = darker), and the tier's coverage of the band against the blades'
// (the smallest ratio over the bands: a sparse tier shows the sky). Elevation 0 is drawn 2
// degrees down (a horizontal axis through the ground sees the field edge on). The tool exits 1
// when a tier covers under a fifth of what the blades cover in a band from 10 degrees up
// (the image tier's one horizontal slice is seen edge on at 0).
// Usage: grass-measure tier-sweep [--backend gl|vk] [--size WxH] [--distance M] [--samples 1|4] [--images DIR] [--quick]
#include "cli.hpp"
#include "coverage_colour.hpp"
#include "headless_host.hpp"
#include "image_io.hpp"
#include "measure.hpp"
#include "tool.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace grass_measure {
namespace tier_sweep {

namespace {

constexpr int kBands = 3;
constexpr uint32_t kCells = 8;
constexpr double kCellSize = 0.25;
constexpr double kPi = 3.14159265358979323846;

struct Options {
    grass_backend backend = GRASS_BACKEND_GL;
    uint32_t width = 160, height = 120;
    double distance = 9.0; // metres from the field's centre
    std::string images;    // a directory for every render, or empty
    bool quick = false;    // elevations 0, 40 and 90 under the suns ahead and at the zenith only
    uint32_t samples = 4;  // the target's samples: 1 or 4
};

struct Sun {
    const char* name;
    float direction[3]; // towards the sun; the camera looks along +z
};
const Sun kSuns[] = {{"ahead", {0.0f, 0.574f, 0.819f}},
                     {"behind", {0.0f, 0.574f, -0.819f}},
                     {"side", {0.819f, 0.574f, 0.0f}},
                     {"zenith", {0.0f, 1.0f, 0.0f}}};

struct Variant {
    const char* name;
    grass_tier_kind kind;
    uint32_t slices;
    bool other_seed;
};
enum { kBlades, kOtherSeed, kFirstTier };
const Variant kVariants[] = {
    {"blades", GRASS_TIER_GEOMETRY, 0, false}, {"blades, other seed", GRASS_TIER_GEOMETRY, 0, true},
    {"volume 8", GRASS_TIER_VOLUME, 8, false}, {"volume 2", GRASS_TIER_VOLUME, 2, false},
    {"volume 1", GRASS_TIER_VOLUME, 1, false}, {"image", GRASS_TIER_IMAGE, 0, false}};
constexpr int kVariantCount = int(sizeof(kVariants) / sizeof(kVariants[0]));

// One host and context over a black or a white sky, with the two patches.
struct Rig {
    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    grass_patch_id patch{}, other{};
    Rig(const Options& o, bool white) {
        grass_host::TargetDesc t;
        t.width = o.width;
        t.height = o.height;
        t.samples = o.samples;
        for (int c = 0; c < 3; ++c) t.clear_color[c] = white ? 1.0f : 0.0f;
        std::string error;
        host = grass_host::Host::create(o.backend, t, &error);
        if (!host) throw grass_sample::Failure(error);
        grass_context_desc cd = grass_default_context_desc();
        cd.log_fn = &grass_sample::log_to_stderr;
        grass_sample::check(host->create_context(cd, &ctx), "grass_*_create_context");
        grass_patch_desc pd = grass_default_patch_desc();
        grass_sample::check(grass_create_patch(ctx, &pd, &patch), "grass_create_patch", ctx);
        pd.seed = 2;
        grass_sample::check(grass_create_patch(ctx, &pd, &other), "grass_create_patch", ctx);
    }
    ~Rig() {
        if (ctx) grass_destroy_context(ctx);
    }
    Rig(const Rig&) = delete;
    Rig& operator=(const Rig&) = delete;

    // `v` drawn over the field of variant `variant`.
    grass_host::Image render(const Variant& variant, const grass_view_desc& v) {
        grass_tier_desc tier{variant.kind, variant.slices};
        grass_lod_test tests[2] = {};
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].end = INFINITY;
        tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
        tests[1].max_macro_cells = 1;
        grass_field_desc d = grass_default_field_desc();
        d.patch = variant.other_seed ? other : patch;
        d.mirror_seed = variant.other_seed ? 1u : 0u;
        d.cells_x = d.cells_z = kCells;
        d.cell_size = kCellSize;
        d.tiers = &tier;
        d.tier_count = 1;
        d.lod_tests = tests;
        d.lod_test_count = variant.kind == GRASS_TIER_GEOMETRY ? 1 : 2;
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &d, &field), "grass_create_field", ctx);
        grass_host::Image image;
        std::string error;
        const grass_result r = host->render(ctx, v, nullptr, &image, &error);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
        if (r != GRASS_SUCCESS) throw grass_sample::Failure("render: " + error);
        return image;
    }
};

// A tier's worst band against the blades: the signed channel difference largest in size, and
// the smallest ratio of its coverage to the blades'.
struct Score {
    double colour = 0.0, coverage = 1.0;
};

Score score(const std::vector<grass_host::BandColour>& tier, const std::vector<grass_host::BandColour>& blades) {
    Score s;
    for (size_t k = 0; k < blades.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
            const double d = tier[k].colour[c] - blades[k].colour[c];
            if (std::fabs(d) > std::fabs(s.colour)) s.colour = d;
        }
        if (blades[k].coverage > 0.0) s.coverage = std::min(s.coverage, tier[k].coverage / blades[k].coverage);
    }
    return s;
}

std::string file_name(int elevation, const char* sun, const char* variant, const char* sky) {
    std::string name = "e" + std::to_string(elevation) + "_" + sun + "_" + variant + "_" + sky + ".png";
    std::replace(name.begin(), name.end(), ' ', '_');
    name.erase(std::remove(name.begin(), name.end(), ','), name.end());
    return name;
}

struct Case {
    int elevation;
    const Sun* sun;
};

// The case's camera (make_view on `host`).
grass_view_desc case_view(const grass_host::Host& host, const Options& o, const Case& c) {
    const double centre = kCells * kCellSize * 0.5;
    const double e = std::clamp(double(c.elevation), 2.0, 89.5) * kPi / 180.0;
    const double eye[3] = {centre, o.distance * std::sin(e), centre - o.distance * std::cos(e)};
    const double target[3] = {centre, 0.0, centre};
    // The field's diagonal fills the view's height (and a little more).
    const float fov = float(2.0 * std::atan(1.05 * centre * std::sqrt(2.0) / o.distance) * 180.0 / kPi);
    grass_view_desc v = grass_host::make_view(host, eye, target, fov, 0.05f, 100.0f);
    for (int i = 0; i < 3; ++i) v.sun_direction[i] = c.sun->direction[i];
    return v;
}

int run(const Options& o) {
    std::vector<Case> cases;
    std::vector<int> elevations = {0, 40, 90};
    if (!o.quick) {
        elevations.clear();
        for (int e = 0; e <= 90; e += 10) elevations.push_back(e);
    }
    for (int elevation : elevations) {
        for (const Sun& sun : kSuns) {
            if (!o.quick || &sun == &kSuns[0] || &sun == &kSuns[3]) cases.push_back({elevation, &sun});
        }
    }
    if (!o.images.empty() && !grass_sample::make_dirs(o.images)) {
        throw grass_sample::Failure("cannot make the directory " + o.images);
    }
    // Every case over black, then over white (a GL host's context is current while it lives).
    std::vector<grass_host::CoveragePair> pairs(cases.size() * kVariantCount);
    std::string device;
    for (int white = 0; white < 2; ++white) {
        Rig rig(o, white == 1);
        device = rig.host->device_name();
        for (size_t k = 0; k < cases.size(); ++k) {
            const grass_view_desc v = case_view(*rig.host, o, cases[k]);
            for (int i = 0; i < kVariantCount; ++i) {
                grass_host::CoveragePair& p = pairs[k * kVariantCount + size_t(i)];
                (white ? p.white : p.black) = rig.render(kVariants[i], v);
                if (o.images.empty()) continue;
                std::string error;
                const std::string name =
                    file_name(cases[k].elevation, cases[k].sun->name, kVariants[i].name, white ? "white" : "black");
                if (!grass_host::write_png(o.images + "/" + name, white ? p.white : p.black, &error)) {
                    throw grass_sample::Failure(error);
                }
            }
        }
    }
    std::printf("grass-measure tier-sweep: %s (%s), %ux%u at %u samples, %u x %u cells of %.2f m seen from %.1f m\n",
                grass_sample::backend_name(o.backend), device.c_str(), o.width, o.height, o.samples, kCells, kCells,
                kCellSize, o.distance);
    // Per case: [0] over the host's ground, [1] the grass's own colour; the seed spread and
    // each tier's score.
    struct Row {
        double spread[2] = {};
        Score s[2][kVariantCount];
    };
    std::vector<Row> rows(cases.size());
    std::string missing; // tiers that drew (almost) nothing where they must draw
    const grass_host::TargetDesc defaults;
    const double ground[3] = {defaults.ground_color[0], defaults.ground_color[1], defaults.ground_color[2]};
    for (size_t k = 0; k < cases.size(); ++k) {
        const grass_host::CoveragePair* p = &pairs[k * kVariantCount];
        uint32_t first = 0, last = 0;
        grass_host::covered_rows(p[kBlades], 2.0, &first, &last);
        if (last < first + kBands) {
            throw grass_sample::Failure("no grass in the blades' render at elevation " +
                                        std::to_string(cases[k].elevation));
        }
        const std::vector<grass_host::RowSpan> spans = grass_host::row_spans(p[kBlades], first, last, 0.05);
        std::vector<grass_host::BandColour> bands[2][kVariantCount];
        for (int i = 0; i < kVariantCount; ++i) {
            bands[0][i] = grass_host::composite_band_colours(p[i], first, spans, ground, kBands);
            bands[1][i] = grass_host::band_colours(p[i], first, last, kBands);
        }
        for (int i = kFirstTier; i < kVariantCount && cases[k].elevation >= 10; ++i) {
            const double drawn = score(bands[1][i], bands[1][kBlades]).coverage;
            if (drawn < 0.2) {
                missing += "\n  " + std::string(kVariants[i].name) + " at elevation " +
                           std::to_string(cases[k].elevation) + " (sun " + cases[k].sun->name + "): coverage " +
                           std::to_string(drawn) + " of the blades'";
            }
        }
        for (int m = 0; m < 2; ++m) {
            rows[k].spread[m] = std::fabs(score(bands[m][kOtherSeed], bands[m][kBlades]).colour);
            for (int i = kFirstTier; i < kVariantCount; ++i) rows[k].s[m][i] = score(bands[m][i], bands[m][kBlades]);
        }
    }
    const char* const titles[2] = {
        "Over the host's ground (dark soil): the frame's mean colour over the field's outline",
        "The grass's own colour (coverage-weighted, from renders over black and white), and each tier's coverage "
        "against the blades'"};
    for (int m = 0; m < 2; ++m) {
        std::printf("\n%s; levels off the blades in the worst of %d row bands (signed: - darker):\n\n", titles[m],
                    kBands);
        std::printf("| elevation | sun | seed spread | volume 8 | volume 2 | volume 1 | image "
                    "|%s\n|---|---|---|---|---|---|---|%s\n",
                    m == 1 ? " coverage: volume 8 / 2 / 1 / image |" : "", m == 1 ? "---|" : "");
        int within[kVariantCount] = {};
        for (size_t k = 0; k < cases.size(); ++k) {
            const Row& r = rows[k];
            std::printf("| %d | %s | %.1f |", cases[k].elevation, cases[k].sun->name, r.spread[m]);
            for (int i = kFirstTier; i < kVariantCount; ++i) {
                std::printf(" %+.1f |", r.s[m][i].colour);
                within[i] += std::fabs(r.s[m][i].colour) <= r.spread[m] + 1.0;
            }
            if (m == 1) {
                std::printf(" %.2f / %.2f / %.2f / %.2f |", r.s[m][2].coverage, r.s[m][3].coverage, r.s[m][4].coverage,
                            r.s[m][5].coverage);
            }
            std::printf("\n");
        }
        std::printf("\nWithin the seed spread plus 1 level: volume 8 in %d of %zu cases, volume 2 in %d, volume 1 in "
                    "%d, image in %d.\n",
                    within[2], cases.size(), within[3], within[4], within[5]);
    }
    if (!missing.empty()) {
        throw grass_sample::Failure("a tier drew almost nothing from 10 degrees up or more:" + missing);
    }
    return 0;
}

} // namespace

} // namespace tier_sweep

Subcommand add_tier_sweep(CLI::App& measure) {
    auto o = std::make_shared<tier_sweep::Options>();
    CLI::App* app = measure.add_subcommand(
        "tier-sweep", "Each tier alone against the blades at elevations 0-90 degrees under four suns "
                      "(docs/records/tier-sweep.md). Prints a Markdown table.");
    grass_sample::add_backend_option(*app, &o->backend);
    grass_sample::add_size_option(*app, &o->width, &o->height, 32, 1024, "the target's size, WIDTHxHEIGHT");
    app->add_option("--distance", o->distance, "the camera's distance from the field's centre (m)")
        ->capture_default_str()
        ->check(CLI::Range(2.0, 100.0));
    app->add_option("--samples", o->samples, "the target's samples (4: grass's coverage is a share of them)")
        ->capture_default_str()
        ->check(CLI::IsMember({1, 4}));
    app->add_flag("--quick", o->quick, "elevations 0, 40 and 90 under the suns ahead and at the zenith only");
    app->add_option("--images", o->images, "a directory to write every render into (over black and over white)");
    return {app, [o]() { return tier_sweep::run(*o); }};
}

} // namespace grass_measure
