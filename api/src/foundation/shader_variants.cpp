#include "foundation/shader_variants.hpp"

namespace grass {

ShaderVariant draw_variant(const TierDraw& draw, uint32_t view_flags) {
    if ((view_flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0) return {kShaderDebugBoxes, draw.features & kDebugBoxFeatures};
    const ShaderProgram program = draw.kind == GRASS_TIER_GEOMETRY ? kShaderBlades
                                  : draw.kind == GRASS_TIER_VOLUME ? kShaderVolume
                                                                   : kShaderImage;
    return {program, draw.features & (kFeatureMaskCount - 1)};
}

uint32_t declared_feature_bits(uint32_t pipeline_features) {
    uint32_t bits = 0;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_WIND) bits |= kFeatureWind;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_WIND_MAP) bits |= kFeatureWind | kFeatureWindMap;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_INTERACTION) bits |= kFeatureInteraction;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_BLADE_CULLING) bits |= kFeatureBladeCulling;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_DEBUG_VIEWS) bits |= kFeatureDebugView;
    return bits;
}

uint32_t field_variants(uint32_t declared, uint32_t map_features, uint32_t tier_kinds,
                        ShaderVariant out[kMaxFieldVariants]) {
    constexpr uint32_t kBits[] = {kFeatureWind, kFeatureWindMap, kFeatureInteraction, kFeatureBladeCulling,
                                  kFeatureDebugView};
    constexpr uint32_t kBitCount = sizeof(kBits) / sizeof(kBits[0]);
    uint32_t count = 0;
    const auto add = [&](ShaderProgram program, uint32_t features) {
        for (uint32_t i = 0; i < count; ++i) {
            if (out[i] == ShaderVariant{program, features}) return;
        }
        if (count < kMaxFieldVariants) out[count++] = ShaderVariant{program, features};
    };
    // Every subset of the declared bits (2^5 at most).
    for (uint32_t subset = 0; subset < (1u << kBitCount); ++subset) {
        uint32_t bits = 0;
        bool declared_only = true;
        for (uint32_t b = 0; b < kBitCount; ++b) {
            if (((subset >> b) & 1u) == 0) continue;
            declared_only = declared_only && (declared & kBits[b]) != 0;
            bits |= kBits[b];
        }
        if (!declared_only) continue;
        if ((bits & kFeatureWindMap) && !(bits & kFeatureWind)) continue; // a wind map brings wind
        const uint32_t features = map_features | bits;
        if (tier_kinds & (1u << GRASS_TIER_GEOMETRY)) add(kShaderBlades, features);
        if (bits & kFeatureBladeCulling) continue; // geometry draws only
        if (tier_kinds & (1u << GRASS_TIER_VOLUME)) add(kShaderVolume, features);
        if (tier_kinds & (1u << GRASS_TIER_IMAGE)) add(kShaderImage, features);
    }
    // Debug boxes: under GRASS_VIEW_FLAG_DEBUG_CELLS, whatever else the frame does.
    if (declared & kFeatureDebugView) add(kShaderDebugBoxes, map_features & kDebugBoxFeatures);
    return count;
}

} // namespace grass
