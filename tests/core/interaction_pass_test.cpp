// The interaction map's rule (docs/responsive.md), run by the CPU reference of the pass on
// the plans the core makes: frame-rate independence, dt = 0, scrolling, extremes, binning.
#include "dynamics_fixture.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>

namespace {

using grass::InteractionTexel;

// What a blade of rest length L rooted at height g (above the anchor) is capped at by a
// texel (interaction.glsl): the trail's press, or L when it does not press.
double press(const InteractionTexel& t, double L, double g, double depth = 0.5, double recovery = 4.0) {
    if (!(t.age < grass::kAgeNone)) return L;
    const double p0 = std::max(double(t.underside) - g, 0.0) * (1.0 - depth);
    if (p0 >= L) return L;
    return L - (L - p0) * std::exp(-double(t.age) / recovery);
}

struct Difference {
    int contact_mismatch = 0; // one has a contact, the other not
    int contacts = 0;
    double underside = 0, age = 0, press = 0; // largest differences over texels with contacts in both
};

Difference compare(const std::vector<InteractionTexel>& a, const std::vector<InteractionTexel>& b, double ground) {
    Difference d;
    for (size_t i = 0; i < a.size(); ++i) {
        const bool ca = a[i].age < grass::kAgeNone, cb = b[i].age < grass::kAgeNone;
        if (ca != cb) {
            d.contact_mismatch += 1;
            continue;
        }
        if (!ca) continue;
        d.contacts += 1;
        d.underside = std::max(d.underside, std::fabs(double(a[i].underside) - b[i].underside));
        d.age = std::max(d.age, std::fabs(double(a[i].age) - b[i].age));
        d.press = std::max(d.press, std::fabs(press(a[i], 0.2, ground) - press(b[i], 0.2, ground)));
    }
    return d;
}

class InteractionPassTest : public DynamicsTest {
protected:
    // A sphere from `start` moving at `velocity` (m/s) for 1 s, planned at `fps` frames per
    // second (fps 1: one 1 s step), then `rest` more seconds without colliders. Returns level 0.
    std::vector<InteractionTexel> run(int fps, const double start[3], const float velocity[3], float radius,
                                      double rest = 0.0) {
        for (int k = 0; k <= fps; ++k) {
            const double t = double(k) / fps;
            grass_collider c = sphere(start[0] + velocity[0] * t, start[1] + velocity[1] * t,
                                      start[2] + velocity[2] * t, radius, velocity[0], velocity[1], velocity[2]);
            EXPECT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS) << last_message();
            EXPECT_EQ(frame(100.0 + t), GRASS_SUCCESS) << last_message();
        }
        if (rest > 0.0) {
            EXPECT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
            const int steps = std::max(1, int(rest * fps));
            for (int k = 1; k <= steps; ++k) EXPECT_EQ(frame(101.0 + rest * k / steps), GRASS_SUCCESS);
        }
        return map[0];
    }
    // The ground's height above the anchor (the anchor is at the camera, 3 m up).
    double ground() const { return -3.0; }
};

TEST_F(InteractionPassTest, FrameRateIndependenceOfMovingSphere) {
    const double start[3] = {1.0, 0.1, 2.0};
    const float velocity[3] = {1.0f, 0.0f, 0.0f};
    const int fps[3] = {30, 60, 1};
    std::vector<InteractionTexel> result[3];
    for (int i = 0; i < 3; ++i) {
        grass_set_interaction(ctx, nullptr); // a new map for each run
        result[i] = run(fps[i], start, velocity, 0.25f);
    }
    for (int i = 0; i < 2; ++i) {
        const Difference d = compare(result[i], result[2], ground());
        // The trail's footprint is the same at any frame rate (the sweep), and each texel keeps
        // the deepest contact of the passage, so its underside and age agree too (a rule that
        // let each frame's contact replace the stored one differed by 0.19 m and 0.24 s).
        EXPECT_GT(d.contacts, 200);
        EXPECT_EQ(d.contact_mismatch, 0);
        EXPECT_LE(d.underside, 1e-5);
        EXPECT_LE(d.age, 1e-5);
        std::printf("[ fps      ] %d fps vs one 1 s step: %d texels with contacts, %d mismatched, max |dU| "
                    "%.2g m, max |dage| %.2g s, max |dpress| %.2g m\n",
                    fps[i], d.contacts, d.contact_mismatch, d.underside, d.age, d.press);
    }
}

// A world point's texel in level `level`, found as interaction.glsl finds it; nullptr outside
// the window.
const InteractionTexel* read(const grass::FramePlan& plan, const std::vector<InteractionTexel>& texels, uint32_t level,
                             const double eye[3], const double p[3]) {
    const grass::FrameUniforms& f = plan.frame;
    const float rel[3] = {float(p[0] - eye[0]), float(p[1] - eye[1]), float(p[2] - eye[2])};
    const float n = f.map_levels[level][3];
    int32_t texel[2];
    for (int a = 0; a < 2; ++a) {
        const float* axis = a == 0 ? f.map_axis_u : f.map_axis_v;
        const float along = rel[0] * axis[0] + rel[1] * axis[1] + rel[2] * axis[2];
        const float c = f.map_levels[level][a] + along * f.map_levels[level][2];
        if (!(std::fabs(c - f.map_levels[level][a]) < n / 2 - 1)) return nullptr;
        texel[a] = static_cast<int32_t>(std::floor(c - n * std::floor(c / n)));
    }
    return &texels[size_t(texel[1]) * uint32_t(n) + texel[0]];
}

bool pressed(const InteractionTexel& t) { return t.age < grass::kAgeNone; }

TEST_F(InteractionPassTest, ARestingSphereIsTheSameAtAnyFrameRateAndItsTrailAgesAlike) {
    const double start[3] = {2.0, 0.1, 2.5};
    const float still[3] = {0.0f, 0.0f, 0.0f};
    std::vector<InteractionTexel> result[3];
    const int fps[3] = {30, 60, 1};
    for (int i = 0; i < 3; ++i) {
        grass_set_interaction(ctx, nullptr);
        result[i] = run(fps[i], start, still, 0.3f, 1.0); // 1 s on it, then 1 s without it
    }
    for (int i = 0; i < 2; ++i) {
        const Difference d = compare(result[i], result[2], ground());
        EXPECT_GT(d.contacts, 100);
        EXPECT_EQ(d.contact_mismatch, 0);
        EXPECT_EQ(d.underside, 0.0);
        EXPECT_LE(d.age, 1e-5); // 1 s since the last contact, summed in steps of 1/30 or 1/60 s
    }
    // Under the centre: the sphere's lowest point, 1 s ago.
    const double eye[3] = {2.0, 3.0, 2.0};
    const InteractionTexel* t = read(plan(), result[2], 0, eye, start);
    ASSERT_NE(t, nullptr);
    EXPECT_NEAR(t->underside, 0.1 - 0.3 - 3.0, 3e-3); // the texel's centre is within 0.036 m of it
    EXPECT_NEAR(t->age, 1.0, 1e-6);
}

// docs/responsive.md: a new passage replaces what an earlier one left. A sphere rests 0.5 s
// at a spot and leaves (a deep dent that then recovers for 2 s); a new, shallower sphere with
// no velocity rests over it for 2 s. Every texel under the new sphere is pressed by it now
// (age 0, its underside). Before the fix a collider without velocity continued a passage on
// its first frame, so the older, deeper dent was kept and aged: 4 s old inside the new press.
TEST_F(InteractionPassTest, ANewStationarySphereReplacesAnOlderDeeperDent) {
    const double eye[3] = {2.0, 3.0, 2.0};
    const grass_collider old_ball = sphere(2.0, 0.1, 2.5, 0.3f);
    ASSERT_EQ(grass_set_colliders(ctx, &old_ball, 1), GRASS_SUCCESS);
    double t = 10.0;
    for (int k = 0; k < 15; ++k) ASSERT_EQ(frame(t += 1.0 / 30, eye), GRASS_SUCCESS);
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
    for (int k = 0; k < 60; ++k) ASSERT_EQ(frame(t += 1.0 / 30, eye), GRASS_SUCCESS);
    const double old_centre[3] = {2.0, 0.1, 2.5};
    const InteractionTexel* dent = read(plan(), map[0], 0, eye, old_centre);
    ASSERT_NE(dent, nullptr);
    EXPECT_NEAR(dent->age, 2.0, 1e-3);
    const grass_collider ball = sphere(2.1, 0.35, 2.5, 0.4f); // underside -0.05 m; the dent's is -0.2 m
    ASSERT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS);
    for (int k = 0; k < 60; ++k) ASSERT_EQ(frame(t += 1.0 / 30, eye), GRASS_SUCCESS);
    int inside = 0, stale = 0;
    for (double du = -0.35; du <= 0.35; du += 0.025) {
        for (double dv = -0.35; dv <= 0.35; dv += 0.025) {
            if (du * du + dv * dv > 0.35 * 0.35) continue;
            const double p[3] = {2.1 + du, 0.0, 2.5 + dv};
            const InteractionTexel* texel = read(plan(), map[0], 0, eye, p);
            ASSERT_NE(texel, nullptr);
            inside += 1;
            stale += texel->age == 0.0f ? 0 : 1;
        }
    }
    EXPECT_GT(inside, 500);
    EXPECT_EQ(stale, 0) << "texels under the new sphere that keep the older dent";
    const double centre[3] = {2.1, 0.0, 2.5};
    const InteractionTexel* now = read(plan(), map[0], 0, eye, centre);
    EXPECT_NEAR(now->underside, 0.35 - 0.4 - 3.0, 3e-3);
    // Resting on, it continues its own passage: the next frame keeps what it pressed.
    ASSERT_EQ(frame(t += 1.0 / 30, eye), GRASS_SUCCESS);
    EXPECT_NEAR(read(plan(), map[0], 0, eye, centre)->underside, 0.35 - 0.4 - 3.0, 3e-3);
}

TEST_F(InteractionPassTest, AZeroTimeStepFreezesTheMap) {
    const grass_collider c = sphere(2.0, 0.1, 2.5, 0.3f, 1.0f, 0.0f, 0.0f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.5), GRASS_SUCCESS);
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
    ASSERT_EQ(frame(2.0), GRASS_SUCCESS);
    const std::vector<InteractionTexel> before[2] = {map[0], map[1]};
    int contacts = 0;
    for (const auto& t : before[0]) contacts += pressed(t) ? 1 : 0;
    EXPECT_GT(contacts, 100);
    for (int k = 0; k < 5; ++k) ASSERT_EQ(frame(2.0), GRASS_SUCCESS);
    EXPECT_EQ(plan().stats.time_step, 0.0);
    for (int l = 0; l < 2; ++l) {
        EXPECT_EQ(std::memcmp(before[l].data(), map[l].data(), before[l].size() * sizeof(InteractionTexel)), 0) << l;
    }
    // A moving collider with dt = 0 touches only where it is now, at age 0.
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(2.0), GRASS_SUCCESS);
    int now = 0;
    for (const auto& t : map[0]) now += t.age == 0.0f ? 1 : 0;
    EXPECT_GT(now, 50);
    EXPECT_LT(now, 3.1416 * 0.3 * 0.3 / (0.05 * 0.05) * 1.2); // its disc, not a sweep
}

TEST_F(InteractionPassTest, ScrollingKeepsTheWorldsTrailsAndClearsWhatLeftTheWindow) {
    // A trail at a world point, then the camera moves 7 level-0 texels: the trail reads back
    // at the same world point, and texels that entered the window are cleared.
    // Radius 0.45 m: the fine level's texels are tested at their centres; the coarse level
    // (1 m texels) presses every texel the sphere's footprint overlaps.
    const double spot[3] = {2.0, 0.1, 2.5};
    const grass_collider c = sphere(spot[0], spot[1], spot[2], 0.45f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    double eye[3] = {2.0, 3.0, 2.0};
    ASSERT_EQ(frame(1.0, eye), GRASS_SUCCESS);
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.5, eye), GRASS_SUCCESS);
    for (int l = 0; l < 2; ++l) {
        const InteractionTexel* t = read(plan(), map[l], l, eye, spot);
        ASSERT_NE(t, nullptr);
        EXPECT_TRUE(pressed(*t)) << l;
    }
    const std::vector<InteractionTexel> old = map[0];
    eye[0] += 7 * 0.05;
    eye[2] -= 3 * 0.05;
    ASSERT_EQ(frame(2.0, eye), GRASS_SUCCESS);
    for (int l = 0; l < 2; ++l) {
        const InteractionTexel* t = read(plan(), map[l], l, eye, spot);
        ASSERT_NE(t, nullptr);
        EXPECT_TRUE(pressed(*t)) << l;
        EXPECT_NEAR(t->age, 1.0, 1e-6);
    }
    // Texels are either the same world texel as before (kept, aged) or new (cleared).
    const auto& lu = plan().interaction.level[0];
    int kept = 0, entered = 0;
    for (int32_t y = 0; y < 256; ++y) {
        for (int32_t x = 0; x < 256; ++x) {
            const int32_t j[2] = {((x - lu.window[0]) % 256 + 256) % 256, ((y - lu.window[1]) % 256 + 256) % 256};
            const bool stayed = j[0] + lu.window[2] >= 0 && j[0] + lu.window[2] < 256 && j[1] + lu.window[3] >= 0 &&
                                j[1] + lu.window[3] < 256;
            const InteractionTexel& now = map[0][size_t(y) * 256 + x];
            if (stayed) {
                kept += 1;
                const InteractionTexel& was = old[size_t(y) * 256 + x];
                EXPECT_EQ(now.underside, was.underside);
            } else {
                entered += 1;
                EXPECT_FALSE(pressed(now));
            }
        }
    }
    EXPECT_EQ(entered, 256 * 256 - (256 - 7) * (256 - 3));
    EXPECT_EQ(kept, (256 - 7) * (256 - 3));
    // 10 km away, in steps of 100 m: nothing stale remains anywhere, and memory stays flat.
    grass_memory_stats m0{}, m1{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &m0), GRASS_SUCCESS);
    for (int k = 1; k <= 100; ++k) {
        eye[0] += 100.0;
        ASSERT_EQ(frame(2.0 + 0.1 * k, eye), GRASS_SUCCESS);
    }
    for (int l = 0; l < 2; ++l) {
        for (const auto& t : map[l]) ASSERT_FALSE(pressed(t)) << l;
    }
    ASSERT_EQ(grass_get_memory_stats(ctx, &m1), GRASS_SUCCESS);
    EXPECT_EQ(m1.dynamics_gpu_bytes, m0.dynamics_gpu_bytes);
    EXPECT_EQ(m1.host_bytes, m0.host_bytes);
    // And back: the old trail is gone too (it left the window; nothing reappears).
    eye[0] -= 1e4;
    ASSERT_EQ(frame(20.0, eye), GRASS_SUCCESS);
    for (int l = 0; l < 2; ++l) {
        const InteractionTexel* t = read(plan(), map[l], l, eye, spot);
        ASSERT_NE(t, nullptr);
        EXPECT_FALSE(pressed(*t)) << l;
    }
}

// The coarse level misses no collider narrower than its texels (docs/responsive.md): it
// widens the footprint to half a texel's diagonal. A thin sphere (5 cm) resting on the corner
// of four 1 m coarse texels, 0.71 m from each centre, presses all four below its centre and
// no other; the fine level only under it. Tested at the centres alone, the coarse level had
// no mark of it. A ball rolled 1 s leaves the same coarse texels at 30 fps as in one step
// (the widening does not depend on the frame rate).
TEST_F(InteractionPassTest, TheCoarseLevelMissesNoThinCollider) {
    const double eye[3] = {2.0, 3.0, 2.0};
    const grass_collider c = sphere(3.0, 0.05, 3.0, 0.05f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0, eye), GRASS_SUCCESS);
    ASSERT_EQ(plan().interaction.levels, 2u);
    ASSERT_EQ(plan().interaction.level[1].origin[2], 1.0f); // the default coarse texel
    int coarse = 0, fine = 0;
    for (const auto& t : map[1]) coarse += pressed(t) ? 1 : 0;
    for (const auto& t : map[0]) fine += pressed(t) ? 1 : 0;
    EXPECT_EQ(coarse, 4);
    EXPECT_GE(fine, 1);
    EXPECT_LE(fine, 9);
    for (double dx : {-0.5, 0.5}) {
        for (double dz : {-0.5, 0.5}) {
            const double centre[3] = {3.0 + dx, 0.0, 3.0 + dz};
            const InteractionTexel* t = read(plan(), map[1], 1, eye, centre);
            ASSERT_NE(t, nullptr);
            EXPECT_TRUE(pressed(*t)) << dx << " " << dz;
            EXPECT_LT(t->underside, ground() + 0.05); // below its centre: grass 0.2 m tall is pressed to 0.025 m
        }
    }
    const double start[3] = {1.3, 0.25, 2.2};
    const float velocity[3] = {1.7f, 0.0f, 0.9f};
    std::vector<InteractionTexel> coarse_at[2];
    const int fps[2] = {30, 1};
    for (int i = 0; i < 2; ++i) {
        grass_set_interaction(ctx, nullptr);
        ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
        ASSERT_EQ(frame(100.0), GRASS_SUCCESS); // the run's first frame steps 0 (no sweep from the last time)
        run(fps[i], start, velocity, 0.25f);
        coarse_at[i] = map[1];
    }
    const Difference d = compare(coarse_at[0], coarse_at[1], ground());
    EXPECT_GE(d.contacts, 3);
    EXPECT_EQ(d.contact_mismatch, 0);
    EXPECT_LE(d.underside, 1e-5);
    EXPECT_LE(d.age, 1e-5);
}

// The distance where a trail is cut (docs/responsive.md): the default coarse level (256 m
// across) keeps a 1 m ball's trail out to 127 m from the camera along the map's axes (and
// 170 m along its diagonal); 128.5 m away the tiers read nothing of it (the window's last
// texel is never read).
TEST_F(InteractionPassTest, TheDefaultCoarseLevelKeepsATrailOutTo127Metres) {
    const double eye[3] = {2.0, 3.0, 2.0};
    const double kept[3][2] = {{126.0, 0.0}, {0.0, -126.0}, {120.0, 120.0}};
    for (const auto& at : kept) {
        grass_set_interaction(ctx, nullptr);
        const double spot[3] = {eye[0] + at[0], 0.5, eye[2] + at[1]};
        const grass_collider c = sphere(spot[0], spot[1], spot[2], 0.5f);
        ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
        ASSERT_EQ(frame(1.0, eye), GRASS_SUCCESS);
        const InteractionTexel* t = read(plan(), map[1], 1, eye, spot);
        ASSERT_NE(t, nullptr) << at[0] << " " << at[1];
        EXPECT_TRUE(pressed(*t)) << at[0] << " " << at[1];
    }
    grass_set_interaction(ctx, nullptr);
    const double beyond[3] = {eye[0] + 128.5, 0.5, eye[2]};
    const grass_collider c = sphere(beyond[0], beyond[1], beyond[2], 0.5f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0, eye), GRASS_SUCCESS);
    EXPECT_EQ(plan().stats.colliders_in_map, 1u); // it reaches the window's last texel
    EXPECT_EQ(read(plan(), map[1], 1, eye, beyond), nullptr);
}

// Colliders of every kind around the camera: spheres and capsules, at rest and moving.
std::vector<grass_collider> random_colliders(size_t count, double half_width, float max_radius, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-half_width, half_width), unit(0.0, 1.0);
    std::vector<grass_collider> out(count);
    for (grass_collider& c : out) {
        c = grass_collider{};
        c.shape = unit(rng) < 0.5 ? GRASS_COLLIDER_SPHERE : GRASS_COLLIDER_CAPSULE;
        c.radius = float(0.01 + unit(rng) * max_radius);
        c.center[0] = 2.0 + pos(rng), c.center[1] = unit(rng) * 0.5, c.center[2] = 2.0 + pos(rng);
        c.end[0] = c.center[0] + pos(rng) * 0.1, c.end[1] = unit(rng), c.end[2] = c.center[2] + pos(rng) * 0.1;
        if (unit(rng) < 0.7) {
            for (float& v : c.velocity) v = float((unit(rng) - 0.5) * 10.0);
        }
    }
    return out;
}

TEST_F(InteractionPassTest, TheTilesMissNoCollider) {
    // The pass with the core's tile lists against the same pass testing every collider in
    // every tile, from the same map: the same map, bit for bit.
    std::vector<grass_collider> colliders = random_colliders(300, 14.0, 1.5f, 7);
    const std::vector<grass_collider> far = random_colliders(100, 500.0, 1.5f, 8); // most beyond level 1
    colliders.insert(colliders.end(), far.begin(), far.end());
    ASSERT_EQ(grass_set_colliders(ctx, colliders.data(), uint32_t(colliders.size())), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.1), GRASS_SUCCESS) << last_message();
    auto_pass = false;
    ASSERT_EQ(frame(1.2), GRASS_SUCCESS);
    const grass::InteractionPlan& ip = plan().interaction;
    grass::InteractionPlan every = ip;
    const uint32_t n = uint32_t(ip.colliders.size());
    EXPECT_GT(n, 100u);
    EXPECT_LT(n, colliders.size()); // some are outside both windows
    for (uint32_t l = 0; l < 2; ++l) {
        const uint32_t tiles = ip.level[l].counts[2] * ip.level[l].counts[2];
        every.tile_offsets[l].resize(tiles + 1);
        every.tile_colliders[l].clear();
        for (uint32_t t = 0; t <= tiles; ++t) every.tile_offsets[l][t] = t * n;
        for (uint32_t t = 0; t < tiles; ++t) {
            for (uint32_t i = 0; i < n; ++i) every.tile_colliders[l].push_back(i);
        }
        // Far fewer tests than every collider everywhere.
        EXPECT_LT(ip.tile_colliders[l].size() * 4, every.tile_colliders[l].size()) << l;
        std::vector<InteractionTexel> tiled = map[l], brute = map[l];
        grass::run_interaction_pass(ip, l, tiled.data());
        grass::run_interaction_pass(every, l, brute.data());
        int contacts = 0;
        for (const auto& t : tiled) contacts += t.age == 0.0f ? 0 : (pressed(t) ? 1 : 0);
        EXPECT_GT(contacts, l == 0 ? 500 : 300) << l; // 420 on level 1's 1 m texels (was over 500 at 0.5 m)
        EXPECT_EQ(std::memcmp(tiled.data(), brute.data(), tiled.size() * sizeof(InteractionTexel)), 0) << l;
    }
}

bool all_finite(const float* v, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

TEST_F(InteractionPassTest, ExtremesGiveNoNaNAndBoundedWork) {
    // The strongest wind and sources, steps of 10 s, radii 0 and 1e6 m, colliders 1e7 m away
    // moving at 1e5 m/s (1e6 m a step: the longest sweep), a capsule 2e7 m long; then the
    // camera 1e11 m from the origin.
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 1e3f;
    w.gust_strength = 4.0f;
    w.gust_length = 0.1f;
    w.turbulence = 1.0f;
    for (float& g : w.gravity) g = -1e3f;
    grass_wind_source src{};
    src.kind = GRASS_WIND_SOURCE_BLAST;
    src.position[0] = -1e12;
    src.direction[0] = 1.0f;
    src.speed = 1e3f, src.radius = 1e6f, src.start_time = -1e9, src.duration = 1e4f, src.front_speed = 1e4f;
    w.sources = &src;
    w.source_count = 1;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << last_message();
    std::vector<grass_collider> c = {sphere(2, 0, 2, 0.0f), sphere(2, 0, 2, 1e6f, 5e4f, -5e4f, 5e4f),
                                     sphere(1e7, 0, 2, 3.0f, 1e5f), sphere(-1e7, 1e7, -1e7, 1e6f),
                                     sphere(3, 0.1, 3, 0.3f, 2.0f)};
    grass_collider capsule = sphere(-1e7, 0.2, 2, 0.5f, 0.0f, 0.0f, 1e5f);
    capsule.shape = GRASS_COLLIDER_CAPSULE;
    capsule.end[0] = 1e7, capsule.end[1] = 0.2, capsule.end[2] = 2;
    c.push_back(capsule);
    ASSERT_EQ(grass_set_colliders(ctx, c.data(), uint32_t(c.size())), GRASS_SUCCESS) << last_message();
    double eye[3] = {2.0, 3.0, 2.0};
    for (int k = 0; k < 4; ++k) {
        if (k == 3) eye[0] = eye[2] = 1e11;
        ASSERT_EQ(frame(-1e9 + 10.0 * k, eye), GRASS_SUCCESS) << last_message();
        const grass::FramePlan& p = plan();
        EXPECT_EQ(p.stats.time_step, k == 0 ? 0.0 : 10.0);
        EXPECT_TRUE(all_finite(reinterpret_cast<const float*>(&p.frame), sizeof(p.frame) / sizeof(float))) << k;
        for (const auto& d : p.draws) {
            EXPECT_TRUE(all_finite(reinterpret_cast<const float*>(&d.uniforms), 16 + 4 * 8)) << k;
        }
        for (const auto& g : p.interaction.colliders) EXPECT_TRUE(all_finite(g.a, 12)) << k;
        for (uint32_t l = 0; l < 2; ++l) {
            EXPECT_TRUE(all_finite(p.interaction.level[l].origin, 4));
            EXPECT_GE(p.frame.map_levels[l][0], 0.0f);
            EXPECT_LT(p.frame.map_levels[l][0], 256.0f);
            // Bounded: at most every tile per collider in the map.
            EXPECT_LE(p.interaction.tile_colliders[l].size(), p.stats.colliders_in_map * 16 * 16) << k;
            for (const auto& t : map[l]) {
                ASSERT_TRUE(all_finite(t.dir, 2) && !std::isnan(t.underside) && !std::isnan(t.age)) << k;
            }
        }
        // In the map near the origin: the 1e6 m sphere over the field, the small one and the
        // long capsule; not the radius 0 one, nor those 1e7 m away (the moving one sweeps 1e6
        // m in 10 s). From 1e11 m: none.
        EXPECT_EQ(p.stats.colliders_in_map, k < 3 ? 3u : 0u) << k;
        EXPECT_EQ(p.stats.colliders, c.size());
    }
}

TEST_F(InteractionPassTest, ACrowdOf10000CollidersIsBinnedCheaply) {
    // Walkers' feet: 10,000 spheres of 0.25 m at 1.4 m/s over the level 0 window (12.8 m).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(-6.0, 6.0), angle(0.0, 6.2831853);
    std::vector<grass_collider> crowd(10000);
    for (grass_collider& c : crowd) {
        const double a = angle(rng);
        c = sphere(2.0 + pos(rng), 0.1, 2.0 + pos(rng), 0.25f, float(1.4 * std::cos(a)), 0.0f,
                   float(1.4 * std::sin(a)));
    }
    auto_pass = false;
    const int frames = 20;
    double still_ms = 0.0, begin_ms = 0.0, plan_ms = 0.0;
    for (int k = 0; k < frames; ++k) { // the same frames without colliders first
        ASSERT_EQ(frame(k / 60.0), GRASS_SUCCESS);
        still_ms += plan().stats.plan_ms;
    }
    ASSERT_EQ(grass_set_colliders(ctx, crowd.data(), uint32_t(crowd.size())), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS);
    for (int k = 1; k <= frames; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        ASSERT_EQ(frame(1.0 + k / 60.0), GRASS_SUCCESS);
        begin_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        plan_ms += plan().stats.plan_ms;
    }
    const grass::InteractionPlan& ip = plan().interaction;
    EXPECT_EQ(plan().stats.colliders_in_map, 10000u);
    // Each foot's swept footprint (0.52 m) reaches at most 2 x 2 tiles of 0.8 m (level 0) or
    // of 8 m (level 1).
    for (uint32_t l = 0; l < 2; ++l) EXPECT_LE(ip.tile_colliders[l].size(), 4u * 10000) << l;
    const auto t0 = std::chrono::steady_clock::now();
    run_pass();
    const double pass_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    size_t tests = 0;
    for (uint32_t l = 0; l < 2; ++l) {
        const uint32_t tiles = ip.level[l].counts[2];
        for (uint32_t t = 0; t < tiles * tiles; ++t)
            tests += size_t(ip.tile_offsets[l][t + 1] - ip.tile_offsets[l][t]) * 256;
    }
    std::printf("[ crowd    ] 10,000 colliders: grass_begin_frame %.2f ms, plan_ms %.2f ms (%.2f ms without "
                "colliders; means of %d frames); tile entries %zu + %zu; the CPU reference pass %.0f ms for %zu "
                "texel-collider tests\n",
                begin_ms / frames, plan_ms / frames, still_ms / frames, frames, ip.tile_colliders[0].size(),
                ip.tile_colliders[1].size(), pass_ms, tests);
}

// What the pass visits (the frame time's proxy): per texel, its tile's colliders.
size_t pass_visits(const grass::InteractionPlan& ip) {
    size_t visits = 0;
    for (uint32_t l = 0; l < ip.levels; ++l) {
        const uint32_t tiles = ip.level[l].counts[2], texels = ip.level[l].counts[1] * ip.level[l].counts[1];
        for (uint32_t t = 0; t < tiles * tiles; ++t) {
            visits += size_t(ip.tile_offsets[l][t + 1] - ip.tile_offsets[l][t]) * texels;
        }
    }
    return visits;
}

size_t most_in_a_tile(const grass::InteractionPlan& ip, uint32_t l) {
    size_t most = 0;
    for (size_t t = 0; t + 1 < ip.tile_offsets[l].size(); ++t) {
        most = std::max<size_t>(most, ip.tile_offsets[l][t + 1] - ip.tile_offsets[l][t]);
    }
    return most;
}

// docs/responsive.md "Colliders per tile": spheres stacked over one spot, at shuffled heights.
// Beyond GRASS_MAX_COLLIDERS_PER_TILE a tile lists the cap's lowest-reaching ones (in index
// order), the pass's visits are bounded by the cap and the map is what every collider would
// press (the deepest wins a texel); GRASS_MSG_COLLIDER_TILE_CAP is said once over the frames.
// At the cap itself nothing is cut and nothing said. Without the cap the visits grew with the
// stack: 65,536 spheres over one spot took 39.7 s a frame on llvmpipe (issue 35).
TEST_F(InteractionPassTest, StackedCollidersBeyondTheCapAreBoundedAndSaidOnce) {
    const uint32_t cap = GRASS_MAX_COLLIDERS_PER_TILE;
    for (const uint32_t count : {cap, cap + 300}) {
        SCOPED_TRACE(count);
        remake_with<RecordingBackend>(&ctx);
        patch = make_patch();
        grass_field_desc d = one_tier_field(patch, 16, &tier, &band);
        ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
        std::vector<grass_collider> stack(count);
        std::vector<double> height(count);
        for (uint32_t k = 0; k < count; ++k) {
            height[k] = 0.1 + 0.0004 * double((k * 7919u) % count); // every height once, shuffled
            stack[k] = sphere(2.3, height[k], 2.4, 0.3f);
        }
        ASSERT_EQ(grass_set_colliders(ctx, stack.data(), count), GRASS_SUCCESS);
        log.clear();
        for (int f = 0; f < 3; ++f) ASSERT_EQ(frame(1.0 + f / 30.0), GRASS_SUCCESS) << last_message();
        int said = 0;
        for (const LogRecord& r : log) said += r.id == GRASS_MSG_COLLIDER_TILE_CAP ? 1 : 0;
        const grass::InteractionPlan& ip = plan().interaction;
        EXPECT_EQ(plan().stats.colliders_in_map, count);
        // The footprint (0.6 m) reaches at most 2 x 2 tiles of a level.
        size_t tiles_reached = 0;
        for (uint32_t l = 0; l < 2; ++l) {
            for (size_t t = 0; t + 1 < ip.tile_offsets[l].size(); ++t) {
                tiles_reached += ip.tile_offsets[l][t + 1] > ip.tile_offsets[l][t] ? 1 : 0;
            }
        }
        ASSERT_GE(tiles_reached, 2u);
        ASSERT_LE(tiles_reached, 8u);
        const size_t visits = pass_visits(ip), uncapped = tiles_reached * size_t(count) * 256;
        std::printf("[ cap      ] %u stacked colliders: %zu tiles reached, %zu collider visits of the pass (%zu "
                    "without the cap)\n",
                    count, tiles_reached, visits, uncapped);
        if (count <= cap) {
            EXPECT_EQ(said, 0) << last_message();
            EXPECT_EQ(visits, uncapped); // nothing cut
            for (uint32_t l = 0; l < 2; ++l) EXPECT_EQ(most_in_a_tile(ip, l), count) << l;
            continue;
        }
        EXPECT_EQ(said, 1);
        EXPECT_LE(visits, tiles_reached * size_t(cap) * 256);
        EXPECT_LT(visits, uncapped);
        // Each tile: the cap's lowest-reaching colliders, in index order.
        std::vector<uint32_t> by_height(count);
        for (uint32_t k = 0; k < count; ++k) by_height[k] = k;
        std::sort(by_height.begin(), by_height.end(), [&](uint32_t a, uint32_t b) { return height[a] < height[b]; });
        std::vector<uint32_t> lowest(by_height.begin(), by_height.begin() + cap);
        std::sort(lowest.begin(), lowest.end());
        for (uint32_t l = 0; l < 2; ++l) {
            EXPECT_EQ(most_in_a_tile(ip, l), cap) << l;
            for (size_t t = 0; t + 1 < ip.tile_offsets[l].size(); ++t) {
                const auto first = ip.tile_colliders[l].begin() + ip.tile_offsets[l][t];
                const auto last = ip.tile_colliders[l].begin() + ip.tile_offsets[l][t + 1];
                if (first == last) continue;
                EXPECT_TRUE(std::equal(first, last, lowest.begin(), lowest.end())) << "level " << l << " tile " << t;
            }
        }
        // The map as every collider would press it: the same, bit for bit.
        grass::InteractionPlan every = ip;
        std::vector<InteractionTexel> kept[2], all[2];
        for (uint32_t l = 0; l < 2; ++l) {
            const uint32_t tiles = ip.level[l].counts[2] * ip.level[l].counts[2];
            every.tile_colliders[l].clear();
            for (uint32_t t = 0; t < tiles; ++t) {
                every.tile_offsets[l][t] = uint32_t(every.tile_colliders[l].size());
                if (ip.tile_offsets[l][t + 1] == ip.tile_offsets[l][t]) continue;
                for (uint32_t i = 0; i < count; ++i) every.tile_colliders[l].push_back(i);
            }
            every.tile_offsets[l][tiles] = uint32_t(every.tile_colliders[l].size());
            kept[l] = all[l] = map[l];
            grass::run_interaction_pass(ip, l, kept[l].data());
            grass::run_interaction_pass(every, l, all[l].data());
            int contacts = 0;
            for (const auto& t : kept[l]) contacts += t.age == 0.0f ? 1 : 0;
            EXPECT_GT(contacts, l == 0 ? 100 : 0) << l;
            EXPECT_EQ(std::memcmp(kept[l].data(), all[l].data(), kept[l].size() * sizeof(InteractionTexel)), 0) << l;
        }
        EXPECT_NE(last_message().find("GRASS_MAX_COLLIDERS_PER_TILE"), std::string::npos) << last_message();
        EXPECT_NE(last_message().find(std::to_string(count)), std::string::npos) << last_message();
    }
}

// docs/responsive.md: a sweep of at most 1e6 m a step keeps its path (a sphere at 1e5 m/s
// over 10 s presses every texel of the row under its path across the fine level's window);
// a longer one is refused by grass_begin_frame and grass_begin_host_frame, naming the
// collider, its velocity and the sweep, and the clock and map stay as they were. Sweeps near
// 1e7 m collapsed to their end point in the float pass (issue 35).
TEST_F(InteractionPassTest, ASweepLongerThan1e6MetresIsRefusedByName) {
    const double eye[3] = {2.0, 3.0, 2.0};
    grass_collider fast = sphere(2.0, 0.1, 2.5, 0.3f, 1e5f, 0.0f, 0.0f);
    ASSERT_EQ(grass_set_colliders(ctx, &fast, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(0.0, eye), GRASS_SUCCESS);
    ASSERT_EQ(frame(10.0, eye), GRASS_SUCCESS) << last_message(); // 1e6 m: the bound itself
    int row = 0, pressed_row = 0;
    for (double x = -4.0; x <= 2.0; x += 0.05) {
        const double p[3] = {x, 0.0, 2.5};
        const InteractionTexel* t = read(plan(), map[0], 0, eye, p);
        ASSERT_NE(t, nullptr);
        row += 1;
        pressed_row += pressed(*t) ? 1 : 0;
    }
    EXPECT_GT(row, 100);
    EXPECT_EQ(pressed_row, row) << "the path of a 1e6 m sweep has gaps";
    const std::vector<InteractionTexel> before = map[0];
    log.clear();
    EXPECT_EQ(frame(20.5, eye), GRASS_ERROR_INVALID_ARGUMENT); // 1.05e6 m
    EXPECT_EQ(last_id(), GRASS_MSG_OUT_OF_RANGE);
    EXPECT_NE(last_message().find("grass_begin_frame: colliders[0].velocity is (100000, 0, 0)"), std::string::npos)
        << last_message();
    EXPECT_NE(last_message().find("sweeps 1.05e+06 m"), std::string::npos) << last_message();
    grass_frame_desc host = grass_default_frame_desc();
    host.frame_index = 1000;
    host.time = 20.5;
    EXPECT_EQ(grass_begin_host_frame(ctx, &host), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass_begin_host_frame: colliders[0].velocity"), std::string::npos)
        << last_message();
    EXPECT_EQ(std::memcmp(before.data(), map[0].data(), before.size() * sizeof(InteractionTexel)), 0);
    // The host says the collider jumped: the frame steps from the last begun one.
    fast.velocity[0] = 0.0f;
    ASSERT_EQ(grass_set_colliders(ctx, &fast, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(20.5, eye), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(plan().stats.time_step, 10.5);
}

} // namespace
