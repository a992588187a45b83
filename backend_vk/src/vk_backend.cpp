#include "vk_backend.hpp"

#include "context.hpp"

#include <cstring>

namespace grass::vk {

namespace {

constexpr VkBufferUsageFlags kVertexUsage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkBufferUsageFlags kIndexUsage = VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kDensityUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

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

} // namespace

VkBackend::VkBackend(grass_context* context, const grass_vk_desc& vk_desc, const Device& device)
    : ctx_(context), desc_(vk_desc), device_(device), fn_(device_.fn),
      memory_(fn_, device_.device, device_.memory, device_.properties.limits.nonCoherentAtomSize),
      descriptors_(fn_, device_.device, &context->host),
      deferred_(memory_, descriptors_, &context->host, vk_desc.frames_in_flight), pipeline_(fn_, device_.device),
      debug_view_(fn_, device_.device),
      ring_(memory_, deferred_, vk_desc.frames_in_flight, device_.properties.limits.minUniformBufferOffsetAlignment),
      batch_(&context->host), patches_(StlAllocator<PatchGpu>(&context->host)),
      fields_(StlAllocator<FieldGpu>(&context->host)) {}

VkBackend::~VkBackend() {
    // The host guarantees the device is idle for grass work: everything goes at once.
    for (PatchGpu& p : patches_) destroy_patch_now(&p);
    for (FieldGpu& f : fields_) destroy_field_now(&f);
    deferred_.collect_all();
    memory_.destroy_buffer(&default_staging_);
    memory_.destroy_image(&default_density_);
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
    if (!debug_view_.create(target, pipeline_.layout(), &failure, &what)) return fail(function, what, failure);
    if (!ring_.create(&failure, &what)) return fail(function, what, failure);

    // The density map of fields without one: a single white texel (density x 1).
    const uint16_t white = 0xffff;
    deferred_.promise(1); // the staging buffer, retired once its copy is recorded
    if (!stage_image(&default_density_, &default_staging_, MapTexels{&white, 1, 1}, &failure, &what)) {
        return fail(function, "the default density map", failure);
    }
    pending_uploads_ += 1;
    return GRASS_SUCCESS;
}

bool VkBackend::stage_image(Image* image, Buffer* staging, const MapTexels& texels, VkFailure* failure,
                            const char** what) {
    *what = "a density map image";
    if (!memory_.create_image(texels.width, texels.height, kDensityMapFormat, kDensityUsage, image, failure)) {
        return false;
    }
    const VkDeviceSize bytes = VkDeviceSize(texels.width) * texels.height * sizeof(uint16_t);
    *what = "a density map staging buffer";
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
}

// ---- Fields -----------------------------------------------------------------------------

void VkBackend::write_set(VkDescriptorSet set, uint32_t slot, VkImageView view) {
    const VkBuffer uniforms = ring_.uniform_buffer(slot);
    const VkDescriptorBufferInfo frame_block{uniforms, 0, sizeof(FrameUniforms)};
    const VkDescriptorBufferInfo field_block{uniforms, 0, sizeof(FieldUniforms)};
    const VkDescriptorImageInfo density{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet writes[3];
    for (uint32_t i = 0; i < 3; ++i) {
        writes[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    }
    writes[kBindingFrame].pBufferInfo = &frame_block;
    writes[kBindingField].pBufferInfo = &field_block;
    writes[kBindingDensityMap].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[kBindingDensityMap].pImageInfo = &density; // the sampler is immutable, in the layout
    fn_.vkUpdateDescriptorSets(device_.device, 3, writes, 0, nullptr);
}

grass_result VkBackend::upload_field(uint32_t slot, const MapTexels& density) {
    const char* function = "grass_create_field";
    if (slot >= fields_.size()) fields_.resize(slot + 1, FieldGpu{}); // may throw: nothing made yet
    const bool has_map = density.texels != nullptr;
    const uint32_t promised = desc_.frames_in_flight + (has_map ? 2 : 0); // sets, image, staging
    deferred_.promise(promised);

    FieldGpu fresh;
    fresh.live = true;
    VkFailure failure;
    const char* what = "";
    bool ok = !has_map || stage_image(&fresh.density, &fresh.staging, density, &failure, &what);
    for (uint32_t i = 0; ok && i < desc_.frames_in_flight; ++i) {
        what = "a field descriptor set";
        ok = descriptors_.allocate(pipeline_.set_layout(), &fresh.sets[i], &failure);
    }
    if (!ok) {
        memory_.destroy_image(&fresh.density);
        memory_.destroy_buffer(&fresh.staging);
        for (DescriptorSet& s : fresh.sets) descriptors_.free(&s);
        deferred_.forgo(promised);
        return fail(function, what, failure);
    }
    const VkImageView view = has_map ? fresh.density.view : default_density_.view;
    for (uint32_t i = 0; i < desc_.frames_in_flight; ++i) write_set(fresh.sets[i].set, i, view);
    if (has_map) {
        fresh.pending = true;
        pending_uploads_ += 1;
    }
    fields_[slot] = fresh;
    return GRASS_SUCCESS;
}

void VkBackend::destroy_field_now(FieldGpu* f) {
    // Context destruction: the device is idle for grass work.
    if (f->pending) pending_uploads_ -= 1;
    memory_.destroy_image(&f->density);
    memory_.destroy_buffer(&f->staging);
    for (DescriptorSet& s : f->sets) descriptors_.free(&s);
    *f = FieldGpu{};
}

void VkBackend::release_field(uint32_t slot) {
    if (slot >= fields_.size() || !fields_[slot].live) return;
    FieldGpu& f = fields_[slot];
    if (f.pending) {
        // Its copy was never recorded: the staging buffer goes now. (Once recorded, the
        // staging buffer was retired by prepare_frame.)
        memory_.destroy_buffer(&f.staging);
        deferred_.forgo(1);
        pending_uploads_ -= 1;
    }
    deferred_.retire(&f.density, frame_);
    for (DescriptorSet& s : f.sets) deferred_.retire(&s, frame_);
    f = FieldGpu{};
}

// ---- Frames -----------------------------------------------------------------------------

grass_result VkBackend::begin_frame(const FramePlan& plan) {
    frame_ += 1;
    slot_ = static_cast<uint32_t>(frame_ % desc_.frames_in_flight);
    // Frame frame_ - frames_in_flight has finished: what it was the last to use can go.
    deferred_.collect(frame_);

    bool uniforms_replaced = false;
    VkFailure failure;
    const char* what = "";
    if (!ring_.write(slot_, plan, frame_, &uniforms_replaced, &failure, &what)) {
        return fail("grass_begin_frame", what, failure);
    }
    if (uniforms_replaced) {
        // This slot's sets were last used by frame frame_ - frames_in_flight, which is done.
        for (const FieldGpu& f : fields_) {
            if (f.live) write_set(f.sets[slot_].set, slot_, f.density.image ? f.density.view : default_density_.view);
        }
    }
    return GRASS_SUCCESS;
}

grass_result VkBackend::prepare_frame(VkCommandBuffer cmd) {
    if (pending_uploads_ == 0) return GRASS_SUCCESS;

    // Build the batch first: it may throw std::bad_alloc, and nothing has changed yet.
    batch_.clear();
    if (default_staging_.buffer) batch_.copy_image(default_staging_.buffer, 0, default_density_.image, 1, 1);
    for (const PatchGpu& p : patches_) {
        if (!p.pending) continue;
        batch_.copy_buffer(p.staging.buffer, 0, p.vertices.buffer, p.vertices.size, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
        batch_.copy_buffer(p.staging.buffer, p.vertices.size, p.indices.buffer, p.indices.size, VK_ACCESS_INDEX_READ_BIT);
    }
    for (const FieldGpu& f : fields_) {
        if (f.pending) batch_.copy_image(f.staging.buffer, 0, f.density.image, f.density.width, f.density.height);
    }
    batch_.record(fn_, cmd);

    // The staging buffers wait until this frame's copies have run on the GPU.
    deferred_.retire(&default_staging_, frame_);
    for (PatchGpu& p : patches_) {
        if (!p.pending) continue;
        deferred_.retire(&p.staging, frame_);
        p.pending = false;
    }
    for (FieldGpu& f : fields_) {
        if (!f.pending) continue;
        deferred_.retire(&f.staging, frame_);
        f.pending = false;
    }
    pending_uploads_ = 0;
    return GRASS_SUCCESS;
}

bool VkBackend::drawn(const TierDraw& d, bool debug_view) const {
    // A draw whose field or patch was destroyed after grass_begin_frame is skipped.
    if (d.instance_count == 0 || d.field_slot >= fields_.size() || !fields_[d.field_slot].live) return false;
    if (debug_view) return true;
    return d.kind == GRASS_TIER_GEOMETRY && d.patch_slot < patches_.size() && patches_[d.patch_slot].live &&
           patches_[d.patch_slot].index_count > 0;
}

bool VkBackend::draw_ready(const TierDraw& draw, bool debug_view, const char** problem) const {
    const FieldGpu& f = fields_[draw.field_slot];
    if (!debug_view && patches_[draw.patch_slot].pending) {
        *problem = "its patch";
        return false;
    }
    // The field's descriptor set points at its density map (or the default one).
    if (f.pending) {
        *problem = "its density map";
        return false;
    }
    if (!f.density.image && default_staging_.buffer) {
        *problem = "the default density map";
        return false;
    }
    return true;
}

grass_result VkBackend::record(VkCommandBuffer cmd) {
    const FramePlan& plan = ctx_->plan;
    const bool debug_view = (plan.flags & GRASS_VIEW_FLAG_DEBUG_TIERS) != 0;
    // Refuse before recording anything, so that the command buffer is left untouched.
    uint32_t draw_count = 0;
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
        draw_count += 1;
    }
    if (draw_count == 0) return GRASS_SUCCESS;

    const int32_t x = plan.viewport[0], y = plan.viewport[1], w = plan.viewport[2], h = plan.viewport[3];
    const VkViewport viewport{float(x), float(y), float(w), float(h), 0.0f, 1.0f};
    // The scissor is the viewport rectangle, clipped to the framebuffer's positive quadrant.
    const int64_t x0 = x < 0 ? 0 : x, y0 = y < 0 ? 0 : y;
    const int64_t x1 = int64_t(x) + w, y1 = int64_t(y) + h;
    VkRect2D scissor{};
    scissor.offset = {static_cast<int32_t>(x0), static_cast<int32_t>(y0)};
    scissor.extent = {static_cast<uint32_t>(x1 > x0 ? x1 - x0 : 0), static_cast<uint32_t>(y1 > y0 ? y1 - y0 : 0)};

    const bool depth_test = (plan.flags & GRASS_VIEW_FLAG_NO_DEPTH_TEST) == 0;
    const VkPipeline pipeline = debug_view ? debug_view_.pipeline(depth_test) : pipeline_.pipeline(depth_test);
    fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    fn_.vkCmdSetViewport(cmd, 0, 1, &viewport);
    fn_.vkCmdSetScissor(cmd, 0, 1, &scissor);

    const VkBuffer instances = ring_.instance_buffer(slot_);
    const VkDeviceSize zero = 0;
    if (debug_view) fn_.vkCmdBindVertexBuffers(cmd, DebugViewPipeline::kInstanceBinding, 1, &instances, &zero);
    uint32_t bound_patch = UINT32_MAX;
    for (uint32_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& d = plan.draws[i];
        if (!drawn(d, debug_view)) continue;
        // Every draw has its Field block, whatever its kind.
        const uint32_t offsets[2] = {ring_.frame_offset(), ring_.field_offset(i)};
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout(), 0, 1,
                                    &fields_[d.field_slot].sets[slot_].set, 2, offsets);
        if (debug_view) {
            fn_.vkCmdDraw(cmd, DebugViewPipeline::kVerticesPerBox, d.instance_count, 0, d.first_instance);
            continue;
        }
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
    return GRASS_SUCCESS;
}

} // namespace grass::vk
