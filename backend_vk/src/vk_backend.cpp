#include "vk_backend.hpp"

#include "context/context.hpp"

#include <algorithm>
#include <cstring>

namespace grass::vk {

namespace {

constexpr VkBufferUsageFlags kVertexUsage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkBufferUsageFlags kIndexUsage = VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kMapUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kSliceUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// Texel sizes of the slice images (colour and normal RGBA8, threshold and coverage curve RGBA16).
constexpr uint32_t kSliceColorBytes = 4, kSliceNormalBytes = 4, kSliceThresholdBytes = 8;

PipelineTarget pipeline_target(const grass_context* ctx, const grass_vk_desc& d) {
    PipelineTarget t;
    t.render_pass = reinterpret_cast<VkRenderPass>(d.render_pass); // non-dispatchable handles are 64-bit
    t.subpass = d.subpass;
    t.color_format = static_cast<VkFormat>(d.color_format);
    t.depth_format = static_cast<VkFormat>(d.depth_format);
    t.samples = static_cast<VkSampleCountFlagBits>(d.sample_count);
    t.depth_greater = ctx->desc.depth_mode == GRASS_DEPTH_GREATER;
    return t;
}

// The staging layout of one slice image: its levels of each layer, layer after layer, each
// starting on a multiple of 4 bytes (vkCmdCopyBufferToImage's bufferOffset rule). Returns
// the offset after the image's last texel; calls visit(layer, level, offset, w, h) per region.
template <typename Visit>
VkDeviceSize slice_staging_layout(const Image& image, uint32_t texel_bytes, VkDeviceSize offset, Visit&& visit) {
    for (uint32_t layer = 0; layer < image.layers; ++layer) {
        for (uint32_t level = 0; level < image.levels; ++level) {
            const uint32_t w = image.width >> level ? image.width >> level : 1;
            const uint32_t h = image.height >> level ? image.height >> level : 1;
            offset = (offset + 3) & ~VkDeviceSize(3);
            visit(layer, level, offset, w, h);
            offset += VkDeviceSize(w) * h * texel_bytes;
        }
    }
    return offset;
}

} // namespace

VkBackend::VkBackend(grass_context* context, const grass_vk_desc& vk_desc, const Device& device)
    : ctx_(context), desc_(vk_desc), device_(device), fn_(device_.fn),
      memory_(fn_, device_.device, device_.memory, device_.properties.limits.nonCoherentAtomSize),
      descriptors_(fn_, device_.device, &context->host), frame_sets_(fn_, device_.device, &context->host),
      deferred_(memory_, descriptors_, &context->host, vk_desc.frames_in_flight), pipeline_(fn_, device_.device),
      ring_(memory_, deferred_, vk_desc.frames_in_flight, device_.properties.limits.minUniformBufferOffsetAlignment,
            vk_desc.sample_count),
      batch_(&context->host), patches_(StlAllocator<PatchGpu>(&context->host)),
      fields_(StlAllocator<FieldGpu>(&context->host)), maps_(StlAllocator<MapGpu>(&context->host)), slices_(StlAllocator<SliceGpu>(&context->host)),
      draw_sets_(StlAllocator<VkDescriptorSet>(&context->host)),
      regions_(StlAllocator<VkBufferImageCopy>(&context->host)),
      timer_ring_(vk_desc.frames_in_flight, TierTimerRing::WhenBusy::drop_results) {}

VkBackend::~VkBackend() {
    // The host guarantees the device is idle for grass work: everything goes at once.
    for (PatchGpu& p : patches_) destroy_patch_now(&p);
    for (SliceGpu& s : slices_) destroy_slices_now(&s);
    for (FieldGpu& f : fields_) destroy_field_now(&f);
    for (MapGpu& m : maps_) destroy_map_now(&m);
    deferred_.collect_all();
    memory_.destroy_buffer(&default_white_staging_);
    memory_.destroy_image(&default_white_);
    memory_.destroy_buffer(&default_black_staging_);
    memory_.destroy_image(&default_black_);
    memory_.destroy_buffer(&default_slices_staging_);
    memory_.destroy_image(&default_slices_);
    if (timer_pool_ != VK_NULL_HANDLE) fn_.vkDestroyQueryPool(device_.device, timer_pool_, nullptr);
    // The frame ring, pipelines and descriptor pools go with their members.
}

grass_result VkBackend::fail(const char* function, const char* what, const VkFailure& failure) {
    return report_failure(ctx_, function, what, failure);
}

grass_result VkBackend::init(const char* function) {
    VkFailure failure;
    const char* what = "";
    const PipelineTarget target = pipeline_target(ctx_, desc_);
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
    deferred_.promise(2); // the staging buffers, retired once their copies are recorded
    if (!stage_image(&default_white_, &default_white_staging_, MapTexels{&white, 1, 1, 1}, &failure, &what)) {
        return fail(function, "the default white map", failure); // the destructor frees what was made
    }
    pending_uploads_ += 1;
    if (!stage_image(&default_black_, &default_black_staging_, MapTexels{black, 1, 1, rgba16_maps_ ? 4u : 1u},
                     &failure, &what)) {
        return fail(function, "the default black map", failure);
    }
    pending_uploads_ += 1;

    // Bindings 3-5 of the draws that sample no slices: one transparent texel, no blade.
    deferred_.promise(1);
    bool ok = memory_.create_array_image(1, 1, 1, 1, kSliceNormalFormat, kSliceUsage, &default_slices_, &failure) &&
              memory_.create_buffer(kSliceNormalBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging,
                                    &default_slices_staging_, &failure);
    if (ok) {
        std::memset(default_slices_staging_.mapped, 0, kSliceNormalBytes);
        ok = memory_.flush(default_slices_staging_, 0, kSliceNormalBytes, &failure);
    }
    if (!ok) return fail(function, "the default slice image", failure); // the destructor frees what was made
    pending_uploads_ += 1;
    return GRASS_SUCCESS;
}

bool VkBackend::stage_image(Image* image, Buffer* staging, const MapTexels& texels, VkFailure* failure,
                            const char** what) {
    *what = "a design map image";
    const VkFormat format = texels.channels == 4 ? VK_FORMAT_R16G16B16A16_UNORM : kDensityMapFormat;
    if (!memory_.create_image(texels.width, texels.height, format, kMapUsage, image, failure)) return false;
    const VkDeviceSize bytes = VkDeviceSize(texels.width) * texels.height * texels.channels * sizeof(uint16_t);
    *what = "a design map staging buffer";
    if (!memory_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, staging, failure)) {
        memory_.destroy_image(image);
        return false;
    }
    std::memcpy(staging->mapped, texels.texels, static_cast<size_t>(bytes));
    if (!memory_.flush(*staging, 0, bytes, failure)) {
        memory_.destroy_buffer(staging);
        memory_.destroy_image(image);
        return false;
    }
    return true;
}

// ---- Patches ----------------------------------------------------------------------------

grass_result VkBackend::upload_patch(uint32_t slot, const PatchData& patch) {
    const char* function = "grass_create_patch";
    if (slot >= patches_.size()) patches_.resize(slot + 1, PatchGpu{}); // may throw: nothing made yet
    PatchGpu fresh;
    fresh.live = true;
    fresh.index_count = static_cast<uint32_t>(patch.indices.size());
    if (patch.vertices.empty() || patch.indices.empty()) {
        fresh.index_count = 0; // nothing to draw
        patches_[slot] = fresh;
        return GRASS_SUCCESS;
    }
    const VkDeviceSize vertex_bytes = VkDeviceSize(patch.vertices.size()) * sizeof(BladeVertex);
    const VkDeviceSize index_bytes = VkDeviceSize(patch.indices.size()) * sizeof(uint32_t);
    deferred_.promise(3); // vertices, indices, staging

    VkFailure failure;
    const char* what = "the patch vertex buffer";
    bool ok = memory_.create_buffer(vertex_bytes, kVertexUsage, MemoryUse::device_local, &fresh.vertices, &failure);
    if (ok) {
        what = "the patch index buffer";
        ok = memory_.create_buffer(index_bytes, kIndexUsage, MemoryUse::device_local, &fresh.indices, &failure);
    }
    if (ok) {
        what = "the patch staging buffer";
        ok = memory_.create_buffer(vertex_bytes + index_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging,
                                   &fresh.staging, &failure);
    }
    if (ok) {
        auto* bytes = static_cast<unsigned char*>(fresh.staging.mapped);
        std::memcpy(bytes, patch.vertices.data(), static_cast<size_t>(vertex_bytes));
        std::memcpy(bytes + vertex_bytes, patch.indices.data(), static_cast<size_t>(index_bytes));
        ok = memory_.flush(fresh.staging, 0, vertex_bytes + index_bytes, &failure);
    }
    if (!ok) {
        destroy_patch_now(&fresh); // never recorded: no GPU work can use it
        deferred_.forgo(3);
        return fail(function, what, failure);
    }
    fresh.pending = true;
    pending_uploads_ += 1;
    patches_[slot] = fresh;
    return GRASS_SUCCESS;
}

void VkBackend::destroy_patch_now(PatchGpu* p) {
    // Context destruction (the device is idle for grass work) or a failed upload.
    if (p->pending) pending_uploads_ -= 1;
    memory_.destroy_buffer(&p->vertices);
    memory_.destroy_buffer(&p->indices);
    memory_.destroy_buffer(&p->staging);
    *p = PatchGpu{};
}

void VkBackend::release_patch(uint32_t slot) {
    if (slot >= patches_.size() || !patches_[slot].live) return;
    PatchGpu& p = patches_[slot];
    if (p.pending) {
        // Its copy was never recorded: the staging buffer goes now.
        memory_.destroy_buffer(&p.staging);
        deferred_.forgo(1);
        pending_uploads_ -= 1;
    }
    // Draws of frames still in flight may read the buffers.
    deferred_.retire(&p.vertices, frame_);
    deferred_.retire(&p.indices, frame_);
    p = PatchGpu{};
    // Its slice sets go with it (swap-remove: no allocation).
    for (size_t i = 0; i < slices_.size();) {
        if (slices_[i].patch_slot != slot) {
            ++i;
            continue;
        }
        release_slices(&slices_[i]);
        slices_[i] = slices_.back();
        slices_.pop_back();
    }
}

// ---- Baked slices -----------------------------------------------------------------------

VkBackend::SliceGpu* VkBackend::find_slices(uint32_t patch_slot, uint32_t slices_per_axis) {
    for (SliceGpu& s : slices_) {
        if (s.patch_slot == patch_slot && s.slices_per_axis == slices_per_axis) return &s;
    }
    return nullptr;
}

const VkBackend::SliceGpu* VkBackend::draw_slices(const TierDraw& d) const {
    const uint32_t n = d.kind == GRASS_TIER_VOLUME ? d.slices : 0;
    for (const SliceGpu& s : slices_) {
        if (s.patch_slot == d.patch_slot && s.slices_per_axis == n) return &s;
    }
    return nullptr;
}

grass_result VkBackend::upload_slices(uint32_t slot, const SliceSet& set) {
    const char* function = "grass_create_field"; // slices are baked and uploaded for a field's tiers
    if (slot >= patches_.size() || !patches_[slot].live) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "%s: baked slices (N = %u) for the patch in slot %u, which the Vulkan backend does not hold "
                          "(internal error)",
                          function, set.slices_per_axis, slot);
    }
    const uint32_t n = set.slices_per_axis;
    SliceGpu fresh;
    fresh.patch_slot = slot;
    fresh.slices_per_axis = n;
    const bool empty = set.width == 0 || set.height == 0 || set.layers == 0 || set.mip_levels == 0;
    // The core checked the set against the layout contract (check_slice_set).
    const VkPhysicalDeviceLimits& limits = device_.properties.limits;
    uint32_t full_chain = 1;
    while (!empty && ((set.width | set.height) >> full_chain) != 0) ++full_chain;
    if (!empty && (set.width > limits.maxImageDimension2D || set.height > limits.maxImageDimension2D ||
                   set.layers > limits.maxImageArrayLayers || set.mip_levels > full_chain)) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: baked slices of %u x %u texels, %u levels, %u layers exceed what the device \"%s\" "
                          "holds in a 2D array image (%u texels, %u layers, %u levels at that size)",
                          function, set.width, set.height, set.mip_levels, set.layers, device_.properties.deviceName,
                          limits.maxImageDimension2D, limits.maxImageArrayLayers, full_chain);
    }
    // Room for the entry before anything is made (may throw).
    if (!find_slices(slot, n)) slices_.reserve(slices_.size() + 1);
    if (empty) {
        if (SliceGpu* old = find_slices(slot, n)) {
            release_slices(old);
            *old = fresh;
        } else {
            slices_.push_back(fresh);
        }
        return GRASS_SUCCESS;
    }

    deferred_.promise(4); // colour, normal, threshold, staging
    VkFailure failure;
    const char* what = "the slice colour image";
    bool ok = memory_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceColorFormat,
                                         kSliceUsage, &fresh.color, &failure);
    if (ok) {
        what = "the slice normal image";
        ok = memory_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceNormalFormat,
                                        kSliceUsage, &fresh.normal, &failure);
    }
    if (ok) {
        what = "the slice threshold image";
        ok = memory_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceThresholdFormat,
                                        kSliceUsage, &fresh.threshold, &failure);
    }
    const auto no_visit = [](uint32_t, uint32_t, VkDeviceSize, uint32_t, uint32_t) {};
    VkDeviceSize bytes = slice_staging_layout(fresh.color, kSliceColorBytes, 0, no_visit);
    bytes = slice_staging_layout(fresh.normal, kSliceNormalBytes, bytes, no_visit);
    bytes = slice_staging_layout(fresh.threshold, kSliceThresholdBytes, bytes, no_visit);
    if (ok) {
        what = "the slice staging buffer";
        ok = memory_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, &fresh.staging,
                                   &failure);
    }
    if (ok) {
        // Level k of layer l starts at texel offset(l, k) of each array.
        auto* staging = static_cast<unsigned char*>(fresh.staging.mapped);
        const auto copier = [&](const void* source, uint32_t texel_bytes) {
            return [&, source, texel_bytes](uint32_t layer, uint32_t level, VkDeviceSize offset, uint32_t w,
                                            uint32_t h) {
                const uint64_t first = set.offset(layer, level);
                std::memcpy(staging + offset, static_cast<const unsigned char*>(source) + first * texel_bytes,
                            size_t(w) * h * texel_bytes);
            };
        };
        VkDeviceSize at = slice_staging_layout(fresh.color, kSliceColorBytes, 0, copier(set.color.data(), 4));
        at = slice_staging_layout(fresh.normal, kSliceNormalBytes, at, copier(set.normal.data(), 4));
        slice_staging_layout(fresh.threshold, kSliceThresholdBytes, at, copier(set.threshold.data(), 8));
        ok = memory_.flush(fresh.staging, 0, bytes, &failure);
    }
    if (!ok) {
        destroy_slices_now(&fresh); // never recorded: no GPU work can use it
        deferred_.forgo(4);
        return fail(function, what, failure);
    }
    fresh.pending = true;
    pending_uploads_ += 1;
    if (SliceGpu* old = find_slices(slot, n)) {
        release_slices(old); // uploaded again: frames in flight may still sample the old images
        *old = fresh;
    } else {
        slices_.push_back(fresh); // reserved above: cannot throw
    }
    return GRASS_SUCCESS;
}

void VkBackend::destroy_slices_now(SliceGpu* s) {
    // Context destruction (the device is idle for grass work) or a failed upload.
    if (s->pending) pending_uploads_ -= 1;
    memory_.destroy_image(&s->color);
    memory_.destroy_image(&s->normal);
    memory_.destroy_image(&s->threshold);
    memory_.destroy_buffer(&s->staging);
    *s = SliceGpu{};
}

void VkBackend::release_slices(SliceGpu* s) {
    if (s->pending) {
        // Its copies were never recorded: the staging buffer goes now.
        memory_.destroy_buffer(&s->staging);
        deferred_.forgo(1);
        pending_uploads_ -= 1;
    }
    deferred_.retire(&s->color, frame_);
    deferred_.retire(&s->normal, frame_);
    deferred_.retire(&s->threshold, frame_);
    *s = SliceGpu{};
}

// ---- Design maps ------------------------------------------------------------------------

bool VkBackend::stage_region(Buffer* staging, const MapTexels& map, const MapRegion& region, VkFailure* failure) {
    const size_t row_bytes = size_t(region.width) * map.channels * sizeof(uint16_t);
    const VkDeviceSize bytes = VkDeviceSize(row_bytes) * region.height;
    if (!memory_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, staging, failure)) {
        return false;
    }
    auto* out = static_cast<unsigned char*>(staging->mapped);
    for (uint32_t row = 0; row < region.height; ++row) {
        const uint16_t* from = map.texels + (size_t(region.y + row) * map.width + region.x) * map.channels;
        std::memcpy(out + row * row_bytes, from, row_bytes);
    }
    if (!memory_.flush(*staging, 0, bytes, failure)) {
        memory_.destroy_buffer(staging);
        return false;
    }
    return true;
}

grass_result VkBackend::upload_map(uint32_t slot, const MapTexels& map) {
    const char* function = "grass_create_map";
    const VkPhysicalDeviceLimits& limits = device_.properties.limits;
    if (map.channels == 4 && !rgba16_maps_) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: the device \"%s\" cannot sample VK_FORMAT_R16G16B16A16_UNORM images with linear "
                          "filtering, which colour maps need",
                          function, device_.properties.deviceName);
    }
    if (map.width > limits.maxImageDimension2D || map.height > limits.maxImageDimension2D) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: a design map of %u x %u texels exceeds what the device \"%s\" holds in a 2D image "
                          "(%u texels a side)",
                          function, map.width, map.height, device_.properties.deviceName, limits.maxImageDimension2D);
    }
    if (slot >= maps_.size()) maps_.resize(slot + 1, MapGpu{}); // may throw: nothing made yet
    deferred_.promise(2);                                        // image, staging

    MapGpu fresh;
    fresh.live = true;
    fresh.channels = map.channels;
    VkFailure failure;
    const char* what = "";
    if (!stage_image(&fresh.image, &fresh.staging, map, &failure, &what)) {
        deferred_.forgo(2);
        return fail(function, what, failure);
    }
    fresh.pending = true;
    pending_uploads_ += 1;
    maps_[slot] = fresh;
    return GRASS_SUCCESS;
}

grass_result VkBackend::update_map(uint32_t slot, const MapTexels& map, const MapRegion& region) {
    const char* function = "grass_update_map";
    if (slot >= maps_.size() || !maps_[slot].live) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "%s: the design map in slot %u, which the Vulkan backend does not hold (internal error)",
                          function, slot);
    }
    MapGpu& m = maps_[slot];
    if (region.width == 0 || region.height == 0) return GRASS_SUCCESS;
    VkFailure failure;
    if (m.pending) {
        // The first copy is not recorded yet: its staging buffer takes the new texels.
        const size_t row_bytes = size_t(region.width) * map.channels * sizeof(uint16_t);
        auto* out = static_cast<unsigned char*>(m.staging.mapped);
        for (uint32_t row = 0; row < region.height; ++row) {
            const size_t at = (size_t(region.y + row) * map.width + region.x) * map.channels;
            std::memcpy(out + at * sizeof(uint16_t), map.texels + at, row_bytes);
        }
        if (!memory_.flush(m.staging, 0, m.staging.size, &failure)) {
            return fail(function, "a design map staging buffer", failure);
        }
        return GRASS_SUCCESS;
    }
    // Updates not recorded yet merge with this one: `map` holds them all, so its texels over
    // the bounding rectangle are what the image must hold there.
    MapRegion merged = region;
    if (m.updating) {
        const uint32_t x0 = std::min(region.x, m.update.x), y0 = std::min(region.y, m.update.y);
        const uint32_t x1 = std::max(region.x + region.width, m.update.x + m.update.width);
        const uint32_t y1 = std::max(region.y + region.height, m.update.y + m.update.height);
        merged = MapRegion{x0, y0, x1 - x0, y1 - y0};
    }
    deferred_.promise(1); // the staging buffer, retired once its copy is recorded
    Buffer staging;
    if (!stage_region(&staging, map, merged, &failure)) {
        deferred_.forgo(1);
        return fail(function, "a design map update staging buffer", failure);
    }
    if (m.updating) {
        // Its copy was never recorded: the old staging buffer goes now.
        memory_.destroy_buffer(&m.update_staging);
        deferred_.forgo(1);
    } else {
        m.updating = true;
        pending_uploads_ += 1;
    }
    m.update_staging = staging;
    m.update = merged;
    return GRASS_SUCCESS;
}

void VkBackend::destroy_map_now(MapGpu* m) {
    // Context destruction: the device is idle for grass work.
    if (m->pending) pending_uploads_ -= 1;
    if (m->updating) pending_uploads_ -= 1;
    memory_.destroy_image(&m->image);
    memory_.destroy_buffer(&m->staging);
    memory_.destroy_buffer(&m->update_staging);
    *m = MapGpu{};
}

void VkBackend::release_map(uint32_t slot) {
    if (slot >= maps_.size() || !maps_[slot].live) return;
    MapGpu& m = maps_[slot];
    // Copies never recorded: their staging buffers go now. (Once recorded, a staging
    // buffer was retired by prepare_frame.)
    if (m.pending) {
        memory_.destroy_buffer(&m.staging);
        deferred_.forgo(1);
        pending_uploads_ -= 1;
    }
    if (m.updating) {
        memory_.destroy_buffer(&m.update_staging);
        deferred_.forgo(1);
        pending_uploads_ -= 1;
    }
    // Draws of frames still in flight may sample it.
    deferred_.retire(&m.image, frame_);
    m = MapGpu{};
}

// ---- Fields -----------------------------------------------------------------------------

VkImageView VkBackend::map_view(const FieldGpu& f, uint32_t role) const {
    const uint32_t slot = f.map_slot[role];
    if (slot != kNoMap && slot < maps_.size() && maps_[slot].live) return maps_[slot].image.view;
    return role == kMapColor || role == kMapHeight ? default_black_.view : default_white_.view;
}

void VkBackend::write_set(VkDescriptorSet set, uint32_t slot, const FieldGpu& field, const VkImageView (&slices)[3]) {
    const VkBuffer uniforms = ring_.uniform_buffer(slot);
    const VkDescriptorBufferInfo frame_block{uniforms, 0, sizeof(FrameUniforms)};
    const VkDescriptorBufferInfo field_block{uniforms, 0, sizeof(FieldUniforms)};
    // The samplers are immutable, in the layout. Bindings 2..9: images[binding - 2].
    VkDescriptorImageInfo images[kBindingCount - kBindingDensityMap];
    for (VkDescriptorImageInfo& i : images) i = {VK_NULL_HANDLE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    for (uint32_t role = 0; role < kMapRoleCount; ++role) {
        images[kMapBinding[role] - kBindingDensityMap].imageView = map_view(field, role);
    }
    images[kBindingSliceColor - kBindingDensityMap].imageView = slices[0];
    images[kBindingSliceNormal - kBindingDensityMap].imageView = slices[1];
    images[kBindingSliceThreshold - kBindingDensityMap].imageView = slices[2];
    VkWriteDescriptorSet writes[kBindingCount];
    for (uint32_t i = 0; i < kBindingCount; ++i) {
        writes[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        if (i < kBindingDensityMap) {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
        } else {
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            writes[i].pImageInfo = &images[i - kBindingDensityMap];
        }
    }
    writes[kBindingFrame].pBufferInfo = &frame_block;
    writes[kBindingField].pBufferInfo = &field_block;
    fn_.vkUpdateDescriptorSets(device_.device, kBindingCount, writes, 0, nullptr);
}

grass_result VkBackend::upload_field(uint32_t slot, const FieldMaps& maps) {
    const char* function = "grass_create_field";
    // The core checked the maps against the feature mask (check_field_maps).
    if (slot >= fields_.size()) fields_.resize(slot + 1, FieldGpu{}); // may throw: nothing made yet
    VkFailure failure;
    const char* what = "";
    // The shader variant of its maps, shared with every field of the same mask.
    if (!pipeline_.create_variant(maps.features, &failure, &what)) return fail(function, what, failure);

    const uint32_t promised = desc_.frames_in_flight; // the sets
    deferred_.promise(promised);
    FieldGpu fresh;
    fresh.live = true;
    fresh.features = maps.features;
    for (uint32_t role = 0; role < kMapRoleCount; ++role) fresh.map_slot[role] = maps.map_slot[role];
    bool ok = true;
    for (uint32_t i = 0; ok && i < desc_.frames_in_flight; ++i) {
        what = "a field descriptor set";
        ok = descriptors_.allocate(pipeline_.set_layout(), &fresh.sets[i], &failure);
    }
    if (!ok) {
        for (DescriptorSet& s : fresh.sets) descriptors_.free(&s);
        deferred_.forgo(promised);
        return fail(function, what, failure);
    }
    const VkImageView none[3] = {default_slices_.view, default_slices_.view, default_slices_.view};
    for (uint32_t i = 0; i < desc_.frames_in_flight; ++i) write_set(fresh.sets[i].set, i, fresh, none);
    fields_[slot] = fresh;
    return GRASS_SUCCESS;
}

void VkBackend::destroy_field_now(FieldGpu* f) {
    // Context destruction: the device is idle for grass work.
    for (DescriptorSet& s : f->sets) descriptors_.free(&s);
    *f = FieldGpu{};
}

void VkBackend::release_field(uint32_t slot) {
    if (slot >= fields_.size() || !fields_[slot].live) return;
    FieldGpu& f = fields_[slot];
    // Its maps live on (the core releases each when no field uses it); the pipelines of its
    // mask stay cached.
    for (DescriptorSet& s : f.sets) deferred_.retire(&s, frame_);
    f = FieldGpu{};
}

// ---- Frames -----------------------------------------------------------------------------

grass_result VkBackend::begin_frame(const FramePlan& plan) {
    frame_ += 1;
    slot_ = static_cast<uint32_t>(frame_ % desc_.frames_in_flight);
    // The previous frame writes no more stamps (the host has submitted it). The set this
    // frame takes was written by frame frame_ - frames_in_flight, which has finished: read
    // it (and any older) now; open_frame drops it if it never ran.
    timer_ring_.close_frame();
    collect_timers();
    timer_set_ = timer_pool_ != VK_NULL_HANDLE ? timer_ring_.open_frame() : TierTimerRing::kUntimed;
    timer_reset_ = false;
    // Frame frame_ - frames_in_flight has finished: what it was the last to use can go,
    // and the sets its volume and image draws used.
    deferred_.collect(frame_);
    frame_sets_.reset(slot_);

    bool uniforms_replaced = false;
    VkFailure failure;
    const char* what = "";
    if (!ring_.write(slot_, plan, frame_, &uniforms_replaced, &failure, &what)) {
        return fail("grass_begin_frame", what, failure);
    }
    if (uniforms_replaced) {
        // This slot's sets were last used by frame frame_ - frames_in_flight, which is done.
        const VkImageView none[3] = {default_slices_.view, default_slices_.view, default_slices_.view};
        for (const FieldGpu& f : fields_) {
            if (f.live) write_set(f.sets[slot_].set, slot_, f, none);
        }
    }
    return GRASS_SUCCESS;
}

grass_result VkBackend::prepare_frame(VkCommandBuffer cmd) {
    // This frame's timestamps (vk_timers.cpp), reset once, outside the render pass.
    if (timer_set_ != TierTimerRing::kUntimed && !timer_reset_) {
        fn_.vkCmdResetQueryPool(cmd, timer_pool_, timer_set_ * TierTimerRing::kStampsPerSet,
                                TierTimerRing::kStampsPerSet);
        timer_reset_ = true;
    }
    if (pending_uploads_ == 0) return GRASS_SUCCESS;

    // Build the batch first: it may throw std::bad_alloc, and nothing has changed yet.
    batch_.clear();
    if (default_white_staging_.buffer) batch_.copy_image(default_white_staging_.buffer, 0, default_white_.image, 1, 1);
    if (default_black_staging_.buffer) batch_.copy_image(default_black_staging_.buffer, 0, default_black_.image, 1, 1);
    if (default_slices_staging_.buffer) {
        batch_.copy_image(default_slices_staging_.buffer, 0, default_slices_.image, 1, 1);
    }
    for (const PatchGpu& p : patches_) {
        if (!p.pending) continue;
        batch_.copy_buffer(p.staging.buffer, 0, p.vertices.buffer, p.vertices.size, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
        batch_.copy_buffer(p.staging.buffer, p.vertices.size, p.indices.buffer, p.indices.size, VK_ACCESS_INDEX_READ_BIT);
    }
    for (const MapGpu& m : maps_) {
        // A map is either new (its whole image) or updated (a rectangle of it), never both.
        if (m.pending) batch_.copy_image(m.staging.buffer, 0, m.image.image, m.image.width, m.image.height);
        if (m.updating) {
            batch_.update_image(m.update_staging.buffer, m.image.image, m.update.x, m.update.y, m.update.width,
                                m.update.height);
        }
    }
    for (const SliceGpu& s : slices_) {
        if (!s.pending) continue;
        // The staging layout upload_slices filled: colour, normal, then threshold texels.
        VkDeviceSize at = 0;
        const struct {
            const Image* image;
            uint32_t texel_bytes;
        } images[3] = {{&s.color, kSliceColorBytes}, {&s.normal, kSliceNormalBytes}, {&s.threshold, kSliceThresholdBytes}};
        for (const auto& im : images) {
            regions_.clear();
            at = slice_staging_layout(*im.image, im.texel_bytes, at,
                                      [&](uint32_t layer, uint32_t level, VkDeviceSize offset, uint32_t w, uint32_t h) {
                                          VkBufferImageCopy r{};
                                          r.bufferOffset = offset;
                                          r.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, layer, 1};
                                          r.imageExtent = {w, h, 1};
                                          regions_.push_back(r);
                                      });
            batch_.copy_image_regions(s.staging.buffer, im.image->image, im.image->levels, im.image->layers,
                                      regions_.data(), static_cast<uint32_t>(regions_.size()));
        }
    }
    batch_.record(fn_, cmd);

    // The staging buffers wait until this frame's copies have run on the GPU.
    deferred_.retire(&default_white_staging_, frame_);
    deferred_.retire(&default_black_staging_, frame_);
    deferred_.retire(&default_slices_staging_, frame_);
    for (SliceGpu& s : slices_) {
        if (!s.pending) continue;
        deferred_.retire(&s.staging, frame_);
        s.pending = false;
    }
    for (PatchGpu& p : patches_) {
        if (!p.pending) continue;
        deferred_.retire(&p.staging, frame_);
        p.pending = false;
    }
    for (MapGpu& m : maps_) {
        if (m.pending) deferred_.retire(&m.staging, frame_);
        if (m.updating) deferred_.retire(&m.update_staging, frame_);
        m.pending = m.updating = false;
    }
    pending_uploads_ = 0;
    return GRASS_SUCCESS;
}

bool VkBackend::drawn(const TierDraw& d, bool debug_view) const {
    // A draw whose field or patch was destroyed after grass_begin_frame is skipped, as is
    // one of an empty patch (no blades: nothing to draw in any tier).
    if (d.instance_count == 0 || d.field_slot >= fields_.size() || !fields_[d.field_slot].live) return false;
    if (debug_view) return true;
    if (d.kind != GRASS_TIER_GEOMETRY && d.kind != GRASS_TIER_VOLUME && d.kind != GRASS_TIER_IMAGE) return false;
    if (d.patch_slot >= patches_.size() || !patches_[d.patch_slot].live || patches_[d.patch_slot].index_count == 0) {
        return false;
    }
    if (d.kind == GRASS_TIER_GEOMETRY) return true;
    // A slice set baked empty has nothing to draw (grass_begin_frame checked that every
    // set a draw samples was uploaded: check_plan).
    const SliceGpu* s = draw_slices(d);
    return s != nullptr && s->color.image != VK_NULL_HANDLE;
}

bool VkBackend::draw_ready(const TierDraw& draw, bool debug_view, const char** problem) const {
    const FieldGpu& f = fields_[draw.field_slot];
    if (!debug_view && patches_[draw.patch_slot].pending) {
        *problem = "its patch";
        return false;
    }
    if (!debug_view && draw.kind != GRASS_TIER_GEOMETRY && draw_slices(draw)->pending) {
        *problem = draw.kind == GRASS_TIER_VOLUME ? "its patch's baked vertical slices" : "its patch's baked horizontal slice";
        return false;
    }
    // The field's descriptor sets point at its maps (or the default ones): each must have
    // its copies recorded, the first and any update since (the plan already follows the
    // updated texels).
    for (uint32_t role = 0; role < kMapRoleCount; ++role) {
        const uint32_t m = f.map_slot[role];
        if (m != kNoMap && m < maps_.size() && (maps_[m].pending || maps_[m].updating)) {
            *problem = maps_[m].pending ? "one of its design maps" : "an update of one of its design maps";
            return false;
        }
    }
    if (default_white_staging_.buffer || default_black_staging_.buffer) {
        *problem = "the default design maps";
        return false;
    }
    if (default_slices_staging_.buffer) {
        *problem = "the default slice image";
        return false;
    }
    return true;
}

grass_result VkBackend::record(VkCommandBuffer cmd) {
    const FramePlan& plan = ctx_->plan;
    const bool debug_view = (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0;
    // Refuse before recording anything, so that the command buffer is left untouched. The
    // plan itself was checked by grass_begin_frame (check_plan in context/invariants.hpp).
    uint32_t draw_count = 0, slice_draws = 0;
    for (const TierDraw& d : plan.draws) {
        if (!drawn(d, debug_view)) continue;
        const char* problem = "";
        if (!draw_ready(d, debug_view, &problem)) {
            return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_UPLOAD_NOT_RECORDED,
                              "grass_vk_record: a field drawn this frame (slot %u) waits for the upload of %s; call "
                              "grass_vk_prepare_frame() with a command buffer that runs before this one, after "
                              "grass_begin_frame() and outside the render pass",
                              d.field_slot, problem);
        }
        // upload_field made the variant of the field's maps; one the plan asks for besides
        // is made here, before anything is recorded.
        VkFailure failure;
        const char* what = "";
        if (!pipeline_.create_variant(d.features, &failure, &what)) return fail("grass_vk_record", what, failure);
        draw_count += 1;
        if (!debug_view && d.kind != GRASS_TIER_GEOMETRY) slice_draws += 1;
    }
    if (draw_count == 0) return GRASS_SUCCESS;

    // The volume and image draws pair the field's design maps with the patch's slices: a
    // fresh set each, from this frame slot's pools (never one a frame in flight may use).
    if (slice_draws > 0) {
        draw_sets_.assign(plan.draws.size(), VK_NULL_HANDLE); // may throw: nothing recorded yet
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (!drawn(d, false) || d.kind == GRASS_TIER_GEOMETRY) continue;
            VkFailure failure;
            if (!frame_sets_.allocate(slot_, pipeline_.set_layout(), &draw_sets_[i], &failure)) {
                return fail("grass_vk_record", "a descriptor set of a volume or image tier", failure);
            }
            const SliceGpu* s = draw_slices(d);
            const VkImageView views[3] = {s->color.view, s->normal.view, s->threshold.view};
            write_set(draw_sets_[i], slot_, fields_[d.field_slot], views);
        }
    }

    const int32_t x = plan.viewport[0], y = plan.viewport[1], w = plan.viewport[2], h = plan.viewport[3];
    const VkViewport viewport{float(x), float(y), float(w), float(h), 0.0f, 1.0f};
    // The scissor is the viewport rectangle, clipped to the framebuffer's positive quadrant.
    const int64_t x0 = x < 0 ? 0 : x, y0 = y < 0 ? 0 : y;
    const int64_t x1 = int64_t(x) + w, y1 = int64_t(y) + h;
    VkRect2D scissor{};
    scissor.offset = {static_cast<int32_t>(x0), static_cast<int32_t>(y0)};
    scissor.extent = {static_cast<uint32_t>(x1 > x0 ? x1 - x0 : 0), static_cast<uint32_t>(y1 > y0 ? y1 - y0 : 0)};

    const bool depth_test = (plan.flags & GRASS_VIEW_FLAG_NO_DEPTH_TEST) == 0;
    fn_.vkCmdSetViewport(cmd, 0, 1, &viewport);
    fn_.vkCmdSetScissor(cmd, 0, 1, &scissor);

    const VkBuffer instances = ring_.instance_buffer(slot_);
    const VkDeviceSize zero = 0;
    const auto bind_set = [&](uint32_t draw, VkDescriptorSet set) {
        // Every draw has its Field block, whatever its kind.
        const uint32_t offsets[2] = {ring_.frame_offset(), ring_.field_offset(draw)};
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout(), 0, 1, &set, 2, offsets);
    };

    if (debug_view) {
        // Every draw as boxes, in plan order.
        VkPipeline bound_pipeline = VK_NULL_HANDLE;
        fn_.vkCmdBindVertexBuffers(cmd, DebugViewPipeline::kInstanceBinding, 1, &instances, &zero);
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (!drawn(d, true)) continue;
            const VkPipeline pipeline = pipeline_.pipeline(kPipelineDebugView, d.features, depth_test);
            if (pipeline != bound_pipeline) {
                fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                bound_pipeline = pipeline;
            }
            bind_set(i, fields_[d.field_slot].sets[slot_].set);
            fn_.vkCmdDraw(cmd, DebugViewPipeline::kVerticesPerBox, d.instance_count, 0, d.first_instance);
        }
        return GRASS_SUCCESS;
    }

    // Blades first (they fill the depth buffer near the camera), then the volumes, then
    // the images on the ground far away.
    // The pipeline of each draw is the variant of its feature mask; binding one keeps the
    // vertex buffers and the descriptor set (same layout).
    const uint32_t stamps = timer_stamps(); // kUntimed: this record is not timed
    write_stamp(cmd, stamps, 0);
    VkPipeline bound_pipeline = VK_NULL_HANDLE;
    uint32_t bound_patch = UINT32_MAX;
    for (uint32_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& d = plan.draws[i];
        if (d.kind != GRASS_TIER_GEOMETRY || !drawn(d, false)) continue;
        const VkPipeline pipeline = pipeline_.pipeline(kPipelineBlade, d.features, depth_test);
        if (pipeline != bound_pipeline) {
            fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            bound_pipeline = pipeline;
        }
        bind_set(i, fields_[d.field_slot].sets[slot_].set);
        const PatchGpu& p = patches_[d.patch_slot];
        if (bound_patch != d.patch_slot) {
            const VkBuffer buffers[2] = {p.vertices.buffer, instances};
            const VkDeviceSize buffer_offsets[2] = {0, 0};
            fn_.vkCmdBindVertexBuffers(cmd, 0, 2, buffers, buffer_offsets);
            fn_.vkCmdBindIndexBuffer(cmd, p.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
            bound_patch = d.patch_slot;
        }
        fn_.vkCmdDrawIndexed(cmd, p.index_count, d.instance_count, 0, 0, d.first_instance);
    }
    write_stamp(cmd, stamps, 1);
    if (slice_draws == 0) {
        write_stamp(cmd, stamps, 2);
        write_stamp(cmd, stamps, 3);
        return GRASS_SUCCESS;
    }
    const struct {
        grass_tier_kind kind;
        PipelineKind pipeline;
        uint32_t vertices;
    } passes[2] = {
        {GRASS_TIER_VOLUME, kPipelineVolume, SlicePipelines::kVerticesPerVolume},
        {GRASS_TIER_IMAGE, kPipelineImage, SlicePipelines::kVerticesPerImage},
    };
    for (const auto& pass : passes) {
        bound_pipeline = VK_NULL_HANDLE;
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (d.kind != pass.kind || !draw_sets_[i]) continue;
            const VkPipeline pipeline = pipeline_.pipeline(pass.pipeline, d.features, depth_test);
            if (pipeline != bound_pipeline) {
                if (!bound_pipeline) {
                    // Binding 0 held the patch vertices of the blades.
                    fn_.vkCmdBindVertexBuffers(cmd, SlicePipelines::kInstanceBinding, 1, &instances, &zero);
                }
                fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                bound_pipeline = pipeline;
            }
            bind_set(i, draw_sets_[i]);
            const bool skirts = pass.kind == GRASS_TIER_IMAGE && (d.features & (1u << kMapHeight)) != 0;
            fn_.vkCmdDraw(cmd, skirts ? SlicePipelines::kVerticesPerImageWithSkirts : pass.vertices, d.instance_count, 0,
                          d.first_instance);
        }
        write_stamp(cmd, stamps, pass.kind == GRASS_TIER_VOLUME ? 2 : 3);
    }
    return GRASS_SUCCESS;
}

} // namespace grass::vk
