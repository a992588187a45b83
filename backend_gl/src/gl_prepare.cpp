// grass_prepare_pipelines on GL: compiles (or loads from the seeded program binaries) every
// program variant the core asks for and the compute programs of the interaction, blade
// window and compaction passes; the program binaries' blob (gl_program_cache.hpp).
#include "gl_backend.hpp"
#include "gl_program.hpp"

namespace grass {

grass_result GlBackend::make_interaction_program(const char* function) {
    interaction_program_ = program_cache_.load(gl_, function, kInteractionProgramKind, 0);
    grass_result result = GRASS_SUCCESS;
    if (interaction_program_ == 0) result = create_interaction_program(ctx_, gl_, function, &interaction_program_);
    if (result == GRASS_SUCCESS) label(GL_PROGRAM, interaction_program_, "grass interaction program");
    return result;
}

// One program draws with the depth test and without; one program draws every G-buffer layout
// (the draw buffers route its outputs: gl_gbuffer.cpp).
grass_result GlBackend::prepare_variants(const char* function, const ShaderVariant* variants, uint32_t count,
                                         bool interaction_pass, bool /*no_depth_test*/,
                                         const GBufferLayout* /*gbuffer*/) {
    for (uint32_t i = 0; i < count; ++i) {
        GLuint unused = 0;
        grass_result result =
            program(static_cast<GlProgramKind>(variants[i].program), variants[i].features, function, &unused);
        // A window variant's draws are posed by the blade window pass of its maps and bits,
        // and compacted by the compaction pass of its maps and bits (gl_blade_compaction.cpp).
        if (result == GRASS_SUCCESS && (variants[i].features & kFeatureBladeWindow) != 0)
            result = blade_window_program(function, variants[i].features, &unused);
        if (result == GRASS_SUCCESS && draw_parameters_ && (variants[i].features & kFeatureBladeWindow) != 0)
            result = blade_compaction_program(function, variants[i].features, &unused);
        if (result != GRASS_SUCCESS) return result;
    }
    if (interaction_pass && interaction_program_ == 0) {
        const grass_result result = make_interaction_program(function);
        if (result != GRASS_SUCCESS) return result;
    }
    return GRASS_SUCCESS;
}

grass_result GlBackend::compute_program(const char* function, uint32_t kind, uint32_t mask, ComputeProgramMaker make,
                                        const char* name, GLuint* slot) {
    if (*slot != 0) return GRASS_SUCCESS;
    // From the seeded program binaries (grass_pipeline_desc.cache_data) where they hold it.
    GLuint program = program_cache_.load(gl_, function, kind, mask);
    if (program != 0) {
        set_sampler_units(gl_, program); // glProgramBinary resets every uniform
    } else {
        const grass_result result = make(ctx_, gl_, function, mask, &program);
        if (result != GRASS_SUCCESS) return result;
    }
    label(GL_PROGRAM, program, name);
    *slot = program;
    return GRASS_SUCCESS;
}

grass_result GlBackend::seed_pipeline_cache(const char* function, const void* data, uint64_t size) {
    program_cache_.seed(function, data, size);
    return GRASS_SUCCESS;
}

grass_result GlBackend::pipeline_cache_data(const char* function, void* data, uint64_t* size) {
    Vector<GlProgramRecord> records(StlAllocator<GlProgramRecord>(&ctx_->host));
    for (uint32_t kind = 0; kind < kProgramKindCount; ++kind) {
        for (uint32_t features = 0; features < kFeatureVariants; ++features) {
            const GLuint program = program_of(static_cast<GlProgramKind>(kind), features);
            if (program != 0) records.push_back({kind, features, program});
        }
    }
    if (interaction_program_ != 0) records.push_back({kInteractionProgramKind, 0, interaction_program_});
    for (uint32_t mask = 0; mask <= kBladeWindowPassFeatures; ++mask)
        if (window_programs_[mask] != 0) records.push_back({kBladeWindowProgramKind, mask, window_programs_[mask]});
    for (uint32_t mask = 0; mask <= (kBladeWindowPassFeatures | kFeatureBladeCulling); ++mask) {
        const GLuint program = compaction_programs_[mask];
        if (program != 0) records.push_back({kBladeCompactionProgramKind, mask, program});
    }
    return program_cache_.save(gl_, function, records.data(), static_cast<uint32_t>(records.size()), data, size);
}

} // namespace grass
