// Poisson-disk sampling on a surface by dart throwing (jahrmann2017 4, after Cline et al.
// 2009): candidates drawn by area are kept when no kept point lies within the minimum
// distance, found through a hashed grid of cells of side r / sqrt(3) (one point a cell).
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

class PoissonDiskSet {
public:
    // `min_distance` > 0 in the points' units; `capacity`: the most points that will be kept.
    PoissonDiskSet(double min_distance, uint32_t capacity, HostAllocator* host);

    // Keeps `p` and returns true when no kept point lies closer than the minimum distance
    // (distances in 3D, through the volume: a chord, not along the surface).
    bool try_insert(const double p[3]);
    uint32_t size() const { return static_cast<uint32_t>(points_.size() / 3); }
    const double* point(uint32_t k) const { return &points_[size_t{k} * 3]; }

private:
    uint64_t cell_key(int64_t x, int64_t y, int64_t z) const;
    uint32_t slot_of(uint64_t key) const; // the open-addressing slot holding or awaiting `key`

    double min_distance_;
    double cell_;
    Vector<double> points_;
    Vector<uint64_t> keys_;  // per slot: cell key + 1, 0 when empty
    Vector<uint32_t> heads_; // per slot: first point of the cell
    Vector<uint32_t> next_;  // per point: next point of its cell, UINT32_MAX at the end
};

} // namespace grass
