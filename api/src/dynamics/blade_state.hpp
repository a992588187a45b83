// The per-blade state of responsive grass (jahrmann2017 5, docs/responsive.md "Per-blade
// state"): what a pass that steps blades keeps per blade instance, and the constants of its
// step. The model itself is written once, in GLSL (api/shaders/blade_state.glsl); this file
// is what the core and the backends size and bind it by. The shader's constants mirror
// these (tests/render/blade_state_test.cpp compares them on the GPU).
#pragma once

#include <cstdint>

namespace grass {

// One blade's state, as blade_state_pack writes it: two vec4 (std430).
struct GpuBladeState {
    float v2_eta[4];   // xyz: the free tip relative to the root (world m; eq. 9 applied, not 11 and 13),
                       // w: collision strength eta (eq. 2-3, 16), 0..1
    float velocity[4]; // xyz: the tip's velocity (m/s), w: 0
};
constexpr uint32_t kBladeStateBytes = 32;
static_assert(sizeof(GpuBladeState) == kBladeStateBytes, "GpuBladeState must match blade_state.glsl");

// A step of dt seconds is split into min(ceil(dt / kBladeStateSubstep), kBladeStateMaxSubsteps)
// equal substeps: 1/60 s or less up to dt = 16/60 s, longer beyond (a 1 s step: 1/16 s; the
// API's longest, 10 s: 0.625 s). Each substep's spring is exact, so any length is stable;
// the substeps bound how far the tip moves between two collider push-outs. 30 and 60 fps
// take the same 1/60 s substeps and agree exactly; 1 s steps agree with them within 0.08 of
// the blade's length while a collider presses it (tests/render/blade_state_test.cpp).
constexpr float kBladeStateSubstep = 1.0f / 60.0f;
constexpr int kBladeStateMaxSubsteps = 16;
// The tip's damping ratio at full recovery: a gust's overshoot is exp(-pi z / sqrt(1 - z^2)),
// 25% of the step for 0.4; a tip moved by a fraction x of its length accelerates back by
// stiffness x (omega^2 = stiffness / length: 1.4 Hz for the default 40 m/s^2 and 0.5 m).
constexpr float kBladeStateDamping = 0.4f;
// Eta rises by this x (d / L)^2 per second, d the push-out colliders give the stateless pose
// of a blade of length L (eq. 16 as a rate), and falls by 1 / recovery_time per second (eq. 2).
constexpr float kBladeStateEtaBuild = 50.0f;
// Eq. 3: recovery is max(1 - eta, kBladeStateMinRecovery) of its strength.
constexpr float kBladeStateMinRecovery = 0.1f;
// The free tip stays within this many blade lengths of its rest tip along each axis.
constexpr float kBladeStateMaxDeflection = 100.0f;

} // namespace grass
