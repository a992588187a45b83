// Executing a frame plan: upload its instances and uniforms once per frame, then one
// instanced draw per planned draw (blades, or debug boxes), inside a guard that restores
// the host's GL state.
#include "gl_backend.hpp"

#include "gl_state_guard.hpp"

#include <cstring>

namespace grass {

namespace {

size_t align_up(size_t value, size_t alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace

// Uniform buffer layout: Frame at offset 0, then one Field block per draw of any kind
// (the debug view draws them all), each at GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT.
void GlBackend::upload_frame() {
    const FramePlan& plan = ctx_->plan;
    const size_t alignment = static_cast<size_t>(uniform_alignment_);

    field_uniform_offsets_.resize(plan.draws.size());
    size_t size = sizeof(FrameUniforms);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        field_uniform_offsets_[i] = static_cast<GLintptr>(align_up(size, alignment));
        size = static_cast<size_t>(field_uniform_offsets_[i]) + sizeof(FieldUniforms);
    }
    uniform_staging_.assign(size, 0);
    std::memcpy(uniform_staging_.data(), &plan.frame, sizeof(FrameUniforms));
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        std::memcpy(uniform_staging_.data() + field_uniform_offsets_[i], &plan.draws[i].uniforms,
                    sizeof(FieldUniforms));
    }
    uniforms_.upload(gl_, uniform_staging_.data(), uniform_staging_.size());
    instances_.upload(gl_, plan.instances.data(), plan.instances.size() * sizeof(TierInstance));
    frame_uploaded_ = true;
}

// Volume and image tiers are not drawn yet (the three-tier issue): only geometry draws.
void GlBackend::draw_blades(const FramePlan& plan) const {
    gl_.UseProgram(program_);
    gl_.BindSampler(0, sampler_);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (draw.kind != GRASS_TIER_GEOMETRY) continue;
        const PatchGpu& patch = patches_[draw.patch_slot];
        const FieldGpu& field = fields_[draw.field_slot];
        if (draw.instance_count == 0 || patch.index_count == 0) continue;
        gl_.BindVertexArray(patch.vertex_array);
        gl_.BindTexture(GL_TEXTURE_2D, field.density_map != 0 ? field.density_map : white_texture_);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[i], sizeof(FieldUniforms));
        gl_.DrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(patch.index_count), GL_UNSIGNED_INT,
                                              nullptr, static_cast<GLsizei>(draw.instance_count), draw.first_instance);
    }
}

grass_result GlBackend::render(const char* function) {
    const FramePlan& plan = ctx_->plan;
    if (plan.draws.empty()) return GRASS_SUCCESS;
    const bool debug = (plan.flags & GRASS_VIEW_FLAG_DEBUG_TIERS) != 0;

    // Check the plan against what was uploaded before touching any GL state. Only the
    // draws that use a patch need one.
    for (const TierDraw& draw : plan.draws) {
        const bool needs_patch = !debug && draw.kind == GRASS_TIER_GEOMETRY;
        const bool patch_ok =
            !needs_patch || (draw.patch_slot < patches_.size() && patches_[draw.patch_slot].vertex_array != 0);
        const bool instances_ok = uint64_t(draw.first_instance) + draw.instance_count <= plan.instances.size();
        if (!patch_ok || draw.field_slot >= fields_.size() || !instances_ok) {
            return ctx_->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                              "%s: the frame plan refers to patch slot %u, field slot %u, instances %u+%u, which the "
                              "GL backend does not hold (internal error)",
                              function, draw.patch_slot, draw.field_slot, draw.first_instance, draw.instance_count);
        }
    }
    if (!frame_uploaded_) upload_frame();

    GlDrawStateGuard guard(gl_); // also makes texture unit 0 active
    gl_.Viewport(plan.viewport[0], plan.viewport[1], plan.viewport[2], plan.viewport[3]);
    if (plan.flags & GRASS_VIEW_FLAG_NO_DEPTH_TEST) {
        gl_.Disable(GL_DEPTH_TEST);
    } else {
        gl_.Enable(GL_DEPTH_TEST);
    }
    gl_.DepthFunc(ctx_->desc.depth_mode == GRASS_DEPTH_GREATER ? GL_GEQUAL : GL_LEQUAL);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_CULL_FACE); // blades are two-sided
    gl_.Disable(GL_BLEND);
    gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    GLint sample_buffers = 0;
    gl_.GetIntegerv(GL_SAMPLE_BUFFERS, &sample_buffers); // of the bound draw framebuffer
    if (sample_buffers > 0) {
        gl_.Enable(GL_MULTISAMPLE);
        gl_.Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    } else {
        gl_.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    }
    gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, uniforms_.name(), 0, sizeof(FrameUniforms));

    if (debug) {
        debug_view_.draw(gl_, plan, uniforms_.name(), field_uniform_offsets_);
    } else {
        draw_blades(plan);
    }
    return GRASS_SUCCESS;
}

} // namespace grass
