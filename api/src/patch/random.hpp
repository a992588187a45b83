// Deterministic random numbers for patch generation: the same seed gives the same bits on
// every platform (the standard library's distributions do not promise that).
#pragma once

#include <cstdint>

namespace grass {

// SplitMix64 (Steele, Lea, Flood 2014): small state, passes BigCrush as a 64-bit stream.
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}
    uint64_t next_u64();
    // Uniform in [0, 1) with 53 random bits.
    double uniform();
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Standard normal (Box-Muller, cached second value not kept: simpler to reproduce).
    double normal();

private:
    uint64_t state_;
};

// FNV-1a 64 over bytes, continuing from `hash` (start with kFnvOffset).
constexpr uint64_t kFnvOffset = 0xcbf29ce484222325ull;
uint64_t fnv1a64(const void* data, uint64_t size, uint64_t hash);

} // namespace grass
