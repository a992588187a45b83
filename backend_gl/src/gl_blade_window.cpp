// The blade window pass in the GL backend (docs/responsive.md "The blade window",
// api/src/plan/blade_window.hpp): once per frame, in the frame's first grass_gl_render
// after the interaction pass, one dispatch of blade_window.comp per geometry draw of view 0
// that the core gave slots (stepping their blades' state), then glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT). Every view's
// responsive geometry draws then read the window's table (shader storage binding 1) and
// poses (binding 2). Nothing here exists for a frame without wind or colliders.
#include "gl_backend.hpp"

#include "gl_program.hpp"

namespace grass {

namespace {

constexpr GLuint kWindowGroupSize = 64; // local_size_x of blade_window.comp
constexpr GLuint kWindowTableStorageBinding = 1;
constexpr GLuint kWindowPosesStorageBinding = 2;
// The pass's bindings (blade_window.comp lists them): the blade curves at 0
// (kBladeCurvesStorageBinding), view 0's instances at 1, the records at 2, the patch's
// vertices at 3, the work items at 4, the colliders at 5 and the fine level's tile offsets
// and tile colliders at 6 and 7; its Interaction block at uniform binding 2.
constexpr GLuint kWindowInstancesStorageBinding = 1;
constexpr GLuint kWindowVerticesStorageBinding = 3;
constexpr GLuint kWindowWorkStorageBinding = 4;
constexpr GLuint kWindowCollidersStorageBinding = 5;
constexpr GLuint kWindowTileOffsetsStorageBinding = 6;
constexpr GLuint kWindowTileCollidersStorageBinding = 7;
constexpr GLuint kWindowLevelUniformBinding = 2;

} // namespace

grass_result GlBackend::blade_window_program(const char* function, uint32_t features, GLuint* out_program) {
    const uint32_t mask = features & kBladeWindowPassFeatures;
    *out_program = 0;
    const grass_result result = compute_program(function, kBladeWindowProgramKind, mask, &create_blade_window_program,
                                                "grass blade window program", &window_programs_[mask]);
    if (result == GRASS_SUCCESS) *out_program = window_programs_[mask];
    return result;
}

grass_result GlBackend::run_blade_window_pass(const FramePlan& plan, const char* function) {
    const BladeWindowPlan& window = plan.blade_window;
    if (window.dispatches.empty()) return GRASS_SUCCESS;
    if (window_pose_capacity_ < window.pose_bytes) {
        // A larger buffer: the slots the core keeps keep their records (copied over).
        GLuint grown = 0;
        gl_.CreateBuffers(1, &grown);
        label(GL_BUFFER, grown, "grass blade window poses");
        gl_.NamedBufferData(grown, static_cast<GLsizeiptr>(window.pose_bytes), nullptr, GL_DYNAMIC_COPY);
        if (window_poses_ != 0) {
            gl_.CopyNamedBufferSubData(window_poses_, grown, 0, 0, static_cast<GLsizeiptr>(window_pose_capacity_));
        }
        const grass_result result = check_errors(function, "making the blade window's poses");
        if (result != GRASS_SUCCESS) {
            gl_.DeleteBuffers(1, &grown);
            return result;
        }
        if (window_poses_ != 0) gl_.DeleteBuffers(1, &window_poses_);
        window_poses_ = grown;
        window_pose_capacity_ = window.pose_bytes;
    }
    if (window_table_.name() == 0) {
        window_table_.create(gl_);
        label(GL_BUFFER, window_table_.name(), "grass blade window table");
    }
    if (window_work_.name() == 0) {
        window_work_.create(gl_);
        label(GL_BUFFER, window_work_.name(), "grass blade window work");
    }
    window_table_.upload(gl_, window.table.data(), window.table.size() * sizeof(uint32_t));
    window_work_.upload(gl_, window.work.data(), window.work.size() * sizeof(uint32_t));

    gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, uniforms_.name(), 0, sizeof(FrameUniforms));
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowInstancesStorageBinding, instances_.name());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowPosesStorageBinding, window_poses_);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowWorkStorageBinding, window_work_.name());
    // The state's colliders: the interaction pass's, binned per tile of its fine level.
    const bool colliders = plan.interaction.levels > 0 && colliders_.name() != 0;
    if (colliders) {
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowCollidersStorageBinding, colliders_.name());
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowTileOffsetsStorageBinding, tile_offsets_[0].name());
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowTileCollidersStorageBinding, tile_colliders_[0].name());
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, kWindowLevelUniformBinding, uniforms_.name(),
                            interaction_uniform_offsets_[0], sizeof(InteractionLevelUniforms));
    }
    bind_interaction_maps();
    for (const GLint unit : kMapUnit) gl_.BindSampler(static_cast<GLuint>(unit), sampler_);
    for (const BladeWindowDispatch& dispatch : window.dispatches) {
        const TierDraw& draw = plan.draws[dispatch.draw];
        const PatchGpu& patch = patches_[draw.patch_slot];
        GLuint program = 0;
        const grass_result result = blade_window_program(function, draw.features, &program);
        if (result != GRASS_SUCCESS) return result;
        gl_.UseProgram(program);
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kBladeCurvesStorageBinding, patch.curves);
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowVerticesStorageBinding, patch.vertices);
        bind_field_maps(fields_[draw.field_slot], draw.features);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[dispatch.draw],
                            sizeof(FieldUniforms));
        const GLuint blades = static_cast<GLuint>(patch.curve_bytes / (8 * sizeof(float)));
        gl_.DispatchCompute((blades + kWindowGroupSize - 1) / kWindowGroupSize, dispatch.items, 1);
    }
    // The draws read the poses; the next frame's pass reads and writes them again.
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl_.UseProgram(0); // as after the interaction pass (gl_dynamics.cpp)
    return GRASS_SUCCESS;
}

void GlBackend::bind_blade_window() const {
    // Without a window this frame the responsive variants read neither buffer
    // (field.transition.y = 0): the blade curves stand in.
    const bool window = window_poses_ != 0 && window_table_.capacity() > 0;
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowTableStorageBinding, window ? window_table_.name() : 0);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWindowPosesStorageBinding, window ? window_poses_ : 0);
}

uint64_t GlBackend::blade_window_bytes() const {
    return window_table_.capacity() + window_work_.capacity() + window_pose_capacity_;
}

void GlBackend::release_blade_window_buffers() {
    if (window_poses_ != 0) gl_.DeleteBuffers(1, &window_poses_);
    window_poses_ = 0;
    window_pose_capacity_ = 0;
    window_table_.destroy(gl_);
    window_work_.destroy(gl_);
}

void GlBackend::release_blade_window() {
    release_blade_window_buffers();
    for (GLuint& program : window_programs_) {
        if (program != 0) gl_.DeleteProgram(program);
        program = 0;
    }
}

} // namespace grass
