// The Vulkan backend of a context: owns the patch buffers, density images, descriptor
// sets, per-frame buffers and pipelines, and records into the host's command buffers.
// It never submits, waits on a queue, or begins a render pass.
#pragma once

#include "backend.hpp"
#include "vk_debug_view.hpp"
#include "vk_deferred.hpp"
#include "vk_descriptors.hpp"
#include "vk_desc_check.hpp"
#include "vk_device.hpp"
#include "vk_frame_ring.hpp"
#include "vk_memory.hpp"
#include "vk_pipeline.hpp"
#include "vk_uploads.hpp"

#include <grass/grass_vk.h>

struct grass_context;

namespace grass::vk {

class VkBackend final : public Backend {
public:
    VkBackend(grass_context* context, const grass_vk_desc& vk_desc, const Device& device);
    ~VkBackend() override;
    VkBackend(const VkBackend&) = delete;
    VkBackend& operator=(const VkBackend&) = delete;

    // Creates the pipelines, the per-frame buffers and the default density map.
    grass_result init(const char* function);

    grass_backend kind() const override { return GRASS_BACKEND_VULKAN; }
    grass_result upload_patch(uint32_t slot, const PatchData& patch) override;
    void release_patch(uint32_t slot) override;
    grass_result upload_field(uint32_t slot, const MapTexels& density) override;
    void release_field(uint32_t slot) override;
    grass_result begin_frame(const FramePlan& plan) override;
    uint64_t gpu_bytes() const override { return memory_.bytes(); }

    // grass_vk_prepare_frame and grass_vk_record (arguments already checked).
    grass_result prepare_frame(VkCommandBuffer cmd);
    grass_result record(VkCommandBuffer cmd);

private:
    // A patch on the GPU: device-local vertex and index buffers, and until the upload is
    // recorded, the staging buffer holding vertices then indices.
    struct PatchGpu {
        bool live = false;
        bool pending = false;
        Buffer vertices;
        Buffer indices;
        Buffer staging;
        uint32_t index_count = 0;
    };
    // A field on the GPU: its density map (none: the default white texel is bound) and one
    // descriptor set per frame in flight (each points at its slot's uniform buffer).
    struct FieldGpu {
        bool live = false;
        bool pending = false;
        Image density;
        Buffer staging;
        DescriptorSet sets[kMaxFramesInFlight];
    };

    grass_result fail(const char* function, const char* what, const VkFailure& failure);
    // Points binding 0 and 1 of `set` at slot `slot`'s uniform buffer, and binding 2 at `view`.
    void write_set(VkDescriptorSet set, uint32_t slot, VkImageView view);
    // Creates a density image and a staging buffer holding `texels` for it.
    bool stage_image(Image* image, Buffer* staging, const MapTexels& texels, VkFailure* failure, const char** what);
    // Whether record() draws `draw`: normal frames draw the geometry tiers with their patch
    // (volume and image tiers: not yet), the debug view every draw of a live field.
    bool drawn(const TierDraw& draw, bool debug_view) const;
    // False when the draw reads data whose upload prepare_frame has not recorded yet;
    // *problem names it. The debug view reads no patch.
    bool draw_ready(const TierDraw& draw, bool debug_view, const char** problem) const;
    void destroy_patch_now(PatchGpu* patch);
    void destroy_field_now(FieldGpu* field);

    grass_context* ctx_;
    grass_vk_desc desc_;
    Device device_;
    const Functions& fn_;
    Memory memory_;
    DescriptorAllocator descriptors_;
    DeferredDeletion deferred_;
    BladePipeline pipeline_;
    DebugViewPipeline debug_view_; // after pipeline_: goes before the layout it uses
    FrameRing ring_;
    UploadBatch batch_;
    Vector<PatchGpu> patches_;
    Vector<FieldGpu> fields_;
    Image default_density_;      // 1x1 white: bound for fields without a density map
    Buffer default_staging_;
    uint32_t pending_uploads_ = 0; // patches, fields and the default map not yet recorded
    uint64_t frame_ = 0;           // frames begun; the current one while in a frame
    uint32_t slot_ = 0;            // frame_ % frames_in_flight
};

} // namespace grass::vk
