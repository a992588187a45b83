// A CPU reference of the interaction pass (api/shaders/interaction.comp): the same rule, in
// float as the GPU runs it, texel by texel. The core's tests run it on the plans the core
// makes (frame-rate independence, scrolling, extremes); a backend's test may compare its
// map against it.
#pragma once

#include "foundation/frame_plan.hpp"

#include <cstdint>

namespace grass {

// One texel of the map (RGBA32F): the direction (map axes u, v) the pressed grass lies
// towards, the collider's underside height at the deepest contact (m above the anchor) and
// the seconds since that contact. A cleared texel is (0, 0, 1e30, 1e30).
struct InteractionTexel {
    float dir[2];
    float underside;
    float age;
};
constexpr float kNoContact = 1e30f; // underside and age of a cleared texel
constexpr float kAgeNone = 1e29f;   // an age at or above this: no contact (ages stop growing there)

inline InteractionTexel cleared_texel() { return InteractionTexel{{0.0f, 0.0f}, kNoContact, kNoContact}; }

// How a contact of this frame combines with the texel's stored one (as interaction.comp):
// when the collider already touched the texel at the start of this frame's sweep (s = 0), the
// contact continues the stored one's passage and the deeper of the two is kept (ties: the
// younger); otherwise it replaces it. A passage then keeps its deepest contact whatever the
// frame rate.
// Runs the pass of `level` of `plan` on `texels` (resolution^2, row y = texel v, x = texel u:
// texels[y * N + x]).
void run_interaction_pass(const InteractionPlan& plan, uint32_t level, InteractionTexel* texels);

} // namespace grass
