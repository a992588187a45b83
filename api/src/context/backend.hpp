// The backend interface: what a GPU backend implements. The core calls it to upload and
// release assets and to hand over each frame's plan; it never asks a backend what is
// visible, and a backend decides nothing about a draw (the plan's TierDraw carries its
// vertex count and complete uniforms). Drawing is started by the backend's own C entry
// point (grass_gl_render, grass_vk_record), which reads the context's plan. What the
// shaders and the C++ side agree on (map roles, feature bits, bindings, vertex counts) is
// the shader interface, foundation/shader_interface.hpp.
//
// Every method is required (pure virtual), responsive grass's included: a backend that
// does not implement one does not compile, rather than silently drawing still grass.
#pragma once

#include "bake/baked_slices.hpp"
#include "context/frame_views.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"
#include "patch/patch_data.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

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
    virtual grass_result upload_blade_curves(uint32_t slot, const PatchData& patch) = 0;
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
    virtual void set_field_wind_map(uint32_t slot, uint32_t map_slot) = 0;

    // Pipelines before the first frame (grass_prepare_pipelines): makes every variant of
    // `variants` not made yet, and the interaction pass's when `interaction_pass`; outside
    // a frame. With `no_depth_test` (declares_no_depth_test) a backend whose pipelines fix
    // the depth test (Vulkan) also makes each variant's pipeline for
    // GRASS_VIEW_FLAG_NO_DEPTH_TEST (the variants that take it: takes_no_depth_test); GL
    // toggles the test and ignores it. The kFeatureGBuffer variants among `variants` are
    // made for `gbuffer` (a layout the host declared; nullptr where there are none): Vulkan
    // makes G-buffer pipelines per layout, GL ignores it. `function` names the public call
    // for messages.
    virtual grass_result prepare_variants(const char* function, const ShaderVariant* variants, uint32_t count,
                                          bool interaction_pass, bool no_depth_test, const GBufferLayout* gbuffer) = 0;
    // Seeds the backend's own cache with a blob (grass_pipeline_desc.cache_data, size > 0):
    // one that does not fit is ignored with a GRASS_MSG_PIPELINE_CACHE warning.
    virtual grass_result seed_pipeline_cache(const char* function, const void* data, uint64_t size) = 0;
    // grass_get_pipeline_cache_data (arguments checked; *size > 0 when data is given).
    virtual grass_result pipeline_cache_data(const char* function, void* data, uint64_t* size) = 0;

    // The host's render target as the shaders must know it (frame_plan.hpp): its samples per
    // pixel and its clip convention. grass_begin_frame writes it into the plan's Frame block
    // (write_render_target); the core never guesses it from kind(). A backend whose host may
    // draw one frame into several targets (GL: the bound framebuffer and glClipControl, read
    // at each grass_gl_render) reports the one it last drew into and writes its copy of the
    // Frame block again with write_render_target when the host's current one differs.
    virtual RenderTarget render_target() const = 0;

    // Frames and views (grass.h): the host's frame `frame` begins (grass_begin_host_frame,
    // grass_begin_frame), and the host reports every frame up to frame.completed finished; with
    // `implied` (grass_begin_frame) also every frame up to frames_in_flight before this one. A
    // backend may refuse a frame whose resources are still in use (nothing changes then).
    virtual grass_result begin_host_frame(const char* function, const HostFrame& frame, bool implied) = 0;
    // View `view` of the begun frame is planned into `plan` (context->views.plan(view), kept
    // unchanged until the frame ends): the backend takes what it needs of it (Vulkan writes it
    // into the view's own per-frame buffers).
    virtual grass_result begin_view(const char* function, uint32_t view, const FramePlan& plan) = 0;
    virtual void end_frame() = 0;

    virtual uint64_t gpu_bytes() const = 0;
    // Responsive grass: the part of gpu_bytes() that it holds: the interaction map's levels
    // and the uploaded blade curves (grass_memory_stats.dynamics_gpu_bytes).
    virtual uint64_t dynamics_gpu_bytes() const = 0;
    // Whether it runs the blade window pass (plan/blade_window.hpp) of view 0's plan and
    // its responsive geometry draws read the window: the core plans one only then.
    virtual bool runs_blade_window() const = 0;
    // Whether its window variant draws only the blades each view draws, compacted by a
    // pass before the view's geometry draws into indirect draws (docs/responsive.md "Culled
    // blades compacted"): the core then marks the frame's plans (FramePlan::
    // compact_blade_window). A backend without it draws every blade of a window draw.
    virtual bool compacts_blade_window() const { return false; }
    // The device memory per heap (grass_memory_stats from heap_count on); a backend that
    // cannot tell leaves them 0.
    virtual void device_memory(grass_memory_stats* stats) const { (void)stats; }

    // grass_get_tier_gpu_ms: the GPU milliseconds of each tier kind in the most recent frame
    // whose timer queries have finished, read without waiting (a backend may poll its
    // queries here). False, with zeros, where the device has no timer queries or no timed
    // frame has finished yet.
    virtual bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) = 0;

    // Whether the GPU context this backend was made with is current on the calling thread
    // (GL: grass_gl.h; a Vulkan device needs no such thing: success). Otherwise logs the
    // refusal of `function` and returns its error, having made no GPU call.
    virtual grass_result check_current(const char* function) = 0;
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
    grass_result upload_blade_curves(uint32_t, const PatchData&) override { return GRASS_SUCCESS; }
    grass_result upload_map(uint32_t, const MapTexels&) override { return GRASS_SUCCESS; }
    grass_result update_map(uint32_t, const MapTexels&, const MapRegion&) override { return GRASS_SUCCESS; }
    void release_map(uint32_t) override {}
    grass_result upload_field(uint32_t, const FieldMaps&) override { return GRASS_SUCCESS; }
    void release_field(uint32_t) override {}
    void set_field_wind_map(uint32_t, uint32_t) override {}
    grass_result prepare_variants(const char*, const ShaderVariant*, uint32_t, bool, bool,
                                  const GBufferLayout*) override {
        return GRASS_SUCCESS;
    }
    grass_result seed_pipeline_cache(const char*, const void*, uint64_t) override { return GRASS_SUCCESS; }
    grass_result pipeline_cache_data(const char*, void*, uint64_t* size) override { // no cache: 0 bytes
        *size = 0;
        return GRASS_SUCCESS;
    }
    RenderTarget render_target() const override { return RenderTarget{}; } // none: the defaults
    grass_result begin_host_frame(const char*, const HostFrame&, bool) override { return GRASS_SUCCESS; }
    grass_result begin_view(const char*, uint32_t, const FramePlan&) override { return GRASS_SUCCESS; }
    void end_frame() override {}
    uint64_t gpu_bytes() const override { return 0; }
    uint64_t dynamics_gpu_bytes() const override { return 0; }
    bool runs_blade_window() const override { return false; }
    bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) override { // no GPU, no timings
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = 0.0;
        return false;
    }
    grass_result check_current(const char*) override { return GRASS_SUCCESS; } // no GPU context
};

} // namespace grass
