// Periodic 2D Perlin noise (Perlin 2002, improved fade curve): the low-frequency map that
// clusters density thresholds (lemme2012 4.1.3). Periodic over the unit square so that a
// tiled patch shows no seam in the clustering.
#pragma once

#include <cstdint>

namespace grass {

class PerlinNoise {
public:
    // `period`: lattice cells across the unit square (noise periods per patch), >= 1.
    PerlinNoise(uint32_t period, uint64_t seed);
    // Noise at (x, z) in the unit square, roughly in [-0.7, 0.7], 0 at lattice points.
    double at(double x, double z) const;

private:
    double gradient_dot(int ix, int iz, double dx, double dz) const;
    uint32_t period_;
    uint8_t permutation_[256];
};

} // namespace grass
