#include "patch/density_threshold.hpp"

#include "patch/perlin_noise.hpp"
#include "patch/random.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

// ranks[k] = position of value k in ascending order (ties broken by index: deterministic).
void rank_of(const Vector<double>& values, Vector<uint32_t>& order, Vector<uint32_t>& ranks) {
    const uint32_t n = static_cast<uint32_t>(values.size());
    order.resize(n);
    for (uint32_t k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return values[a] < values[b] || (values[a] == values[b] && a < b); });
    ranks.resize(n);
    for (uint32_t r = 0; r < n; ++r) ranks[order[r]] = r;
}

// A sample of N(mu, sigma) restricted to (0, 1] by rejection; sigma = 0 returns mu.
double truncated_gaussian(Random& rng, double mu, double sigma) {
    if (sigma <= 0.0) return mu;
    for (int attempt = 0; attempt < 64; ++attempt) {
        const double x = mu + sigma * rng.normal();
        if (x > 0.0 && x <= 1.0) return x;
    }
    return mu; // practically unreachable for mu in (0, 1]
}

} // namespace

void assign_density_thresholds(const ThresholdParams& params, const float* root_x, const float* root_z,
                               uint32_t blade_count, HostAllocator* host, float* out_thresholds) {
    Random rng(params.seed ^ 0x7468726573686f6cull); // "threshol"
    Vector<double> raw{StlAllocator<double>(host)};
    Vector<uint32_t> order{StlAllocator<uint32_t>(host)};
    Vector<uint32_t> ranks{StlAllocator<uint32_t>(host)};
    raw.resize(blade_count);

    if (params.mode == GRASS_THRESHOLD_CLUSTERED) {
        // Equalise the noise at the roots: mu = (rank + 0.5) / N spreads it over (0, 1).
        const PerlinNoise noise(params.cluster_frequency, params.seed ^ 0x6e6f697365ull);
        for (uint32_t b = 0; b < blade_count; ++b) raw[b] = noise.at(root_x[b], root_z[b]);
        rank_of(raw, order, ranks);
        for (uint32_t b = 0; b < blade_count; ++b) {
            const double mu = (ranks[b] + 0.5) / blade_count;
            raw[b] = truncated_gaussian(rng, mu, params.cluster_sigma);
        }
    } else {
        for (uint32_t b = 0; b < blade_count; ++b) raw[b] = 1.0 - rng.uniform(); // (0, 1]
    }

    rank_of(raw, order, ranks);
    for (uint32_t b = 0; b < blade_count; ++b) {
        out_thresholds[b] = static_cast<float>(static_cast<double>(ranks[b] + 1) / blade_count);
    }
}

} // namespace grass
