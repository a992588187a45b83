#include "gl_program_cache.hpp"

#include "context/pipeline_blob.hpp"
#include "patch/random.hpp"

#include <cstring>

namespace grass {

namespace {

constexpr uint64_t kEntryHeaderBytes = 16; // kind, features, format, length

uint64_t hash_string(const GlFunctions& gl, GLenum name, uint64_t hash) {
    const auto* s = reinterpret_cast<const char*>(gl.GetString(name));
    return s ? fnv1a64(s, std::strlen(s) + 1, hash) : hash;
}

uint32_t read_u32(const unsigned char* p) {
    uint32_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return v;
}

} // namespace

void GlProgramCache::init(const GlFunctions& gl, uint64_t shader_hash) {
    gl.GetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats_);
    uint64_t hash = fnv1a64(&shader_hash, sizeof shader_hash, kFnvOffset);
    hash = hash_string(gl, GL_VENDOR, hash);
    hash = hash_string(gl, GL_RENDERER, hash);
    identity_ = hash_string(gl, GL_VERSION, hash);
}

void GlProgramCache::seed(const char* function, const void* data, uint64_t size) {
    if (!binaries()) {
        ctx_->warn(GRASS_MSG_PIPELINE_CACHE,
                   "%s: desc->cache_data is ignored: the GL driver reports no program binary format "
                   "(GL_NUM_PROGRAM_BINARY_FORMATS 0); grass compiles instead",
                   function);
        return;
    }
    uint64_t bytes = 0;
    const unsigned char* p = open_pipeline_blob(ctx_, function, GRASS_BACKEND_GL, identity_, data, size, &bytes);
    if (p == nullptr) return;
    // Every entry inside the payload, or none is kept.
    Vector<Entry> entries(StlAllocator<Entry>(&ctx_->host));
    const uint32_t count = bytes >= 4 ? read_u32(p) : 0;
    uint64_t at = 4;
    bool ok = bytes >= 4;
    for (uint32_t i = 0; ok && i < count; ++i) {
        if (bytes - at < kEntryHeaderBytes) {
            ok = false;
            break;
        }
        Entry e{read_u32(p + at), read_u32(p + at + 4), read_u32(p + at + 8), read_u32(p + at + 12),
                at + kEntryHeaderBytes};
        const uint64_t padded = (uint64_t(e.length) + 3) & ~uint64_t(3);
        ok = e.kind <= kBladeCompactionProgramKind && e.features < kFeatureMaskCount && e.length > 0 &&
             padded <= bytes - e.offset;
        if (ok) entries.push_back(e);
        at = e.offset + padded;
    }
    if (!ok || at != bytes) {
        ctx_->warn(GRASS_MSG_PIPELINE_CACHE,
                   "%s: desc->cache_data is ignored: its program list does not fit its size; grass compiles instead",
                   function);
        return;
    }
    payload_.assign(p, p + bytes);
    entries_ = std::move(entries);
}

GLuint GlProgramCache::load(const GlFunctions& gl, const char* function, uint32_t kind, uint32_t features) {
    for (Entry& e : entries_) {
        if (e.kind != kind || e.features != features || e.length == 0) continue;
        const GLuint program = gl.CreateProgram();
        if (program == 0) return 0;
        gl.ProgramBinary(program, e.format, payload_.data() + e.offset, static_cast<GLsizei>(e.length));
        GLint linked = GL_FALSE;
        gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
        if (linked == GL_TRUE) return program;
        gl.DeleteProgram(program);
        e.length = 0; // never tried again
        ctx_->warn(GRASS_MSG_PIPELINE_CACHE,
                   "%s: the GL driver refused the program binary of kind %u, features 0x%x in desc->cache_data; "
                   "grass compiles it instead",
                   function, kind, features);
        return 0;
    }
    return 0;
}

grass_result GlProgramCache::save(const GlFunctions& gl, const char* function, const GlProgramRecord* programs,
                                  uint32_t count, void* data, uint64_t* size) const {
    if (!binaries()) {
        *size = 0;
        return GRASS_SUCCESS;
    }
    // The payload: count, then each program's entry.
    Vector<unsigned char> payload(4, 0, StlAllocator<unsigned char>(&ctx_->host));
    uint32_t saved = 0;
    for (uint32_t i = 0; i < count; ++i) {
        GLint length = 0;
        gl.GetProgramiv(programs[i].program, GL_PROGRAM_BINARY_LENGTH, &length);
        if (length <= 0) continue;
        const size_t at = payload.size();
        const size_t padded = (static_cast<size_t>(length) + 3) & ~size_t(3);
        payload.resize(at + kEntryHeaderBytes + padded, 0);
        GLenum format = 0;
        GLsizei written = 0;
        gl.GetProgramBinary(programs[i].program, length, &written, &format, payload.data() + at + kEntryHeaderBytes);
        if (written <= 0) {
            payload.resize(at);
            continue;
        }
        const uint32_t header[4] = {programs[i].kind, programs[i].features, static_cast<uint32_t>(format),
                                    static_cast<uint32_t>(written)};
        std::memcpy(payload.data() + at, header, sizeof header);
        payload.resize(at + kEntryHeaderBytes + ((static_cast<size_t>(written) + 3) & ~size_t(3)));
        saved += 1;
    }
    std::memcpy(payload.data(), &saved, sizeof saved);
    const uint64_t total = kPipelineBlobHeaderBytes + payload.size();
    if (data == nullptr) {
        *size = total;
        return GRASS_SUCCESS;
    }
    if (*size < total) {
        return ctx_->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                          "%s: *size is %llu; the blob needs %llu bytes (call with data NULL to learn the size)",
                          function, static_cast<unsigned long long>(*size), static_cast<unsigned long long>(total));
    }
    write_pipeline_blob_header(GRASS_BACKEND_GL, identity_, payload.data(), payload.size(), data);
    std::memcpy(static_cast<unsigned char*>(data) + kPipelineBlobHeaderBytes, payload.data(), payload.size());
    *size = total;
    return GRASS_SUCCESS;
}

} // namespace grass
