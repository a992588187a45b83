// Responsive grass in the GL backend (docs/responsive.md): each patch's blade curves in a
// shader storage buffer, the interaction map's levels (GL_RGBA32F textures), and the
// interaction pass (interaction.comp) dispatched by the frame's first grass_gl_render
// before any draw, followed by glMemoryBarrier. Nothing here exists for a context that
// never has wind or colliders.
#include "gl_backend.hpp"

#include "gl_program.hpp"

namespace grass {

namespace {

constexpr GLuint kInteractionGroupSize = 8; // local_size_x/y of interaction.comp
constexpr float kClearedTexel[4] = {0.0f, 0.0f, 1e30f, 1e30f};
constexpr uint64_t kInteractionTexelBytes = 16; // RGBA32F

size_t align_to(size_t value, size_t alignment) { return (value + alignment - 1) / alignment * alignment; }

// Uploads `count` elements, or one zero element when there are none: a bound storage
// buffer must have storage.
template <class T>
void upload_or_zero(const GlFunctions& gl, GlStreamBuffer& buffer, const Vector<T>& values) {
    if (!values.empty()) {
        buffer.upload(gl, values.data(), values.size() * sizeof(T));
    } else {
        const T zero{};
        buffer.upload(gl, &zero, sizeof(T));
    }
}

} // namespace

grass_result GlBackend::upload_blade_curves(uint32_t slot, const PatchData& patch) {
    if (slot >= patches_.size() || patches_[slot].vertex_array == 0) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "grass_begin_frame: blade curves for patch slot %u, which has no geometry (internal error)",
                          slot);
    }
    PatchGpu& gpu = patches_[slot];
    if (gpu.curves != 0) gl_.DeleteBuffers(1, &gpu.curves);
    gpu.curves = 0;
    gpu.curve_bytes = 0;
    const size_t bytes = patch.blade_curves.size() * sizeof(float);
    gl_.CreateBuffers(1, &gpu.curves);
    label(GL_BUFFER, gpu.curves, "grass blade curves");
    const float none[8] = {};
    gl_.NamedBufferStorage(gpu.curves, static_cast<GLsizeiptr>(bytes > 0 ? bytes : sizeof none),
                           bytes > 0 ? patch.blade_curves.data() : none, 0);
    const grass_result result = check_errors("grass_begin_frame", "uploading the patch's blade curves");
    if (result != GRASS_SUCCESS) {
        gl_.DeleteBuffers(1, &gpu.curves);
        gpu.curves = 0;
        return result;
    }
    gpu.curve_bytes = bytes;
    return GRASS_SUCCESS;
}

uint64_t GlBackend::dynamics_gpu_bytes() const {
    uint64_t bytes =
        uint64_t(interaction_levels_) * interaction_resolution_ * interaction_resolution_ * kInteractionTexelBytes;
    for (const PatchGpu& p : patches_) bytes += p.curve_bytes;
    return bytes + blade_window_bytes() + blade_compaction_bytes();
}

void GlBackend::release_interaction_map() {
    for (GLuint& texture : interaction_maps_) {
        if (texture != 0) gl_.DeleteTextures(1, &texture);
        texture = 0;
    }
    interaction_resolution_ = 0;
    interaction_levels_ = 0;
}

// The levels' Interaction blocks go after the draws' Field blocks (upload_frame), each at
// the uniform offset alignment. Returns the staging's new size.
size_t GlBackend::stage_interaction_uniforms(const FramePlan& plan, size_t size) {
    const size_t alignment = static_cast<size_t>(uniform_alignment_);
    for (uint32_t l = 0; l < plan.interaction.levels && l < 2; ++l) {
        interaction_uniform_offsets_[l] = static_cast<GLintptr>(align_to(size, alignment));
        size = static_cast<size_t>(interaction_uniform_offsets_[l]) + sizeof(InteractionLevelUniforms);
    }
    return size;
}

grass_result GlBackend::run_interaction_pass(const FramePlan& plan, const char* function) {
    const InteractionPlan& pass = plan.interaction;
    const uint32_t levels = pass.levels < 2 ? pass.levels : 2;
    if (levels == 0) return GRASS_SUCCESS;
    if (interaction_program_ == 0) {
        const grass_result result = make_interaction_program(function);
        if (result != GRASS_SUCCESS) return result;
    }
    // The map's textures: made (cleared) when the core makes the map, or if they are missing
    // (a frame without a render in between).
    if (pass.map_is_new || interaction_resolution_ != pass.resolution || interaction_levels_ != levels) {
        release_interaction_map();
        const GLsizei n = static_cast<GLsizei>(pass.resolution);
        for (uint32_t l = 0; l < levels; ++l) {
            gl_.CreateTextures(GL_TEXTURE_2D, 1, &interaction_maps_[l]);
            label(GL_TEXTURE, interaction_maps_[l], "grass interaction map");
            gl_.TextureStorage2D(interaction_maps_[l], 1, GL_RGBA32F, n, n);
            gl_.TextureParameteri(interaction_maps_[l], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            gl_.TextureParameteri(interaction_maps_[l], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            gl_.ClearTexImage(interaction_maps_[l], 0, GL_RGBA, GL_FLOAT, kClearedTexel);
        }
        interaction_resolution_ = pass.resolution;
        interaction_levels_ = levels;
        const grass_result result = check_errors(function, "making the interaction map's textures");
        if (result != GRASS_SUCCESS) {
            release_interaction_map();
            return result;
        }
    }

    upload_or_zero(gl_, colliders_, pass.colliders);
    gl_.UseProgram(interaction_program_);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCollidersStorageBinding, colliders_.name());
    const GLuint groups = (pass.resolution + kInteractionGroupSize - 1) / kInteractionGroupSize;
    for (uint32_t l = 0; l < levels; ++l) {
        upload_or_zero(gl_, tile_offsets_[l], pass.tile_offsets[l]);
        upload_or_zero(gl_, tile_colliders_[l], pass.tile_colliders[l]);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, kInteractionUniformBinding, uniforms_.name(),
                            interaction_uniform_offsets_[l], sizeof(InteractionLevelUniforms));
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileOffsetsStorageBinding, tile_offsets_[l].name());
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileCollidersStorageBinding, tile_colliders_[l].name());
        gl_.BindImageTexture(kInteractionImageUnit, interaction_maps_[l], 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        gl_.DispatchCompute(groups, groups, 1);
    }
    // The draws fetch the texels; the next frame's pass loads them as images.
    gl_.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // Unbind the compute program before a draw program is bound: Mesa's context keeps the
    // program bound next, in place of the compute stage, referenced until the compute stage
    // changes again, so that a host that never runs compute kept a grass program that
    // grass_destroy_context had deleted (GlAllocationFailure's count of GL names).
    gl_.UseProgram(0);
    return GRASS_SUCCESS;
}

void GlBackend::bind_interaction_maps() const {
    for (int l = 0; l < 2; ++l) {
        // One level: the second unit holds the first level too (never read: map_up.w = 1).
        const GLuint texture = interaction_maps_[l] != 0 ? interaction_maps_[l] : interaction_maps_[0];
        gl_.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kInteractionMapUnit[l]));
        gl_.BindTexture(GL_TEXTURE_2D, texture);
        gl_.BindSampler(static_cast<GLuint>(kInteractionMapUnit[l]), 0);
    }
    gl_.ActiveTexture(GL_TEXTURE0);
}

} // namespace grass
