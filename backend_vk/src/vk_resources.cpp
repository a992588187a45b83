// The Vulkan backend's resources: uploads and releases of patches, baked slice sets,
// design maps and fields. New data waits in staging buffers until prepare_frame records
// its copies (vk_record.cpp); what frames in flight may still read is retired to the
// deferred deletion queue.
#include "vk_backend.hpp"

#include "context/context.hpp"
#include "vk_staging.hpp"

#include <algorithm>
#include <cstring>

namespace grass::vk {

namespace {

// A storage buffer too: the blade window pass reads the blades' roots (vk_blade_window.hpp).
constexpr VkBufferUsageFlags kVertexUsage =
    VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkBufferUsageFlags kIndexUsage = VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

} // namespace

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

    VkFailure failure;
    const char* what = "the patch vertex buffer";
    bool ok = deferred_.create_buffer(vertex_bytes, kVertexUsage, MemoryUse::device_local, &fresh.vertices, &failure);
    if (ok) {
        what = "the patch index buffer";
        ok = deferred_.create_buffer(index_bytes, kIndexUsage, MemoryUse::device_local, &fresh.indices, &failure);
    }
    if (ok) {
        what = "the patch staging buffer";
        ok = deferred_.create_buffer(vertex_bytes + index_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging,
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
    deferred_.destroy_now(&p->vertices);
    deferred_.destroy_now(&p->indices);
    deferred_.destroy_now(&p->staging);
    if (p->curves_pending) pending_uploads_ -= 1;
    deferred_.destroy_now(&p->curves);
    deferred_.destroy_now(&p->curves_staging);
    *p = PatchGpu{};
}

void VkBackend::release_patch(uint32_t slot) {
    if (slot >= patches_.size() || !patches_[slot].live) return;
    PatchGpu& p = patches_[slot];
    if (p.pending) {
        // Its copy was never recorded: the staging buffer goes now.
        deferred_.destroy_now(&p.staging);
        pending_uploads_ -= 1;
    }
    if (p.curves_pending) {
        deferred_.destroy_now(&p.curves_staging);
        pending_uploads_ -= 1;
    }
    // Draws of frames still in flight may read the buffers.
    deferred_.retire(&p.vertices, frame_);
    deferred_.retire(&p.indices, frame_);
    deferred_.retire(&p.curves, frame_);
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

grass_result VkBackend::upload_blade_curves(uint32_t slot, const PatchData& patch) {
    const char* function = "grass_begin_frame"; // the core uploads them for the first frame that needs them
    if (slot >= patches_.size() || !patches_[slot].live) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "%s: blade curves for the patch in slot %u, which the Vulkan backend does not hold "
                          "(internal error)",
                          function, slot);
    }
    PatchGpu& p = patches_[slot];
    if (p.curves.buffer || patch.blade_curves.empty()) return GRASS_SUCCESS; // once per patch; empty: nothing drawn
    const VkDeviceSize bytes = VkDeviceSize(patch.blade_curves.size()) * sizeof(float);
    Buffer curves, staging;
    VkFailure failure;
    const char* what = "the patch's blade curves buffer";
    bool ok = deferred_.create_buffer(bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      MemoryUse::device_local, &curves, &failure);
    if (ok) {
        what = "the patch's blade curves staging buffer";
        ok = deferred_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, &staging, &failure);
    }
    if (ok) {
        std::memcpy(staging.mapped, patch.blade_curves.data(), static_cast<size_t>(bytes));
        ok = memory_.flush(staging, 0, bytes, &failure);
    }
    if (!ok) {
        deferred_.destroy_now(&curves); // never recorded: no GPU work can use them
        deferred_.destroy_now(&staging);
        return fail(function, what, failure);
    }
    p.curves = curves;
    p.curves_staging = staging;
    p.curves_pending = true;
    pending_uploads_ += 1;
    return GRASS_SUCCESS;
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

    VkFailure failure;
    const char* what = "the slice colour image";
    bool ok = deferred_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceColorFormat,
                                           kSliceUsage, &fresh.color, &failure);
    if (ok) {
        what = "the slice normal image";
        ok = deferred_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceNormalFormat,
                                          kSliceUsage, &fresh.normal, &failure);
    }
    if (ok) {
        what = "the slice threshold image";
        ok = deferred_.create_array_image(set.width, set.height, set.layers, set.mip_levels, kSliceThresholdFormat,
                                          kSliceUsage, &fresh.threshold, &failure);
    }
    const auto no_visit = [](uint32_t, uint32_t, VkDeviceSize, uint32_t, uint32_t) {};
    VkDeviceSize bytes = slice_staging_layout(fresh.color, kSliceColorBytes, 0, no_visit);
    bytes = slice_staging_layout(fresh.normal, kSliceNormalBytes, bytes, no_visit);
    bytes = slice_staging_layout(fresh.threshold, kSliceThresholdBytes, bytes, no_visit);
    if (ok) {
        what = "the slice staging buffer";
        ok = deferred_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, &fresh.staging,
                                     &failure);
    }
    if (ok) {
        // Level k of layer l starts at texel offset(l, k) of each array.
        auto* staging = static_cast<unsigned char*>(fresh.staging.mapped);
        const auto copier = [&](const void* source, uint32_t texel_bytes) {
            return
                [&, source, texel_bytes](uint32_t layer, uint32_t level, VkDeviceSize offset, uint32_t w, uint32_t h) {
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
    deferred_.destroy_now(&s->color);
    deferred_.destroy_now(&s->normal);
    deferred_.destroy_now(&s->threshold);
    deferred_.destroy_now(&s->staging);
    *s = SliceGpu{};
}

void VkBackend::release_slices(SliceGpu* s) {
    if (s->pending) {
        // Its copies were never recorded: the staging buffer goes now.
        deferred_.destroy_now(&s->staging);
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
    if (!deferred_.create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::staging, staging, failure)) {
        return false;
    }
    auto* out = static_cast<unsigned char*>(staging->mapped);
    for (uint32_t row = 0; row < region.height; ++row) {
        const uint16_t* from = map.texels + (size_t(region.y + row) * map.width + region.x) * map.channels;
        std::memcpy(out + row * row_bytes, from, row_bytes);
    }
    if (!memory_.flush(*staging, 0, bytes, failure)) {
        deferred_.destroy_now(staging);
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

    MapGpu fresh;
    fresh.live = true;
    fresh.channels = map.channels;
    VkFailure failure;
    const char* what = "";
    if (!stage_image(&fresh.image, &fresh.staging, map, &failure, &what)) {
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
    Buffer staging;
    if (!stage_region(&staging, map, merged, &failure)) {
        return fail(function, "a design map update staging buffer", failure);
    }
    if (m.updating) {
        // Its copy was never recorded: the old staging buffer goes now.
        deferred_.destroy_now(&m.update_staging);
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
    deferred_.destroy_now(&m->image);
    deferred_.destroy_now(&m->staging);
    deferred_.destroy_now(&m->update_staging);
    *m = MapGpu{};
}

void VkBackend::release_map(uint32_t slot) {
    if (slot >= maps_.size() || !maps_[slot].live) return;
    MapGpu& m = maps_[slot];
    // Copies never recorded: their staging buffers go now. (Once recorded, a staging
    // buffer was retired by prepare_frame.)
    if (m.pending) {
        deferred_.destroy_now(&m.staging);
        pending_uploads_ -= 1;
    }
    if (m.updating) {
        deferred_.destroy_now(&m.update_staging);
        pending_uploads_ -= 1;
    }
    // Draws of frames still in flight may sample it.
    deferred_.retire(&m.image, frame_);
    m = MapGpu{};
}

// ---- Fields -----------------------------------------------------------------------------

grass_result VkBackend::upload_field(uint32_t slot, const FieldMaps& maps) {
    const char* function = "grass_create_field";
    // The core checked the maps against the feature mask (check_field_maps).
    if (slot >= fields_.size()) fields_.resize(slot + 1, FieldGpu{}); // may throw: nothing made yet
    VkFailure failure;
    const char* what = "";
    // The shader variant of its maps, shared with every field of the same mask.
    if (!pipeline_.create_variants(maps.features, &failure, &what)) return fail(function, what, failure);

    FieldGpu fresh;
    fresh.live = true;
    fresh.features = maps.features;
    for (uint32_t role = 0; role < kMapRoleCount; ++role) fresh.map_slot[role] = maps.map_slot[role];
    for (uint32_t view = 0; view < views_made_; ++view) {
        if (!make_field_sets(&fresh, view, &failure)) {
            for (DescriptorSet& s : fresh.sets) deferred_.destroy_now(&s);
            return fail(function, "a field descriptor set", failure);
        }
    }
    fields_[slot] = fresh;
    return GRASS_SUCCESS;
}

bool VkBackend::make_field_sets(FieldGpu* field, uint32_t view, VkFailure* failure) {
    for (uint32_t i = 0; i < desc_.frames_in_flight; ++i) {
        const uint32_t vs = view_slot(i, view);
        if (field->sets[vs].set != VK_NULL_HANDLE) continue; // made by an earlier, failed try
        if (!deferred_.allocate_set(pipeline_.set_layout(), &field->sets[vs], failure)) return false;
        write_set(field->sets[vs].set, vs, *field, still_views());
    }
    return true;
}

bool VkBackend::make_view_slots(uint32_t view, VkFailure* failure, const char** what) {
    while (views_made_ <= view) {
        const uint32_t v = views_made_;
        for (uint32_t i = 0; i < desc_.frames_in_flight; ++i) {
            if (!ring_.create_slot(view_slot(i, v), failure, what)) return false;
        }
        *what = "a field descriptor set";
        for (FieldGpu& f : fields_) {
            if (f.live && !make_field_sets(&f, v, failure)) return false;
        }
        views_made_ = v + 1;
    }
    return true;
}

void VkBackend::destroy_field_now(FieldGpu* f) {
    // Context destruction: the device is idle for grass work.
    for (DescriptorSet& s : f->sets) deferred_.destroy_now(&s);
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

void VkBackend::set_field_wind_map(uint32_t slot, uint32_t map_slot) {
    // Only the sets written for its draws with kFeatureWindMap (record) point at it; the
    // field's own sets keep the stand-in.
    if (slot < fields_.size() && fields_[slot].live) fields_[slot].wind_map = map_slot;
}

} // namespace grass::vk
