#include "mesh/poisson_disk.hpp"

#include <cmath>

namespace grass {

namespace {
constexpr uint32_t kEnd = 0xffffffffu;

// The grid cell of a coordinate. A quotient beyond +-2^62 (a coordinate of 1e30 m, or a
// minimum distance of 1e-300 m) would overflow int64: it is held at the bound, so that far
// points share a cell and are told apart by their distance, which try_insert compares anyway.
int64_t cell_coordinate(double v, double cell) {
    constexpr double kBound = 4611686018427387904.0; // 2^62
    const double q = std::floor(v / cell);
    if (!(q > -kBound)) return -static_cast<int64_t>(kBound);
    if (!(q < kBound)) return static_cast<int64_t>(kBound);
    return static_cast<int64_t>(q);
}
} // namespace

PoissonDiskSet::PoissonDiskSet(double min_distance, uint32_t capacity, HostAllocator* host)
    : min_distance_(min_distance), cell_(min_distance / std::sqrt(3.0)), points_(StlAllocator<double>(host)),
      keys_(StlAllocator<uint64_t>(host)), heads_(StlAllocator<uint32_t>(host)), next_(StlAllocator<uint32_t>(host)) {
    uint32_t slots = 64;
    while (slots < capacity * 2ull && slots < (1u << 31)) slots *= 2;
    keys_.assign(slots, 0);
    heads_.assign(slots, kEnd);
    points_.reserve(size_t{capacity} * 3);
    next_.reserve(capacity);
}

uint64_t PoissonDiskSet::cell_key(int64_t x, int64_t y, int64_t z) const {
    // 21 bits per axis (two's complement wrapped): cells that collide are only compared, never merged wrongly.
    const uint64_t m = (uint64_t{1} << 21) - 1;
    return (static_cast<uint64_t>(x) & m) | ((static_cast<uint64_t>(y) & m) << 21) |
           ((static_cast<uint64_t>(z) & m) << 42);
}

uint32_t PoissonDiskSet::slot_of(uint64_t key) const {
    const uint32_t mask = static_cast<uint32_t>(keys_.size() - 1);
    uint64_t h = key * 0x9e3779b97f4a7c15ull;
    uint32_t slot = static_cast<uint32_t>(h >> 32) & mask;
    while (keys_[slot] != 0 && keys_[slot] != key + 1) slot = (slot + 1) & mask;
    return slot;
}

bool PoissonDiskSet::try_insert(const double p[3]) {
    const int64_t cx = cell_coordinate(p[0], cell_), cy = cell_coordinate(p[1], cell_),
                  cz = cell_coordinate(p[2], cell_);
    if (size_t{size()} * 2 >= keys_.size()) return false; // full: the capacity given
    const double r2 = min_distance_ * min_distance_;
    // A point closer than r lies within two cells (r = cell * sqrt(3) < 2 cells) on each axis.
    for (int64_t dz = -2; dz <= 2; ++dz) {
        for (int64_t dy = -2; dy <= 2; ++dy) {
            for (int64_t dx = -2; dx <= 2; ++dx) {
                const uint32_t slot = slot_of(cell_key(cx + dx, cy + dy, cz + dz));
                for (uint32_t q = keys_[slot] ? heads_[slot] : kEnd; q != kEnd; q = next_[q]) {
                    const double* o = point(q);
                    const double ex = o[0] - p[0], ey = o[1] - p[1], ez = o[2] - p[2];
                    if (ex * ex + ey * ey + ez * ez < r2) return false;
                }
            }
        }
    }
    const uint64_t key = cell_key(cx, cy, cz);
    const uint32_t slot = slot_of(key);
    const uint32_t index = size();
    points_.insert(points_.end(), p, p + 3);
    next_.push_back(keys_[slot] ? heads_[slot] : kEnd);
    keys_[slot] = key + 1;
    heads_[slot] = index;
    return true;
}

} // namespace grass
