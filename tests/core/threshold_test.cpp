// Density thresholds (lemme2012 4.1.3): values uniform in (0, 1] in both modes, the
// clustered mode clustered in space.
#include "core_fixture.hpp"

#include "context/context.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

std::vector<float> thresholds(grass_context* ctx, grass_patch_id p, uint32_t n) {
    std::vector<float> t(n);
    EXPECT_EQ(grass_get_patch_thresholds(ctx, p, t.data(), n), GRASS_SUCCESS);
    return t;
}

// Kolmogorov-Smirnov distance between the sample and U(0, 1].
double ks_uniform(std::vector<float> t) {
    std::sort(t.begin(), t.end());
    const double n = static_cast<double>(t.size());
    double d = 0.0;
    for (size_t k = 0; k < t.size(); ++k) {
        d = std::max({d, std::fabs((k + 1) / n - t[k]), std::fabs(k / n - t[k])});
    }
    return d;
}

// Mean |threshold difference| between each blade and its nearest neighbour (in the tiled
// unit square). Small = neighbours share thresholds = clusters.
double neighbour_difference(grass_context* ctx, grass_patch_id id) {
    const grass::PatchData& p = ctx->patches.get(id.index - 1)->data;
    double sum = 0.0;
    for (uint32_t a = 0; a < p.blade_count; ++a) {
        const float* ra = p.vertices[size_t(a) * p.vertices_per_blade].root_shape;
        double best = 1e9;
        uint32_t nearest = a;
        for (uint32_t b = 0; b < p.blade_count; ++b) {
            if (a == b) continue;
            const float* rb = p.vertices[size_t(b) * p.vertices_per_blade].root_shape;
            double dx = std::fabs(ra[0] - rb[0]), dz = std::fabs(ra[1] - rb[1]);
            dx = std::min(dx, 1.0 - dx);
            dz = std::min(dz, 1.0 - dz);
            if (dx * dx + dz * dz < best) best = dx * dx + dz * dz, nearest = b;
        }
        sum += std::fabs(p.thresholds[a] - p.thresholds[nearest]);
    }
    return sum / p.blade_count;
}

class ThresholdTest : public CoreTest, public ::testing::WithParamInterface<grass_threshold_mode> {};

TEST_P(ThresholdTest, ValuesAreUniformInTheOpenClosedUnitInterval) {
    grass_patch_desc d = grass_default_patch_desc();
    d.blade_count = 2000;
    d.threshold_mode = GetParam();
    const auto t = thresholds(ctx, make_patch(d), d.blade_count);
    for (float v : t) {
        ASSERT_GT(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
    // 95% critical value of the KS test for n = 2000 is 1.36 / sqrt(n) = 0.030.
    EXPECT_LT(ks_uniform(t), 1.36 / std::sqrt(2000.0));
    // Linear density response: density d passes floor(d N) blades.
    for (double density : {0.0, 0.1, 0.25, 0.5, 0.9, 1.0}) {
        const auto passing = std::count_if(t.begin(), t.end(), [&](float v) { return v <= density + 1e-6; });
        EXPECT_EQ(passing, static_cast<long>(std::floor(density * d.blade_count + 1e-6))) << "density " << density;
    }
}

INSTANTIATE_TEST_SUITE_P(BothModes, ThresholdTest,
                         ::testing::Values(GRASS_THRESHOLD_UNIFORM, GRASS_THRESHOLD_CLUSTERED),
                         [](const auto& p) { return p.param == GRASS_THRESHOLD_UNIFORM ? "uniform" : "clustered"; });

TEST_F(CoreTest, ClusteredThresholdsAreSpatiallyCoherentAndSigmaControlsIt) {
    grass_patch_desc d = grass_default_patch_desc();
    d.blade_count = 1500;
    d.threshold_mode = GRASS_THRESHOLD_UNIFORM;
    const double uniform = neighbour_difference(ctx, make_patch(d));
    d.threshold_mode = GRASS_THRESHOLD_CLUSTERED;
    d.cluster_sigma = 0.0f; // strongest clustering (lemme figure 4.3c)
    const double strong = neighbour_difference(ctx, make_patch(d));
    d.cluster_sigma = 0.12f;
    const double slight = neighbour_difference(ctx, make_patch(d));
    // Independent uniform neighbours differ by 1/3 on average.
    EXPECT_NEAR(uniform, 1.0 / 3.0, 0.04);
    EXPECT_LT(strong, 0.5 * uniform);
    EXPECT_LT(strong, slight);
    EXPECT_LT(slight, uniform);
}

} // namespace
