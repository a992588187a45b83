#include "gl_stream_buffer.hpp"

namespace grass {

void GlStreamBuffer::create(const GlFunctions& gl) { gl.CreateBuffers(1, &name_); }

void GlStreamBuffer::destroy(const GlFunctions& gl) {
    if (name_ != 0) gl.DeleteBuffers(1, &name_);
    name_ = 0;
    capacity_ = 0;
}

void GlStreamBuffer::upload(const GlFunctions& gl, const void* data, size_t size) {
    if (size == 0) return;
    if (size > capacity_) {
        size_t capacity = capacity_ < kMinCapacity ? kMinCapacity : capacity_;
        while (capacity < size) capacity *= 2;
        capacity_ = capacity;
    }
    gl.NamedBufferData(name_, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
    gl.NamedBufferSubData(name_, 0, static_cast<GLsizeiptr>(size), data);
}

} // namespace grass
