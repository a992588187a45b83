// The Vulkan backend of a context: owns the patch buffers, baked slice images, design map
// images, descriptor sets, per-frame buffers and pipelines, and records into the host's
// command buffers.
// It never submits, waits on a queue, or begins a render pass.
#pragma once

#include "context/backend.hpp"
#include "timing/tier_timer_ring.hpp"
#include "vk_blade_window.hpp"
#include "vk_debug_view.hpp"
#include "vk_deferred.hpp"
#include "vk_desc_check.hpp"
#include "vk_descriptors.hpp"
#include "vk_device.hpp"
#include "vk_frame_ring.hpp"
#include "vk_interaction.hpp"
#include "vk_memory.hpp"
#include "vk_pipeline.hpp"
#include "vk_slice_pipelines.hpp"
#include "vk_uploads.hpp"
#include "vk_view_extras_sets.hpp"

#include <grass/grass_vk.h>

struct grass_context;

namespace grass::vk {

class VkBackend final : public Backend {
public:
    VkBackend(grass_context* context, const grass_vk_desc& vk_desc, const Device& device);
    ~VkBackend() override;
    VkBackend(const VkBackend&) = delete;
    VkBackend& operator=(const VkBackend&) = delete;

    // Creates the pipelines, the per-frame buffers and the default map images.
    grass_result init(const char* function);

    grass_backend kind() const override { return GRASS_BACKEND_VULKAN; }
    grass_result upload_patch(uint32_t slot, const PatchData& patch) override;
    grass_result upload_slices(uint32_t slot, const SliceSet& set) override;
    void release_patch(uint32_t slot) override;
    grass_result upload_blade_curves(uint32_t slot, const PatchData& patch) override;
    grass_result upload_map(uint32_t slot, const MapTexels& map) override;
    grass_result update_map(uint32_t slot, const MapTexels& map, const MapRegion& region) override;
    void release_map(uint32_t slot) override;
    grass_result upload_field(uint32_t slot, const FieldMaps& maps) override;
    void release_field(uint32_t slot) override;
    void set_field_wind_map(uint32_t slot, uint32_t map_slot) override;
    // vk_pipeline_cache.cpp: grass_prepare_pipelines and the pipeline cache.
    grass_result prepare_variants(const char* function, const ShaderVariant* variants, uint32_t count,
                                  bool interaction_pass, bool no_depth_test, const GBufferLayout* gbuffer) override;
    grass_result seed_pipeline_cache(const char* function, const void* data, uint64_t size) override;
    grass_result pipeline_cache_data(const char* function, void* data, uint64_t* size) override;
    // The render pass's sample count (grass_vk_desc) and Vulkan's one clip convention, 0..1;
    // the depth-only target, when the host gave one (grass_vk_depth_pass_desc).
    RenderTarget render_target() const override {
        RenderTarget target;
        target.samples = desc_.sample_count;
        target.clip_zero_to_one = true;
        target.views = device_.view_mask != 0 ? 2u : 1u; // view_mask is 0 or 0x3 (check_vk_desc)
        target.depth_pass = device_.has_depth_pass;      // grass_vk_depth_pass_desc: depth views draw
        target.depth_pass_samples = device_.has_depth_pass ? device_.depth_pass.sample_count : 0;
        target.velocity_attachment = device_.has_velocity ? device_.velocity.velocity_attachment : 0;
        target.gbuffer_attachments = device_.has_gbuffer ? device_.gbuffer.color_attachment_count : 0;
        return target;
    }
    grass_result begin_host_frame(const char* function, const HostFrame& frame, bool implied) override;
    grass_result begin_view(const char* function, uint32_t view, const FramePlan& plan) override;
    void end_frame() override {} // the host submits: a frame ends with nothing to do here
    uint64_t gpu_bytes() const override { return memory_.bytes(); }
    uint64_t dynamics_gpu_bytes() const override;
    // The blade window pass (vk_blade_window.hpp): recorded by grass_vk_prepare.
    // The pass needs kWindowPassStorageBuffers storage buffers in its compute stage.
    bool runs_blade_window() const override {
        return device_.properties.limits.maxPerStageDescriptorStorageBuffers >= kWindowPassStorageBuffers;
    }
    void device_memory(grass_memory_stats* stats) const override;
    bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) override;
    // A Vulkan device is not current on a thread: every call may use it.
    grass_result check_current(const char*) override { return GRASS_SUCCESS; }

    // grass_vk_prepare and grass_vk_record (arguments already checked).
    grass_result prepare_frame(VkCommandBuffer cmd);
    grass_result record(const char* function, VkCommandBuffer cmd, uint32_t view);

private:
    // A patch on the GPU: device-local vertex and index buffers, and until the upload is
    // recorded, the staging buffer holding vertices then indices. Responsive grass: the
    // blade control points (a device-local storage buffer, binding 12), made by
    // upload_blade_curves, with their own staging buffer until their copy is recorded.
    struct PatchGpu {
        bool live = false;
        bool pending = false;
        bool curves_pending = false;
        Buffer vertices;
        Buffer indices;
        Buffer staging;
        Buffer curves;
        Buffer curves_staging;
        uint32_t index_count = 0;
    };
    // A baked slice set of a patch on the GPU (api/src/baked_slices.hpp): three device-local
    // 2D array images with full mip chains, and until the upload is recorded, the staging
    // buffer holding colour, normal then threshold texels (see slice_staging_layout()).
    // No images: an empty set, nothing to draw.
    struct SliceGpu {
        uint32_t patch_slot = 0;
        uint32_t slices_per_axis = 0; // N; 0 = the horizontal slice
        bool pending = false;
        Image color;
        Image normal;
        Image threshold;
        Buffer staging;
    };
    // A design map on the GPU: a single-mip R16 or R16G16B16A16 unorm image. Until its
    // first copy is recorded, `staging` holds every texel (pending); afterwards an update
    // stages the changed rectangle `update` in `update_staging` (updating) until the next
    // prepare_frame records its copy. Updates before that merge into one rectangle.
    struct MapGpu {
        bool live = false;
        bool pending = false;
        bool updating = false;
        uint32_t channels = 1;
        Image image;
        Buffer staging;
        Buffer update_staging;
        MapRegion update;
    };
    // A field on the GPU: the map slot of each role (kNoMap: the role's default image is
    // bound), its feature mask, and one descriptor set per view slot (each points at its
    // slot's uniform buffer).
    struct FieldGpu {
        bool live = false;
        uint32_t features = 0;
        uint32_t map_slot[kMapRoleCount] = {kNoMap, kNoMap, kNoMap, kNoMap, kNoMap};
        uint32_t wind_map = kNoMap;        // responsive grass: bound by its draws with kFeatureWindMap
        DescriptorSet sets[kMaxViewSlots]; // per view slot (view_slot()), made for the views made so far
    };

    // Timer queries (vk_timers.cpp): one timestamp query per stamp of the core's ring
    // (timing/tier_timer_ring.hpp) of frames_in_flight sets; a frame's range is reset by
    // prepare_frame (outside the pass) and each record of the frame is one pass of it.
    void create_timers(); // no pool where the queue family has no timestamps
    // The first query of this record's stamps, or TierTimerRing::kUntimed.
    uint32_t timer_stamps();
    void write_stamp(VkCommandBuffer cmd, uint32_t first, uint32_t stamp);
    // Reads the finished sets without waiting (TierTimerRing::collect).
    void collect_timers();

    grass_result fail(const char* function, const char* what, const VkFailure& failure);
    // The cache every pipeline goes through: the host's, or one of grass's own (init).
    bool create_pipeline_cache(VkFailure* failure, const char** what);
    void destroy_pipeline_cache();
    // What a set binds besides the uniforms and the field's maps: the slices of a volume or
    // image draw (bindings 3-5) and responsive grass (bindings 10-15).
    struct SetViews {
        VkImageView slices[3];
        VkImageView interaction[2];
        VkImageLayout interaction_layout;
        VkBuffer curves;
        VkImageView wind_map;
        VkBuffer window_table; // the blade window's (kFeatureBladeWindow and its pass)
        VkBuffer window_poses;
    };
    // The stand-ins of a draw that samples no slices and is not responsive: the default
    // slice image, the default black map for the interaction levels, the 16-byte
    // default curves buffer (for the blade window's table and poses too). The shaders of
    // such a draw never read them.
    SetViews still_views() const;
    // What draw `d` binds: its slices, the interaction map's levels (kFeatureInteraction),
    // its patch's blade curves (once uploaded), the blade window's table and poses
    // (kFeatureBladeWindow); the stand-ins for the rest.
    SetViews draw_views(const TierDraw& d) const;
    // Whether `d` needs a set of its own this frame (record()): volume and image draws (the
    // field's maps with the patch's slices) and responsive draws (its patch's curves).
    static bool own_set(const TierDraw& d);
    // Points binding 0 and 1 of `set` at slot `slot`'s uniform buffer, the map bindings
    // (kMapBinding) at the maps of `field` (or the defaults), and the rest at `views`.
    void write_set(VkDescriptorSet set, uint32_t slot, const FieldGpu& field, const SetViews& views);
    // The image a field's sets bind for `role`: its map or the role's default.
    VkImageView map_view(const FieldGpu& field, uint32_t role) const;
    // Creates a map image (R16 or R16G16B16A16 unorm by texels.channels) and a staging
    // buffer holding `texels` for it.
    bool stage_image(Image* image, Buffer* staging, const MapTexels& texels, VkFailure* failure, const char** what);
    // Creates a staging buffer holding the texels of `region` of `map`, rows tightly packed.
    bool stage_region(Buffer* staging, const MapTexels& map, const MapRegion& region, VkFailure* failure);
    // Whether record() draws `draw`: normal frames draw every tier of a live field with a
    // live, non-empty patch, the debug view every draw of a live field.
    bool drawn(const TierDraw& draw, bool debug_view) const;
    // The slice set a volume or image draw samples (nullptr: never uploaded).
    const SliceGpu* draw_slices(const TierDraw& draw) const;
    SliceGpu* find_slices(uint32_t patch_slot, uint32_t slices_per_axis);
    // False when the draw reads data whose upload prepare_frame has not recorded yet;
    // *problem names it. The debug view reads no patch.
    bool draw_ready(const TierDraw& draw, bool debug_view, const char** problem) const;
    // prepare_frame: the copies of every pending upload, with their barriers.
    void record_uploads(VkCommandBuffer cmd);
    // vk_blade_window.cpp: view 0 begins: the window's pipelines and buffers for `plan`
    // (none: released), and the pass pending; prepare_frame records it after the
    // interaction pass, one dispatch per draw of the plan's window with sets of this frame.
    bool prepare_blade_window(const FramePlan& plan, VkFailure* failure, const char** what);
    grass_result record_blade_window(VkCommandBuffer cmd);
    void destroy_patch_now(PatchGpu* patch);
    void destroy_slices_now(SliceGpu* slices);
    // Retires the images of `slices` (frames in flight may sample them) and drops its staging.
    void release_slices(SliceGpu* slices);
    void destroy_field_now(FieldGpu* field);
    // The descriptor sets of `field` for `view` in every frame slot (those not made yet).
    bool make_field_sets(FieldGpu* field, uint32_t view, VkFailure* failure);
    // The per-frame buffers and field sets of every view up to `view`, made on first use:
    // a host that plans one view a frame holds view 0's only.
    bool make_view_slots(uint32_t view, VkFailure* failure, const char** what);
    void destroy_map_now(MapGpu* map);

    grass_context* ctx_;
    grass_vk_desc desc_;
    Device device_;
    const Functions& fn_;
    Memory memory_;
    DescriptorAllocator descriptors_;
    FrameDescriptors frame_sets_; // the volume and image draws' sets, written per frame
    DeferredDeletion deferred_;
    VkPipelineCache cache_ = VK_NULL_HANDLE;     // the host's (grass_vk_host_objects_desc.pipeline_cache) or own_cache_
    VkPipelineCache own_cache_ = VK_NULL_HANDLE; // grass's own, when the host gave none
    BladePipeline pipeline_;
    ViewExtrasSets extras_; // views that receive shadows, write motion vectors or are lit: set 1 per view slot
    FrameRing ring_;
    UploadBatch batch_;
    Vector<PatchGpu> patches_;
    Vector<FieldGpu> fields_;
    Vector<MapGpu> maps_;
    Vector<SliceGpu> slices_;           // every patch's slice sets, in no order
    Vector<VkDescriptorSet> draw_sets_; // record(): the set of each volume and image draw
    Vector<VkBufferImageCopy> regions_; // prepare_frame(): scratch for slice copies
    Image default_white_;               // 1x1 white R16: density, ambient and diffuse of fields without them
    Buffer default_white_staging_;
    Image default_black_; // 1x1 transparent black RGBA16 (R16 where the device lacks it): colour, height
    Buffer default_black_staging_;
    bool rgba16_maps_ = false; // the device samples R16G16B16A16_UNORM with linear filtering
    Image default_slices_;     // 1x1, one layer, zero: bindings 3-5 of draws without slices
    Buffer default_slices_staging_;
    Buffer default_curves_;            // 16 bytes, never written or read: binding 12 of draws that are not responsive
    InteractionPass interaction_;      // responsive grass: the interaction map and its pass
    bool interaction_pending_ = false; // this frame's pass is planned, not recorded yet (prepare_frame)
    BladeWindowPass window_;           // responsive grass: the blade window and its pass
    bool window_pending_ = false;      // this frame's window pass is planned, not recorded yet
    Vector<WindowDispatch> window_dispatches_; // prepare_frame: the window pass's dispatches
    uint32_t pending_uploads_ = 0; // patches, slice sets, maps, map updates and the default images not yet recorded
    uint64_t frame_ = 0;           // the host's index of the begun (or last) frame (grass_frame_desc)
    uint32_t slot_ = 0;            // its frame slot: the one whose last frame finished longest ago
    uint32_t views_made_ = 1;      // views whose view slots exist (make_view_slots)
    uint64_t slot_frame_[kMaxFramesInFlight] = {}; // the last frame of each frame slot (0: none)
    VkQueryPool timer_pool_ = VK_NULL_HANDLE;      // frames_in_flight x TierTimerRing::kStampsPerSet timestamps
    TierTimerRing timer_ring_;
    uint32_t timer_set_ = TierTimerRing::kUntimed; // the current frame's set
    bool timer_reset_ = false;                     // prepare_frame recorded the reset of its range this frame
};

} // namespace grass::vk
