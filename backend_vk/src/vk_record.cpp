// The Vulkan backend's frames: begin_frame writes the plan into the frame slot's buffers,
// prepare_frame records the pending uploads (outside the render pass), record draws the
// plan into the host's command buffer (inside it).
#include "vk_backend.hpp"

#include "context/context.hpp"
#include "vk_labels.hpp"
#include "vk_staging.hpp"

#include <optional>

namespace grass::vk {

// ---- Frames -----------------------------------------------------------------------------

grass_result VkBackend::begin_host_frame(const char* function, const HostFrame& frame, bool implied) {
    const uint32_t frames = desc_.frames_in_flight;
    uint64_t completed = frame.completed;
    // grass_begin_frame's promise: the frame frames_in_flight before this one has finished.
    if (implied && frame.index > frames) completed = std::max<uint64_t>(completed, frame.index - frames);
    // The frame slot whose last frame finished longest ago; it must have finished.
    uint32_t slot = 0;
    for (uint32_t s = 1; s < frames; ++s) {
        if (slot_frame_[s] < slot_frame_[slot]) slot = s;
    }
    if (slot_frame_[slot] > completed) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAMES_IN_FLIGHT,
                          "%s: frame %llu needs a frame slot, but all %u (grass_vk_desc.frames_in_flight) hold "
                          "unfinished frames: the oldest is frame %llu and the newest finished one is frame %llu "
                          "(completed_frame_index); wait for frame %llu on the GPU first, or create the context "
                          "with more frames in flight",
                          function, static_cast<unsigned long long>(frame.index), frames,
                          static_cast<unsigned long long>(slot_frame_[slot]),
                          static_cast<unsigned long long>(completed),
                          static_cast<unsigned long long>(slot_frame_[slot]));
    }
    frame_ = frame.index;
    slot_ = slot;
    slot_frame_[slot] = frame.index;
    interaction_pending_ = false; // set by view 0 when this frame has a pass
    // The previous frame writes no more stamps (the host has submitted it). The set this
    // frame takes was written frames_in_flight frames ago, which has finished: read it (and
    // any older) now; open_frame drops it if it never ran.
    timer_ring_.close_frame();
    collect_timers();
    timer_set_ = timer_pool_ != VK_NULL_HANDLE ? timer_ring_.open_frame() : TierTimerRing::kUntimed;
    timer_reset_ = false;
    // What finished frames were the last to use can go.
    deferred_.collect(completed);
    return GRASS_SUCCESS;
}

grass_result VkBackend::begin_view(const char* function, uint32_t view, const FramePlan& plan) {
    VkFailure failure;
    const char* what = "";
    if (view >= views_made_ && !make_view_slots(view, &failure, &what)) return fail(function, what, failure);
    // The view slot's last frame has finished (begin_host_frame chose its frame slot so).
    const uint32_t vs = view_slot(slot_, view);
    frame_sets_.reset(vs);
    bool uniforms_replaced = false;
    if (!ring_.write(vs, plan, frame_, &uniforms_replaced, &failure, &what)) return fail(function, what, failure);
    if (uniforms_replaced) {
        for (const FieldGpu& f : fields_) {
            if (f.live) write_set(f.sets[vs].set, vs, f, still_views());
        }
    }
    if (view > 0) return GRASS_SUCCESS;
    // Responsive grass: the interaction map and this frame's pass (recorded by prepare_frame),
    // view 0's (every view reads the map).
    if (plan.interaction.levels > 0) {
        if (!interaction_.prepare(slot_, frame_, plan.interaction, &failure, &what))
            return fail(function, what, failure);
        interaction_pending_ = true;
    } else if (interaction_.has_map()) {
        interaction_.release(frame_); // the core holds no map (frame_plan.hpp)
    }
    // The blade window of view 0's plan (its pass recorded by prepare_frame, after the map's).
    if (!prepare_blade_window(plan, &failure, &what)) return fail(function, what, failure);
    return GRASS_SUCCESS;
}

grass_result VkBackend::prepare_frame(VkCommandBuffer cmd) {
    // This frame's timestamps (vk_timers.cpp), reset once, outside the render pass.
    if (timer_set_ != TierTimerRing::kUntimed && !timer_reset_) {
        fn_.vkCmdResetQueryPool(cmd, timer_pool_, timer_set_ * TierTimerRing::kStampsPerSet,
                                TierTimerRing::kStampsPerSet);
        timer_reset_ = true;
    }
    if (pending_uploads_ > 0) record_uploads(cmd);
    // Responsive grass: the interaction pass, once per frame (grass_vk.h).
    if (interaction_pending_) {
        const LabelScope label(fn_, cmd, "grass interaction pass");
        interaction_.record(cmd, slot_, ctx_->plan.interaction);
        interaction_pending_ = false;
    }
    // Then the blade window pass, which reads the map (grass_vk.h).
    if (window_pending_) return record_blade_window(cmd);
    return GRASS_SUCCESS;
}

void VkBackend::record_uploads(VkCommandBuffer cmd) {
    // Build the batch first: it may throw std::bad_alloc, and nothing has changed yet.
    batch_.clear();
    if (default_white_staging_.buffer) batch_.copy_image(default_white_staging_.buffer, 0, default_white_.image, 1, 1);
    if (default_black_staging_.buffer) batch_.copy_image(default_black_staging_.buffer, 0, default_black_.image, 1, 1);
    if (default_slices_staging_.buffer) {
        batch_.copy_image(default_slices_staging_.buffer, 0, default_slices_.image, 1, 1);
    }
    for (const PatchGpu& p : patches_) {
        if (!p.pending) continue;
        batch_.copy_buffer(p.staging.buffer, 0, p.vertices.buffer, p.vertices.size,
                           VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
        batch_.copy_buffer(p.staging.buffer, p.vertices.size, p.indices.buffer, p.indices.size,
                           VK_ACCESS_INDEX_READ_BIT);
    }
    for (const PatchGpu& p : patches_) {
        if (p.curves_pending) {
            batch_.copy_buffer(p.curves_staging.buffer, 0, p.curves.buffer, p.curves.size, VK_ACCESS_SHADER_READ_BIT);
        }
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
        } images[3] = {
            {&s.color, kSliceColorBytes}, {&s.normal, kSliceNormalBytes}, {&s.threshold, kSliceThresholdBytes}};
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
    {
        const LabelScope label(fn_, cmd, "grass uploads"); // after the batch is built: nothing can throw
        batch_.record(fn_, cmd);
    }

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
        if (p.pending) deferred_.retire(&p.staging, frame_);
        if (p.curves_pending) deferred_.retire(&p.curves_staging, frame_);
        p.pending = p.curves_pending = false;
    }
    for (MapGpu& m : maps_) {
        if (m.pending) deferred_.retire(&m.staging, frame_);
        if (m.updating) deferred_.retire(&m.update_staging, frame_);
        m.pending = m.updating = false;
    }
    pending_uploads_ = 0;
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
        *problem = "the upload of its patch";
        return false;
    }
    if (!debug_view && draw.kind != GRASS_TIER_GEOMETRY && draw_slices(draw)->pending) {
        *problem = draw.kind == GRASS_TIER_VOLUME ? "the upload of its patch's baked vertical slices"
                                                  : "the upload of its patch's baked horizontal slice";
        return false;
    }
    // The field's descriptor sets point at its maps (or the default ones): each must have
    // its copies recorded, the first and any update since (the plan already follows the
    // updated texels).
    for (uint32_t role = 0; role < kMapRoleCount; ++role) {
        const uint32_t m = f.map_slot[role];
        if (m != kNoMap && m < maps_.size() && (maps_[m].pending || maps_[m].updating)) {
            *problem = maps_[m].pending ? "the upload of one of its design maps"
                                        : "the upload of an update of one of its design maps";
            return false;
        }
    }
    const uint32_t wind = f.wind_map;
    if ((draw.features & kFeatureWindMap) && wind != kNoMap && wind < maps_.size() &&
        (maps_[wind].pending || maps_[wind].updating)) {
        *problem = maps_[wind].pending ? "the upload of its wind map" : "the upload of an update of its wind map";
        return false;
    }
    if (default_white_staging_.buffer || default_black_staging_.buffer) {
        *problem = "the upload of the default design maps";
        return false;
    }
    if (default_slices_staging_.buffer) {
        *problem = "the upload of the default slice image";
        return false;
    }
    if (debug_view) return true;
    // Responsive grass: blades bend from their patch's control points; the map's pass of
    // this frame runs before any draw reads it.
    if (draw.kind == GRASS_TIER_GEOMETRY && (draw.features & kBladeCurveFeatures) &&
        (!patches_[draw.patch_slot].curves.buffer || patches_[draw.patch_slot].curves_pending)) {
        *problem = "the upload of its patch's blade control points";
        return false;
    }
    if ((draw.features & kFeatureInteraction) && (interaction_pending_ || !interaction_.map_ready())) {
        *problem = "this frame's interaction pass (responsive grass)";
        return false;
    }
    if ((draw.features & kFeatureBladeWindow) && (window_pending_ || !window_.has_window())) {
        *problem = "this frame's blade window pass (responsive grass)";
        return false;
    }
    return true;
}

grass_result VkBackend::record(const char* function, VkCommandBuffer cmd, uint32_t view) {
    const FramePlan& plan = ctx_->views.plan(view);
    const uint32_t vs = view_slot(slot_, view); // this view's buffers and sets in the frame's slot
    const bool debug_view = (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0;
    const bool depth_test = (plan.flags & GRASS_VIEW_FLAG_NO_DEPTH_TEST) == 0;
    if (plan.gbuffer) pipeline_.select_gbuffer(GBufferRoutes::of(plan)); // its layout's pipelines
    // Refuse before recording anything, so that the command buffer is left untouched. The
    // plan itself was checked by grass_begin_frame (check_plan in context/invariants.hpp).
    uint32_t draw_count = 0, slice_draws = 0, own_sets = 0;
    for (const TierDraw& d : plan.draws) {
        if (!drawn(d, debug_view)) continue;
        const char* problem = "";
        if (!draw_ready(d, debug_view, &problem)) {
            return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_UPLOAD_NOT_RECORDED,
                              "%s: a field drawn this frame (slot %u) waits for %s; call "
                              "grass_vk_prepare() with a command buffer that runs before this one, after "
                              "grass_begin_frame() and outside the render pass",
                              function, d.field_slot, problem);
        }
        // upload_field made the variants of the field's maps, grass_prepare_pipelines those of
        // the features the host declared (without the depth test too when it declared the
        // debug views); one the plan asks for besides, or its depth-off pipeline in a frame
        // with GRASS_VIEW_FLAG_NO_DEPTH_TEST, is made here, before anything is recorded.
        VkFailure failure;
        const char* what = "";
        if (!pipeline_.create_variant(draw_variant(d, plan.flags), depth_test, &failure, &what))
            return fail(function, what, failure);
        draw_count += 1;
        if (!debug_view && d.kind != GRASS_TIER_GEOMETRY) slice_draws += 1;
        if (!debug_view && own_set(d)) own_sets += 1;
    }
    if (draw_count == 0) return GRASS_SUCCESS;
    // A view that receives shadows, writes motion vectors or is lit by the host's lights (its
    // draws' pipelines made above): this view's GrassShadow, GrassMotion and GrassLights
    // blocks, as it uses them, in set 1 of the view extras' layout, and a receiving view's map
    // in set 2.
    const bool extras = (plan.shadow_receive || plan.motion || plan.host_lights || plan.gbuffer) && !debug_view;
    if (extras) {
        VkFailure failure;
        const char* what = "";
        if (!extras_.write(vs, frame_, plan, pipeline_.extras(), &failure, &what)) return fail(function, what, failure);
    }
    const VkPipelineLayout layout = extras ? pipeline_.extras().layout() : pipeline_.layout();

    // The volume and image draws pair the field's design maps with the patch's slices, and
    // responsive draws with the patch's blade curves and the interaction map: a fresh set
    // each, from this frame slot's pools (never one a frame in flight may use).
    if (own_sets > 0) {
        draw_sets_.assign(plan.draws.size(), VK_NULL_HANDLE); // may throw: nothing recorded yet
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (!drawn(d, false) || !own_set(d)) continue;
            VkFailure failure;
            if (!frame_sets_.allocate(vs, pipeline_.set_layout(), &draw_sets_[i], &failure)) {
                return fail(function, "a descriptor set of a volume, image or responsive draw", failure);
            }
            write_set(draw_sets_[i], vs, fields_[d.field_slot], draw_views(d));
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

    const LabelScope draw_label(fn_, cmd, "grass draw"); // around everything recorded below
    fn_.vkCmdSetViewport(cmd, 0, 1, &viewport);
    fn_.vkCmdSetScissor(cmd, 0, 1, &scissor);
    // A depth pass: the view's bias (its pipelines take it as dynamic state).
    if (plan.depth_pass) fn_.vkCmdSetDepthBias(cmd, plan.depth_bias[0], 0.0f, plan.depth_bias[1]);
    if (device_.indexed_blocks) {
        // The index the shaders read the Frame and Field blocks at (vk_spirv.hpp); it holds
        // for every pipeline of the layout, whatever is bound after it.
        const uint32_t block_index = 0;
        fn_.vkCmdPushConstants(cmd, layout, kBlockIndexStages, 0, kBlockIndexBytes, &block_index);
    }
    if (extras) {
        // Set 1, and set 2 (the host's map) for a receiving view alone.
        const VkDescriptorSet sets[2] = {extras_.set(vs), extras_.map_set(vs)};
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kExtrasSet,
                                    plan.shadow_receive ? 2 : 1, sets, 0, nullptr);
    }

    const VkBuffer instances = ring_.instance_buffer(vs);
    const VkDeviceSize zero = 0;
    const auto bind_set = [&](uint32_t draw, VkDescriptorSet set) {
        // Every draw has its Field block, whatever its kind.
        const uint32_t offsets[2] = {ring_.frame_offset(), ring_.field_offset(draw)};
        fn_.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 2, offsets);
    };

    if (debug_view) {
        // Every draw as boxes, in plan order.
        const LabelScope label(fn_, cmd, "grass debug cells");
        VkPipeline bound_pipeline = VK_NULL_HANDLE;
        fn_.vkCmdBindVertexBuffers(cmd, DebugViewPipeline::kInstanceBinding, 1, &instances, &zero);
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (!drawn(d, true)) continue;
            const VkPipeline pipeline =
                pipeline_.pipeline(kPipelineDebugView, d.features & kDebugBoxFeatures, depth_test);
            if (pipeline != bound_pipeline) {
                fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                bound_pipeline = pipeline;
            }
            bind_set(i, fields_[d.field_slot].sets[vs].set);
            fn_.vkCmdDraw(cmd, d.vertex_count, d.instance_count, 0, d.first_instance);
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
    std::optional<LabelScope> blades_label; // "grass blades" around the geometry tiers' draws
    for (uint32_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& d = plan.draws[i];
        if (d.kind != GRASS_TIER_GEOMETRY || !drawn(d, false)) continue;
        if (!blades_label) blades_label.emplace(fn_, cmd, "grass blades");
        const VkPipeline pipeline = pipeline_.pipeline(kPipelineBlade, d.features, depth_test);
        if (pipeline != bound_pipeline) {
            fn_.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            bound_pipeline = pipeline;
        }
        bind_set(i, own_set(d) ? draw_sets_[i] : fields_[d.field_slot].sets[vs].set);
        const PatchGpu& p = patches_[d.patch_slot];
        if (bound_patch != d.patch_slot) {
            const VkBuffer buffers[2] = {p.vertices.buffer, instances};
            const VkDeviceSize buffer_offsets[2] = {0, 0};
            fn_.vkCmdBindVertexBuffers(cmd, 0, 2, buffers, buffer_offsets);
            fn_.vkCmdBindIndexBuffer(cmd, p.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
            bound_patch = d.patch_slot;
        }
        // The indices of the blades' tessellation level the core chose (first_index 0: the full blades).
        fn_.vkCmdDrawIndexed(cmd, d.vertex_count, d.instance_count, d.first_index, 0, d.first_instance);
    }
    blades_label.reset();
    write_stamp(cmd, stamps, 1);
    if (slice_draws == 0) {
        write_stamp(cmd, stamps, 2);
        write_stamp(cmd, stamps, 3);
        return GRASS_SUCCESS;
    }
    const struct {
        grass_tier_kind kind;
        PipelineKind pipeline;
    } passes[2] = {{GRASS_TIER_VOLUME, kPipelineVolume}, {GRASS_TIER_IMAGE, kPipelineImage}};
    for (const auto& pass : passes) {
        std::optional<LabelScope> label; // around the pass's draws, where it has some
        bound_pipeline = VK_NULL_HANDLE;
        for (uint32_t i = 0; i < plan.draws.size(); ++i) {
            const TierDraw& d = plan.draws[i];
            if (d.kind != pass.kind || !draw_sets_[i]) continue;
            if (!label) label.emplace(fn_, cmd, pass.kind == GRASS_TIER_VOLUME ? "grass volumes" : "grass images");
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
            fn_.vkCmdDraw(cmd, d.vertex_count, d.instance_count, 0, d.first_instance);
        }
        write_stamp(cmd, stamps, pass.kind == GRASS_TIER_VOLUME ? 2 : 3);
    }
    return GRASS_SUCCESS;
}

} // namespace grass::vk
