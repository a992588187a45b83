// Out-of-line parts of the SliceSet contract (baked_slices.hpp).
#include "bake/baked_slices.hpp"

#include "bake/slice_set_hash.hpp"
#include "patch/random.hpp"

namespace grass {

uint64_t slice_layer_texels(uint32_t width, uint32_t height, uint32_t mip_levels) {
    uint64_t texels = 0;
    for (uint32_t k = 0; k < mip_levels; ++k) {
        const uint64_t w = k < 32 && (width >> k) ? width >> k : 1;
        const uint64_t h = k < 32 && (height >> k) ? height >> k : 1;
        texels += w * h;
    }
    return texels;
}

uint64_t SliceSet::offset(uint32_t layer, uint32_t level) const {
    return static_cast<uint64_t>(layer) * slice_layer_texels(width, height, mip_levels) +
           slice_layer_texels(width, height, level);
}

uint64_t slice_content_hash(const SliceSet& set) {
    uint64_t h = fnv1a64(set.color.data(), set.color.size(), kFnvOffset);
    h = fnv1a64(set.normal.data(), set.normal.size(), h);
    return fnv1a64(set.threshold.data(), set.threshold.size() * sizeof(uint16_t), h);
}

} // namespace grass
