// GL program binaries (GL_ARB_get_program_binary, core in 4.1): grass_get_pipeline_cache_data
// saves the binary of every program compiled so far, grass_pipeline_desc.cache_data hands them
// back, and a program found there is loaded with glProgramBinary instead of compiled. The
// blob (context/pipeline_blob.hpp) names the driver (GL_VENDOR, GL_RENDERER, GL_VERSION) and
// the shader sources; its payload is a count, then per program its kind, feature mask,
// binary format, length and bytes (padded to 4). A driver that reports no binary format
// (GL_NUM_PROGRAM_BINARY_FORMATS 0) saves an empty blob and ignores any given one.
#pragma once

#include "gl_functions.hpp"

#include "context/context.hpp"

#include <cstdint>

namespace grass {

// The kind of the interaction pass's program in a blob (after the GlProgramKind values).
constexpr uint32_t kInteractionProgramKind = 4;
// The kind of a blade window pass's program (one per mask of kBladeWindowPassFeatures).
constexpr uint32_t kBladeWindowProgramKind = 5;
// The kind of a blade compaction pass's program (one per mask, gl_blade_compaction.cpp).
constexpr uint32_t kBladeCompactionProgramKind = 6;

// A program to save: its kind (GlProgramKind, kInteractionProgramKind, kBladeWindowProgramKind or
// kBladeCompactionProgramKind), mask and name.
struct GlProgramRecord {
    uint32_t kind;
    uint32_t features;
    GLuint program;
};

class GlProgramCache {
public:
    explicit GlProgramCache(grass_context* ctx)
        : ctx_(ctx), payload_(StlAllocator<unsigned char>(&ctx->host)), entries_(StlAllocator<Entry>(&ctx->host)) {}

    // Reads the driver's binary formats and identity. `shader_hash`: of every shader source.
    void init(const GlFunctions& gl, uint64_t shader_hash);
    // The driver can give and take program binaries.
    bool binaries() const { return formats_ > 0; }
    // Keeps the programs of a blob for load(); a blob that does not fit is ignored (warned).
    void seed(const char* function, const void* data, uint64_t size);
    // The program of (kind, features) made from a seeded binary, or 0: none, or the driver
    // refused it (warned once per program; then it is compiled as usual).
    GLuint load(const GlFunctions& gl, const char* function, uint32_t kind, uint32_t features);
    // grass_get_pipeline_cache_data over `programs`.
    grass_result save(const GlFunctions& gl, const char* function, const GlProgramRecord* programs, uint32_t count,
                      void* data, uint64_t* size) const;

private:
    struct Entry {
        uint32_t kind, features, format, length;
        uint64_t offset; // into payload_
    };
    grass_context* ctx_;
    GLint formats_ = 0;
    uint64_t identity_ = 0;
    Vector<unsigned char> payload_;
    Vector<Entry> entries_;
};

} // namespace grass
