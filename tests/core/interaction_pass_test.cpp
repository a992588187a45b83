// The interaction map's rule (docs/responsive.md), run by the CPU reference of the pass on
// the plans the core makes: frame-rate independence, dt = 0, scrolling, extremes, binning.
#include "dynamics_fixture.hpp"

#include <algorithm>
#include <cstdio>

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
    for (grass::ContactRule r : {grass::ContactRule::replace, grass::ContactRule::keep_deepest_of_passage}) {
        rule = r;
        std::vector<InteractionTexel> result[3];
        for (int i = 0; i < 3; ++i) {
            grass_set_interaction(ctx, nullptr); // a new map for each run
            result[i] = run(fps[i], start, velocity, 0.25f);
        }
        for (int i = 0; i < 2; ++i) {
            const Difference d = compare(result[i], result[2], ground());
            std::printf("[ fps      ] %s: %d fps vs one 1 s step: %d texels with contacts, %d mismatched, max |dU| "
                        "%.4f m, max |dage| %.4f s, max |dpress| %.4f m\n",
                        r == grass::ContactRule::replace ? "replace" : "passage", fps[i], d.contacts,
                        d.contact_mismatch, d.underside, d.age, d.press);
        }
    }
}

} // namespace
