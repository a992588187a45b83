#include "gltf_accessor.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace grass_sample {

namespace {

[[noreturn]] void refuse(const std::string& what, int accessor, const std::string& why) {
    throw std::runtime_error("accessor " + std::to_string(accessor) + " (" + what + ") " + why);
}

size_t component_size(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

int type_components(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    default:
        return 0;
    }
}

// The accessor's elements: where each begins (nullptr data: all zeros, as the spec says of
// an accessor without a buffer view) and the stride between them.
struct Elements {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    uint64_t count = 0;
    int components = 0;
    int component_type = 0;
    bool normalized = false;
};

Elements locate(const tinygltf::Model& model, int index, const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size()) {
        throw std::runtime_error(what + " names accessor " + std::to_string(index) + "; the file has " +
                                 std::to_string(model.accessors.size()));
    }
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) refuse(what, index, "is sparse; sparse accessors are not supported");
    Elements e;
    e.count = a.count;
    e.components = type_components(a.type);
    e.component_type = a.componentType;
    e.normalized = a.normalized;
    const size_t csize = component_size(a.componentType);
    if (e.components == 0) refuse(what, index, "has type " + std::to_string(a.type) + ", not SCALAR or VEC2..4");
    if (csize == 0) refuse(what, index, "has componentType " + std::to_string(a.componentType));
    if (e.count > kMaxAccessorCount) {
        refuse(what, index,
               "has count " + std::to_string(e.count) + "; at most " + std::to_string(kMaxAccessorCount) + " are read");
    }
    if (a.bufferView < 0) return e; // zeros
    size_t view_size = 0;
    const unsigned char* view =
        buffer_view_bytes(model, a.bufferView, &view_size, "the buffer view of accessor " + std::to_string(index));
    const size_t element = csize * size_t(e.components);
    const size_t declared = model.bufferViews[size_t(a.bufferView)].byteStride;
    e.stride = declared ? declared : element;
    if (e.stride < element) {
        refuse(what, index,
               "has byteStride " + std::to_string(e.stride) + ", less than its element (" + std::to_string(element) +
                   " bytes)");
    }
    if (e.count == 0) return e;
    // Every byte of the last element must lie in the view (64-bit: count <= 2^24, stride < 2^32).
    const uint64_t end = uint64_t(a.byteOffset) + (e.count - 1) * uint64_t(e.stride) + element;
    if (a.byteOffset > view_size || end > view_size) {
        refuse(what, index,
               "needs bytes up to " + std::to_string(end) + " (byteOffset " + std::to_string(a.byteOffset) +
                   ", count " + std::to_string(e.count) + ") of a buffer view of " + std::to_string(view_size));
    }
    e.data = view + a.byteOffset;
    return e;
}

template <class T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

} // namespace

const unsigned char* buffer_view_bytes(const tinygltf::Model& model, int index, size_t* size, const std::string& what) {
    if (index < 0 || size_t(index) >= model.bufferViews.size()) {
        throw std::runtime_error(what + " is buffer view " + std::to_string(index) + "; the file has " +
                                 std::to_string(model.bufferViews.size()));
    }
    const tinygltf::BufferView& v = model.bufferViews[size_t(index)];
    if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size()) {
        throw std::runtime_error("buffer view " + std::to_string(index) + " names buffer " + std::to_string(v.buffer) +
                                 "; the file has " + std::to_string(model.buffers.size()));
    }
    const std::vector<unsigned char>& data = model.buffers[size_t(v.buffer)].data;
    if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset) {
        throw std::runtime_error("buffer view " + std::to_string(index) + " (byteOffset " +
                                 std::to_string(v.byteOffset) + ", byteLength " + std::to_string(v.byteLength) +
                                 ") lies outside buffer " + std::to_string(v.buffer) + " of " +
                                 std::to_string(data.size()) + " bytes");
    }
    *size = v.byteLength;
    return data.data() + v.byteOffset;
}

std::vector<float> read_float_accessor(const tinygltf::Model& model, int index, int components, bool normalized_ok,
                                       const std::string& what) {
    const Elements e = locate(model, index, what);
    const bool colour = normalized_ok && components == 4;
    if (e.components != components && !(colour && e.components == 3)) {
        refuse(what, index,
               "has " + std::to_string(e.components) + " components; " + std::to_string(components) + " expected");
    }
    const bool is_float = e.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool is_unorm = e.normalized && (e.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                           e.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (!is_float && !(normalized_ok && is_unorm)) {
        refuse(what, index,
               "has componentType " + std::to_string(e.component_type) +
                   (normalized_ok ? "; float or normalized unsigned byte/short expected" : "; float expected"));
    }
    std::vector<float> out(size_t(e.count) * size_t(components), 0.0f);
    for (uint64_t i = 0; i < e.count; ++i) {
        float* dst = &out[size_t(i) * size_t(components)];
        if (e.components < components) dst[components - 1] = 1.0f; // VEC3 colour: alpha 1
        if (!e.data) continue;
        const unsigned char* p = e.data + size_t(i) * e.stride;
        for (int c = 0; c < e.components; ++c) {
            float v = 0.0f;
            if (e.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                v = load<float>(p + 4 * c);
            } else if (e.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                v = float(p[c]) / 255.0f;
            } else {
                v = float(load<uint16_t>(p + 2 * c)) / 65535.0f;
            }
            if (!std::isfinite(v)) {
                refuse(what, index,
                       "element " + std::to_string(i) + " component " + std::to_string(c) + " is " +
                           (std::isnan(v) ? "NaN" : "infinite"));
            }
            dst[c] = v;
        }
    }
    return out;
}

std::vector<uint32_t> read_index_accessor(const tinygltf::Model& model, int index, uint64_t vertex_count,
                                          const std::string& what) {
    const Elements e = locate(model, index, what);
    const size_t csize = component_size(e.component_type);
    if (e.components != 1 || e.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        e.component_type == TINYGLTF_COMPONENT_TYPE_BYTE || e.component_type == TINYGLTF_COMPONENT_TYPE_SHORT ||
        e.component_type == TINYGLTF_COMPONENT_TYPE_INT) {
        refuse(what, index, "is not a SCALAR of unsigned byte, short or int");
    }
    std::vector<uint32_t> out(size_t(e.count), 0u);
    for (uint64_t i = 0; i < e.count && e.data; ++i) {
        const unsigned char* p = e.data + size_t(i) * e.stride;
        const uint32_t v = csize == 1 ? p[0] : csize == 2 ? load<uint16_t>(p) : load<uint32_t>(p);
        if (v >= vertex_count) {
            refuse(what, index,
                   "index " + std::to_string(i) + " is " + std::to_string(v) + "; the primitive has " +
                       std::to_string(vertex_count) + " vertices");
        }
        out[size_t(i)] = v;
    }
    return out;
}

} // namespace grass_sample
