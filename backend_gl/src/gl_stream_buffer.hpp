// A buffer rewritten every frame. Each upload orphans the old storage (glNamedBufferData
// with NULL), so the driver never stalls on, or overwrites, data a draw still reads.
#pragma once

#include "gl_functions.hpp"

#include <cstddef>
#include <cstdint>

namespace grass {

class GlStreamBuffer {
public:
    // Creates the buffer object (no storage yet); its name stays the same for life, so
    // vertex arrays may reference it.
    void create(const GlFunctions& gl);
    void destroy(const GlFunctions& gl);

    // Replaces the contents with `size` bytes (grows the storage when needed).
    void upload(const GlFunctions& gl, const void* data, size_t size);

    GLuint name() const { return name_; }
    uint64_t capacity() const { return capacity_; }

private:
    static constexpr size_t kMinCapacity = 4096;
    GLuint name_ = 0;
    size_t capacity_ = 0;
};

} // namespace grass
