#include "mesh/mesh_patches.hpp"

#include <algorithm>

namespace grass {

namespace {

// Orders blades [begin, end) of `order` along a k-d tree of their roots: the range is cut
// at the median of its box's longest axis, at a whole number of patches while it spans
// more than one, so that every patch is one subtree, compact, and its order along the
// tree keeps neighbours together.
void kd_order(const Vector<MeshBlade>& blades, uint32_t* begin, uint32_t* end, uint32_t patch_blades) {
    const size_t count = static_cast<size_t>(end - begin);
    if (count < 2) return;
    float lo[3], hi[3];
    for (int i = 0; i < 3; ++i) lo[i] = hi[i] = blades[*begin].root[i];
    for (const uint32_t* b = begin; b != end; ++b) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], blades[*b].root[i]);
            hi[i] = std::max(hi[i], blades[*b].root[i]);
        }
    }
    int axis = 0;
    for (int i = 1; i < 3; ++i)
        if (hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
    const size_t patches = count / patch_blades;
    const size_t left = patches > 1 ? (patches / 2) * patch_blades : count / 2;
    std::nth_element(begin, begin + left, end, [&](uint32_t a, uint32_t b) {
        return blades[a].root[axis] < blades[b].root[axis] || (blades[a].root[axis] == blades[b].root[axis] && a < b);
    });
    kd_order(blades, begin, begin + left, patch_blades);
    kd_order(blades, begin + left, end, patch_blades);
}

uint32_t reverse_bits(uint32_t v, uint32_t bits) {
    uint32_t r = 0;
    for (uint32_t b = 0; b < bits; ++b) r |= ((v >> b) & 1u) << (bits - 1 - b);
    return r;
}

} // namespace

void group_into_patches(Vector<MeshBlade>& blades, uint32_t patch_blades, Vector<MeshPatch>& patches) {
    const size_t n = blades.size();
    HostAllocator* host = blades.get_allocator().host();
    Vector<uint32_t> order{StlAllocator<uint32_t>(host)};
    order.resize(n);
    for (size_t b = 0; b < n; ++b) order[b] = static_cast<uint32_t>(b);
    kd_order(blades, order.data(), order.data() + n, patch_blades);

    // Within a patch, blade j of the prefix order is the blade at the bit-reversed rank along
    // the tree (van der Corput): the first 2^k blades take one blade of every P / 2^k, one per subtree.
    uint32_t bits = 0;
    while ((1ull << bits) < patch_blades) ++bits;
    Vector<uint32_t> prefix{StlAllocator<uint32_t>(host)};
    prefix.reserve(patch_blades);
    for (uint32_t j = 0; j < (1u << bits); ++j) {
        const uint32_t r = reverse_bits(j, bits);
        if (r < patch_blades) prefix.push_back(r);
    }

    Vector<MeshBlade> sorted{StlAllocator<MeshBlade>(host)};
    sorted.resize(n);
    patches.clear();
    patches.resize(n / patch_blades);
    for (size_t p = 0; p < patches.size(); ++p) {
        MeshPatch& patch = patches[p];
        patch.first_blade = static_cast<uint32_t>(p * patch_blades);
        for (uint32_t j = 0; j < patch_blades; ++j) {
            const MeshBlade& blade = blades[order[patch.first_blade + prefix[j]]];
            sorted[patch.first_blade + j] = blade;
            for (int i = 0; i < 3; ++i) {
                patch.bounds_min[i] = j ? std::min(patch.bounds_min[i], blade.root[i]) : blade.root[i];
                patch.bounds_max[i] = j ? std::max(patch.bounds_max[i], blade.root[i]) : blade.root[i];
            }
        }
    }
    blades.swap(sorted);
}

} // namespace grass
