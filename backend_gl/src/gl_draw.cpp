// Executing a frame plan: upload its instances and uniforms once per frame, then one
// instanced draw per planned draw (blades, volume cuboids, image quads, or debug boxes),
// inside a guard that restores the host's GL state.
#include "gl_backend.hpp"

#include "gl_program.hpp"
#include "gl_state_guard.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>

namespace grass {

namespace {

size_t align_up(size_t value, size_t alignment) { return (value + alignment - 1) / alignment * alignment; }

} // namespace

// Uniform buffer layout: Frame at offset 0, then one Field block per draw of any kind
// (the debug view draws them all), each at GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, as the plan
// holds them. The Frame block gets the host's target of this render (write_render_target):
// the plan holds the one of the previous render, and a frame may draw into several.
void GlBackend::upload_frame(const RenderTarget& target, uint32_t view) {
    const FramePlan& plan = ctx_->views.plan(view);
    const size_t alignment = static_cast<size_t>(uniform_alignment_);

    field_uniform_offsets_.resize(plan.draws.size());
    size_t size = sizeof(FrameUniforms);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        field_uniform_offsets_[i] = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(field_uniform_offsets_[i]) + sizeof(FieldUniforms);
    }
    if (plan.shadow_receive) { // a receiving view's GrassShadow block: no other view has one
        shadow_uniform_offset_ = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(shadow_uniform_offset_) + sizeof(ShadowUniforms);
    }
    if (plan.motion) { // a motion view's GrassMotion block: no other view has one
        motion_uniform_offset_ = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(motion_uniform_offset_) + sizeof(MotionUniforms);
    }
    if (plan.host_lights) { // a lit view's GrassLights block: no other view has one
        lights_uniform_offset_ = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(lights_uniform_offset_) + sizeof(LightUniforms);
    }
    if (plan.gbuffer) { // a G-buffer view's GrassGBuffer block: no other view has one
        gbuffer_uniform_offset_ = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(gbuffer_uniform_offset_) + sizeof(GBufferUniforms);
    }
    size = stage_interaction_uniforms(plan, size); // the pass's blocks: view 0's plan only has them
    uniform_staging_.assign(size, 0);
    FrameUniforms frame = plan.frame;
    write_render_target(&frame, target);
    std::memcpy(uniform_staging_.data(), &frame, sizeof(FrameUniforms));
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        std::memcpy(uniform_staging_.data() + field_uniform_offsets_[i], &plan.draws[i].uniforms,
                    sizeof(FieldUniforms));
    }
    if (plan.shadow_receive) {
        std::memcpy(uniform_staging_.data() + shadow_uniform_offset_, &plan.shadow, sizeof(ShadowUniforms));
    }
    if (plan.motion) {
        std::memcpy(uniform_staging_.data() + motion_uniform_offset_, &plan.motion_uniforms, sizeof(MotionUniforms));
    }
    if (plan.host_lights) {
        std::memcpy(uniform_staging_.data() + lights_uniform_offset_, &plan.lights, sizeof(LightUniforms));
    }
    if (plan.gbuffer) {
        std::memcpy(uniform_staging_.data() + gbuffer_uniform_offset_, &plan.gbuffer_uniforms, sizeof(GBufferUniforms));
    }
    for (uint32_t l = 0; l < plan.interaction.levels && l < 2; ++l) {
        std::memcpy(uniform_staging_.data() + interaction_uniform_offsets_[l], &plan.interaction.level[l],
                    sizeof(InteractionLevelUniforms));
    }
    uniforms_.upload(gl_, uniform_staging_.data(), uniform_staging_.size());
    instances_.upload(gl_, plan.instances.data(), plan.instances.size() * sizeof(TierInstance));
    uploaded_view_ = view;
    frame_target_ = target;
}

void GlBackend::bind_field_maps(const FieldGpu& field, uint32_t features) const {
    if ((features & kFeatureWindMap) != 0 && field.wind_map != kNoMap) { // read with texelFetch: no sampler
        gl_.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kWindMapUnit));
        gl_.BindTexture(GL_TEXTURE_2D, maps_[field.wind_map].texture);
        gl_.BindSampler(static_cast<GLuint>(kWindMapUnit), 0);
    }
    for (uint32_t role = kMapRoleCount; role-- > 0;) { // ends with unit 0 active
        const uint32_t map = field.maps.map_slot[role];
        if (map == kNoMap && role != kMapDensity) continue; // not sampled by the field's variant
        gl_.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kMapUnit[role]));
        gl_.BindTexture(GL_TEXTURE_2D, map != kNoMap ? maps_[map].texture : white_texture_);
    }
}

// A receiving view (grass_shadow_receive_desc): the host's map with grass's depth-compare
// sampler at kShadowMapUnit and the GrassShadow block at kShadowUniformBinding, for every
// draw of the view (GlDrawStateGuard::begin_shadow_receive saved the host's). The sampler is
// made on the first receiving view; its comparison is the view's. Leaves unit 0 active.
void GlBackend::bind_host_shadows(const FramePlan& plan) {
    if (shadow_sampler_ == 0) {
        gl_.CreateSamplers(1, &shadow_sampler_);
        gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        label(GL_SAMPLER, shadow_sampler_, "grass host shadow sampler");
    }
    // Lit where the point's depth compares with the stored one as the host's convention says.
    gl_.SamplerParameteri(shadow_sampler_, GL_TEXTURE_COMPARE_FUNC,
                          plan.shadow.params[0] > 0.0f ? GL_LEQUAL : GL_GEQUAL);
    gl_.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kShadowMapUnit));
    gl_.BindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(plan.shadow_map));
    gl_.BindSampler(static_cast<GLuint>(kShadowMapUnit), shadow_sampler_);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindBufferRange(GL_UNIFORM_BUFFER, kShadowUniformBinding, uniforms_.name(), shadow_uniform_offset_,
                        sizeof(ShadowUniforms));
}

// Geometry draws: the patch's blades, instances front to back.
void GlBackend::draw_blades(const FramePlan& plan) const {
    GLuint bound_program = 0;
    std::optional<DebugGroup> group; // "grass blades" around the geometry tiers' draws
    for (const GLint unit : kMapUnit) gl_.BindSampler(static_cast<GLuint>(unit), sampler_);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (draw.kind != GRASS_TIER_GEOMETRY) continue;
        const PatchGpu& patch = patches_[draw.patch_slot];
        if (draw.instance_count == 0 || draw.vertex_count == 0) continue;
        if (!group) group.emplace(*this, "grass blades");
        const GLuint program = program_of(kProgramBlades, draw.features);
        if (program != bound_program) {
            gl_.UseProgram(program);
            bound_program = program;
        }
        gl_.BindVertexArray(patch.vertex_array);
        if ((draw.features & kBladeCurveFeatures) != 0) {
            gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kBladeCurvesStorageBinding, patch.curves);
            bind_blade_window();
        }
        bind_field_maps(fields_[draw.field_slot], draw.features);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[i], sizeof(FieldUniforms));
        if (i < compact_command_.size() && compact_command_[i] >= 0) { // the window variant: compacted blades
            draw_compacted(draw, i);
            continue;
        }
        // The indices of the blades' tessellation level the core chose (first_index 0: the full blades).
        const void* first_index = reinterpret_cast<const void*>(uintptr_t(draw.first_index) * sizeof(uint32_t));
        gl_.DrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(draw.vertex_count), GL_UNSIGNED_INT,
                                              first_index, static_cast<GLsizei>(draw.instance_count),
                                              draw.first_instance);
    }
}

// Volume or image draws: instances only, sampling the patch's baked slices (grass_begin_frame
// checked that every set was uploaded: check_plan). Unit 0 is active.
void GlBackend::draw_sliced(const FramePlan& plan, grass_tier_kind kind) const {
    bool bound = false;
    GLuint bound_program = 0;
    const GlProgramKind program_kind = kind == GRASS_TIER_VOLUME ? kProgramVolume : kProgramImage;
    std::optional<DebugGroup> group; // around the tier kind's draws, where it has some
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (draw.kind != kind || draw.instance_count == 0) continue;
        if (!group) group.emplace(*this, kind == GRASS_TIER_VOLUME ? "grass volumes" : "grass images");
        if (!bound) {
            gl_.BindVertexArray(tier_vertex_array_);
            for (const GLint unit : kMapUnit) gl_.BindSampler(static_cast<GLuint>(unit), sampler_);
            gl_.BindSampler(static_cast<GLuint>(kSliceColorUnit), slice_sampler_);
            gl_.BindSampler(static_cast<GLuint>(kSliceNormalUnit), slice_sampler_);
            gl_.BindSampler(static_cast<GLuint>(kSliceThresholdUnit), threshold_sampler_);
            bound = true;
        }
        const GLuint program = program_of(program_kind, draw.features);
        if (program != bound_program) {
            gl_.UseProgram(program);
            bound_program = program;
        }
        const SliceGpu* slices = find_slices(draw.patch_slot, draw_slice_set(draw));
        const GLuint textures[3][2] = {{static_cast<GLuint>(kSliceColorUnit), slices->color},
                                       {static_cast<GLuint>(kSliceNormalUnit), slices->normal},
                                       {static_cast<GLuint>(kSliceThresholdUnit), slices->threshold}};
        for (const auto& t : textures) {
            gl_.ActiveTexture(GL_TEXTURE0 + t[0]);
            gl_.BindTexture(GL_TEXTURE_2D_ARRAY, t[1]);
        }
        bind_field_maps(fields_[draw.field_slot], draw.features);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[i], sizeof(FieldUniforms));
        gl_.DrawArraysInstancedBaseInstance(GL_TRIANGLES, 0, static_cast<GLsizei>(draw.vertex_count),
                                            static_cast<GLsizei>(draw.instance_count), draw.first_instance);
    }
}

// The debug view: one box per instance of every draw, on the terrain when the field has a
// height map (its program variant samples that map alone).
void GlBackend::draw_debug(const FramePlan& plan) const {
    GLuint bound_program = 0;
    gl_.BindVertexArray(tier_vertex_array_);
    for (const GLint unit : kMapUnit) gl_.BindSampler(static_cast<GLuint>(unit), sampler_);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (draw.instance_count == 0) continue;
        const GLuint program = program_of(kProgramDebugTiers, draw.features & kDebugBoxFeatures);
        if (program != bound_program) {
            gl_.UseProgram(program);
            bound_program = program;
        }
        bind_field_maps(fields_[draw.field_slot], draw.features);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[i], sizeof(FieldUniforms));
        gl_.DrawArraysInstancedBaseInstance(GL_TRIANGLES, 0, static_cast<GLsizei>(draw.vertex_count),
                                            static_cast<GLsizei>(draw.instance_count), draw.first_instance);
    }
}

grass_result GlBackend::render(const char* function, uint32_t view) {
    const FramePlan& plan = ctx_->views.plan(view);
    const FramePlan& first = ctx_->views.plan(0); // the frame's interaction pass is view 0's
    // No map in the core (never made, or dropped by grass_set_interaction): nor here.
    if (first.interaction.levels == 0 && interaction_resolution_ != 0) release_interaction_map();
    // The interaction pass runs once per frame, at its first render of any view, even when
    // nothing is drawn: trails age.
    const bool pass_pending = first.interaction.pass && !interaction_ran_;
    // So does the blade window pass (gl_blade_window.cpp), after it. A frame without a
    // window keeps no buffers of it.
    if (first.blade_window.dispatches.empty() && window_poses_ != 0) {
        release_blade_window_buffers();
        release_blade_compaction_buffers();
    }
    const bool window_pending = !first.blade_window.dispatches.empty() && !window_ran_;
    if (plan.draws.empty() && !pass_pending && !window_pending) return GRASS_SUCCESS;
    const bool debug = (plan.flags & GRASS_VIEW_FLAG_DEBUG_CELLS) != 0;
    // Responsive grass: draws that read the blade curves or the interaction map.
    bool dynamics = pass_pending || window_pending;
    bool reads_map = false;
    for (const TierDraw& draw : plan.draws) {
        dynamics = dynamics || (draw.features & (kFeatureWind | kFeatureInteraction)) != 0;
        reads_map = reads_map || (draw.features & kFeatureInteraction) != 0;
        if (!debug && draw.kind == GRASS_TIER_GEOMETRY && (draw.features & kBladeCurveFeatures) != 0 &&
            patches_[draw.patch_slot].curves == 0) {
            return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                              "%s: patch slot %u is drawn with responsive grass but its blade curves were never "
                              "uploaded (internal error)",
                              function, draw.patch_slot);
        }
    }

    // grass_begin_frame checked the plan against what the core uploaded (check_plan in
    // context/invariants.hpp): every draw's field, patch and slice set is here.
    // Every program variant the plan draws with (upload_field compiled the fields' tiers';
    // the debug view's are compiled on first use). Compiling binds nothing.
    for (const TierDraw& draw : plan.draws) {
        const ShaderVariant variant = draw_variant(draw, plan.flags);
        GLuint unused = 0;
        const grass_result result =
            program(static_cast<GlProgramKind>(variant.program), variant.features, function, &unused);
        if (result != GRASS_SUCCESS) return result;
    }
    const bool motion = plan.motion && !debug; // the debug boxes write no velocity
    if (plan.gbuffer) {                        // every attachment grass writes has a draw buffer (gl_gbuffer.cpp)
        const grass_result result = check_gbuffer_target(plan, function);
        if (result != GRASS_SUCCESS) return result;
    } else if (motion) {
        const grass_result result = check_velocity_target(plan, function);
        if (result != GRASS_SUCCESS) return result;
    }
    GLint sample_buffers = 0, samples = 0;
    gl_.GetIntegerv(GL_SAMPLE_BUFFERS, &sample_buffers); // of the bound draw framebuffer
    gl_.GetIntegerv(GL_SAMPLES, &samples);
    const bool multisampled = sample_buffers > 0;
    const uint32_t sample_count = multisampled ? static_cast<uint32_t>(std::max(samples, 1)) : 1u;
    // The host's clip convention (glClipControl), read and never changed: the volume tier
    // maps its gl_FragDepth with it (window_depth() of blade_interface.glsl).
    GLint clip_depth_mode = GL_NEGATIVE_ONE_TO_ONE;
    gl_.GetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth_mode);
    RenderTarget target;
    target.samples = sample_count;
    target.clip_zero_to_one = clip_depth_mode == GL_ZERO_TO_ONE;
    // The interaction and blade window passes read their blocks (and the window pass view 0's
    // instances) from view 0's upload.
    if ((pass_pending || window_pending) && (uploaded_view_ != 0 || frame_target_ != target)) upload_frame(target, 0);

    GlDrawStateGuard guard(gl_, dynamics);                // also makes texture unit 0 active
    const DebugGroup render_group(*this, "grass render"); // popped before the guard restores
    if (pass_pending) {
        // Before any draw of the frame, and before the Frame block is bound at uniform
        // binding 0 (the pass binds its level's block there).
        interaction_ran_ = true;
        const DebugGroup group(*this, "grass interaction pass");
        const grass_result result = run_interaction_pass(first, function);
        if (result != GRASS_SUCCESS) return result;
    }
    if (window_pending) { // after the interaction pass: the poses read the map as it is now
        window_ran_ = true;
        const DebugGroup group(*this, "grass blade window pass");
        const grass_result result = run_blade_window_pass(first, function);
        if (result != GRASS_SUCCESS) return result;
    }
    if (plan.draws.empty()) return GRASS_SUCCESS;
    // Once per view and frame; again if a later call of the frame draws into a target of
    // another kind or with another clip convention.
    if (uploaded_view_ != view || frame_target_ != target) upload_frame(target, view);
    if (reads_map && interaction_maps_[0] != 0) bind_interaction_maps();
    compact_command_.clear();
    if (!debug && window_poses_ != 0) { // before the view's blocks take uniform binding 2
        const DebugGroup group(*this, "grass blade compaction");
        const grass_result result = compact_blade_window(plan, function);
        if (result != GRASS_SUCCESS) return result;
    }
    // Viewport 0 alone (glViewport would set every viewport): grass draws through it.
    gl_.ViewportIndexedf(0, static_cast<GLfloat>(plan.viewport[0]), static_cast<GLfloat>(plan.viewport[1]),
                         static_cast<GLfloat>(plan.viewport[2]), static_cast<GLfloat>(plan.viewport[3]));
    if (plan.flags & GRASS_VIEW_FLAG_NO_DEPTH_TEST) {
        gl_.Disable(GL_DEPTH_TEST);
    } else {
        gl_.Enable(GL_DEPTH_TEST);
    }
    gl_.DepthFunc(ctx_->desc.depth_mode == GRASS_DEPTH_GREATER ? GL_GEQUAL : GL_LEQUAL);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_CULL_FACE); // blades are two-sided; the volume shader picks its faces itself
    gl_.Disablei(GL_BLEND, 0); // draw buffer 0's: the others are masked off (GlDrawStateGuard)
    gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    if (multisampled) gl_.Enable(GL_MULTISAMPLE);
    if (multisampled && !plan.depth_pass && !plan.gbuffer) { // depth and G-buffer: alpha-tested
        gl_.Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    } else {
        gl_.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    }
    // A depth pass writes no colour (every draw buffer masked off) and biases its depth.
    if (plan.depth_pass) guard.begin_depth_pass(plan.depth_bias[0], plan.depth_bias[1]);
    gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, uniforms_.name(), 0, sizeof(FrameUniforms));
    if (plan.shadow_receive && !debug) {
        guard.begin_shadow_receive();
        bind_host_shadows(plan);
    }
    if (plan.gbuffer) { // routes every output, the velocity's too
        guard.begin_gbuffer(plan.gbuffer_attachment, plan.gbuffer_mask, motion);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, kGBufferUniformBinding, uniforms_.name(), gbuffer_uniform_offset_,
                            sizeof(GBufferUniforms));
        if (motion) bind_motion(plan);
    } else if (motion) {
        guard.begin_motion(plan.velocity_attachment);
        bind_motion(plan);
    }
    if (plan.host_lights && !debug) {
        guard.begin_host_lights();
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, kLightsUniformBinding, uniforms_.name(), lights_uniform_offset_,
                            sizeof(LightUniforms));
    }

    if (debug) {
        const DebugGroup group(*this, "grass debug cells");
        draw_debug(plan);
    } else {
        // Near tiers first, so the depth test rejects most of the far tiers' fragments.
        // Timestamps around each kind's draws (gl_timers.cpp); they change no GL state.
        const GLuint* stamps = timer_stamps();
        if (stamps) gl_.QueryCounter(stamps[0], GL_TIMESTAMP);
        draw_blades(plan);
        if (stamps) gl_.QueryCounter(stamps[1], GL_TIMESTAMP);
        // The volume and image shaders write their coverage as a sample mask themselves.
        gl_.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        draw_sliced(plan, GRASS_TIER_VOLUME);
        if (stamps) gl_.QueryCounter(stamps[2], GL_TIMESTAMP);
        draw_sliced(plan, GRASS_TIER_IMAGE);
        if (stamps) gl_.QueryCounter(stamps[3], GL_TIMESTAMP);
    }
    return GRASS_SUCCESS;
}

} // namespace grass
