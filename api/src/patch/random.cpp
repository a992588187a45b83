#include "patch/random.hpp"

#include <cmath>

namespace grass {

uint64_t Random::next_u64() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double Random::uniform() { return static_cast<double>(next_u64() >> 11) * (1.0 / 9007199254740992.0); }

double Random::normal() {
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

uint64_t fnv1a64(const void* data, uint64_t size, uint64_t hash) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (uint64_t k = 0; k < size; ++k) {
        hash ^= bytes[k];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

} // namespace grass
