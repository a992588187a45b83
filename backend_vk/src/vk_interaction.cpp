#include "vk_interaction.hpp"

#include "vk_labels.hpp"
#include "vk_pipeline.hpp"
#include "vk_uploads.hpp"

#include <cstring>

namespace grass_vk_spirv {
extern const uint32_t interaction_comp[];
extern const uint32_t interaction_comp_size; // bytes
} // namespace grass_vk_spirv

namespace grass::vk {

namespace {

constexpr VkImageUsageFlags kMapImageUsage =
    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// A cleared texel (docs/responsive.md): no direction, underside and age "never".
constexpr VkClearColorValue kClearedTexel = {{0.0f, 0.0f, 1e30f, 1e30f}};

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

// The map's images are always GENERAL; `from` is UNDEFINED only for new ones.
VkImageMemoryBarrier map_barrier(VkImage image, VkImageLayout from, VkAccessFlags src, VkAccessFlags dst) {
    return image_barrier(image, 1, 1, from, VK_IMAGE_LAYOUT_GENERAL, src, dst);
}

} // namespace

InteractionPass::InteractionPass(const Functions& functions, VkDevice device, Memory& memory,
                                 DeferredDeletion& deferred, uint32_t frames_in_flight,
                                 const VkPhysicalDeviceLimits& limits)
    : fn_(functions), device_(device), memory_(memory), deferred_(deferred), frames_in_flight_(frames_in_flight),
      uniform_alignment_(limits.minUniformBufferOffsetAlignment ? limits.minUniformBufferOffsetAlignment : 1),
      storage_alignment_(limits.minStorageBufferOffsetAlignment ? limits.minStorageBufferOffsetAlignment : 1) {}

InteractionPass::~InteractionPass() {
    // The host guarantees the device is idle for grass work (context destruction).
    for (Image& m : maps_) deferred_.destroy_now(&m);
    for (Slot& s : slots_) deferred_.destroy_now(&s.data);
    if (pool_) fn_.vkDestroyDescriptorPool(device_, pool_, fn_.callbacks()); // frees the sets
    if (pipeline_) fn_.vkDestroyPipeline(device_, pipeline_, fn_.callbacks());
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
}

VkImageView InteractionPass::level_view(uint32_t level) const {
    if (levels_ == 0) return VK_NULL_HANDLE;
    return maps_[level < levels_ ? level : 0].view;
}

uint64_t InteractionPass::map_bytes() const { return maps_[0].allocated + maps_[1].allocated; }

bool InteractionPass::create_pipeline(VkFailure* failure, const char** what) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorSetLayoutBinding bindings[kInteractionBindingCount] = {
        {kInteractionBindingMap, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, compute, nullptr},
        {kInteractionBindingLevel, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, compute, nullptr},
        {kInteractionBindingColliders, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute, nullptr},
        {kInteractionBindingTileOffsets, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute, nullptr},
        {kInteractionBindingTileColliders, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute, nullptr},
    };
    if (!create_set_and_pipeline_layout(
            fn_, device_, bindings, kInteractionBindingCount, nullptr, "the interaction pass's descriptor set layout",
            "the interaction pass's pipeline layout", &set_layout_, &layout_, failure, what)) {
        return false;
    }

    const uint32_t sets = 2 * frames_in_flight_;
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, sets},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * sets},
    };
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = sets;
    pool_info.poolSizeCount = 3;
    pool_info.pPoolSizes = sizes;
    *what = "the interaction pass's descriptor pool";
    if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &pool_info, fn_.callbacks(), &pool_), "vkCreateDescriptorPool",
               failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, *what);
    VkDescriptorSetLayout set_layouts[2 * kMaxFramesInFlight];
    for (uint32_t i = 0; i < sets; ++i) set_layouts[i] = set_layout_;
    VkDescriptorSet allocated[2 * kMaxFramesInFlight] = {};
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = sets;
    alloc.pSetLayouts = set_layouts;
    *what = "the interaction pass's descriptor sets";
    if (!vk_ok(fn_.vkAllocateDescriptorSets(device_, &alloc, allocated), "vkAllocateDescriptorSets", failure)) {
        return false;
    }
    for (uint32_t i = 0; i < frames_in_flight_; ++i) {
        slots_[i].sets[0] = allocated[2 * i];
        slots_[i].sets[1] = allocated[2 * i + 1];
    }

    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = grass_vk_spirv::interaction_comp_size;
    module_info.pCode = grass_vk_spirv::interaction_comp;
    VkShaderModule module = VK_NULL_HANDLE;
    *what = "the interaction pass's shader module";
    if (!vk_ok(fn_.vkCreateShaderModule(device_, &module_info, fn_.callbacks(), &module), "vkCreateShaderModule",
               failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_SHADER_MODULE, module, *what);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = layout_;
    *what = "the interaction pass's compute pipeline";
    const bool ok = vk_ok(fn_.vkCreateComputePipelines(device_, cache_, 1, &info, fn_.callbacks(), &pipeline_),
                          "vkCreateComputePipelines", failure);
    fn_.vkDestroyShaderModule(device_, module, fn_.callbacks());
    if (!ok) pipeline_ = VK_NULL_HANDLE;
    if (ok) name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE, pipeline_, *what);
    return ok;
}

bool InteractionPass::create_map(const InteractionPlan& plan, uint64_t frame, VkFailure* failure, const char** what) {
    Image fresh[2];
    *what = "an interaction map image";
    for (uint32_t l = 0; l < plan.levels; ++l) {
        if (!deferred_.create_image(plan.resolution, plan.resolution, kInteractionMapFormat, kMapImageUsage, &fresh[l],
                                    failure)) {
            for (Image& f : fresh) deferred_.destroy_now(&f);
            return false;
        }
    }
    // Frames in flight may still read the old map.
    for (uint32_t l = 0; l < 2; ++l) {
        deferred_.retire(&maps_[l], frame);
        maps_[l] = fresh[l];
    }
    levels_ = plan.levels;
    resolution_ = plan.resolution;
    defined_ = false;
    clear_pending_ = true;
    return true;
}

void InteractionPass::release(uint64_t frame) {
    for (Image& m : maps_) deferred_.retire(&m, frame);
    for (Slot& s : slots_) deferred_.retire(&s.data, frame);
    levels_ = resolution_ = 0;
    defined_ = clear_pending_ = false;
}

VkDeviceSize InteractionPass::layout(Slot& s, const InteractionPlan& plan) const {
    // [Interaction block of each level][colliders][tile offsets 0][tile colliders 0][1][1];
    // an empty array still gets a few bytes (a descriptor's range is never 0).
    VkDeviceSize at = 0;
    const auto place = [&](uint32_t binding, uint32_t level, VkDeviceSize bytes, VkDeviceSize alignment) {
        at = align_up(at, alignment);
        s.offsets[binding][level] = at;
        s.ranges[binding][level] = bytes > 0 ? bytes : 16;
        at += s.ranges[binding][level];
    };
    for (uint32_t l = 0; l < 2; ++l) {
        place(kInteractionBindingLevel, l, sizeof(InteractionLevelUniforms), uniform_alignment_);
    }
    place(kInteractionBindingColliders, 0, plan.colliders.size() * sizeof(GpuCollider), storage_alignment_);
    s.offsets[kInteractionBindingColliders][1] = s.offsets[kInteractionBindingColliders][0];
    s.ranges[kInteractionBindingColliders][1] = s.ranges[kInteractionBindingColliders][0];
    for (uint32_t l = 0; l < 2; ++l) {
        place(kInteractionBindingTileOffsets, l, plan.tile_offsets[l].size() * sizeof(uint32_t), storage_alignment_);
        place(kInteractionBindingTileColliders, l, plan.tile_colliders[l].size() * sizeof(uint32_t),
              storage_alignment_);
    }
    return at;
}

bool InteractionPass::prepare(uint32_t slot, uint64_t frame, const InteractionPlan& plan, VkFailure* failure,
                              const char** what) {
    if (!pipeline_ && !create_pipeline(failure, what)) return false;
    if (plan.map_is_new || levels_ != plan.levels || resolution_ != plan.resolution) {
        if (!create_map(plan, frame, failure, what)) return false;
    }
    Slot& s = slots_[slot];
    Slot laid = s;
    const VkDeviceSize bytes = layout(laid, plan);
    if (bytes > s.data.size) {
        // Double so that a growing crowd reallocates a few times only.
        Buffer fresh;
        *what = "the interaction pass's per-frame buffer";
        const VkDeviceSize size = bytes > 2 * s.data.size ? bytes : 2 * s.data.size;
        if (!deferred_.create_buffer(size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     MemoryUse::streaming, &fresh, failure)) {
            return false;
        }
        deferred_.retire(&laid.data, frame); // the slot's last frame has finished; retiring is cheap
        laid.data = fresh;
    }
    s = laid;

    auto* out = static_cast<unsigned char*>(s.data.mapped);
    const auto copy = [&](uint32_t binding, uint32_t level, const void* from, size_t size) {
        if (size > 0) std::memcpy(out + s.offsets[binding][level], from, size);
    };
    for (uint32_t l = 0; l < 2; ++l)
        copy(kInteractionBindingLevel, l, &plan.level[l], sizeof(InteractionLevelUniforms));
    copy(kInteractionBindingColliders, 0, plan.colliders.data(), plan.colliders.size() * sizeof(GpuCollider));
    for (uint32_t l = 0; l < 2; ++l) {
        copy(kInteractionBindingTileOffsets, l, plan.tile_offsets[l].data(),
             plan.tile_offsets[l].size() * sizeof(uint32_t));
        copy(kInteractionBindingTileColliders, l, plan.tile_colliders[l].data(),
             plan.tile_colliders[l].size() * sizeof(uint32_t));
    }
    *what = "the interaction pass's per-frame buffer";
    if (!memory_.flush(s.data, 0, bytes, failure)) return false;

    // The slot's sets were last used by its frame of frames_in_flight ago, which is done.
    for (uint32_t l = 0; l < levels_; ++l) {
        const VkDescriptorImageInfo image{VK_NULL_HANDLE, maps_[l].view, VK_IMAGE_LAYOUT_GENERAL};
        VkDescriptorBufferInfo buffers[kInteractionBindingMap];
        VkWriteDescriptorSet writes[kInteractionBindingCount];
        for (uint32_t b = 0; b < kInteractionBindingCount; ++b) {
            writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[b].dstSet = s.sets[l];
            writes[b].dstBinding = b;
            writes[b].descriptorCount = 1;
            if (b == kInteractionBindingMap) {
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
                writes[b].pImageInfo = &image;
                continue;
            }
            buffers[b] = {s.data.buffer, s.offsets[b][l], s.ranges[b][l]};
            writes[b].descriptorType =
                b == kInteractionBindingLevel ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[b].pBufferInfo = &buffers[b];
        }
        fn_.vkUpdateDescriptorSets(device_, kInteractionBindingCount, writes, 0, nullptr);
    }
    return true;
}

void InteractionPass::record(VkCommandBuffer cmd, uint32_t slot, const InteractionPlan& plan) {
    const Slot& s = slots_[slot];
    VkImageMemoryBarrier barriers[2];
    const uint32_t levels = levels_ < plan.levels ? levels_ : plan.levels;
    if (clear_pending_) {
        // New images: UNDEFINED -> GENERAL, then every texel cleared (the pass would clear
        // them too when the core asks for it; this keeps the map defined whatever it asks).
        for (uint32_t l = 0; l < levels_; ++l) {
            barriers[l] = map_barrier(maps_[l].image, VK_IMAGE_LAYOUT_UNDEFINED, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
        }
        fn_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr,
                                 0, nullptr, levels_, barriers);
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        for (uint32_t l = 0; l < levels_; ++l) {
            fn_.vkCmdClearColorImage(cmd, maps_[l].image, VK_IMAGE_LAYOUT_GENERAL, &kClearedTexel, 1, &range);
        }
    }
    // Before the pass: the map persists from frame to frame. Earlier frames' draws read it
    // (vertex and fragment shaders: write-after-read, an execution dependency), their pass
    // wrote it and the clear above may have (write-after-write / read-after-write).
    const VkPipelineStageFlags src_stages = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    for (uint32_t l = 0; l < levels; ++l) {
        barriers[l] = map_barrier(maps_[l].image, VK_IMAGE_LAYOUT_GENERAL,
                                  VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
    fn_.vkCmdPipelineBarrier(cmd, src_stages, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, levels,
                             barriers);

    fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const uint32_t groups = (plan.resolution + kInteractionGroupSize - 1) / kInteractionGroupSize;
    for (uint32_t l = 0; l < levels; ++l) {
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &s.sets[l], 0, nullptr);
        fn_.vkCmdDispatch(cmd, groups, groups, 1);
    }

    // After it: the compute writes -> this frame's draws (texelFetch in the vertex and
    // fragment shaders).
    for (uint32_t l = 0; l < levels; ++l) {
        barriers[l] =
            map_barrier(maps_[l].image, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
    }
    fn_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr,
                             0, nullptr, levels, barriers);
    clear_pending_ = false;
    defined_ = true;
}

bool InteractionPass::state_inputs(uint32_t slot, VkDescriptorBufferInfo out[4]) const {
    const Slot& s = slots_[slot];
    if (s.data.buffer == VK_NULL_HANDLE) return false;
    const uint32_t bindings[4] = {kInteractionBindingColliders, kInteractionBindingTileOffsets,
                                  kInteractionBindingTileColliders, kInteractionBindingLevel};
    for (uint32_t i = 0; i < 4; ++i) out[i] = {s.data.buffer, s.offsets[bindings[i]][0], s.ranges[bindings[i]][0]};
    return true;
}

} // namespace grass::vk
