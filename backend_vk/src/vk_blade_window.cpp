// The blade window pass on Vulkan (vk_blade_window.hpp; the barriers in grass_vk.h): the
// pass's pipelines, buffers and recording, and the backend's side of it: begin_view plans
// the buffers (prepare_blade_window), grass_vk_prepare records the pass after the
// interaction pass (record_blade_window), the draws bind the table and poses (window_views).
#include "vk_blade_window.hpp"

#include "vk_backend.hpp"
#include "vk_labels.hpp"
#include "vk_pipeline.hpp"

#include "context/context.hpp"

#include <cstring>

namespace grass_vk_spirv {
extern const uint32_t blade_window_comp_grass_responsive[];
extern const uint32_t blade_window_comp_grass_responsive_size; // bytes
extern const uint32_t blade_window_comp_grass_responsive_grass_indexed_blocks[];
extern const uint32_t blade_window_comp_grass_responsive_grass_indexed_blocks_size;
} // namespace grass_vk_spirv

namespace grass::vk {

namespace {

// Set 1's bindings (WindowPassBinding), all read by the compute stage only.
constexpr VkDescriptorSetLayoutBinding kPassBindings[kWindowPassBindingCount] = {
    {kWindowPassBindingInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {kWindowPassBindingVertices, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {kWindowPassBindingWork, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
};
// Set 2's bindings (WindowStateBinding).
constexpr VkDescriptorSetLayoutBinding kStateBindings[kWindowStateBindingCount] = {
    {kWindowStateBindingColliders, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {kWindowStateBindingTileOffsets, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {kWindowStateBindingTileColliders, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {kWindowStateBindingLevel, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
};
// The work items' buffers are at least this large: they stand in for the state set's uniform
// block (InteractionLevelUniforms) when there are no colliders.
constexpr VkDeviceSize kMinWorkBytes = 256;

} // namespace

BladeWindowPass::BladeWindowPass(const Functions& functions, VkDevice device, Memory& memory,
                                 DeferredDeletion& deferred, uint32_t frames_in_flight, bool indexed_blocks,
                                 HostAllocator* host)
    : fn_(functions), device_(device), memory_(memory), deferred_(deferred), frames_in_flight_(frames_in_flight),
      indexed_blocks_(indexed_blocks), pipelines_(StlAllocator<Pipeline>(host)) {}

BladeWindowPass::~BladeWindowPass() {
    // The host guarantees the device is idle for grass work (context destruction).
    deferred_.destroy_now(&poses_);
    for (Buffer& t : tables_) deferred_.destroy_now(&t);
    for (Buffer& w : works_) deferred_.destroy_now(&w);
    if (state_pool_) fn_.vkDestroyDescriptorPool(device_, state_pool_, fn_.callbacks()); // frees its sets
    if (state_layout_) fn_.vkDestroyDescriptorSetLayout(device_, state_layout_, fn_.callbacks());
    for (Pipeline& p : pipelines_) fn_.vkDestroyPipeline(device_, p.pipeline, fn_.callbacks());
    if (layout_) fn_.vkDestroyPipelineLayout(device_, layout_, fn_.callbacks());
    if (set_layout_) fn_.vkDestroyDescriptorSetLayout(device_, set_layout_, fn_.callbacks());
}

uint64_t BladeWindowPass::bytes() const {
    uint64_t bytes = poses_.allocated;
    for (const Buffer& t : tables_) bytes += t.allocated;
    for (const Buffer& w : works_) bytes += w.allocated;
    return bytes;
}

VkPipeline BladeWindowPass::pipeline(uint32_t features) const {
    for (const Pipeline& p : pipelines_) {
        if (p.features == (features & kBladeWindowPassFeatures)) return p.pipeline;
    }
    return VK_NULL_HANDLE;
}

bool BladeWindowPass::create_layouts(VkDescriptorSetLayout blade_set, VkFailure* failure, const char** what) {
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = kWindowPassBindingCount;
    set_info.pBindings = kPassBindings;
    *what = "the blade window pass's descriptor set layout";
    if (!vk_ok(fn_.vkCreateDescriptorSetLayout(device_, &set_info, fn_.callbacks(), &set_layout_),
               "vkCreateDescriptorSetLayout", failure)) {
        set_layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, set_layout_, *what);
    set_info.bindingCount = kWindowStateBindingCount;
    set_info.pBindings = kStateBindings;
    *what = "the blade window pass's state descriptor set layout";
    if (!vk_ok(fn_.vkCreateDescriptorSetLayout(device_, &set_info, fn_.callbacks(), &state_layout_),
               "vkCreateDescriptorSetLayout", failure)) {
        state_layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, state_layout_, *what);
    if (!create_state_sets(failure, what)) return false;
    const VkDescriptorSetLayout sets[3] = {blade_set, set_layout_, state_layout_};
    // The indexed-block module reads the Frame and Field blocks at a pushed index (0).
    const VkPushConstantRange block_index{VK_SHADER_STAGE_COMPUTE_BIT, 0, kBlockIndexBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 3;
    info.pSetLayouts = sets;
    info.pushConstantRangeCount = indexed_blocks_ ? 1 : 0;
    info.pPushConstantRanges = &block_index;
    *what = "the blade window pass's pipeline layout";
    if (!vk_ok(fn_.vkCreatePipelineLayout(device_, &info, fn_.callbacks(), &layout_), "vkCreatePipelineLayout",
               failure)) {
        layout_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, *what);
    return true;
}

bool BladeWindowPass::create_state_sets(VkFailure* failure, const char** what) {
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * frames_in_flight_},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frames_in_flight_},
    };
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = frames_in_flight_;
    pool_info.poolSizeCount = 2;
    pool_info.pPoolSizes = sizes;
    *what = "the blade window pass's state descriptor pool";
    if (!vk_ok(fn_.vkCreateDescriptorPool(device_, &pool_info, fn_.callbacks(), &state_pool_), "vkCreateDescriptorPool",
               failure)) {
        state_pool_ = VK_NULL_HANDLE;
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, state_pool_, *what);
    VkDescriptorSetLayout layouts[kMaxFramesInFlight];
    for (uint32_t s = 0; s < frames_in_flight_; ++s) layouts[s] = state_layout_;
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = state_pool_;
    alloc.descriptorSetCount = frames_in_flight_;
    alloc.pSetLayouts = layouts;
    *what = "the blade window pass's state descriptor sets";
    return vk_ok(fn_.vkAllocateDescriptorSets(device_, &alloc, state_sets_), "vkAllocateDescriptorSets", failure);
}

bool BladeWindowPass::ensure_pipeline(VkDescriptorSetLayout blade_set, uint32_t features, VkFailure* failure,
                                      const char** what) {
    const uint32_t mask = features & kBladeWindowPassFeatures;
    if (pipeline(mask) != VK_NULL_HANDLE) return true;
    if (layout_ == VK_NULL_HANDLE && !create_layouts(blade_set, failure, what)) return false;
    pipelines_.reserve(pipelines_.size() + 1); // may throw: nothing made yet

    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = indexed_blocks_
                               ? grass_vk_spirv::blade_window_comp_grass_responsive_grass_indexed_blocks_size
                               : grass_vk_spirv::blade_window_comp_grass_responsive_size;
    module_info.pCode = indexed_blocks_ ? grass_vk_spirv::blade_window_comp_grass_responsive_grass_indexed_blocks
                                        : grass_vk_spirv::blade_window_comp_grass_responsive;
    VkShaderModule module = VK_NULL_HANDLE;
    *what = "the blade window pass's shader module";
    if (!vk_ok(fn_.vkCreateShaderModule(device_, &module_info, fn_.callbacks(), &module), "vkCreateShaderModule",
               failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_SHADER_MODULE, module, *what);
    // GRASS_FEATURES (constant id 0, blade_interface.glsl): the draw's maps, wind and map.
    const VkSpecializationMapEntry entry{0, 0, sizeof(uint32_t)};
    const VkSpecializationInfo specialization{1, &entry, sizeof(uint32_t), &mask};
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &specialization;
    info.layout = layout_;
    VkPipeline made = VK_NULL_HANDLE;
    *what = "the blade window pass's compute pipeline";
    const bool ok = vk_ok(fn_.vkCreateComputePipelines(device_, cache_, 1, &info, fn_.callbacks(), &made),
                          "vkCreateComputePipelines", failure);
    fn_.vkDestroyShaderModule(device_, module, fn_.callbacks());
    if (!ok) return false;
    name_object(fn_, device_, VK_OBJECT_TYPE_PIPELINE, made, *what);
    pipelines_.push_back(Pipeline{mask, made}); // reserved above
    return true;
}

bool BladeWindowPass::grow_streaming(Buffer* buffers, VkDeviceSize bytes, uint64_t frame, const char* name,
                                     VkFailure* failure) {
    if (bytes <= buffers[0].size) return true;
    // Every slot's buffer at once, all of one size: the window's memory is the plan's, not
    // the history of which slot grew when. Frames in flight keep reading the old ones.
    Buffer fresh[kMaxFramesInFlight];
    const VkDeviceSize size = bytes > 2 * buffers[0].size ? bytes : 2 * buffers[0].size;
    for (uint32_t s = 0; s < frames_in_flight_; ++s) {
        if (!deferred_.create_buffer(size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                     MemoryUse::streaming, &fresh[s], failure)) {
            for (Buffer& f : fresh) deferred_.destroy_now(&f);
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, fresh[s].buffer, name);
    }
    for (uint32_t s = 0; s < frames_in_flight_; ++s) {
        deferred_.retire(&buffers[s], frame);
        buffers[s] = fresh[s];
    }
    return true;
}

bool BladeWindowPass::prepare(uint32_t slot, uint64_t frame, const BladeWindowPlan& plan, VkFailure* failure,
                              const char** what) {
    // The sizes are the plan's (the core's records per blade and slot, its table's entries).
    const VkDeviceSize pose_bytes = plan.pose_bytes > 0 ? plan.pose_bytes : 16;
    const VkDeviceSize table_bytes = plan.table.empty() ? 16 : VkDeviceSize(plan.table.size()) * sizeof(uint32_t);
    const VkDeviceSize work_bytes = VkDeviceSize(plan.work.size()) * sizeof(uint32_t);
    *what = "the blade window's table";
    if (!grow_streaming(tables_, table_bytes, frame, "grass blade window table", failure)) return false;
    *what = "the blade window's work items";
    if (!grow_streaming(works_, work_bytes > kMinWorkBytes ? work_bytes : kMinWorkBytes, frame,
                        "grass blade window work", failure)) {
        return false;
    }
    if (pose_bytes > poses_.size) {
        // Grown to what the plan asks, no more (up to kMaxBladeWindowPoseBytes). The slots the
        // core keeps keep their records: record() copies the old buffer into the new one, which
        // is retired at this frame (frames in flight read it, this frame's copy too).
        Buffer fresh;
        *what = "the blade window's poses";
        if (!deferred_.create_buffer(pose_bytes,
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                     MemoryUse::device_local, &fresh, failure)) {
            return false;
        }
        name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, fresh.buffer, "grass blade window poses");
        // Grown twice before a pass: the first source (retired at this frame too) is still the one.
        if (poses_.buffer != VK_NULL_HANDLE && grown_from_ == VK_NULL_HANDLE) {
            grown_from_ = poses_.buffer;
            grown_bytes_ = poses_.size;
        }
        deferred_.retire(&poses_, frame);
        poses_ = fresh;
    }
    Buffer& table = tables_[slot];
    Buffer& work = works_[slot];
    if (!plan.table.empty()) std::memcpy(table.mapped, plan.table.data(), plan.table.size() * sizeof(uint32_t));
    if (!plan.work.empty()) std::memcpy(work.mapped, plan.work.data(), work_bytes);
    *what = "the blade window's table";
    if (!memory_.flush(table, 0, table_bytes, failure)) return false;
    *what = "the blade window's work items";
    return work_bytes == 0 || memory_.flush(work, 0, work_bytes, failure);
}

void BladeWindowPass::release(uint64_t frame) {
    deferred_.retire(&poses_, frame);
    for (Buffer& t : tables_) deferred_.retire(&t, frame);
    for (Buffer& w : works_) deferred_.retire(&w, frame);
    grown_from_ = VK_NULL_HANDLE;
}

void BladeWindowPass::write_state_set(uint32_t slot, const VkDescriptorBufferInfo* inputs) const {
    const VkDescriptorBufferInfo stand_in{works_[slot].buffer, 0, kMinWorkBytes};
    VkWriteDescriptorSet writes[kWindowStateBindingCount];
    for (uint32_t b = 0; b < kWindowStateBindingCount; ++b) {
        writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = state_sets_[slot];
        writes[b].dstBinding = kStateBindings[b].binding;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = kStateBindings[b].descriptorType;
        writes[b].pBufferInfo = inputs != nullptr ? &inputs[b] : &stand_in;
    }
    fn_.vkUpdateDescriptorSets(device_, kWindowStateBindingCount, writes, 0, nullptr);
}

void BladeWindowPass::write_dispatch_set(VkDescriptorSet set, uint32_t slot, VkBuffer instances,
                                         VkBuffer vertices) const {
    const VkDescriptorBufferInfo buffers[kWindowPassBindingCount] = {
        {instances, 0, VK_WHOLE_SIZE}, {vertices, 0, VK_WHOLE_SIZE}, {works_[slot].buffer, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet writes[kWindowPassBindingCount];
    for (uint32_t b = 0; b < kWindowPassBindingCount; ++b) {
        writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = set;
        writes[b].dstBinding = kPassBindings[b].binding;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = kPassBindings[b].descriptorType;
        writes[b].pBufferInfo = &buffers[b];
    }
    fn_.vkUpdateDescriptorSets(device_, kWindowPassBindingCount, writes, 0, nullptr);
}

void BladeWindowPass::record(VkCommandBuffer cmd, uint32_t slot, const WindowDispatch* dispatches, uint32_t count) {
    if (grown_from_ != VK_NULL_HANDLE) {
        // The records grew: the earlier frames' passes wrote the old buffer (write -> copy read).
        VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        fn_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                                 &written, 0, nullptr, 0, nullptr);
        const VkBufferCopy region{0, 0, grown_bytes_};
        fn_.vkCmdCopyBuffer(cmd, grown_from_, poses_.buffer, 1, &region);
        grown_from_ = VK_NULL_HANDLE;
    }
    // Before the pass (grass_vk.h): the earlier frames' draws read the poses (write-after-read:
    // frames in flight share them), their pass wrote them (write-after-write), this frame's
    // interaction pass wrote the map and its uploads the patches' vertices and curves that the
    // pass reads (read-after-write).
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    fn_.vkCmdPipelineBarrier(cmd,
                             VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    if (indexed_blocks_) {
        const uint32_t block_index = 0;
        fn_.vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, kBlockIndexBytes, &block_index);
    }
    VkPipeline bound = VK_NULL_HANDLE;
    for (uint32_t i = 0; i < count; ++i) {
        const WindowDispatch& d = dispatches[i];
        const VkPipeline p = pipeline(d.features);
        if (p != bound) {
            fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p);
            bound = p;
        }
        const VkDescriptorSet sets[3] = {d.blade_set, d.pass_set, state_sets_[slot]};
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 3, sets, 2, d.block_offsets);
        fn_.vkCmdDispatch(cmd, (d.blades + kWindowGroupSize - 1) / kWindowGroupSize, d.items, 1);
    }
    // After it: the poses -> every view's window variant this frame (blade.vert).
    VkBufferMemoryBarrier after{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    after.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    after.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    after.buffer = poses_.buffer;
    after.offset = 0;
    after.size = VK_WHOLE_SIZE;
    fn_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT, 0, 0,
                             nullptr, 1, &after, 0, nullptr);
}

// ---- The backend's side ------------------------------------------------------------------

bool VkBackend::prepare_blade_window(const FramePlan& plan, VkFailure* failure, const char** what) {
    const BladeWindowPlan& window = plan.blade_window;
    if (window.dispatches.empty()) {
        if (window_.has_window()) window_.release(frame_); // still grass holds no window
        window_pending_ = false;
        return true;
    }
    for (const BladeWindowDispatch& d : window.dispatches) {
        if (!window_.ensure_pipeline(pipeline_.set_layout(), plan.draws[d.draw].features, failure, what)) return false;
    }
    if (!window_.prepare(slot_, frame_, window, failure, what)) return false;
    window_pending_ = true;
    return true;
}

grass_result VkBackend::record_blade_window(VkCommandBuffer cmd) {
    const FramePlan& plan = ctx_->views.plan(0);
    const uint32_t vs = view_slot(slot_, 0);
    // Every set first (may throw std::bad_alloc or fail), then the writes and the commands.
    window_dispatches_.clear();
    for (const BladeWindowDispatch& bd : plan.blade_window.dispatches) {
        const TierDraw& d = plan.draws[bd.draw];
        if (!drawn(d, false) || !patches_[d.patch_slot].curves.buffer) continue; // its draw is skipped or refused
        WindowDispatch w{};
        w.block_offsets[0] = ring_.frame_offset();
        w.block_offsets[1] = ring_.field_offset(bd.draw);
        w.features = d.features;
        w.blades = static_cast<uint32_t>(patches_[d.patch_slot].curves.size / (8 * sizeof(float)));
        w.items = bd.items;
        VkFailure failure;
        if (!frame_sets_.allocate(vs, pipeline_.set_layout(), &w.blade_set, &failure) ||
            !frame_sets_.allocate(vs, window_.set_layout(), &w.pass_set, &failure)) {
            return fail("grass_vk_prepare", "a descriptor set of the blade window pass", failure);
        }
        window_dispatches_.push_back(w);
    }
    uint32_t n = 0;
    for (const BladeWindowDispatch& bd : plan.blade_window.dispatches) {
        const TierDraw& d = plan.draws[bd.draw];
        if (!drawn(d, false) || !patches_[d.patch_slot].curves.buffer) continue;
        const WindowDispatch& w = window_dispatches_[n++];
        // The draw's set with the window bound whatever its variant: the pass writes the poses.
        SetViews views = draw_views(d);
        views.window_table = window_.table(slot_);
        views.window_poses = window_.poses();
        write_set(w.blade_set, vs, fields_[d.field_slot], views);
        window_.write_dispatch_set(w.pass_set, slot_, ring_.instance_buffer(vs),
                                   patches_[d.patch_slot].vertices.buffer);
    }
    // The state's push-out reads the colliders the interaction pass binned to its fine level.
    VkDescriptorBufferInfo inputs[kWindowStateBindingCount];
    const bool colliders = ctx_->plan.interaction.levels > 0 && interaction_.state_inputs(slot_, inputs);
    window_.write_state_set(slot_, colliders ? inputs : nullptr);
    const LabelScope label(fn_, cmd, "grass blade window pass");
    window_.record(cmd, slot_, window_dispatches_.data(), static_cast<uint32_t>(window_dispatches_.size()));
    window_pending_ = false;
    return GRASS_SUCCESS;
}

} // namespace grass::vk
