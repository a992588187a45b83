// Responsive grass (issue 13) as drawn: still grass unchanged, colliders that press the
// grass under them, trails that recover with the documented time constant, blade tips
// above the terrain, trails visible in every tier, and wind that moves every tier and
// freezes at dt = 0. Heights are read back from the depth buffer of an orthographic view
// straight down (TargetDesc::read_depth).
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace grass_test {
namespace {

constexpr double kEyeHeight = 2.0; // the orthographic camera, metres above the ground
constexpr float kNear = 0.5f, kFar = 3.0f;
constexpr float kNoGrass = -1e30f;

struct Under;

class ResponsiveTest : public RenderTest {
protected:
    void SetUp() override {
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = t.height = 96;
        t.read_depth = true;
        start(t);
        mechanics = grass_default_blade_mechanics();
        mechanics.variation = 0.0f;
    }

    // Straight down over (cx, cz), `half` metres to each side, orthographic, at `time`.
    grass_view_desc top_view(double cx, double cz, double half, double time) const {
        const double eye[3] = {cx, kEyeHeight, cz}, target[3] = {cx, 0.0, cz};
        grass_view_desc v = view(eye, target);
        // The host's clip convention (GL: y up, z -1..1; Vulkan: y down, z 0..1); either way
        // the stored depth runs linearly from 0 at kNear to 1 at kFar.
        const bool vulkan = GetParam() == GRASS_BACKEND_VULKAN;
        std::memset(v.projection, 0, sizeof v.projection);
        v.projection[0] = float(1.0 / half);
        v.projection[5] = float((vulkan ? -1.0 : 1.0) / half);
        v.projection[10] = vulkan ? -1.0f / (kFar - kNear) : -2.0f / (kFar - kNear);
        v.projection[14] = vulkan ? -kNear / (kFar - kNear) : -(kFar + kNear) / (kFar - kNear);
        v.projection[15] = 1.0f;
        v.time = time;
        return v;
    }

    // Renders `v` (a top_view) and reads the grass height (m) of each pixel, top row first
    // (kNoGrass where the ray met nothing).
    std::vector<float> heights(const grass_view_desc& v, grass_host::Image* image_out = nullptr) {
        const uint32_t w = host->target().width, h = host->target().height;
        grass_host::Image image = render(v);
        if (image_out) *image_out = image;
        std::vector<float> depth = image.depth;
        EXPECT_EQ(depth.size(), size_t(w) * h) << "no depth read back";
        depth.resize(size_t(w) * h, 1.0f);
        std::vector<float> out(depth.size(), kNoGrass);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                const float d = depth[size_t(y) * w + x];
                if (d < 1.0f) out[size_t(y) * w + x] = float(kEyeHeight - (kNear + d * (kFar - kNear)));
            }
        }
        return out;
    }

    // The ground point (x, z) of pixel (px, py) of a top_view over (cx, cz).
    void pixel_ground(double cx, double cz, double half, uint32_t px, uint32_t py, double* x, double* z) const {
        *x = cx - half + (px + 0.5) * 2.0 * half / host->target().width;
        *z = cz - half + (py + 0.5) * 2.0 * half / host->target().height;
    }

    Under under(const grass_collider& c, const std::vector<float>& before, const std::vector<float>& after, double cx,
                double cz, double half, double tolerance) const;

    void set_mechanics() { ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &mechanics), GRASS_SUCCESS) << log; }
    void set_fine_map() {
        grass_interaction_desc d = grass_default_interaction_desc();
        d.texel_size[0] = 0.01f; // 2.56 m across: the colliders' footprints to a centimetre
        d.texel_size[1] = 0.1f;
        ASSERT_EQ(grass_set_interaction(ctx, &d), GRASS_SUCCESS) << log;
    }

    grass_blade_mechanics mechanics{};
};

// A sphere resting on the grass, or a capsule lying on it (its axis level).
grass_collider sphere(double x, double y, double z, float r) {
    grass_collider c{};
    c.shape = GRASS_COLLIDER_SPHERE;
    c.radius = r;
    c.center[0] = x;
    c.center[1] = y;
    c.center[2] = z;
    return c;
}
grass_collider capsule(double x0, double x1, double y, double z, float r) {
    grass_collider c = sphere(x0, y, z, r);
    c.shape = GRASS_COLLIDER_CAPSULE;
    c.end[0] = x1;
    c.end[1] = y;
    c.end[2] = z;
    return c;
}

// The collider's underside at ground point (x, z): its lowest point over it, or +inf
// outside its footprint (the footprint shrunk by `inset` metres).
double underside(const grass_collider& c, double x, double z, double inset) {
    double ax = c.center[0], az = c.center[2], bx = c.end[0], bz = c.end[2];
    if (c.shape == GRASS_COLLIDER_SPHERE) {
        bx = ax;
        bz = az;
    }
    const double ex = bx - ax, ez = bz - az, l2 = ex * ex + ez * ez;
    const double t = l2 > 0.0 ? std::clamp(((x - ax) * ex + (z - az) * ez) / l2, 0.0, 1.0) : 0.0;
    const double dx = x - (ax + t * ex), dz = z - (az + t * ez), d = std::sqrt(dx * dx + dz * dz);
    const double r = c.radius - inset;
    if (d >= r) return INFINITY;
    return c.center[1] - std::sqrt(double(c.radius) * c.radius - d * d);
}

// The grass under a collider's footprint (shrunk by 1 cm) in two height images of a top_view
// over (cx, cz): pixels, those standing above the underside + `tolerance` before, those with
// grass after, those standing above it after, and the highest grass after over the underside.
struct Under {
    size_t footprint = 0, above_before = 0, grass_after = 0, inside = 0;
    double worst = -1e9;
};

Under ResponsiveTest::under(const grass_collider& c, const std::vector<float>& before, const std::vector<float>& after,
                            double cx, double cz, double half, double tolerance) const {
    Under r;
    for (uint32_t py = 0; py < host->target().height; ++py) {
        for (uint32_t px = 0; px < host->target().width; ++px) {
            double x, z;
            pixel_ground(cx, cz, half, px, py, &x, &z);
            const double u = underside(c, x, z, 0.01);
            if (!std::isfinite(u)) continue;
            ++r.footprint;
            const size_t i = size_t(py) * host->target().width + px;
            r.above_before += before[i] != kNoGrass && before[i] > u + tolerance;
            if (after[i] == kNoGrass) continue;
            ++r.grass_after;
            r.worst = std::max(r.worst, after[i] - u);
            r.inside += after[i] > u + tolerance;
        }
    }
    return r;
}

// A resting sphere and a level capsule: over each one's footprint the grass's top stays
// below its underside (within the tolerance: a blade's width and the map's texels), where
// before the collider came most of it stood above.
TEST_P(ResponsiveTest, NoBladeInsideRestingColliders) {
    set_fine_map();
    const grass_field_id f = make_field(field_desc(8)); // 2 m x 2 m
    (void)f;
    constexpr double kTolerance = 0.01; // metres
    const grass_collider colliders[2] = {sphere(1.0, 0.25 + 0.03, 0.7, 0.25f),
                                         capsule(0.6, 1.4, 0.1 + 0.05, 1.4, 0.1f)};
    const double cx = 1.0, cz = 1.05, half = 0.65;
    const std::vector<float> before = heights(top_view(cx, cz, half, 0.0));
    ASSERT_EQ(grass_set_colliders(ctx, colliders, 2), GRASS_SUCCESS) << log;
    grass_host::Image image;
    const std::vector<float> after = heights(top_view(cx, cz, half, 0.0), &image);
    save(image, "pressed");
    for (const grass_collider& c : colliders) {
        const auto [footprint, above_before, grass_after, inside, worst] =
            under(c, before, after, cx, cz, half, kTolerance);
        const char* name = c.shape == GRASS_COLLIDER_SPHERE ? "sphere" : "capsule";
        ASSERT_GT(footprint, 100u) << name;
        // Not vacuous: the grass stood above the underside before, and is still drawn.
        EXPECT_GT(double(above_before) / footprint, 0.2) << name;
        EXPECT_GT(double(grass_after) / footprint, 0.3) << name << ": the pressed grass must still be drawn";
        EXPECT_EQ(inside, 0u) << name << ": grass up to " << worst << " m above the underside";
    }
}

// Frames and views (grass.h): view 0, a camera 0.6 m aside and 1.2 m up, moves the collider
// map; view 1, the top view over the colliders, reads that map from its own camera
// (FrameUniforms::map_offset) and shows the grass pressed under them, as view 0 of its own
// frame does above. Without the offset it read the press 0.6 m off, and grass stood inside.
TEST_P(ResponsiveTest, ALaterViewOfTheFrameReadsTheMapOfView0) {
    set_fine_map();
    make_field(field_desc(8));          // 2 m x 2 m
    constexpr double kTolerance = 0.01; // metres
    const grass_collider colliders[2] = {sphere(1.0, 0.25 + 0.03, 0.7, 0.25f),
                                         capsule(0.6, 1.4, 0.1 + 0.05, 1.4, 0.1f)};
    const double cx = 1.0, cz = 1.05, half = 0.65;
    const std::vector<float> before = heights(top_view(cx, cz, half, 0.0));
    ASSERT_EQ(grass_set_colliders(ctx, colliders, 2), GRASS_SUCCESS) << log;
    const double main_eye[3] = {cx + 0.6, 1.2, cz - 0.3}, main_look[3] = {cx, 0.0, cz};
    const grass_view_desc main_view = view(main_eye, main_look);
    const grass_view_desc top = top_view(cx, cz, half, 0.0);
    uint64_t next_frame = 100;
    host->begin_grass_frame = [&](grass_context* c) {
        grass_frame_desc frame = grass_default_frame_desc();
        frame.frame_index = next_frame;
        frame.completed_frame_index = next_frame - 1;
        next_frame += 1;
        uint32_t index = 0;
        grass_result r = grass_begin_host_frame(c, &frame);
        if (r == GRASS_SUCCESS) r = grass_plan_view(c, &main_view, &index); // planned, never drawn
        if (r == GRASS_SUCCESS) r = grass_plan_view(c, &top, &index);
        return r;
    };
    host->draw_grass = [&](grass_context* c, void* cmd) {
        if (GetParam() == GRASS_BACKEND_GL) return grass_gl_render_view(c, 1);
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = cmd;
        return grass_vk_record_view(c, 1, &record);
    };
    grass_host::Image image;
    const std::vector<float> after = heights(top, &image);
    host->begin_grass_frame = nullptr;
    host->draw_grass = nullptr;
    save(image, "pressed_view_1");
    for (const grass_collider& c : colliders) {
        const auto [footprint, above_before, grass_after, inside, worst] =
            under(c, before, after, cx, cz, half, kTolerance);
        const char* name = c.shape == GRASS_COLLIDER_SPHERE ? "sphere" : "capsule";
        ASSERT_GT(footprint, 100u) << name;
        EXPECT_GT(double(above_before) / footprint, 0.2) << name;
        EXPECT_GT(double(grass_after) / footprint, 0.3) << name << ": the pressed grass must still be drawn";
        EXPECT_EQ(inside, 0u) << name << ": grass up to " << worst << " m above the underside";
    }
}

// A new passage replaces what an earlier one left (docs/responsive.md): a deep dent recovers
// for 3 s, then a sphere without velocity comes to rest over it. A second later no grass
// stands inside the new sphere. Before the fix a collider without velocity continued a
// passage on its first frame, so the older, deeper dent was kept and recovered on: a disc of
// standing grass inside the new press.
TEST_P(ResponsiveTest, ANewRestingSphereReplacesAnOlderDeeperDent) {
    set_fine_map();
    mechanics.recovery_time = 0.5f;
    set_mechanics();
    make_field(field_desc(8));
    constexpr double kTolerance = 0.01;                           // metres, as NoBladeInsideRestingColliders
    const grass_collider old_ball = sphere(1.0, 0.1, 1.05, 0.3f); // underside 0.2 m below the ground
    const grass_collider ball = sphere(1.0, 0.25 + 0.03, 1.05, 0.25f);
    const double cx = 1.0, cz = 1.05, half = 0.4;
    ASSERT_EQ(grass_set_colliders(ctx, &old_ball, 1), GRASS_SUCCESS) << log;
    heights(top_view(cx, cz, half, 10.0));
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
    const std::vector<float> recovered = heights(top_view(cx, cz, half, 13.0));
    ASSERT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS) << log;
    heights(top_view(cx, cz, half, 13.0 + 1.0 / 30));
    grass_host::Image image;
    const std::vector<float> after = heights(top_view(cx, cz, half, 14.0), &image);
    save(image, "new_passage");
    const Under r = under(ball, recovered, after, cx, cz, half, kTolerance);
    ASSERT_GT(r.footprint, 100u);
    EXPECT_GT(double(r.above_before) / r.footprint, 0.2) << "the dent must have recovered before the new sphere came";
    EXPECT_EQ(r.inside, 0u) << "grass up to " << r.worst << " m above the new sphere's underside";
}

// Recovery: once the collider has gone, the trail's depth decays as exp(-t / recovery_time).
// Pressed flat (trample depth 1), the grass's height under the trail is L (1 - exp(-t/T))
// for blades of length L, so the ratio of two heights gives T whatever L is.
TEST_P(ResponsiveTest, TrailRecoversWithTheTimeConstant) {
    constexpr float kRecovery = 3.0f;
    mechanics.trample_depth = 1.0f;
    mechanics.recovery_time = kRecovery;
    start([] {
        grass_host::TargetDesc t; // finer: the blades' pointed tips within a few millimetres
        t.width = t.height = 192;
        t.read_depth = true;
        return t;
    }());
    // Wide blades: a blade's pointed tip is narrower than a pixel over its last tenth at the
    // default widths, and the highest drawn pixel would fall short of the tip.
    grass_patch_desc wide = grass_default_patch_desc();
    wide.width_min = wide.width_max = 0.2f;
    ASSERT_EQ(grass_create_patch(ctx, &wide, &patch), GRASS_SUCCESS) << log;
    set_fine_map();
    set_mechanics();
    make_field(field_desc(8));
    const grass_collider c = sphere(1.0, 1.0 + 0.02, 1.0, 1.0f); // presses the whole field flat
    const double cx = 1.0, cz = 1.0, half = 0.3;
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << log;
    heights(top_view(cx, cz, half, 10.0));
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS) << log;
    const double times[3] = {1.0, 2.0, 3.0}; // the tips below 0.64 L: under the rest tops
    double top[3] = {};
    for (int k = 0; k < 3; ++k) {
        grass_host::Image image;
        std::vector<float> h = heights(top_view(cx, cz, half, 10.0 + times[k]), &image);
        save(image, "recovery" + std::to_string(k));
        // The highest grass in view: the tip of the longest of ~2000 blades (all pressed),
        // whichever of them lie in view as their reach changes.
        std::vector<float> inner;
        for (uint32_t py = 0; py < host->target().height; ++py) {
            for (uint32_t px = 0; px < host->target().width; ++px) {
                double x, z;
                pixel_ground(cx, cz, half, px, py, &x, &z);
                const float v = h[size_t(py) * host->target().width + px];
                if (v != kNoGrass) inner.push_back(v);
            }
        }
        ASSERT_GT(inner.size(), 200u);
        top[k] = *std::max_element(inner.begin(), inner.end());
        if (k == 0) { // dt = 0 freezes the trail: the same time again draws the same heights
            EXPECT_EQ(heights(top_view(cx, cz, half, 10.0 + times[k])), h) << "a time step of 0 must change nothing";
        }
    }
    EXPECT_GT(top[0], 0.005) << "the trail must have started to recover";
    EXPECT_LT(top[0], top[1]);
    EXPECT_LT(top[1], top[2]);
    // T from the ratio of two heights: (1 - e^(-t0/T)) / (1 - e^(-t1/T)), increasing in T.
    for (int k = 1; k < 3; ++k) {
        const double ratio = top[0] / top[k];
        double lo = 0.01, hi = 100.0;
        for (int i = 0; i < 100; ++i) {
            const double mid = std::sqrt(lo * hi);
            const double r = (1.0 - std::exp(-times[0] / mid)) / (1.0 - std::exp(-times[k] / mid));
            (r > ratio ? lo : hi) = mid; // r falls from 1 (T -> 0) to t0 / t1
        }
        std::printf("recovery: T = %.3f s from t = %g and %g s (set %g s)\n", lo, times[0], times[k],
                    double(kRecovery));
        EXPECT_NEAR(lo / kRecovery, 1.0, 0.1) << "time constant from t = " << times[0] << " and " << times[k]
                                              << " s: heights " << top[0] << ", " << top[k] << " m";
    }
}

// Tips above the terrain on a height map: a strong wind lays the blades uphill onto a 27
// degree ramp. Seen from below (no host terrain), the lowest grass of each pixel stays
// above the terrain there, within the tolerance of a blade's half width on the slope.
TEST_P(ResponsiveTest, TipsStayAboveTheTerrain) {
    constexpr uint32_t kTexels = 64;
    constexpr double kScale = 0.5; // metres: the ramp rises 0.5 m over the field's middle metre
    const auto ramp = [](double x) { return std::clamp((x - 0.5) / 1.0, 0.0, 1.0); };
    std::vector<uint16_t> texels(kTexels * 2);
    for (uint32_t y = 0; y < 2; ++y) {
        for (uint32_t x = 0; x < kTexels; ++x) {
            texels[y * kTexels + x] = uint16_t(std::lround(ramp((x + 0.5) / kTexels * 2.0) * 65535.0));
        }
    }
    grass_map_desc m = grass_default_map_desc();
    m.pixels = texels.data();
    m.width = kTexels;
    m.height = 2;
    m.format = GRASS_MAP_FORMAT_R16_UNORM;
    grass_map_id map{};
    ASSERT_EQ(grass_create_map(ctx, &m, &map), GRASS_SUCCESS) << log;
    grass_field_desc d = field_desc(8);
    d.maps.height = map;
    d.maps.height_scale = float(kScale);
    make_field(d);
    grass_wind_desc w = grass_default_wind_desc();
    w.direction[0] = 1.0f; // uphill
    w.direction[1] = 0.0f;
    w.direction[2] = 0.0f;
    w.speed = 40.0f;
    w.gust_strength = 0.0f;
    w.turbulence = 0.0f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;

    // From below, looking up: the depth is the lowest grass. Image x runs along -x.
    const double cx = 1.0, cz = 1.0, half = 0.7, below = -1.5;
    const double eye[3] = {cx, below, cz}, target[3] = {cx, 0.0, cz};
    grass_view_desc v = top_view(cx, cz, half, 1.0);
    const grass_view_desc up_view = view(eye, target);
    std::memcpy(v.view, up_view.view, sizeof v.view);
    for (int c = 0; c < 3; ++c) v.camera_position[c] = eye[c];
    grass_host::Image image;
    const std::vector<float> h = heights(v, &image);
    save(image, "from_below");
    size_t grass = 0, below_terrain = 0;
    double worst = 0.0;
    for (uint32_t py = 0; py < host->target().height; ++py) {
        for (uint32_t px = 0; px < host->target().width; ++px) {
            const float depth_height = h[size_t(py) * host->target().width + px];
            if (depth_height == kNoGrass) continue;
            // heights() assumed a camera kEyeHeight above: convert to this one's distance.
            const double distance = kEyeHeight - depth_height;
            const double lowest = below + distance;
            const double x = cx + half - (px + 0.5) * 2.0 * half / host->target().width;
            if (x < 0.55 || x > 1.45) continue; // on the slope
            ++grass;
            const double terrain = kScale * ramp(x);
            worst = std::min(worst, lowest - terrain);
            below_terrain += lowest < terrain - 0.015;
        }
    }
    ASSERT_GT(grass, 1500u) << "the slope must be covered";
    EXPECT_EQ(below_terrain, 0u) << "grass down to " << worst << " m below the terrain";
}

// Length: a single straight blade (0.3 m long, 10 cm wide: its pointed tip is narrower
// than a pixel only over its last 0.6%) bent by a strong gravity, which with jahrmann's
// front gravity (eq. 5) lays it along its facing: its width stays across the bend, so the
// top-down heights along the bend, root first, trace its centreline. The traced length
// stays within 1% of 0.3 m where the bend is far from the rest pose.
TEST_P(ResponsiveTest, BladeLengthIsPreserved) {
    start([] {
        grass_host::TargetDesc t;
        t.width = t.height = 480; // 1 mm pixels
        t.read_depth = true;
        return t;
    }());
    grass_patch_desc one = grass_default_patch_desc();
    one.blade_count = 1;
    one.length_min = one.length_max = 1.2f; // patch units: 0.3 m
    one.width_min = one.width_max = 0.4f;
    one.tilt_min = one.tilt_max = 0.0f;
    one.bend_min = one.bend_max = 0.0f; // straight up at rest
    ASSERT_EQ(grass_create_patch(ctx, &one, &patch), GRASS_SUCCESS) << log;
    set_mechanics();
    grass_field_desc d = field_desc(1);
    d.mirror_tiling = 0;
    make_field(d);
    grass_wind_desc w = grass_default_wind_desc();
    w.gravity[1] = -9.81f - 36.0f; // v2 = I_v2 + L (-36 up + 9 front) / 40
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << log;
    const double cx = 0.125, cz = 0.125, half = 0.24;
    grass_host::Image image;
    const std::vector<float> h = heights(top_view(cx, cz, half, 1.0), &image);
    save(image, "bent");
    // The grass pixels, their principal axis, and the root end: where the blade is widest.
    struct P {
        double x, z, h;
    };
    std::vector<P> pts;
    const uint32_t size = host->target().width;
    for (uint32_t py = 0; py < size; ++py) {
        for (uint32_t px = 0; px < size; ++px) {
            const float v = h[size_t(py) * size + px];
            if (v == kNoGrass) continue;
            double x, z;
            pixel_ground(cx, cz, half, px, py, &x, &z);
            pts.push_back({x, z, v});
        }
    }
    ASSERT_GT(pts.size(), 2000u) << "the bent blade must be seen";
    double mx = 0, mz = 0;
    for (const P& p : pts) mx += p.x / pts.size(), mz += p.z / pts.size();
    double sxx = 0, sxz = 0, szz = 0;
    for (const P& p : pts)
        sxx += (p.x - mx) * (p.x - mx), sxz += (p.x - mx) * (p.z - mz), szz += (p.z - mz) * (p.z - mz);
    const double angle = 0.5 * std::atan2(2.0 * sxz, sxx - szz);
    double ax = std::cos(angle), az = std::sin(angle);
    double lo = 1e9, hi = -1e9;
    for (const P& p : pts) {
        const double s = (p.x - mx) * ax + (p.z - mz) * az;
        lo = std::min(lo, s), hi = std::max(hi, s);
    }
    const double bin = 2.0 * half / size;
    const size_t bins = size_t((hi - lo) / bin) + 1;
    std::vector<double> top(bins, -1.0), across_lo(bins, 1e9), across_hi(bins, -1e9);
    for (const P& p : pts) {
        const double s = (p.x - mx) * ax + (p.z - mz) * az, c = -(p.x - mx) * az + (p.z - mz) * ax;
        const size_t b = std::min(bins - 1, size_t((s - lo) / bin));
        top[b] = std::max(top[b], p.h);
        across_lo[b] = std::min(across_lo[b], c), across_hi[b] = std::max(across_hi[b], c);
    }
    // The axis runs from the root edge (as wide as the blade) to the pointed tip.
    const double width_first = across_hi[0] - across_lo[0], width_last = across_hi[bins - 1] - across_lo[bins - 1];
    EXPECT_GT(std::max(width_first, width_last), 0.07) << "the axis must cross the root edge";
    EXPECT_LT(std::min(width_first, width_last), 0.02) << "the axis must end at the tip";
    if (width_first < width_last) std::reverse(top.begin(), top.end());
    double len = std::hypot(0.5 * bin, top[0]), prev = top[0];
    size_t seen = 1;
    for (size_t b = 1; b < bins; ++b) {
        if (top[b] < 0.0) continue;
        len += std::hypot(bin, top[b] - prev); // a bin without grass: skipped along the axis
        prev = top[b];
        ++seen;
    }
    std::printf("bent blade: traced %.4f m over %zu of %zu bins, tip at %.4f m\n", len, seen, bins, prev);
    EXPECT_GT(hi - lo, 0.12) << "the blade must be bent well away from upright";
    EXPECT_NEAR(len, 0.3, 0.003);
}

INSTANTIATE_TEST_SUITE_P(Backends, ResponsiveTest, ::testing::ValuesIn(enabled_backends()),
                         [](const ::testing::TestParamInfo<grass_backend>& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
