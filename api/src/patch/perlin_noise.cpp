#include "patch/perlin_noise.hpp"

#include "patch/random.hpp"

#include <cmath>

namespace grass {

PerlinNoise::PerlinNoise(uint32_t period, uint64_t seed) : period_(period < 1 ? 1 : period) {
    for (int k = 0; k < 256; ++k) permutation_[k] = static_cast<uint8_t>(k);
    Random r(seed);
    for (int k = 255; k > 0; --k) { // Fisher-Yates
        const int j = static_cast<int>(r.next_u64() % static_cast<uint64_t>(k + 1));
        const uint8_t t = permutation_[k];
        permutation_[k] = permutation_[j];
        permutation_[j] = t;
    }
}

double PerlinNoise::gradient_dot(int ix, int iz, double dx, double dz) const {
    const int p = static_cast<int>(period_);
    ix = ((ix % p) + p) % p; // wrap: the noise repeats every unit square
    iz = ((iz % p) + p) % p;
    const uint8_t h = permutation_[(permutation_[ix & 255] + iz) & 255];
    // Eight unit gradients; the diagonals are scaled so all have length 1.
    static const double g[8][2] = {{1, 0},
                                   {-1, 0},
                                   {0, 1},
                                   {0, -1},
                                   {0.70710678118654752, 0.70710678118654752},
                                   {-0.70710678118654752, 0.70710678118654752},
                                   {0.70710678118654752, -0.70710678118654752},
                                   {-0.70710678118654752, -0.70710678118654752}};
    return g[h & 7][0] * dx + g[h & 7][1] * dz;
}

double PerlinNoise::at(double x, double z) const {
    const double fx = x * period_, fz = z * period_;
    const double x0f = std::floor(fx), z0f = std::floor(fz);
    const int x0 = static_cast<int>(x0f), z0 = static_cast<int>(z0f);
    const double dx = fx - x0f, dz = fz - z0f;
    auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
    const double u = fade(dx), v = fade(dz);
    const double n00 = gradient_dot(x0, z0, dx, dz);
    const double n10 = gradient_dot(x0 + 1, z0, dx - 1.0, dz);
    const double n01 = gradient_dot(x0, z0 + 1, dx, dz - 1.0);
    const double n11 = gradient_dot(x0 + 1, z0 + 1, dx - 1.0, dz - 1.0);
    const double a = n00 + u * (n10 - n00);
    const double b = n01 + u * (n11 - n01);
    return a + v * (b - a);
}

} // namespace grass
