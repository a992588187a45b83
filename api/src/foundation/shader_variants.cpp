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
    if (pipeline_features & GRASS_PIPELINE_FEATURE_DEPTH_PASS) bits |= kFeatureDepthPass;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_SHADOW_RECEIVE) bits |= kFeatureShadowReceive;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_MOTION_VECTORS) bits |= kFeatureMotion;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_HOST_LIGHTS) bits |= kFeatureHostLights;
    if (pipeline_features & GRASS_PIPELINE_FEATURE_GBUFFER) bits |= kFeatureGBuffer;
    return bits;
}

uint32_t drawable_view_bits(uint32_t declared, const RenderTarget& target, bool fixed_targets) {
    uint32_t views = declared & kViewModeBits;
    if (!target.depth_pass) views &= ~kFeatureDepthPass;
    if (target.views != 1) views &= kFeatureDepthPass;
    if (fixed_targets && target.velocity_attachment == 0) views &= ~kFeatureMotion;
    if (fixed_targets && target.gbuffer_attachments == 0) views &= ~kFeatureGBuffer;
    return views;
}

bool GBufferLayout::operator==(const GBufferLayout& o) const {
    for (uint32_t i = 0; i < kGBufferOutputs; ++i) {
        if (attachment[i] != o.attachment[i] || mask[i] != o.mask[i]) return false;
    }
    return true;
}

uint32_t view_modes(uint32_t views, uint32_t out[kMaxViewModes]) {
    uint32_t count = 0;
    out[count++] = 0;
    if (views & kFeatureDepthPass) out[count++] = kFeatureDepthPass;
    constexpr uint32_t kExtras[] = {kFeatureShadowReceive, kFeatureMotion, kFeatureHostLights};
    for (uint32_t subset = 1; subset < 8; ++subset) {
        uint32_t mode = 0;
        for (uint32_t b = 0; b < 3; ++b) {
            if ((subset >> b) & 1u) mode |= kExtras[b];
        }
        if ((mode & views) == mode) out[count++] = mode;
    }
    return count;
}

uint32_t gbuffer_view_mode(const GBufferLayout& layout) {
    const bool velocity = layout.attachment[kGBufferOutput[GRASS_GBUFFER_VELOCITY]] != kNoGBufferOutput;
    return kFeatureGBuffer | (velocity ? kFeatureMotion : 0u);
}

uint32_t field_variants(uint32_t declared, const uint32_t* modes, uint32_t mode_count, uint32_t map_features,
                        uint32_t tier_kinds, ShaderVariant out[kMaxFieldVariants]) {
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
        for (uint32_t m = 0; m < mode_count; ++m) {
            // A depth pass and a G-buffer view take no debug view (check_pass).
            if ((bits & kFeatureDebugView) && (modes[m] & (kFeatureDepthPass | kFeatureGBuffer))) continue;
            const uint32_t features = map_features | bits | modes[m];
            if (tier_kinds & (1u << GRASS_TIER_GEOMETRY)) add(kShaderBlades, features);
            if (bits & kFeatureBladeCulling) continue; // geometry draws only
            if (tier_kinds & (1u << GRASS_TIER_VOLUME)) add(kShaderVolume, features);
            if (tier_kinds & (1u << GRASS_TIER_IMAGE)) add(kShaderImage, features);
        }
    }
    // Debug boxes: under GRASS_VIEW_FLAG_DEBUG_CELLS, whatever else a colour view does.
    bool colour = false;
    for (uint32_t m = 0; m < mode_count; ++m)
        colour = colour || (modes[m] & (kFeatureDepthPass | kFeatureGBuffer)) == 0;
    if ((declared & kFeatureDebugView) && colour) add(kShaderDebugBoxes, map_features & kDebugBoxFeatures);
    return count;
}

uint32_t blade_window_variants(const ShaderVariant* variants, uint32_t count, ShaderVariant out[kMaxFieldVariants]) {
    uint32_t written = 0;
    for (uint32_t i = 0; i < count && written < kMaxFieldVariants; ++i) {
        const ShaderVariant& v = variants[i];
        if (v.program != kShaderBlades || (v.features & (kFeatureWind | kFeatureInteraction)) == 0) continue;
        out[written++] = ShaderVariant{v.program, v.features | kFeatureBladeWindow};
    }
    return written;
}

} // namespace grass
