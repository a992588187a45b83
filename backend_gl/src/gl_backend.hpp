// The GL 4.5 backend: owns the programs (blades, volume, image, debug view) in one variant
// per design-map feature mask, one vertex array per patch, the patches' baked slice
// textures, one texture per design map and the per-frame streaming buffers, all made with
// DSA in the host's GL context. Drawing is grass_gl_render -> GlBackend::render.
#pragma once

#include "gl_functions.hpp"
#include "gl_program.hpp"
#include "gl_program_cache.hpp"
#include "gl_stream_buffer.hpp"

#include "context/backend.hpp"
#include "context/context.hpp"
#include "timing/tier_timer_ring.hpp"

#include <cstdint>

namespace grass {

class GlBackend final : public Backend {
public:
    // Makes the backend of a new context from a validated desc (grass_gl_create_context).
    // The host's GL 4.5 context must be current. On failure nothing is left behind.
    static grass_result create(grass_context* ctx, const grass_gl_desc& desc, Backend** out_backend);

    // Use create(); public only for HostAllocator::create.
    explicit GlBackend(grass_context* ctx);
    ~GlBackend() override;
    GlBackend(const GlBackend&) = delete;
    GlBackend& operator=(const GlBackend&) = delete;

    grass_backend kind() const override { return GRASS_BACKEND_GL; }
    grass_result upload_patch(uint32_t slot, const PatchData& patch) override;
    grass_result upload_slices(uint32_t slot, const SliceSet& set) override;
    void release_patch(uint32_t slot) override;
    grass_result upload_map(uint32_t slot, const MapTexels& map) override;
    grass_result update_map(uint32_t slot, const MapTexels& map, const MapRegion& region) override;
    void release_map(uint32_t slot) override;
    grass_result upload_field(uint32_t slot, const FieldMaps& maps) override;
    void release_field(uint32_t slot) override;
    void set_field_wind_map(uint32_t slot, uint32_t map_slot) override;
    // gl_prepare.cpp: grass_prepare_pipelines and the program binaries.
    grass_result prepare_variants(const char* function, const ShaderVariant* variants, uint32_t count,
                                  bool interaction_pass, bool no_depth_test, const GBufferLayout* gbuffer) override;
    grass_result seed_pipeline_cache(const char* function, const void* data, uint64_t size) override;
    grass_result pipeline_cache_data(const char* function, void* data, uint64_t* size) override;
    grass_result begin_host_frame(const char* function, const HostFrame& frame, bool implied) override;
    grass_result begin_view(const char* function, uint32_t view, const FramePlan& plan) override;
    void end_frame() override;
    uint64_t gpu_bytes() const override;
    // The target of the last render (gl_draw.cpp): each grass_gl_render reads the host's.
    RenderTarget render_target() const override { return frame_target_; }
    // Responsive grass (gl_dynamics.cpp).
    grass_result upload_blade_curves(uint32_t slot, const PatchData& patch) override;
    uint64_t dynamics_gpu_bytes() const override;
    bool runs_blade_window() const override { return true; }
    // gl_blade_compaction.cpp; its vertex shader needs GL_ARB_shader_draw_parameters (gl_DrawID's
    // base instance), which a GL 4.5 driver may lack: then the window variant draws every blade.
    bool compacts_blade_window() const override { return draw_parameters_; }
    bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) override;
    // The host's GL context of this grass context is current (gl_current.cpp).
    grass_result check_current(const char* function) override;

    // Draws view `view` of the begun frame (< context->views.count()) into the bound draw
    // framebuffer (gl_draw.cpp). In a debug
    // context (GL_CONTEXT_FLAG_DEBUG_BIT) the GL error flags are checked after the draws:
    // an error there fails the call with GRASS_ERROR_BACKEND naming it (errors the host left
    // pending before the call are cleared first, with a warning, and not counted as grass's).
    grass_result render_checked(const char* function, uint32_t view);

private:
    struct PatchGpu {
        GLuint vertex_array = 0;
        GLuint vertices = 0;
        GLuint indices = 0;
        uint64_t bytes = 0;
        GLuint curves = 0; // responsive grass: the blade curves (shader storage), 0 until needed
        uint64_t curve_bytes = 0;
    };
    // One uploaded SliceSet of a patch: three 2D array textures with full mip chains.
    struct SliceGpu {
        uint32_t patch_slot = 0;
        uint32_t slices_per_axis = 0; // N; 0 = the horizontal slice
        GLuint color = 0;             // GL_SRGB8_ALPHA8
        GLuint normal = 0;            // GL_RGBA8
        GLuint threshold = 0;         // GL_R16
        uint64_t bytes = 0;
    };
    // A design map: GL_R16 or GL_RGBA16, one level.
    struct MapGpu {
        GLuint texture = 0;
        uint32_t width = 0;
        uint32_t height = 0;
        uint32_t channels = 0;
        uint64_t bytes = 0;
    };
    // The maps a field samples (slots into maps_) and its program variant.
    struct FieldGpu {
        FieldMaps maps;
        uint32_t wind_map = kNoMap; // responsive grass: the field's wind map (map slot)
    };

    grass_result init(const grass_gl_desc& desc);
    // gl_current.cpp: gives tier_vertex_array_ (a container object: never shared between GL
    // contexts) a label unique in the process, which check_current looks for.
    void label_context();
    // The program of `kind` for `features`, compiled on first use (upload_field compiles a
    // field's variants ahead of its first frame).
    grass_result program(GlProgramKind kind, uint32_t features, const char* function, GLuint* out_program);
    // Binds the field's maps at their units (kMapUnit): the density map, or the white
    // texture, at unit 0; the others where the field has them. Leaves unit 0 active.
    // The field's design maps, and its wind map for a draw with kFeatureWindMap.
    void bind_field_maps(const FieldGpu& field, uint32_t features) const;
    grass_result check_errors(const char* function, const char* what);
    grass_result render(const char* function, uint32_t view);
    void delete_slices(SliceGpu& slices);
    const SliceGpu* find_slices(uint32_t patch_slot, uint32_t slices_per_axis) const;
    // gl_draw.cpp
    // Uploads view `view`'s plan (its instances, Frame and Field blocks, and the interaction
    // pass's blocks where it has the pass) for `target`.
    void upload_frame(const RenderTarget& target, uint32_t view);
    void draw_blades(const FramePlan& plan) const;
    void draw_sliced(const FramePlan& plan, grass_tier_kind kind) const; // volume or image draws
    void draw_debug(const FramePlan& plan) const;                        // GRASS_VIEW_FLAG_DEBUG_CELLS
    // gl_dynamics.cpp: the interaction pass of the frame (plan.interaction), run by its first
    // render before any draw: (re)makes the map's textures when the plan says so, uploads
    // the colliders and tile lists, dispatches interaction.comp per level, then a barrier.
    grass_result run_interaction_pass(const FramePlan& plan, const char* function);
    // Binds what the draws of responsive grass read: the map's levels at units 10-11.
    void bind_interaction_maps() const;
    void release_interaction_map();
    // Uniform staging: the interaction pass's level blocks after the draws' Field blocks.
    size_t stage_interaction_uniforms(const FramePlan& plan, size_t size);
    // Timer queries (gl_timers.cpp): one GL_TIMESTAMP query per stamp of the core's ring
    // (timing/tier_timer_ring.hpp) of kTimerSets frames; each grass_gl_render of a frame is
    // one pass of it.
    static constexpr uint32_t kTimerSets = 4;
    static constexpr uint32_t kTimerQueries = kTimerSets * TierTimerRing::kStampsPerSet;
    void create_timers();
    void delete_timers();
    // The stamps of this render (TierTimerRing::kStampsPerPass), or nullptr when it is not
    // timed: no timer queries, the ring is full of unfinished frames (never waited for), or
    // too many renders in this frame.
    const GLuint* timer_stamps();
    // Reads the finished sets without waiting (TierTimerRing::collect).
    void collect_timers();
    GLuint program_of(GlProgramKind kind, uint32_t features) const {
        features &= kFeatureVariants - 1;
        if (features < kColourVariants) return programs_[kind][features];
        return depth_programs_.empty() ? 0u : depth_programs_[kind * kPassVariants + (features - kColourVariants)];
    }
    // Where the program of `kind` and `features` is kept (0: not made yet); the table of the
    // depth pass's and the shadow receivers' variants is allocated on the first such view
    // (may throw std::bad_alloc).
    GLuint* program_slot(GlProgramKind kind, uint32_t features);

    grass_context* ctx_;
    bool loaded_ = false; // gl_ holds every entry point
    GlFunctions gl_;
    GLuint programs_[kProgramKindCount][kColourVariants] = {}; // 0: not compiled yet
    // [kind * kPassVariants + mask - kColourVariants]: empty until a depth pass or a view
    // that receives shadows.
    Vector<GLuint> depth_programs_;
    GlProgramCache program_cache_; // program binaries: seeded by grass_prepare_pipelines
    GLuint tier_vertex_array_ = 0; // instances only: the volume and image tiers, debug boxes
    char context_label_[48] = {};  // tier_vertex_array_'s label (label_context)
    GLsizei context_label_length_ = 0;
    GLuint white_texture_ = 0;
    GLuint sampler_ = 0;           // design maps: linear, clamped
    GLuint slice_sampler_ = 0;     // slice colour and normal: trilinear, clamped
    GLuint threshold_sampler_ = 0; // slice thresholds: nearest, never blended
    GLuint shadow_sampler_ = 0;    // the host's shadow map: linear, depth compare; made on the first receiving view
    GLintptr shadow_uniform_offset_ = 0; // a receiving view's GrassShadow block, into uniforms_
    // A receiving view's map and block at kShadowMapUnit and uniform binding 2 (gl_draw.cpp).
    void bind_host_shadows(const FramePlan& plan);
    GLintptr motion_uniform_offset_ = 0;  // a motion view's GrassMotion block, into uniforms_
    GLintptr lights_uniform_offset_ = 0;  // a lit view's GrassLights block, into uniforms_
    GLintptr gbuffer_uniform_offset_ = 0; // a G-buffer view's GrassGBuffer block, into uniforms_
    // A G-buffer view (gl_gbuffer.cpp): the bound draw framebuffer has a draw buffer at every
    // attachment grass writes (else GRASS_MSG_GBUFFER_TARGET), checked before anything is drawn.
    grass_result check_gbuffer_target(const FramePlan& plan, const char* function) const;
    // A motion view (gl_motion.cpp): the bound draw framebuffer has a draw buffer at the
    // velocity attachment (else GRASS_MSG_VELOCITY_TARGET), checked before anything is drawn.
    grass_result check_velocity_target(const FramePlan& plan, const char* function) const;
    // Its block at kMotionUniformBinding.
    void bind_motion(const FramePlan& plan) const;
    GLint uniform_alignment_ = 256;
    GLint max_texture_size_ = 0;
    GLint max_array_layers_ = 0;
    bool draw_parameters_ = false;              // GL_ARB_shader_draw_parameters (compacts_blade_window)
    bool has_extension(const char* name) const; // in GL_EXTENSIONS (glGetStringi)
    bool debug_context_ = false;                // GL_CONTEXT_FLAG_DEBUG_BIT: glGetError after every render
    // Debug labels and object names (grass.h, grass_debug_labels), decided at creation: ON,
    // or AUTO in a debug context.
    bool labels_ = false;
    // Names a GL object "grass ..." (KHR_debug) where labels are on: one branch when off.
    void label(GLenum identifier, GLuint name, const char* text) const {
        if (labels_ && name != 0) gl_.ObjectLabel(identifier, name, -1, text);
    }
    // A debug group around the GL calls made while it lives, where labels are on.
    class DebugGroup {
    public:
        DebugGroup(const GlBackend& backend, const char* name) : gl_(backend.labels_ ? &backend.gl_ : nullptr) {
            if (gl_) gl_->PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
        }
        ~DebugGroup() {
            if (gl_) gl_->PopDebugGroup();
        }
        DebugGroup(const DebugGroup&) = delete;
        DebugGroup& operator=(const DebugGroup&) = delete;

    private:
        const GlFunctions* gl_;
    };
    GlStreamBuffer instances_;
    GlStreamBuffer uniforms_;
    Vector<unsigned char> uniform_staging_;
    Vector<GLintptr> field_uniform_offsets_; // per draw (all kinds), into uniforms_
    static constexpr uint32_t kNoView = ~0u;
    uint32_t uploaded_view_ = kNoView; // the view of the begun frame whose plan the buffers hold
    RenderTarget frame_target_;        // the Frame block's target as last uploaded: the host's at the last render
    Vector<PatchGpu> patches_;
    Vector<SliceGpu> slices_; // every patch's sets, unordered
    Vector<FieldGpu> fields_;
    Vector<MapGpu> maps_;
    bool timers_ = false; // GL_TIMESTAMP has counter bits
    GLuint timer_queries_[kTimerQueries] = {};
    TierTimerRing timer_ring_{kTimerSets, TierTimerRing::WhenBusy::skip_frame};
    bool frame_timer_opened_ = false; // the first render of the frame has opened its set
    // Responsive grass.
    GLuint interaction_program_ = 0; // compiled on the first frame with an interaction pass (or prepared)
    grass_result make_interaction_program(const char* function);
    GLuint interaction_maps_[2] = {};     // GL_RGBA32F, one per level
    uint32_t interaction_resolution_ = 0; // N of the textures made
    uint32_t interaction_levels_ = 0;     // levels made
    bool interaction_ran_ = false;        // this frame's pass has run
    GLintptr interaction_uniform_offsets_[2] = {};
    GlStreamBuffer colliders_;
    GlStreamBuffer tile_offsets_[2];
    GlStreamBuffer tile_colliders_[2];
    // gl_blade_window.cpp: the blade window pass (plan.blade_window of view 0), run by the
    // frame's first render after the interaction pass; its programs per feature mask
    // (kBladeWindowPassFeatures), made on first use; the table and work items (made on the
    // first pass) and the records (poses and state), grown as a frame needs, keeping the
    // slots' state across the growth.
    grass_result run_blade_window_pass(const FramePlan& plan, const char* function);
    grass_result blade_window_program(const char* function, uint32_t features, GLuint* out_program);
    // A compute pass's program of `mask` in `*slot`: from the seeded binaries (kind `kind`) or
    // made by `make`, labelled `name` (gl_prepare.cpp).
    using ComputeProgramMaker = grass_result (*)(grass_context*, const GlFunctions&, const char*, uint32_t, GLuint*);
    grass_result compute_program(const char* function, uint32_t kind, uint32_t mask, ComputeProgramMaker make,
                                 const char* name, GLuint* slot);
    void bind_blade_window() const; // for the responsive geometry draws: table and poses
    uint64_t blade_window_bytes() const;
    void release_blade_window_buffers(); // a frame without a window: still grass holds none
    void release_blade_window();
    GLuint window_programs_[kBladeWindowPassFeatures + 1] = {};
    GlStreamBuffer window_table_;
    GlStreamBuffer window_work_;
    GLuint window_poses_ = 0;
    uint64_t window_pose_capacity_ = 0;
    bool window_ran_ = false; // this frame's blade window pass has run
    // gl_blade_compaction.cpp: culled blades compacted. Before a view's geometry draws, one
    // dispatch per draw that runs the window variant (compacts) writes the blades the view
    // draws and the draw's indirect arguments; draw_compacted draws them. Its programs per
    // feature mask (kBladeWindowPassFeatures and kFeatureBladeCulling), made on first use; the
    // buffers grow as a view needs and go with the window's.
    grass_result blade_compaction_program(const char* function, uint32_t features, GLuint* out_program);
    bool compacts(const FramePlan& plan, const TierDraw& draw) const;
    grass_result compact_blade_window(const FramePlan& plan, const char* function);
    void draw_compacted(const TierDraw& draw, size_t index) const;
    uint64_t blade_compaction_bytes() const;
    void release_blade_compaction_buffers();
    void release_blade_compaction();
    GLuint compaction_programs_[(kBladeWindowPassFeatures | kFeatureBladeCulling) + 1] = {};
    GLuint compact_items_ = 0; // (instance, blade) per drawn blade, the draws' items after each other
    uint64_t compact_item_capacity_ = 0;
    GlStreamBuffer compact_commands_;        // DrawElementsIndirectCommand per instance of the view's compacted draws
    GlStreamBuffer compact_blocks_;          // the CompactDraw block per compacted draw, at the uniform alignment
    Vector<int32_t> compact_command_;        // per draw of the view: its block's index, or -1
    Vector<uint32_t> compact_first_command_; // ... and its first indirect arguments (one per instance)
    Vector<uint32_t> command_staging_;
    Vector<unsigned char> compact_staging_;
};

} // namespace grass
