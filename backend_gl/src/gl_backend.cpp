#include "gl_backend.hpp"

#include "gl_instance_input.hpp"
#include "gl_program.hpp"
#include "gl_state_guard.hpp"

#include <cstddef>
#include <cstring>

namespace grass {

namespace {

constexpr const char* kCreateFunction = "grass_gl_create_context";

struct VertexAttribute {
    GLuint location;
    GLint size;
    GLenum type;
    GLboolean normalized;
    GLuint offset;
    GLuint binding;
    bool integer; // read as an integer (uvec) in the shader
};

// The vertex input of blade.vert: patch vertices on binding 0, instances on
// kInstanceBinding (1).
constexpr GLuint kVertexBinding = 0;
const VertexAttribute kBladeAttributes[] = {
    {0, 3, GL_FLOAT, GL_FALSE, offsetof(BladeVertex, position), kVertexBinding, false},
    {1, 3, GL_FLOAT, GL_FALSE, offsetof(BladeVertex, normal), kVertexBinding, false},
    {2, 4, GL_FLOAT, GL_FALSE, offsetof(BladeVertex, root_shape), kVertexBinding, false},
    {3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(BladeVertex, color), kVertexBinding, false},
    {4, 1, GL_FLOAT, GL_FALSE, offsetof(BladeVertex, threshold), kVertexBinding, false},
    {5, 4, GL_FLOAT, GL_FALSE, offsetof(TierInstance, origin), kInstanceBinding, false},
    {6, 4, GL_UNSIGNED_INT, GL_FALSE, offsetof(TierInstance, cell), kInstanceBinding, true},
    {7, 4, GL_FLOAT, GL_FALSE, offsetof(TierInstance, terrain), kInstanceBinding, false},
};

const char* gl_error_name(GLenum error) {
    switch (error) {
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW:
        return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
        return "GL_STACK_UNDERFLOW";
    default:
        return "an unknown GL error";
    }
}

} // namespace

GlBackend::GlBackend(grass_context* ctx)
    : ctx_(ctx), depth_programs_(StlAllocator<GLuint>(&ctx->host)), program_cache_(ctx),
      uniform_staging_(StlAllocator<unsigned char>(&ctx->host)),
      field_uniform_offsets_(StlAllocator<GLintptr>(&ctx->host)), patches_(StlAllocator<PatchGpu>(&ctx->host)),
      slices_(StlAllocator<SliceGpu>(&ctx->host)), fields_(StlAllocator<FieldGpu>(&ctx->host)),
      maps_(StlAllocator<MapGpu>(&ctx->host)), compact_command_(StlAllocator<int32_t>(&ctx->host)),
      compact_first_command_(StlAllocator<uint32_t>(&ctx->host)), command_staging_(StlAllocator<uint32_t>(&ctx->host)),
      compact_staging_(StlAllocator<unsigned char>(&ctx->host)) {}

grass_result GlBackend::create(grass_context* ctx, const grass_gl_desc& desc, Backend** out_backend) {
    GlBackend* backend = nullptr;
    const grass_result result = guarded(ctx, kCreateFunction, [&] {
        backend = ctx->host.create<GlBackend>(ctx);
        return backend->init(desc);
    });
    if (result != GRASS_SUCCESS) {
        ctx->host.destroy(backend);
        return result;
    }
    *out_backend = backend;
    return GRASS_SUCCESS;
}

bool GlBackend::has_extension(const char* name) const {
    GLint count = 0;
    gl_.GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* extension = gl_.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
        if (extension != nullptr && std::strcmp(reinterpret_cast<const char*>(extension), name) == 0) return true;
    }
    return false;
}

grass_result GlBackend::init(const grass_gl_desc& desc) {
    if (const char* missing = gl_.load(desc.get_proc_address, desc.get_proc_address_user_data)) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: gl_desc->get_proc_address returned NULL for %s; an OpenGL 4.5 context is required",
                          kCreateFunction, missing);
    }
    loaded_ = true;

    GLint major = 0;
    GLint minor = 0;
    gl_.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl_.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 4 || (major == 4 && minor < 5)) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: the current GL context is version %d.%d; OpenGL 4.5 is required (is a context current "
                          "on this thread?)",
                          kCreateFunction, major, minor);
    }
    gl_.GetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &uniform_alignment_);
    if (uniform_alignment_ < 1) uniform_alignment_ = 256;
    gl_.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture_size_);
    gl_.GetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_array_layers_);
    GLint flags = 0;
    gl_.GetIntegerv(GL_CONTEXT_FLAGS, &flags);
    debug_context_ = (flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0;
    draw_parameters_ = has_extension("GL_ARB_shader_draw_parameters");
    program_cache_.init(gl_, shader_sources_hash());
    labels_ = ctx_->debug_labels == GRASS_DEBUG_LABELS_ON ||
              (ctx_->debug_labels == GRASS_DEBUG_LABELS_AUTO && debug_context_);

    // The variants of fields without design maps; the others come with their fields.
    grass_result result = GRASS_SUCCESS;
    for (uint32_t kind = 0; kind < kProgramKindCount; ++kind) {
        GLuint unused = 0;
        result = program(static_cast<GlProgramKind>(kind), 0, kCreateFunction, &unused);
        if (result != GRASS_SUCCESS) return result;
    }

    gl_.CreateTextures(GL_TEXTURE_2D, 1, &white_texture_);
    label(GL_TEXTURE, white_texture_, "grass default design map");
    gl_.TextureStorage2D(white_texture_, 1, GL_R16, 1, 1);
    {
        const uint16_t white = 0xFFFF;
        GlUnpackStateGuard unpack(gl_, 2);
        gl_.TextureSubImage2D(white_texture_, 0, 0, 0, 1, 1, GL_RED, GL_UNSIGNED_SHORT, &white);
    }

    gl_.CreateSamplers(1, &sampler_);
    label(GL_SAMPLER, sampler_, "grass design map sampler");
    gl_.SamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.SamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.SamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.SamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // Slice colour and normal: trilinear. Thresholds are ids, not signals: never blended.
    gl_.CreateSamplers(1, &slice_sampler_);
    label(GL_SAMPLER, slice_sampler_, "grass slice sampler");
    gl_.SamplerParameteri(slice_sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl_.SamplerParameteri(slice_sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.SamplerParameteri(slice_sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.SamplerParameteri(slice_sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.CreateSamplers(1, &threshold_sampler_);
    label(GL_SAMPLER, threshold_sampler_, "grass slice threshold sampler");
    gl_.SamplerParameteri(threshold_sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    gl_.SamplerParameteri(threshold_sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.SamplerParameteri(threshold_sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.SamplerParameteri(threshold_sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    instances_.create(gl_);
    uniforms_.create(gl_);
    colliders_.create(gl_);
    label(GL_BUFFER, instances_.name(), "grass instances");
    label(GL_BUFFER, uniforms_.name(), "grass uniforms");
    label(GL_BUFFER, colliders_.name(), "grass colliders");
    for (int l = 0; l < 2; ++l) {
        tile_offsets_[l].create(gl_);
        tile_colliders_[l].create(gl_);
        label(GL_BUFFER, tile_offsets_[l].name(), "grass collider tile offsets");
        label(GL_BUFFER, tile_colliders_[l].name(), "grass collider tiles");
    }
    tier_vertex_array_ = create_instance_vertex_array(gl_, instances_.name());
    label_context(); // always: the current-context check reads this label (gl_current.cpp)
    create_timers();
    result = check_errors(kCreateFunction, "creating the programs, white texture, samplers and timer queries");
    if (result != GRASS_SUCCESS) return result;

    return GRASS_SUCCESS;
}

GlBackend::~GlBackend() {
    if (!loaded_ || abandoned()) return; // abandoned: the GL objects go with their GL context
    for (uint32_t slot = 0; slot < patches_.size(); ++slot) release_patch(slot);
    for (uint32_t slot = 0; slot < fields_.size(); ++slot) release_field(slot);
    for (uint32_t slot = 0; slot < maps_.size(); ++slot) release_map(slot);
    for (SliceGpu& s : slices_) delete_slices(s); // sets of slots never given a patch
    slices_.clear();
    delete_timers();
    if (tier_vertex_array_ != 0) gl_.DeleteVertexArrays(1, &tier_vertex_array_);
    instances_.destroy(gl_);
    uniforms_.destroy(gl_);
    colliders_.destroy(gl_);
    for (int l = 0; l < 2; ++l) {
        tile_offsets_[l].destroy(gl_);
        tile_colliders_[l].destroy(gl_);
    }
    release_interaction_map();
    release_blade_window();
    release_blade_compaction();
    if (interaction_program_ != 0) gl_.DeleteProgram(interaction_program_);
    if (sampler_ != 0) gl_.DeleteSamplers(1, &sampler_);
    if (slice_sampler_ != 0) gl_.DeleteSamplers(1, &slice_sampler_);
    if (threshold_sampler_ != 0) gl_.DeleteSamplers(1, &threshold_sampler_);
    if (shadow_sampler_ != 0) gl_.DeleteSamplers(1, &shadow_sampler_);
    if (white_texture_ != 0) gl_.DeleteTextures(1, &white_texture_);
    for (auto& variants : programs_) {
        for (GLuint program : variants) {
            if (program != 0) gl_.DeleteProgram(program);
        }
    }
    for (GLuint program : depth_programs_) {
        if (program != 0) gl_.DeleteProgram(program);
    }
}

GLuint* GlBackend::program_slot(GlProgramKind kind, uint32_t features) {
    features &= kFeatureVariants - 1;
    if (features < kColourVariants) return &programs_[kind][features];
    if (depth_programs_.empty()) depth_programs_.assign(size_t(kProgramKindCount) * kPassVariants, 0u);
    return &depth_programs_[kind * kPassVariants + (features - kColourVariants)];
}

grass_result GlBackend::program(GlProgramKind kind, uint32_t features, const char* function, GLuint* out_program) {
    features &= kFeatureVariants - 1;
    if (kind == kProgramDebugTiers) features &= kDebugBoxFeatures; // the boxes sample the height map only
    GLuint& cached = *program_slot(kind, features);
    if (cached == 0) {
        cached = program_cache_.load(gl_, function, kind, features);
        if (cached != 0) set_sampler_units(gl_, cached);
        if (cached == 0) {
            const grass_result result = create_program(ctx_, gl_, function, kind, features, draw_parameters_, &cached);
            if (result != GRASS_SUCCESS) return result;
        }
        static const char* const kNames[kProgramKindCount] = {"grass blades program", "grass volume program",
                                                              "grass image program", "grass debug cells program"};
        label(GL_PROGRAM, cached, kNames[kind]); // made or loaded from the binary cache
    }
    *out_program = cached;
    return GRASS_SUCCESS;
}

// Drains the GL error flags. glGetError is the only way to see GL_OUT_OF_MEMORY; it is
// called on the (rare) upload paths only, never while drawing.
grass_result GlBackend::check_errors(const char* function, const char* what) {
    GLenum first = GL_NO_ERROR;
    bool out_of_memory = false;
    for (int i = 0; i < 32; ++i) {
        const GLenum error = gl_.GetError();
        if (error == GL_NO_ERROR) break;
        if (first == GL_NO_ERROR) first = error;
        out_of_memory = out_of_memory || error == GL_OUT_OF_MEMORY;
    }
    if (out_of_memory) {
        return ctx_->fail(GRASS_ERROR_OUT_OF_MEMORY, GRASS_MSG_OUT_OF_MEMORY, "%s: GL_OUT_OF_MEMORY while %s", function,
                          what);
    }
    if (first != GL_NO_ERROR) {
        return ctx_->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: %s (0x%04X) while %s", function,
                          gl_error_name(first), first, what);
    }
    return GRASS_SUCCESS;
}

grass_result GlBackend::render_checked(const char* function, uint32_t view) {
    if (!debug_context_) return render(function, view); // glGetError stalls: only where the host asked to debug
    GLenum pending = gl_.GetError();
    if (pending != GL_NO_ERROR) {
        ctx_->warn(GRASS_MSG_BACKEND_CALL_FAILED,
                   "%s: the host's GL context had %s (0x%04X) pending before the call; grass cleared it", function,
                   gl_error_name(pending), pending);
        for (int i = 0; i < 32 && pending != GL_NO_ERROR; ++i) pending = gl_.GetError();
    }
    const grass_result result = render(function, view);
    return result == GRASS_SUCCESS ? check_errors(function, "drawing (a debug context is checked after each call)")
                                   : result;
}

grass_result GlBackend::upload_patch(uint32_t slot, const PatchData& patch) {
    if (slot >= patches_.size()) patches_.resize(slot + 1);
    release_patch(slot);
    PatchGpu& gpu = patches_[slot];

    const size_t vertex_bytes = patch.vertices.size() * sizeof(BladeVertex);
    const size_t index_bytes = patch.indices.size() * sizeof(uint32_t);
    gl_.CreateBuffers(1, &gpu.vertices);
    gl_.CreateBuffers(1, &gpu.indices);
    label(GL_BUFFER, gpu.vertices, "grass patch vertices");
    label(GL_BUFFER, gpu.indices, "grass patch indices");
    if (vertex_bytes > 0) {
        gl_.NamedBufferStorage(gpu.vertices, static_cast<GLsizeiptr>(vertex_bytes), patch.vertices.data(), 0);
    }
    if (index_bytes > 0) {
        gl_.NamedBufferStorage(gpu.indices, static_cast<GLsizeiptr>(index_bytes), patch.indices.data(), 0);
    }

    gl_.CreateVertexArrays(1, &gpu.vertex_array);
    label(GL_VERTEX_ARRAY, gpu.vertex_array, "grass patch vertex array");
    const GLuint vao = gpu.vertex_array;
    gl_.VertexArrayVertexBuffer(vao, kVertexBinding, gpu.vertices, 0, sizeof(BladeVertex));
    gl_.VertexArrayVertexBuffer(vao, kInstanceBinding, instances_.name(), 0, sizeof(TierInstance));
    gl_.VertexArrayBindingDivisor(vao, kInstanceBinding, 1);
    gl_.VertexArrayElementBuffer(vao, gpu.indices);
    for (const VertexAttribute& a : kBladeAttributes) {
        gl_.EnableVertexArrayAttrib(vao, a.location);
        if (a.integer) {
            gl_.VertexArrayAttribIFormat(vao, a.location, a.size, a.type, a.offset);
        } else {
            gl_.VertexArrayAttribFormat(vao, a.location, a.size, a.type, a.normalized, a.offset);
        }
        gl_.VertexArrayAttribBinding(vao, a.location, a.binding);
    }

    const grass_result result = check_errors("grass_create_patch", "uploading the patch's blade geometry");
    if (result != GRASS_SUCCESS) {
        release_patch(slot);
        return result;
    }
    gpu.bytes = vertex_bytes + index_bytes;
    return GRASS_SUCCESS;
}

grass_result GlBackend::upload_slices(uint32_t slot, const SliceSet& set) {
    constexpr const char* kFunction = "grass_create_field";
    const uint32_t n = set.slices_per_axis;
    const uint64_t total_texels = set.offset(set.layers, 0);
    // The core checked the set against the layout contract (check_slice_set).
    if (set.width > static_cast<uint32_t>(max_texture_size_) || set.height > static_cast<uint32_t>(max_texture_size_) ||
        set.layers > static_cast<uint32_t>(max_array_layers_)) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: the baked slices (N = %u) are %u layers of %ux%u texels; this GL device's "
                          "GL_MAX_TEXTURE_SIZE is %d and GL_MAX_ARRAY_TEXTURE_LAYERS %d",
                          kFunction, n, set.layers, set.width, set.height, max_texture_size_, max_array_layers_);
    }

    // A set is uploaded once per patch and N; a repeat replaces it.
    for (size_t i = 0; i < slices_.size(); ++i) {
        if (slices_[i].patch_slot == slot && slices_[i].slices_per_axis == n) {
            delete_slices(slices_[i]);
            slices_[i] = slices_.back();
            slices_.pop_back();
            break;
        }
    }

    SliceGpu gpu;
    gpu.patch_slot = slot;
    gpu.slices_per_axis = n;
    struct Array {
        GLuint* texture;
        GLenum internal_format;
        GLenum format;
        GLenum type;
        const void* texels;
        size_t texel_bytes;
        const char* name; // its label (debug labels)
    };
    const Array arrays[] = {
        {&gpu.color, GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, set.color.data(), 4, "grass slice colours"},
        {&gpu.normal, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, set.normal.data(), 4, "grass slice normals"},
        {&gpu.threshold, GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, set.threshold.data(), 8, "grass slice thresholds"},
    };
    {
        GlUnpackStateGuard unpack(gl_, 1); // rows tightly packed, whatever their width
        for (const Array& a : arrays) {
            gl_.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, a.texture);
            label(GL_TEXTURE, *a.texture, a.name);
            gl_.TextureStorage3D(*a.texture, static_cast<GLsizei>(set.mip_levels), a.internal_format,
                                 static_cast<GLsizei>(set.width), static_cast<GLsizei>(set.height),
                                 static_cast<GLsizei>(set.layers));
            const auto* bytes = static_cast<const unsigned char*>(a.texels);
            for (uint32_t level = 0; level < set.mip_levels; ++level) {
                for (uint32_t layer = 0; layer < set.layers; ++layer) {
                    gl_.TextureSubImage3D(*a.texture, static_cast<GLint>(level), 0, 0, static_cast<GLint>(layer),
                                          static_cast<GLsizei>(set.level_width(level)),
                                          static_cast<GLsizei>(set.level_height(level)), 1, a.format, a.type,
                                          bytes + set.offset(layer, level) * a.texel_bytes);
                }
            }
        }
    }
    const grass_result result = check_errors(kFunction, "uploading the patch's baked slices");
    if (result != GRASS_SUCCESS) {
        delete_slices(gpu);
        return result;
    }
    gpu.bytes = total_texels * (4 + 4 + 2);
    slices_.push_back(gpu);
    return GRASS_SUCCESS;
}

void GlBackend::delete_slices(SliceGpu& slices) {
    if (slices.color != 0) gl_.DeleteTextures(1, &slices.color);
    if (slices.normal != 0) gl_.DeleteTextures(1, &slices.normal);
    if (slices.threshold != 0) gl_.DeleteTextures(1, &slices.threshold);
    slices = SliceGpu{};
}

const GlBackend::SliceGpu* GlBackend::find_slices(uint32_t patch_slot, uint32_t slices_per_axis) const {
    for (const SliceGpu& s : slices_) {
        if (s.patch_slot == patch_slot && s.slices_per_axis == slices_per_axis) return &s;
    }
    return nullptr;
}

void GlBackend::release_patch(uint32_t slot) {
    for (size_t i = 0; i < slices_.size();) {
        if (slices_[i].patch_slot == slot) {
            delete_slices(slices_[i]);
            slices_[i] = slices_.back();
            slices_.pop_back();
        } else {
            ++i;
        }
    }
    if (slot >= patches_.size()) return;
    PatchGpu& gpu = patches_[slot];
    if (gpu.vertex_array != 0) gl_.DeleteVertexArrays(1, &gpu.vertex_array);
    if (gpu.vertices != 0) gl_.DeleteBuffers(1, &gpu.vertices);
    if (gpu.indices != 0) gl_.DeleteBuffers(1, &gpu.indices);
    if (gpu.curves != 0) gl_.DeleteBuffers(1, &gpu.curves);
    gpu = PatchGpu{};
}

grass_result GlBackend::upload_map(uint32_t slot, const MapTexels& map) {
    constexpr const char* kFunction = "grass_create_map";
    if (slot >= maps_.size()) maps_.resize(slot + 1);
    release_map(slot);
    if (map.texels == nullptr || map.width == 0 || map.height == 0 || (map.channels != 1 && map.channels != 4)) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "%s: map slot %u has %ux%u texels of %u channels (internal error)", kFunction, slot,
                          map.width, map.height, map.channels);
    }
    if (map.width > static_cast<uint32_t>(max_texture_size_) || map.height > static_cast<uint32_t>(max_texture_size_)) {
        return ctx_->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                          "%s: the map is %ux%u texels; this GL device's GL_MAX_TEXTURE_SIZE is %d", kFunction,
                          map.width, map.height, max_texture_size_);
    }
    MapGpu& gpu = maps_[slot];
    const bool rgba = map.channels == 4;
    gl_.CreateTextures(GL_TEXTURE_2D, 1, &gpu.texture);
    label(GL_TEXTURE, gpu.texture, "grass design map");
    gl_.TextureStorage2D(gpu.texture, 1, rgba ? GL_RGBA16 : GL_R16, static_cast<GLsizei>(map.width),
                         static_cast<GLsizei>(map.height));
    {
        GlUnpackStateGuard unpack(gl_, 2);
        gl_.TextureSubImage2D(gpu.texture, 0, 0, 0, static_cast<GLsizei>(map.width), static_cast<GLsizei>(map.height),
                              rgba ? GL_RGBA : GL_RED, GL_UNSIGNED_SHORT, map.texels);
    }
    const grass_result result = check_errors(kFunction, "uploading a design map");
    if (result != GRASS_SUCCESS) {
        release_map(slot);
        return result;
    }
    gpu.width = map.width;
    gpu.height = map.height;
    gpu.channels = map.channels;
    gpu.bytes = uint64_t(map.width) * map.height * map.channels * sizeof(uint16_t);
    return GRASS_SUCCESS;
}

// Copies just the region, read from the core's whole copy: the row length is the map's
// width and the pointer the region's first texel.
grass_result GlBackend::update_map(uint32_t slot, const MapTexels& map, const MapRegion& region) {
    constexpr const char* kFunction = "grass_update_map";
    const bool known = slot < maps_.size() && maps_[slot].texture != 0;
    const bool fits = known && map.texels != nullptr && map.width == maps_[slot].width &&
                      map.height == maps_[slot].height && map.channels == maps_[slot].channels &&
                      uint64_t(region.x) + region.width <= map.width &&
                      uint64_t(region.y) + region.height <= map.height;
    if (!fits) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                          "%s: region %u,%u %ux%u of map slot %u does not fit the uploaded map (internal error)",
                          kFunction, region.x, region.y, region.width, region.height, slot);
    }
    if (region.width == 0 || region.height == 0) return GRASS_SUCCESS;
    const MapGpu& gpu = maps_[slot];
    {
        GlUnpackStateGuard unpack(gl_, 2);
        gl_.PixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(map.width));
        const uint16_t* first = map.texels + (size_t(region.y) * map.width + region.x) * map.channels;
        gl_.TextureSubImage2D(gpu.texture, 0, static_cast<GLint>(region.x), static_cast<GLint>(region.y),
                              static_cast<GLsizei>(region.width), static_cast<GLsizei>(region.height),
                              gpu.channels == 4 ? GL_RGBA : GL_RED, GL_UNSIGNED_SHORT, first);
    }
    return check_errors(kFunction, "updating a design map");
}

void GlBackend::release_map(uint32_t slot) {
    if (slot >= maps_.size()) return;
    MapGpu& gpu = maps_[slot];
    if (gpu.texture != 0) gl_.DeleteTextures(1, &gpu.texture);
    gpu = MapGpu{};
}

grass_result GlBackend::upload_field(uint32_t slot, const FieldMaps& maps) {
    constexpr const char* kFunction = "grass_create_field";
    if (slot >= fields_.size()) fields_.resize(slot + 1);
    release_field(slot);
    // The core checked the maps against the feature mask (check_field_maps).
    const uint32_t features = maps.features;
    // The field's program variants now, so that its first frame does not compile them (the
    // debug view's compiles when first drawn).
    for (GlProgramKind kind : {kProgramBlades, kProgramVolume, kProgramImage}) {
        GLuint unused = 0;
        const grass_result result = program(kind, features, kFunction, &unused);
        if (result != GRASS_SUCCESS) return result;
    }
    fields_[slot].maps = maps;
    return GRASS_SUCCESS;
}

void GlBackend::release_field(uint32_t slot) {
    if (slot >= fields_.size()) return;
    fields_[slot] = FieldGpu{};
}

void GlBackend::set_field_wind_map(uint32_t slot, uint32_t map_slot) {
    if (slot < fields_.size()) fields_[slot].wind_map = map_slot;
}

grass_result GlBackend::begin_host_frame(const char*, const HostFrame&, bool) {
    // GL orders buffer reuse itself (a stream buffer is orphaned when rewritten): the host's
    // finished frames change nothing here. Each view's plan is uploaded by the first
    // grass_gl_render_view that draws it, where the host's GL context is current by contract.
    uploaded_view_ = kNoView;
    interaction_ran_ = false;
    window_ran_ = false;
    timer_ring_.close_frame(); // a frame's timer set is closed when it ends; this is a safeguard
    frame_timer_opened_ = false;
    return GRASS_SUCCESS;
}

// A view's plan stays in the context until the frame ends; render() uploads it.
grass_result GlBackend::begin_view(const char*, uint32_t, const FramePlan&) { return GRASS_SUCCESS; }

void GlBackend::end_frame() { timer_ring_.close_frame(); }

uint64_t GlBackend::gpu_bytes() const {
    uint64_t bytes = instances_.capacity() + uniforms_.capacity();
    if (white_texture_ != 0) bytes += sizeof(uint16_t);
    for (const PatchGpu& p : patches_) bytes += p.bytes;
    for (const SliceGpu& s : slices_) bytes += s.bytes;
    for (const MapGpu& m : maps_) bytes += m.bytes;
    bytes += colliders_.capacity();
    for (int l = 0; l < 2; ++l) bytes += tile_offsets_[l].capacity() + tile_colliders_[l].capacity();
    return bytes + dynamics_gpu_bytes();
}

} // namespace grass
