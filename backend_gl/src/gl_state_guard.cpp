#include "gl_state_guard.hpp"

#include "gl_program.hpp"

#include <algorithm>

namespace grass {

namespace {

void set_enabled(const GlFunctions& gl, GLenum capability, GLboolean enabled) {
    if (enabled) {
        gl.Enable(capability);
    } else {
        gl.Disable(capability);
    }
}

constexpr GLenum kUnpackParameters[] = {
    GL_UNPACK_ALIGNMENT,  GL_UNPACK_ROW_LENGTH,   GL_UNPACK_SKIP_ROWS,   GL_UNPACK_SKIP_PIXELS,
    GL_UNPACK_SWAP_BYTES, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES,
};

constexpr GLint kDynamicsUnits[] = {kInteractionMapUnit[0], kInteractionMapUnit[1], kWindMapUnit};
constexpr GLint kSliceUnitList[] = {kSliceColorUnit, kSliceNormalUnit, kSliceThresholdUnit};
constexpr GLint kMapUnitList[] = {kMapUnit[kMapColor], kMapUnit[kMapAmbient], kMapUnit[kMapDiffuse],
                                  kMapUnit[kMapHeight]};

static_assert(sizeof(kUnpackParameters) / sizeof(kUnpackParameters[0]) == 7, "GlUnpackStateGuard::kParameters");

// Host state that would hide or distort grass if it stayed on while grass draws: disabled
// for the draws, enabled again afterwards (grass_gl.h lists them). Every GL 4.5 context has
// at least 8 clip distances.
constexpr GLenum kHostDisabled[] = {
    GL_STENCIL_TEST,
    GL_SCISSOR_TEST,
    GL_POLYGON_OFFSET_FILL,
    GL_RASTERIZER_DISCARD,
    GL_SAMPLE_MASK,
    GL_SAMPLE_SHADING,
    GL_SAMPLE_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_DEPTH_CLAMP,
    GL_PRIMITIVE_RESTART,
    GL_PRIMITIVE_RESTART_FIXED_INDEX,
    GL_COLOR_LOGIC_OP,
    GL_CLIP_DISTANCE0,
    GL_CLIP_DISTANCE1,
    GL_CLIP_DISTANCE2,
    GL_CLIP_DISTANCE3,
    GL_CLIP_DISTANCE4,
    GL_CLIP_DISTANCE5,
    GL_CLIP_DISTANCE6,
    GL_CLIP_DISTANCE7,
};
constexpr int kHostDisabledCount = sizeof(kHostDisabled) / sizeof(kHostDisabled[0]);
static_assert(kHostDisabledCount <= 32, "GlDrawStateGuard::host_enabled_ holds one bit each");

} // namespace

void GlDrawStateGuard::save_dynamics() {
    const GlFunctions& gl = gl_;
    save_binding(kWindowLevelUniformBinding, &window_level_binding_);
    gl.GetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storage_buffer_);
    gl.GetIntegerv(GL_DRAW_INDIRECT_BUFFER_BINDING, &draw_indirect_buffer_);
    for (GLuint i = 0; i < kStorageBindings; ++i) {
        gl.GetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &storage_bindings_[i].buffer);
        gl.GetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, i, &storage_bindings_[i].start);
        gl.GetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, i, &storage_bindings_[i].size);
    }
    const GLuint unit = kInteractionImageUnit;
    gl.GetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &image_unit0_.texture);
    gl.GetIntegeri_v(GL_IMAGE_BINDING_LEVEL, unit, &image_unit0_.level);
    gl.GetIntegeri_v(GL_IMAGE_BINDING_LAYER, unit, &image_unit0_.layer);
    gl.GetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &image_unit0_.access);
    gl.GetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &image_unit0_.format);
    gl.GetBooleani_v(GL_IMAGE_BINDING_LAYERED, unit, &image_unit0_.layered);
    for (int i = 0; i < 3; ++i) {
        gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kDynamicsUnits[i]));
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &interaction_units_[i].texture_2d);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &interaction_units_[i].sampler);
    }
}

void GlDrawStateGuard::restore_dynamics() const {
    const GlFunctions& gl = gl_;
    restore_binding(kWindowLevelUniformBinding, window_level_binding_);
    for (GLuint i = 0; i < kStorageBindings; ++i) {
        const UniformBinding& b = storage_bindings_[i];
        if (b.buffer != 0 && b.size > 0) {
            gl.BindBufferRange(GL_SHADER_STORAGE_BUFFER, i, static_cast<GLuint>(b.buffer),
                               static_cast<GLintptr>(b.start), static_cast<GLsizeiptr>(b.size));
        } else {
            gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, static_cast<GLuint>(b.buffer));
        }
    }
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storage_buffer_));
    gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, static_cast<GLuint>(draw_indirect_buffer_));
    // GL_IMAGE_BINDING_FORMAT reads GL_R8 for a unit never bound: a valid format to restore.
    gl.BindImageTexture(kInteractionImageUnit, static_cast<GLuint>(image_unit0_.texture), image_unit0_.level,
                        image_unit0_.layered, image_unit0_.layer, static_cast<GLenum>(image_unit0_.access),
                        static_cast<GLenum>(image_unit0_.format));
    for (int i = 0; i < 3; ++i) {
        const GLuint unit = static_cast<GLuint>(kDynamicsUnits[i]);
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(interaction_units_[i].texture_2d));
        gl.BindSampler(unit, static_cast<GLuint>(interaction_units_[i].sampler));
    }
    gl.ActiveTexture(GL_TEXTURE0); // the destructor restores unit 0 next
}

GlDrawStateGuard::GlDrawStateGuard(const GlFunctions& gl, bool dynamics) : gl_(gl) {
    dynamics_ = dynamics;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &program_);
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
    gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
    gl.GetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniform_buffer_);
    for (GLuint i = 0; i < kUniformBindings; ++i) {
        gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, i, &uniform_bindings_[i].buffer);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_START, i, &uniform_bindings_[i].start);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, i, &uniform_bindings_[i].size);
    }
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
    if (dynamics_) save_dynamics(); // changes the active texture unit
    static_assert(sizeof(kSliceUnitList) / sizeof(kSliceUnitList[0]) == kSliceUnits, "slice units");
    for (int i = 0; i < kSliceUnits; ++i) {
        const GLuint unit = static_cast<GLuint>(kSliceUnitList[i]);
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &slice_units_[i].texture_2d_array);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &slice_units_[i].sampler);
    }
    static_assert(sizeof(kMapUnitList) / sizeof(kMapUnitList[0]) == kMapUnits, "map units");
    for (int i = 0; i < kMapUnits; ++i) {
        const GLuint unit = static_cast<GLuint>(kMapUnitList[i]);
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &map_units_[i].texture_2d);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &map_units_[i].sampler);
    }
    gl.ActiveTexture(GL_TEXTURE0);
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &texture_2d_unit0_);
    gl.GetIntegerv(GL_SAMPLER_BINDING, &sampler_unit0_);
    gl.GetFloati_v(GL_VIEWPORT, 0, viewport_);
    depth_test_ = gl.IsEnabled(GL_DEPTH_TEST);
    gl.GetIntegerv(GL_DEPTH_FUNC, &depth_func_);
    gl.GetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
    cull_face_ = gl.IsEnabled(GL_CULL_FACE);
    blend_ = gl.IsEnabledi(GL_BLEND, 0);
    multisample_ = gl.IsEnabled(GL_MULTISAMPLE);
    alpha_to_coverage_ = gl.IsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl.GetIntegerv(GL_POLYGON_MODE, polygon_mode_); // core profiles report front and back alike
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, 0, color_mask_);
    gl.ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // The host's other draw buffers (a G-buffer's normals, motion vectors...): grass's
    // shaders write location 0 alone, and GL leaves what the others get undefined.
    GLint max_draw_buffers = 1;
    gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    const GLuint buffers = std::min(static_cast<GLuint>(max_draw_buffers), kMaxDrawBuffers);
    for (GLuint i = 1; i < buffers; ++i) {
        GLint buffer = GL_NONE;
        gl.GetIntegerv(GL_DRAW_BUFFER0 + i, &buffer);
        if (buffer == GL_NONE) continue;
        other_buffers_ |= 1u << i;
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, i, other_masks_[i]);
        gl.ColorMaski(i, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    }
    for (int i = 0; i < kHostDisabledCount; ++i) {
        if (!gl.IsEnabled(kHostDisabled[i])) continue;
        host_enabled_ |= 1u << i;
        gl.Disable(kHostDisabled[i]);
    }
}

void GlDrawStateGuard::begin_depth_pass(GLfloat constant, GLfloat slope) {
    const GlFunctions& gl = gl_;
    if (!depth_pass_) {
        depth_pass_ = true;
        gl.GetFloatv(GL_POLYGON_OFFSET_FACTOR, &polygon_offset_[0]);
        gl.GetFloatv(GL_POLYGON_OFFSET_UNITS, &polygon_offset_[1]);
    }
    gl.ColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); // the others are off already
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(slope, constant);
}

void GlDrawStateGuard::save_binding(GLuint index, UniformBinding* out) const {
    gl_.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, index, &out->buffer);
    gl_.GetInteger64i_v(GL_UNIFORM_BUFFER_START, index, &out->start);
    gl_.GetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, index, &out->size);
}

void GlDrawStateGuard::restore_binding(GLuint index, const UniformBinding& b) const {
    if (b.buffer != 0 && b.size > 0) {
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, index, static_cast<GLuint>(b.buffer), static_cast<GLintptr>(b.start),
                            static_cast<GLsizeiptr>(b.size));
    } else {
        gl_.BindBufferBase(GL_UNIFORM_BUFFER, index, static_cast<GLuint>(b.buffer));
    }
}

void GlDrawStateGuard::begin_host_lights() {
    if (host_lights_) return;
    host_lights_ = true;
    save_binding(kLightsUniformBinding, &lights_binding_);
}

void GlDrawStateGuard::begin_shadow_receive() {
    const GlFunctions& gl = gl_;
    if (shadow_receive_) return;
    shadow_receive_ = true;
    GLint active = 0;
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kShadowMapUnit));
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &shadow_unit_.texture_2d_array);
    gl.GetIntegerv(GL_SAMPLER_BINDING, &shadow_unit_.sampler);
    gl.ActiveTexture(static_cast<GLenum>(active));
    save_binding(kShadowUniformBinding, &shadow_binding_);
}

void GlDrawStateGuard::begin_motion(uint32_t velocity) {
    const GlFunctions& gl = gl_;
    if (motion_) return;
    motion_ = true;
    save_draw_buffers();
    save_binding(kMotionUniformBinding, &motion_binding_);
    gl.GetBooleani_v(GL_COLOR_WRITEMASK, kVelocityOutput, velocity_mask_);
    velocity_blend_ = gl.IsEnabledi(GL_BLEND, kVelocityOutput);
    const GLenum routed[2] = {draw_buffers_[0], draw_buffers_[velocity]}; // check_velocity_target: not GL_NONE
    gl.DrawBuffers(2, routed);
    gl.ColorMaski(kVelocityOutput, GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE);
    gl.Disablei(GL_BLEND, kVelocityOutput);
}

void GlDrawStateGuard::save_draw_buffers() {
    const GlFunctions& gl = gl_;
    GLint max_draw_buffers = 1;
    gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    draw_buffer_count_ = static_cast<GLsizei>(std::min(static_cast<GLuint>(max_draw_buffers), kMaxDrawBuffers));
    for (GLsizei i = 0; i < draw_buffer_count_; ++i) {
        GLint buffer = GL_NONE;
        gl.GetIntegerv(static_cast<GLenum>(GL_DRAW_BUFFER0 + i), &buffer);
        draw_buffers_[i] = static_cast<GLenum>(buffer);
    }
}

void GlDrawStateGuard::begin_gbuffer(const uint32_t attachment[kGBufferOutputs], const uint32_t mask[kGBufferOutputs],
                                     bool motion_block) {
    const GlFunctions& gl = gl_;
    if (gbuffer_) return;
    gbuffer_ = true;
    save_draw_buffers();
    save_binding(kGBufferUniformBinding, &gbuffer_binding_);
    motion_block_ = motion_block;
    if (motion_block) save_binding(kMotionUniformBinding, &motion_binding_);
    GLenum routed[kGBufferOutputs];
    for (GLuint i = 0; i < kGBufferOutputs; ++i) {
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, i, gbuffer_masks_[i]);
        gbuffer_blend_[i] = gl.IsEnabledi(GL_BLEND, i);
        // check_gbuffer_target: an attachment grass writes is within the list and not GL_NONE.
        const bool written = attachment[i] != kNoGBufferOutput;
        routed[i] = written ? draw_buffers_[attachment[i]] : static_cast<GLenum>(GL_NONE);
        const uint32_t m = written ? mask[i] : 0u;
        gl.ColorMaski(i, (m & 1u) != 0, (m & 2u) != 0, (m & 4u) != 0, (m & 8u) != 0);
        gl.Disablei(GL_BLEND, i);
    }
    gl.DrawBuffers(static_cast<GLsizei>(kGBufferOutputs), routed);
}

// Before the host's masks and blend enables of draw buffer 0 and the others are restored
// (the constructor had set them before begin_gbuffer saved them).
void GlDrawStateGuard::restore_gbuffer() const {
    const GlFunctions& gl = gl_;
    gl.DrawBuffers(draw_buffer_count_, draw_buffers_);
    for (GLuint i = 0; i < kGBufferOutputs; ++i) {
        const GLboolean* m = gbuffer_masks_[i];
        gl.ColorMaski(i, m[0], m[1], m[2], m[3]);
        if (gbuffer_blend_[i]) {
            gl.Enablei(GL_BLEND, i);
        } else {
            gl.Disablei(GL_BLEND, i);
        }
    }
    restore_binding(kGBufferUniformBinding, gbuffer_binding_);
    if (motion_block_) restore_binding(kMotionUniformBinding, motion_binding_);
}

// Before the other draw buffers' masks are restored (draw buffer 1's, if the host had one
// there, is among them: the constructor had masked it off before begin_motion saved it).
void GlDrawStateGuard::restore_motion() const {
    const GlFunctions& gl = gl_;
    gl.DrawBuffers(draw_buffer_count_, draw_buffers_);
    gl.ColorMaski(kVelocityOutput, velocity_mask_[0], velocity_mask_[1], velocity_mask_[2], velocity_mask_[3]);
    if (velocity_blend_) {
        gl.Enablei(GL_BLEND, kVelocityOutput);
    } else {
        gl.Disablei(GL_BLEND, kVelocityOutput);
    }
    restore_binding(kMotionUniformBinding, motion_binding_);
}

GlDrawStateGuard::~GlDrawStateGuard() {
    const GlFunctions& gl = gl_;
    if (motion_) restore_motion();   // before the generic uniform binding and the masks are restored
    if (gbuffer_) restore_gbuffer(); // likewise
    if (shadow_receive_) {           // before the generic uniform binding and the active unit are restored
        gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLuint>(kShadowMapUnit));
        gl.BindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(shadow_unit_.texture_2d_array));
        gl.BindSampler(static_cast<GLuint>(kShadowMapUnit), static_cast<GLuint>(shadow_unit_.sampler));
        gl.ActiveTexture(GL_TEXTURE0);
        restore_binding(kShadowUniformBinding, shadow_binding_);
    }
    if (host_lights_) restore_binding(kLightsUniformBinding, lights_binding_);
    if (depth_pass_) {
        gl.PolygonOffset(polygon_offset_[0], polygon_offset_[1]);
        gl.Disable(GL_POLYGON_OFFSET_FILL); // enabled again below where the host had it
    }
    if (dynamics_) restore_dynamics(); // before the active texture is restored
    gl.UseProgram(static_cast<GLuint>(program_));
    gl.BindVertexArray(static_cast<GLuint>(vertex_array_)); // brings back its element buffer
    gl.BindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
    for (GLuint i = 0; i < kUniformBindings; ++i) {
        const UniformBinding& b = uniform_bindings_[i];
        // A whole-buffer binding (glBindBufferBase) reports start 0 and size 0.
        if (b.buffer != 0 && b.size > 0) {
            gl.BindBufferRange(GL_UNIFORM_BUFFER, i, static_cast<GLuint>(b.buffer), static_cast<GLintptr>(b.start),
                               static_cast<GLsizeiptr>(b.size));
        } else {
            gl.BindBufferBase(GL_UNIFORM_BUFFER, i, static_cast<GLuint>(b.buffer));
        }
    }
    gl.BindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniform_buffer_));
    // Unit 0 is active (set in the constructor).
    gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_2d_unit0_));
    gl.BindSampler(0, static_cast<GLuint>(sampler_unit0_));
    for (int i = 0; i < kSliceUnits; ++i) {
        const GLuint unit = static_cast<GLuint>(kSliceUnitList[i]);
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.BindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(slice_units_[i].texture_2d_array));
        gl.BindSampler(unit, static_cast<GLuint>(slice_units_[i].sampler));
    }
    for (int i = 0; i < kMapUnits; ++i) {
        const GLuint unit = static_cast<GLuint>(kMapUnitList[i]);
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(map_units_[i].texture_2d));
        gl.BindSampler(unit, static_cast<GLuint>(map_units_[i].sampler));
    }
    gl.ActiveTexture(static_cast<GLenum>(active_texture_));
    gl.ViewportIndexedf(0, viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    set_enabled(gl, GL_DEPTH_TEST, depth_test_);
    gl.DepthFunc(static_cast<GLenum>(depth_func_));
    gl.DepthMask(depth_mask_);
    set_enabled(gl, GL_CULL_FACE, cull_face_);
    if (blend_) {
        gl.Enablei(GL_BLEND, 0);
    } else {
        gl.Disablei(GL_BLEND, 0);
    }
    set_enabled(gl, GL_MULTISAMPLE, multisample_);
    set_enabled(gl, GL_SAMPLE_ALPHA_TO_COVERAGE, alpha_to_coverage_);
    gl.PolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
    gl.ColorMaski(0, color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
    for (GLuint i = 1; i < kMaxDrawBuffers; ++i) {
        if ((other_buffers_ & (1u << i)) == 0) continue;
        const GLboolean* m = other_masks_[i];
        gl.ColorMaski(i, m[0], m[1], m[2], m[3]);
    }
    for (int i = 0; i < kHostDisabledCount; ++i) {
        if (host_enabled_ & (1u << i)) gl.Enable(kHostDisabled[i]);
    }
}

GlUnpackStateGuard::GlUnpackStateGuard(const GlFunctions& gl, GLint alignment) : gl_(gl) {
    gl.GetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
    for (int i = 0; i < kParameters; ++i) gl.GetIntegerv(kUnpackParameters[i], &values_[i]);
    if (unpack_buffer_ != 0) gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (int i = 0; i < kParameters; ++i) {
        gl.PixelStorei(kUnpackParameters[i], kUnpackParameters[i] == GL_UNPACK_ALIGNMENT ? alignment : 0);
    }
}

GlUnpackStateGuard::~GlUnpackStateGuard() {
    for (int i = 0; i < kParameters; ++i) gl_.PixelStorei(kUnpackParameters[i], values_[i]);
    if (unpack_buffer_ != 0) gl_.BindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
}

} // namespace grass
