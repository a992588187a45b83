// The shader variants a draw runs and the set grass_prepare_pipelines compiles: the one place
// that says which program and feature mask a draw needs (draw_variant, both backends pick
// their pipeline or program with it) and which masks a host's grass_pipeline_desc implies
// for a field (field_variants). A variant is a program (blade, volume, image, debug boxes)
// and a feature mask (shader_interface.hpp); the render target is no part of it (Vulkan:
// fixed per context by grass_vk_desc; GL: programs do not depend on it).
#pragma once

#include "foundation/frame_plan.hpp"
#include "foundation/shader_interface.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// The programs of both backends (GL programs, Vulkan pipeline kinds), in this order.
enum ShaderProgram : uint32_t {
    kShaderBlades = 0,     // blade.vert + blade.frag: geometry tiers
    kShaderVolume = 1,     // volume.*: volume tiers
    kShaderImage = 2,      // image.*: image tiers
    kShaderDebugBoxes = 3, // debug_tiers.*: every draw under GRASS_VIEW_FLAG_DEBUG_CELLS
    kShaderProgramCount = 4
};

struct ShaderVariant {
    ShaderProgram program = kShaderBlades;
    uint32_t features = 0; // < kFeatureMaskCount
    bool operator==(const ShaderVariant& o) const { return program == o.program && features == o.features; }
};

// The variant `draw` runs in a frame whose view flags are `view_flags`: the debug boxes
// sample the height map alone, so only that bit of their mask counts.
ShaderVariant draw_variant(const TierDraw& draw, uint32_t view_flags);

// The feature bits (kFeatureWind ...) a grass_pipeline_desc.features declares.
uint32_t declared_feature_bits(uint32_t pipeline_features);

// Whether the host that declared `declared` (declared_feature_bits) may draw frames with
// GRASS_VIEW_FLAG_NO_DEPTH_TEST: a debugging flag, declared with the debug views
// (GRASS_PIPELINE_FEATURE_DEBUG_VIEWS). A backend whose pipelines fix the depth test (Vulkan)
// then makes each prepared variant without it too; otherwise the first frame that sets the
// flag does.
inline bool declares_no_depth_test(uint32_t declared) { return (declared & kFeatureDebugView) != 0; }

// Every variant the draws of a field whose maps give `map_features` and whose tiers are of
// the kinds in `tier_kinds` (bit = 1 << grass_tier_kind) may run while the host uses at most
// `declared` (declared_feature_bits): each subset of the declared bits that a frame can plan
// (kFeatureWindMap only with kFeatureWind, kFeatureBladeCulling on geometry only), for the
// program of each of its tier kinds, and the debug boxes with kFeatureDebugView. Writes at
// most kMaxFieldVariants; returns how many.
constexpr uint32_t kMaxFieldVariants = 64;
uint32_t field_variants(uint32_t declared, uint32_t map_features, uint32_t tier_kinds,
                        ShaderVariant out[kMaxFieldVariants]);

} // namespace grass
