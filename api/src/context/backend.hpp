// The interface a GPU backend implements. The core calls it to upload and release
// assets; it never asks a backend what is visible. Drawing is started by the backend's
// own C entry point (grass_gl_render, grass_vk_record), which reads the context's plan.
#pragma once

#include "bake/baked_slices.hpp"
#include "foundation/frame_plan.hpp"
#include "patch/patch_data.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// The roles of a field's design maps (grass_map_stack). A shader variant samples the maps
// of the roles in its feature mask (bit = 1 << role) and no others; the texture bindings
// are those of api/shaders/blade_interface.glsl.
enum MapRole : uint32_t {
    kMapDensity = 0,
    kMapColor = 1,
    kMapAmbient = 2,
    kMapDiffuse = 3,
    kMapHeight = 4,
    kMapRoleCount = 5
};
constexpr uint32_t kMapBinding[kMapRoleCount] = {2, 6, 7, 8, 9};

// Feature bits of a draw past the map roles (TierDraw::features, GRASS_FEATURES in the
// shaders): responsive grass. A draw without them runs the shader of still grass.
constexpr uint32_t kFeatureWind = 1u << 5;        // wind or gravity: blades bend, slices sway (wind.glsl)
constexpr uint32_t kFeatureInteraction = 1u << 6; // the interaction map is bound (interaction.glsl)
constexpr uint32_t kFeatureWindMap = 1u << 7;     // the field's wind map is bound (wind.glsl); with kFeatureWind
// Per-blade culling (jahrmann2017 6.2, blade_culling.glsl): geometry draws only.
constexpr uint32_t kFeatureBladeCulling = 1u << 8;
// The features whose shaders are the responsive variants (GRASS_RESPONSIVE): they read the
// patch's blade control points (kBladeCurvesBinding) and the vertices per blade (trample.w).
// (kFeatureWindMap comes with kFeatureWind.)
constexpr uint32_t kBladeCurveFeatures = kFeatureWind | kFeatureInteraction | kFeatureBladeCulling;
// The frame draws a debug view that changes the grass's colour (kDebugViewFlags): only then
// do the shaders hold that code (GRASS_DEBUG_VIEW). A branch on a Frame value is not free:
// where the rasteriser cannot tell that all its lanes take the same side (lavapipe reads the
// blocks lane by lane), it runs both, and the threshold view's share (tier_blade_opacity)
// cost every volume hit a second transition interval (docs/records/tier-cost.md).
constexpr uint32_t kFeatureDebugView = 1u << 9;
constexpr uint32_t kDebugViewFlags = GRASS_VIEW_FLAG_DEBUG_TIERS | GRASS_VIEW_FLAG_DEBUG_THRESHOLDS;
// Every feature mask is below this (the variants a backend may compile).
constexpr uint32_t kFeatureMaskCount = kFeatureDebugView << 1;
// Bindings of responsive grass in the draw shaders (Vulkan set 0): the interaction map's
// levels (sampler2D, RGBA32F, read with texelFetch) and the patch's blade control points
// (readonly std430 buffer `BladeCurves`: PatchData::blade_curves).
constexpr uint32_t kInteractionMapBinding[2] = {10, 11};
constexpr uint32_t kBladeCurvesBinding = 12;
// The field's wind map (grass_set_field_wind_map): an RGBA design map, read with texelFetch.
constexpr uint32_t kWindMapBinding = 13;
constexpr uint32_t kNoMap = 0xffffffffu;

// A design map converted by the core to 16-bit unorm, row-major, tightly packed: width x
// channels values per row. Colour maps (4 channels) are already linear RGB + alpha.
struct MapTexels {
    const uint16_t* texels = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 1; // 1 or 4
};

// A rectangle of texels of a map.
struct MapRegion {
    uint32_t x = 0, y = 0, width = 0, height = 0;
};

// The maps a field samples: the map slot of each role (kNoMap: none) and the feature mask.
struct FieldMaps {
    uint32_t map_slot[kMapRoleCount] = {kNoMap, kNoMap, kNoMap, kNoMap, kNoMap};
    uint32_t features = 0; // bit r set <=> map_slot[r] != kNoMap
};

class Backend {
public:
    virtual ~Backend() = default;
    virtual grass_backend kind() const = 0;

    // Slots are the index of the object in its pool; a slot is released before reuse.
    virtual grass_result upload_patch(uint32_t slot, const PatchData& patch) = 0;
    // A baked slice set of the patch in `slot` (after upload_patch): the vertical slices of a
    // volume tier (set.slices_per_axis = N >= 1) or the horizontal slice (N = 0). Each N is
    // uploaded once per patch; draws of kind VOLUME use the set with their `slices`, draws of
    // kind IMAGE the set with N = 0. release_patch releases them with the patch.
    virtual grass_result upload_slices(uint32_t slot, const SliceSet& set) = 0;
    virtual void release_patch(uint32_t slot) = 0;
    // Responsive grass: the blade control points of the patch in `slot` (patch.blade_curves),
    // uploaded by the core before the first frame that draws the patch with kFeatureWind or
    // kFeatureInteraction, once per patch (released with the patch). A context that never
    // draws responsive grass never calls it, so it holds no such memory.
    virtual grass_result upload_blade_curves(uint32_t slot, const PatchData& patch) {
        (void)slot;
        (void)patch;
        return GRASS_SUCCESS;
    }
    // A design map (slot in the context's map pool). Fields reference maps by slot; a map is
    // released only when no field uses it.
    virtual grass_result upload_map(uint32_t slot, const MapTexels& map) = 0;
    // The texels of `region` changed; `map` is the core's whole, updated copy. GL copies at
    // once; Vulkan records the copy in the next prepare_frame, before any draw that reads it.
    virtual grass_result update_map(uint32_t slot, const MapTexels& map, const MapRegion& region) = 0;
    virtual void release_map(uint32_t slot) = 0;
    // A field and the maps it samples (already uploaded).
    virtual grass_result upload_field(uint32_t slot, const FieldMaps& maps) = 0;
    virtual void release_field(uint32_t slot) = 0;
    // Responsive grass: the wind map of the field in `slot` (a map slot, already uploaded, or
    // kNoMap: none). Draws of the field with kFeatureWindMap bind it; no other draw does.
    virtual void set_field_wind_map(uint32_t slot, uint32_t map_slot) {
        (void)slot;
        (void)map_slot;
    }

    // Called by grass_begin_frame after the plan is built.
    virtual grass_result begin_frame(const FramePlan& plan) = 0;
    virtual void end_frame() {}

    virtual uint64_t gpu_bytes() const = 0;
    // The part of gpu_bytes() that responsive grass holds: the interaction map's levels and
    // the uploaded blade curves (grass_memory_stats.dynamics_gpu_bytes).
    virtual uint64_t dynamics_gpu_bytes() const { return 0; }

    // grass_get_tier_gpu_ms: the GPU milliseconds of each tier kind in the most recent frame
    // whose timer queries have finished, read without waiting (a backend may poll its
    // queries here). False, with zeros, where the device has no timer queries or no timed
    // frame has finished yet.
    virtual bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) {
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = 0.0;
        return false;
    }

    // Whether the GPU context this backend was made with is current on the calling thread
    // (GL: grass_gl.h; a Vulkan device needs no such thing). Otherwise logs the refusal of
    // `function` and returns its error, having made no GPU call.
    virtual grass_result check_current(const char* function) {
        (void)function;
        return GRASS_SUCCESS;
    }
    // The context is destroyed while its GPU context is not current: the backend releases
    // no GPU object (they go with the GPU context) and frees only host memory.
    void abandon() { abandoned_ = true; }
    bool abandoned() const { return abandoned_; }

private:
    bool abandoned_ = false;
};

// The backend of a context made by grass_create_context(): holds nothing, draws nothing.
class NullBackend final : public Backend {
public:
    grass_backend kind() const override { return GRASS_BACKEND_NONE; }
    grass_result upload_patch(uint32_t, const PatchData&) override { return GRASS_SUCCESS; }
    grass_result upload_slices(uint32_t, const SliceSet&) override { return GRASS_SUCCESS; }
    void release_patch(uint32_t) override {}
    grass_result upload_map(uint32_t, const MapTexels&) override { return GRASS_SUCCESS; }
    grass_result update_map(uint32_t, const MapTexels&, const MapRegion&) override { return GRASS_SUCCESS; }
    void release_map(uint32_t) override {}
    grass_result upload_field(uint32_t, const FieldMaps&) override { return GRASS_SUCCESS; }
    void release_field(uint32_t) override {}
    grass_result begin_frame(const FramePlan&) override { return GRASS_SUCCESS; }
    uint64_t gpu_bytes() const override { return 0; }
    // tier_gpu_ms: the default (no GPU, no timings).
};

} // namespace grass
