// Seamless transitions between tiers (boulanger2006 3.4 eq. 2-5, lemme2012 5.4 eq.
// 5.22-5.26), generalised to any number of tiers. The CPU twin of tier_transitions.glsl:
// the shaders run the same arithmetic, the tests check it here.
//
//  - Each tier t has a weight w_t(d) at distance d: 0 outside its band, ramping linearly
//    from 0 to 1 over transition_in after begin and back to 0 over transition_out before
//    end (boulanger eq. 2-4, lemme eq. 5.23-5.24).
//  - The weights are normalised over the field's tiers, so that they sum to 1 wherever a
//    tier draws.
//  - A blade visible at local density ld (threshold th <= ld) has r = th / ld in (0, 1]. The
//    tiers split (0, 1] into consecutive intervals of their weights' lengths, coarser tiers
//    (higher index) first: tier t draws r in (lo_t, hi_t]. Two tiers in a transition zone
//    give Boulanger's threshold inversion: the coarse tier draws r <= w_coarse, the fine
//    tier r > w_coarse, i.e. 1 - r < w_fine. No blade is drawn by two tiers or by none.
//  - At the interval ends a smoothstep window of half-width `window` fades a crossing
//    blade out of one tier as it fades into the next (lemme eq. 5.26): the opacities of a
//    blade over all tiers always sum to 1.
#pragma once

#include <cstdint>

namespace grass {

struct TierBand {
    float begin, end, transition_in, transition_out; // metres; end may be huge (infinity)
};

// w_t(d) before normalisation.
float band_weight(const TierBand& band, float distance);

// Opacity in [0, 1] of a blade (threshold in (0, 1]) drawn by tier `tier` of `count` tiers
// at `distance` metres, where the local density is `density`.
float tier_blade_opacity(const TierBand* bands, uint32_t count, uint32_t tier, float distance, float threshold,
                         float density, float window);

} // namespace grass
