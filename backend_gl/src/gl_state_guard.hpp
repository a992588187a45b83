// Saves the host's GL state that the backend changes and restores it on scope exit.
#pragma once

#include "gl_functions.hpp"

#include "foundation/shader_interface.hpp"

#include <cstdint>

namespace grass {

// Around drawing: exactly the state grass_gl.h documents for grass_gl_render, with the
// slice units 3-5 (their 2D array texture and sampler) and the design-map units 6-9 (their
// 2D texture and sampler). On construction texture unit 0 is made active, and the host's
// draw state that would change or hide grass is set aside: draw buffer 0's colour mask is
// made all true, the colour masks of the other draw buffers the framebuffer has
// (GL_DRAW_BUFFERi not GL_NONE) all false (grass writes draw buffer 0 alone; the blend
// state of buffers 1..N-1 is never touched), and the capabilities of kHostDisabled are
// disabled (only those the host left enabled are touched; the destructor enables them
// again). Viewport 0 and draw buffer 0's blend enable are saved for the draw code, which
// sets them with glViewportIndexedf(0, ...) and glDisablei(GL_BLEND, 0): the host's other
// viewports and buffers keep theirs. With `dynamics` (a frame
// of responsive grass) also the state of gl_dynamics.cpp: image unit 0, shader storage
// bindings 0-3 and the generic one, texture units 10-11 and 13 (2D texture and sampler).
class GlDrawStateGuard {
public:
    GlDrawStateGuard(const GlFunctions& gl, bool dynamics);
    ~GlDrawStateGuard();
    // A depth pass (FramePlan::depth_pass): every draw buffer's colour mask off and the
    // depth biased by glPolygonOffset(slope, constant) with GL_POLYGON_OFFSET_FILL, the
    // host's polygon offset saved first and restored with the rest.
    void begin_depth_pass(GLfloat constant, GLfloat slope);
    // A view that receives the host's shadows (FramePlan::shadow_receive): the host's
    // GL_TEXTURE_2D_ARRAY and sampler of texture unit 14 and its uniform binding 2 saved
    // first and restored with the rest.
    void begin_shadow_receive();
    // A view with motion vectors (FramePlan::motion): the framebuffer's draw buffers are
    // routed so that draw buffer 0 stays the host's and draw buffer 1 (the shaders' velocity
    // output) is the host's draw buffer `velocity`, every other GL_NONE; draw buffer 1 writes
    // red and green alone, unblended. The host's draw buffer list, uniform binding 3 and
    // draw buffer 1's colour mask and blend enable are saved first and restored with the rest.
    void begin_motion(uint32_t velocity);
    // A view lit by the host's lights (FramePlan::host_lights): the host's uniform binding 4
    // saved first and restored with the rest.
    void begin_host_lights();
    // A G-buffer view (FramePlan::gbuffer): output location i (kGBufferOutput) is routed to
    // the host's draw buffer attachment[i] (kNoGBufferOutput: GL_NONE) with the colour mask
    // mask[i] (bit 1 r, 2 g, 4 b, 8 a), unblended; no other draw buffer is written. The host's
    // draw buffer list, uniform binding 5 (and 3 with `motion_block`: a view whose G-buffer
    // has velocity) and the colour masks and blend enables of draw buffers 0-3 are saved
    // first and restored with the rest.
    void begin_gbuffer(const uint32_t attachment[kGBufferOutputs], const uint32_t mask[kGBufferOutputs],
                       bool motion_block);
    GlDrawStateGuard(const GlDrawStateGuard&) = delete;
    GlDrawStateGuard& operator=(const GlDrawStateGuard&) = delete;

private:
    struct UniformBinding {
        GLint buffer;
        GLint64 start;
        GLint64 size;
    };
    static constexpr GLuint kUniformBindings = 2; // Frame (0) and Field (1)
    static constexpr int kSliceUnits = 3;         // units 3, 4, 5 (gl_program.hpp)
    struct SliceUnit {
        GLint texture_2d_array;
        GLint sampler;
    };
    static constexpr int kMapUnits = 4; // units 6, 7, 8, 9 (gl_program.hpp)
    struct MapUnit {
        GLint texture_2d;
        GLint sampler;
    };
    // Responsive grass.
    static constexpr GLuint kStorageBindings = 8; // curves (0), colliders and tiles (1-3), the window pass's (4-7)
    struct ImageUnit {
        GLint texture, level, layer, access, format;
        GLboolean layered;
    };
    void save_dynamics();
    void restore_dynamics() const;
    bool dynamics_ = false;
    UniformBinding storage_bindings_[kStorageBindings] = {};
    static constexpr GLuint kWindowLevelUniformBinding = 2; // the blade window pass's Interaction block
    UniformBinding window_level_binding_ = {};
    GLint storage_buffer_ = 0;       // the generic binding
    GLint draw_indirect_buffer_ = 0; // the compacted window draws' indirect arguments bind it
    ImageUnit image_unit0_ = {};
    MapUnit interaction_units_[3] = {}; // units 10, 11 (interaction map), 13 (wind map)

    const GlFunctions& gl_;
    GLint program_ = 0;
    GLint vertex_array_ = 0;
    GLint array_buffer_ = 0;
    GLint uniform_buffer_ = 0; // the generic binding, which glBindBufferRange also changes
    UniformBinding uniform_bindings_[kUniformBindings] = {};
    GLint active_texture_ = 0;
    GLint texture_2d_unit0_ = 0;
    GLint sampler_unit0_ = 0;
    SliceUnit slice_units_[kSliceUnits] = {};
    MapUnit map_units_[kMapUnits] = {};
    GLfloat viewport_[4] = {0, 0, 0, 0}; // viewport 0, as floats (a host may set fractional ones)
    GLboolean depth_test_ = GL_FALSE;
    GLint depth_func_ = GL_LESS;
    GLboolean depth_mask_ = GL_TRUE;
    GLboolean cull_face_ = GL_FALSE;
    GLboolean blend_ = GL_FALSE; // draw buffer 0's
    GLboolean multisample_ = GL_FALSE;
    GLboolean alpha_to_coverage_ = GL_FALSE;
    GLint polygon_mode_[2] = {GL_FILL, GL_FILL};
    GLboolean color_mask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE}; // draw buffer 0's
    uint32_t host_enabled_ = 0;                                      // bit i: kHostDisabled[i] was enabled by the host
    // Draw buffers 1..kMaxDrawBuffers-1 that the bound framebuffer writes (bit i), with
    // their colour masks: masked off while grass draws.
    static constexpr GLuint kMaxDrawBuffers = 32;
    uint32_t other_buffers_ = 0;
    GLboolean other_masks_[kMaxDrawBuffers][4] = {};
    // A depth pass: the host's polygon offset factor and units.
    bool depth_pass_ = false;
    GLfloat polygon_offset_[2] = {0.0f, 0.0f};
    // A receiving view: the host's unit 14 and uniform binding 2.
    bool shadow_receive_ = false;
    SliceUnit shadow_unit_ = {};
    UniformBinding shadow_binding_ = {};
    // A motion view: the host's draw buffer list (its length: draw_buffer_count_), uniform
    // binding 3, draw buffer 1's colour mask and blend enable.
    bool motion_ = false;
    GLsizei draw_buffer_count_ = 0;
    GLenum draw_buffers_[kMaxDrawBuffers] = {};
    UniformBinding motion_binding_ = {};
    GLboolean velocity_mask_[4] = {};
    GLboolean velocity_blend_ = GL_FALSE;
    void restore_motion() const;
    void save_draw_buffers(); // draw_buffer_count_ and draw_buffers_
    // A G-buffer view: uniform binding 5, draw buffers 0-3's colour masks and blend enables
    // (the draw buffer list in draw_buffers_; binding 3 in motion_binding_ with motion_block_).
    bool gbuffer_ = false;
    bool motion_block_ = false;
    UniformBinding gbuffer_binding_ = {};
    GLboolean gbuffer_masks_[kGBufferOutputs][4] = {};
    GLboolean gbuffer_blend_[kGBufferOutputs] = {};
    void restore_gbuffer() const;
    // A lit view: the host's uniform binding 4.
    bool host_lights_ = false;
    UniformBinding lights_binding_ = {};
    void save_binding(GLuint index, UniformBinding* out) const;
    void restore_binding(GLuint index, const UniformBinding& b) const;
};

// Around texture uploads from client memory: the unpack pixel-store state and the pixel
// unpack buffer (a host's bound PBO would turn our pointer into an offset). On
// construction they are set for tightly packed rows of `alignment`-byte texels.
class GlUnpackStateGuard {
public:
    GlUnpackStateGuard(const GlFunctions& gl, GLint alignment);
    ~GlUnpackStateGuard();
    GlUnpackStateGuard(const GlUnpackStateGuard&) = delete;
    GlUnpackStateGuard& operator=(const GlUnpackStateGuard&) = delete;

private:
    static constexpr int kParameters = 7;
    const GlFunctions& gl_;
    GLint unpack_buffer_ = 0;
    GLint values_[kParameters] = {};
};

} // namespace grass
