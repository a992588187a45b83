// Density thresholds per blade (lemme2012 4.1.3, boulanger2006 3.4): each blade gets a
// value in (0, 1]; a blade is drawn where the local density is at least its threshold.
#pragma once

#include "foundation/allocator.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct ThresholdParams {
    grass_threshold_mode mode = GRASS_THRESHOLD_UNIFORM;
    double cluster_sigma = 0.12;    // width of the Gaussian around the noise value
    uint32_t cluster_frequency = 3; // noise periods per patch
    uint64_t seed = 1;
};

// Writes one threshold per blade from the blade roots (x, z in the unit square).
//   uniform:   a random value per blade;
//   clustered: mu = histogram-equalised periodic Perlin noise at the root, then a sample of
//              a Gaussian (mu, sigma) truncated to (0, 1] (eq. 4.4-4.6).
// Both modes end with a rank equalisation: the k-th smallest raw value becomes (k+1)/N.
// This keeps the spatial pattern of each mode and makes the value distribution exactly
// uniform, so a density d draws floor(d * N) blades of the patch, for any d.
void assign_density_thresholds(const ThresholdParams& params, const float* root_x, const float* root_z,
                               uint32_t blade_count, HostAllocator* host, float* out_thresholds);

} // namespace grass
