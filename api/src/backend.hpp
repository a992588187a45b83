// The interface a GPU backend implements. The core calls it to upload and release
// assets; it never asks a backend what is visible. Drawing is started by the backend's
// own C entry point (grass_gl_render, grass_vk_record), which reads the context's plan.
#pragma once

#include "baked_slices.hpp"
#include "frame_plan.hpp"
#include "patch_data.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// A design map converted by the core to 16-bit unorm, row-major, tightly packed.
struct MapTexels {
    const uint16_t* texels = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
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
    // `density` has texels == nullptr when the field has no density map.
    virtual grass_result upload_field(uint32_t slot, const MapTexels& density) = 0;
    virtual void release_field(uint32_t slot) = 0;

    // Called by grass_begin_frame after the plan is built.
    virtual grass_result begin_frame(const FramePlan& plan) = 0;
    virtual void end_frame() {}

    virtual uint64_t gpu_bytes() const = 0;
};

// The backend of a context made by grass_create_context(): holds nothing, draws nothing.
class NullBackend final : public Backend {
public:
    grass_backend kind() const override { return GRASS_BACKEND_NONE; }
    grass_result upload_patch(uint32_t, const PatchData&) override { return GRASS_SUCCESS; }
    grass_result upload_slices(uint32_t, const SliceSet&) override { return GRASS_SUCCESS; }
    void release_patch(uint32_t) override {}
    grass_result upload_field(uint32_t, const MapTexels&) override { return GRASS_SUCCESS; }
    void release_field(uint32_t) override {}
    grass_result begin_frame(const FramePlan&) override { return GRASS_SUCCESS; }
    uint64_t gpu_bytes() const override { return 0; }
};

} // namespace grass
