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

// The feature bits (kFeatureWind ..., and the view bits kFeatureDepthPass ...
// kFeatureGBuffer) a grass_pipeline_desc.features declares.
uint32_t declared_feature_bits(uint32_t pipeline_features);

// The bits of `declared` that name a view of an engine's frame (kViewModeBits), less those the
// context cannot draw into `target` (a view it would refuse: grass_begin_frame's check_views):
// the depth pass without a depth target; receiving, motion, lights and G-buffer views in a
// multiview pass; on Vulkan (`fixed_targets`: pipelines made for the context's targets)
// motion without a velocity target and G-buffer views without a G-buffer target. GL draws
// into whatever framebuffer is bound and drops only what a multiview pass would.
constexpr uint32_t kViewModeBits =
    kFeatureDepthPass | kFeatureShadowReceive | kFeatureMotion | kFeatureHostLights | kFeatureGBuffer;
uint32_t drawable_view_bits(uint32_t declared, const RenderTarget& target, bool fixed_targets);

// Where a G-buffer view's outputs go (FramePlan::gbuffer_attachment and gbuffer_mask): per
// output location (kGBufferOutput) the host's attachment (kNoGBufferOutput: none) and its
// write mask. Vulkan makes a G-buffer view's pipelines per layout; GL programs ignore it.
struct GBufferLayout {
    uint32_t attachment[kGBufferOutputs] = {kNoGBufferOutput, kNoGBufferOutput, kNoGBufferOutput, kNoGBufferOutput};
    uint32_t mask[kGBufferOutputs] = {0, 0, 0, 0};
    bool operator==(const GBufferLayout& o) const;
};

// The view modes (the bits a view adds to every draw of its plan) that the view bits `views`
// (drawable_view_bits) bring: always 0, a plain colour view; kFeatureDepthPass; each
// non-empty combination of kFeatureShadowReceive, kFeatureMotion and kFeatureHostLights
// (one view may have all three). G-buffer views are not here: their mode comes with a
// layout (gbuffer_view_mode). Writes at most kMaxViewModes; returns how many.
constexpr uint32_t kMaxViewModes = 9;
uint32_t view_modes(uint32_t views, uint32_t out[kMaxViewModes]);

// The mode of a G-buffer view of `layout`: kFeatureGBuffer, with kFeatureMotion where the
// layout has a velocity attachment (such a view needs a grass_view_motion_desc, and a view
// without one writes no motion vectors).
uint32_t gbuffer_view_mode(const GBufferLayout& layout);

// Whether `variant` may draw without the depth test (GRASS_VIEW_FLAG_NO_DEPTH_TEST): a
// colour view's; a depth pass and a G-buffer view keep the test (check_pass).
inline bool takes_no_depth_test(const ShaderVariant& variant) {
    return (variant.features & (kFeatureDepthPass | kFeatureGBuffer)) == 0;
}

// Whether the host that declared `declared` (declared_feature_bits) may draw frames with
// GRASS_VIEW_FLAG_NO_DEPTH_TEST: a debugging flag, declared with the debug views
// (GRASS_PIPELINE_FEATURE_DEBUG_VIEWS). A backend whose pipelines fix the depth test (Vulkan)
// then makes each prepared variant without it too; otherwise the first frame that sets the
// flag does.
inline bool declares_no_depth_test(uint32_t declared) { return (declared & kFeatureDebugView) != 0; }

// Every variant the draws of a field whose maps give `map_features` and whose tiers are of
// the kinds in `tier_kinds` (bit = 1 << grass_tier_kind) may run in a view of one of the
// `modes` (view_modes, gbuffer_view_mode) while the host uses at most `declared`
// (declared_feature_bits; its view bits are ignored here): each subset of the declared bits
// that a frame can plan (kFeatureWindMap only with kFeatureWind, kFeatureBladeCulling on
// geometry only, kFeatureDebugView in a colour view only), with each mode, for the program
// of each of its tier kinds, and the debug boxes with kFeatureDebugView where a mode is a
// colour view's. Writes at most kMaxFieldVariants; returns how many. All declared, with the
// 9 modes of view_modes: 409 variants; a G-buffer mode adds 24.
constexpr uint32_t kMaxFieldVariants = 512;
uint32_t field_variants(uint32_t declared, const uint32_t* modes, uint32_t mode_count, uint32_t map_features,
                        uint32_t tier_kinds, ShaderVariant out[kMaxFieldVariants]);

// The blade window's variants (kFeatureBladeWindow) of the responsive blade variants among
// the `count` of `variants`, for a backend that runs the window pass: written to `out`
// (at most kMaxFieldVariants); returns how many.
uint32_t blade_window_variants(const ShaderVariant* variants, uint32_t count, ShaderVariant out[kMaxFieldVariants]);

} // namespace grass
