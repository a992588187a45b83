// The Vulkan backend's construction, destruction and the helpers its resources
// (vk_resources.cpp) and its recording (vk_record.cpp) share.
#include "vk_backend.hpp"

#include "context/context.hpp"
#include "vk_staging.hpp"

#include <algorithm>
#include <cstring>

namespace grass::vk {

namespace {

PipelineTarget pipeline_target(const grass_context* ctx, const grass_vk_desc& d, const Device& device) {
    PipelineTarget t;
    t.render_pass = reinterpret_cast<VkRenderPass>(d.render_pass); // non-dispatchable handles are 64-bit
    t.subpass = d.subpass;
    t.color_format = static_cast<VkFormat>(d.color_format);
    t.depth_format = static_cast<VkFormat>(d.depth_format);
    t.samples = static_cast<VkSampleCountFlagBits>(d.sample_count);
    t.depth_greater = ctx->desc.depth_mode == GRASS_DEPTH_GREATER;
    t.indexed_blocks = device.indexed_blocks;
    t.view_mask = device.view_mask;
    return t;
}

} // namespace

VkBackend::VkBackend(grass_context* context, const grass_vk_desc& vk_desc, const Device& device)
    : ctx_(context), desc_(vk_desc), device_(device), fn_(device_.fn),
      memory_(fn_, device_.device, device_.memory, device_.properties.limits, &context->host),
      descriptors_(fn_, device_.device, &context->host), frame_sets_(fn_, device_.device, &context->host),
      deferred_(memory_, descriptors_, &context->host), pipeline_(fn_, device_.device, &context->host),
      extras_(fn_, device_.device, memory_),
      ring_(memory_, deferred_, vk_desc.frames_in_flight, device_.properties.limits.minUniformBufferOffsetAlignment,
            device_.view_mask != 0),
      batch_(&context->host), patches_(StlAllocator<PatchGpu>(&context->host)),
      fields_(StlAllocator<FieldGpu>(&context->host)), maps_(StlAllocator<MapGpu>(&context->host)),
      slices_(StlAllocator<SliceGpu>(&context->host)), draw_sets_(StlAllocator<VkDescriptorSet>(&context->host)),
      regions_(StlAllocator<VkBufferImageCopy>(&context->host)),
      interaction_(fn_, device_.device, memory_, deferred_, vk_desc.frames_in_flight, device_.properties.limits),
      window_(fn_, device_.device, memory_, deferred_, vk_desc.frames_in_flight, device_.indexed_blocks,
              &context->host),
      window_dispatches_(StlAllocator<WindowDispatch>(&context->host)),
      timer_ring_(vk_desc.frames_in_flight, TierTimerRing::WhenBusy::drop_results) {}

VkBackend::~VkBackend() {
    // The host guarantees the device is idle for grass work: everything goes at once.
    for (PatchGpu& p : patches_) destroy_patch_now(&p);
    for (SliceGpu& s : slices_) destroy_slices_now(&s);
    for (FieldGpu& f : fields_) destroy_field_now(&f);
    for (MapGpu& m : maps_) destroy_map_now(&m);
    deferred_.collect_all();
    deferred_.destroy_now(&default_white_staging_);
    deferred_.destroy_now(&default_white_);
    deferred_.destroy_now(&default_black_staging_);
    deferred_.destroy_now(&default_black_);
    deferred_.destroy_now(&default_slices_staging_);
    memory_.destroy_image(&default_slices_); // never retired
    deferred_.destroy_now(&default_curves_);
    if (timer_pool_ != VK_NULL_HANDLE) fn_.vkDestroyQueryPool(device_.device, timer_pool_, fn_.callbacks());
    extras_.destroy();
    pipeline_.destroy();
    destroy_pipeline_cache();
    // The frame ring, interaction pass and descriptor pools go with their members.
}

grass_result VkBackend::fail(const char* function, const char* what, const VkFailure& failure) {
    return report_failure(ctx_, function, what, failure);
}

grass_result VkBackend::init(const char* function) {
    VkFailure failure;
    const char* what = "";
    if (!create_pipeline_cache(&failure, &what)) return fail(function, what, failure);
    interaction_.use_cache(cache_);
    window_.use_cache(cache_);
    PipelineTarget target = pipeline_target(ctx_, desc_, device_);
    target.cache = cache_;
    if (device_.has_depth_pass) { // depth views' pipelines: made on the first (record)
        PipelineTarget depth = target;
        depth.render_pass = reinterpret_cast<VkRenderPass>(device_.depth_pass.render_pass);
        depth.subpass = device_.depth_pass.subpass;
        depth.color_format = VK_FORMAT_UNDEFINED;
        depth.depth_format = static_cast<VkFormat>(device_.depth_pass.depth_format);
        depth.samples = static_cast<VkSampleCountFlagBits>(device_.depth_pass.sample_count);
        depth.depth_only = true;
        pipeline_.set_depth_target(depth);
    }
    if (device_.has_velocity) {
        // The pass has the host's colour attachments: every pipeline has a blend state for
        // each (the plain ones write attachment 0 alone); the motion views' pipelines, made on
        // the first (record), write the velocity attachment too.
        target.color_count = device_.velocity.color_attachment_count;
        for (uint32_t i = 0; i < 7; ++i)
            target.other_formats[i] = static_cast<VkFormat>(device_.velocity.color_formats[i]);
        PipelineTarget velocity = target;
        velocity.velocity_attachment = device_.velocity.velocity_attachment;
        pipeline_.set_velocity_target(velocity);
    }
    if (device_.has_gbuffer) {
        // The pass has the host's G-buffer attachments: every pipeline has a blend state for
        // each; a G-buffer view's, made on the first that draws each layout (record), write
        // the attachments its layout routes grass's outputs to.
        target.color_count = device_.gbuffer.color_attachment_count;
        for (uint32_t i = 1; i < 8; ++i)
            target.other_formats[i - 1] = static_cast<VkFormat>(device_.gbuffer.color_formats[i]);
        pipeline_.set_gbuffer_target(target);
    }
    if (!pipeline_.create(target, &failure, &what)) return fail(function, what, failure);
    if (!ring_.create(&failure, &what)) return fail(function, what, failure);
    create_timers();

    // Colour maps are RGBA16; the device check (load_device) asked only for R16.
    VkFormatProperties rgba16{};
    fn_.vkGetPhysicalDeviceFormatProperties(device_.physical_device, VK_FORMAT_R16G16B16A16_UNORM, &rgba16);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    rgba16_maps_ = (rgba16.optimalTilingFeatures & needed) == needed;

    // The maps of fields without them (every binding must hold a valid image, though a
    // variant samples only its own maps): a white texel for density, ambient and diffuse
    // (x 1), a transparent black one for colour (weight 0) and height (0).
    const uint16_t white = 0xffff;
    const uint16_t black[4] = {0, 0, 0, 0};
    if (!stage_image(&default_white_, &default_white_staging_, MapTexels{&white, 1, 1, 1}, &failure, &what)) {
        return fail(function, "the default white map", failure); // the destructor frees what was made
    }
    pending_uploads_ += 1;
    if (!stage_image(&default_black_, &default_black_staging_, MapTexels{black, 1, 1, rgba16_maps_ ? 4u : 1u}, &failure,
                     &what)) {
        return fail(function, "the default black map", failure);
    }
    pending_uploads_ += 1;

    // Bindings 3-5 of the draws that sample no slices: one transparent texel, no blade.
    bool ok = memory_.create_array_image(1, 1, 1, 1, kSliceNormalFormat, kSliceUsage, &default_slices_, &failure) &&
              deferred_.create_buffer(kSliceNormalBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging,
                                      &default_slices_staging_, &failure); // retired once its copy is recorded
    if (ok) {
        std::memset(default_slices_staging_.mapped, 0, kSliceNormalBytes);
        ok = memory_.flush(default_slices_staging_, 0, kSliceNormalBytes, &failure);
    }
    if (!ok) return fail(function, "the default slice image", failure); // the destructor frees what was made
    pending_uploads_ += 1;

    // Binding 12 of draws that are not responsive: a valid buffer the shaders never read.
    if (!deferred_.create_buffer(16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::device_local, &default_curves_,
                                 &failure)) {
        return fail(function, "the default blade curves buffer", failure);
    }
    return GRASS_SUCCESS;
}

bool VkBackend::stage_image(Image* image, Buffer* staging, const MapTexels& texels, VkFailure* failure,
                            const char** what) {
    *what = "a design map image";
    const VkFormat format = texels.channels == 4 ? VK_FORMAT_R16G16B16A16_UNORM : kDensityMapFormat;
    if (!deferred_.create_image(texels.width, texels.height, format, kMapUsage, image, failure)) return false;
    const VkDeviceSize bytes = VkDeviceSize(texels.width) * texels.height * texels.channels * sizeof(uint16_t);
    *what = "a design map staging buffer";
    if (!deferred_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, staging, failure)) {
        deferred_.destroy_now(image);
        return false;
    }
    std::memcpy(staging->mapped, texels.texels, static_cast<size_t>(bytes));
    if (!memory_.flush(*staging, 0, bytes, failure)) {
        deferred_.destroy_now(staging);
        deferred_.destroy_now(image);
        return false;
    }
    return true;
}

// ---- Descriptor sets (fields at upload, volume and image draws at record) ----------------

VkImageView VkBackend::map_view(const FieldGpu& f, uint32_t role) const {
    const uint32_t slot = f.map_slot[role];
    if (slot != kNoMap && slot < maps_.size() && maps_[slot].live) return maps_[slot].image.view;
    return role == kMapColor || role == kMapHeight ? default_black_.view : default_white_.view;
}

VkBackend::SetViews VkBackend::still_views() const {
    return SetViews{{default_slices_.view, default_slices_.view, default_slices_.view},
                    {default_black_.view, default_black_.view},
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    default_curves_.buffer,
                    default_black_.view,
                    default_curves_.buffer,
                    default_curves_.buffer};
}

bool VkBackend::own_set(const TierDraw& d) {
    return d.kind != GRASS_TIER_GEOMETRY || (d.features & kBladeCurveFeatures) != 0;
}

VkBackend::SetViews VkBackend::draw_views(const TierDraw& d) const {
    SetViews v = still_views();
    if (d.kind != GRASS_TIER_GEOMETRY) {
        const SliceGpu* s = draw_slices(d);
        v.slices[0] = s->color.view;
        v.slices[1] = s->normal.view;
        v.slices[2] = s->threshold.view;
    }
    if ((d.features & kFeatureInteraction) && interaction_.map_ready()) {
        v.interaction[0] = interaction_.level_view(0);
        v.interaction[1] = interaction_.level_view(1);
        v.interaction_layout = VK_IMAGE_LAYOUT_GENERAL;
    }
    const PatchGpu& p = patches_[d.patch_slot];
    if (p.curves.buffer && !p.curves_pending) v.curves = p.curves.buffer;
    const uint32_t wind = fields_[d.field_slot].wind_map;
    if ((d.features & kFeatureWindMap) && wind != kNoMap && wind < maps_.size() && maps_[wind].live) {
        v.wind_map = maps_[wind].image.view;
    }
    if ((d.features & kFeatureBladeWindow) && window_.has_window()) {
        v.window_table = window_.table(slot_); // view 0's of this frame, read by every view
        v.window_poses = window_.poses();
    }
    return v;
}

void VkBackend::write_set(VkDescriptorSet set, uint32_t slot, const FieldGpu& field, const SetViews& views) {
    const VkBuffer uniforms = ring_.uniform_buffer(slot);
    const VkDescriptorBufferInfo frame_block{uniforms, 0, ring_.frame_block_bytes()};
    const VkDescriptorBufferInfo field_block{uniforms, 0, sizeof(FieldUniforms)};
    const VkDescriptorBufferInfo curves{views.curves, 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo window_table{views.window_table, 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo window_poses{views.window_poses, 0, VK_WHOLE_SIZE};
    // The samplers are immutable, in the layout. Bindings 2..11 and 13: images[binding - 2]
    // (14 and 15 are buffers: their entries stay unused).
    VkDescriptorImageInfo images[kBindingCount - kBindingDensityMap];
    for (VkDescriptorImageInfo& i : images)
        i = {VK_NULL_HANDLE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    for (uint32_t role = 0; role < kMapRoleCount; ++role) {
        images[kMapBinding[role] - kBindingDensityMap].imageView = map_view(field, role);
    }
    images[kBindingSliceColor - kBindingDensityMap].imageView = views.slices[0];
    images[kBindingSliceNormal - kBindingDensityMap].imageView = views.slices[1];
    images[kBindingSliceThreshold - kBindingDensityMap].imageView = views.slices[2];
    for (uint32_t l = 0; l < 2; ++l) {
        images[kBindingInteractionMap0 + l - kBindingDensityMap] = {VK_NULL_HANDLE, views.interaction[l],
                                                                    views.interaction_layout};
    }
    images[kBindingWindMap - kBindingDensityMap].imageView = views.wind_map;
    VkWriteDescriptorSet writes[kBindingCount];
    for (uint32_t i = 0; i < kBindingCount; ++i) {
        writes[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        if (i < kBindingDensityMap) {
            writes[i].descriptorType = kBlockDescriptorType;
        } else if (i == kBindingBladeCurves || i == kBindingWindowTable || i == kBindingWindowPoses) {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = i == kBindingBladeCurves   ? &curves
                                    : i == kBindingWindowTable ? &window_table
                                                               : &window_poses;
        } else {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            writes[i].pImageInfo = &images[i - kBindingDensityMap];
        }
    }
    writes[kBindingFrame].pBufferInfo = &frame_block;
    writes[kBindingField].pBufferInfo = &field_block;
    fn_.vkUpdateDescriptorSets(device_.device, kBindingCount, writes, 0, nullptr);
}

uint64_t VkBackend::dynamics_gpu_bytes() const {
    uint64_t bytes = interaction_.map_bytes() + window_.bytes();
    for (const PatchGpu& p : patches_) bytes += p.curves.allocated;
    return bytes;
}

void VkBackend::device_memory(grass_memory_stats* stats) const {
    const VkPhysicalDeviceMemoryProperties& m = device_.memory;
    stats->heap_count = m.memoryHeapCount;
    stats->device_allocations = memory_.blocks().device_allocations();
    uint64_t allocated[VK_MAX_MEMORY_HEAPS], in_use[VK_MAX_MEMORY_HEAPS];
    memory_.blocks().heap_bytes(allocated, in_use);
    for (uint32_t h = 0; h < m.memoryHeapCount && h < GRASS_MAX_MEMORY_HEAPS; ++h) {
        stats->heap_size[h] = m.memoryHeaps[h].size;
        stats->heap_allocated[h] = allocated[h];
        stats->heap_in_use[h] = in_use[h];
    }
    if (!device_.memory_budget) return;
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
    properties.pNext = &budget;
    fn_.vkGetPhysicalDeviceMemoryProperties2(device_.physical_device, &properties);
    stats->heap_budget_known = 1;
    for (uint32_t h = 0; h < m.memoryHeapCount && h < GRASS_MAX_MEMORY_HEAPS; ++h) {
        stats->heap_budget[h] = budget.heapBudget[h];
        stats->heap_usage[h] = budget.heapUsage[h];
    }
}

} // namespace grass::vk
