// Checked reads of glTF accessors: the index, the type, the component type, the count and
// every byte range are verified against the model before a byte is read, and float values
// must be finite. Errors name the accessor and what it is for.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace grass_sample {

// Most elements one accessor may hold (a safeguard against huge counts).
constexpr uint64_t kMaxAccessorCount = uint64_t(1) << 24;

// Reads accessor `index` as floats, `components` per element (2, 3 or 4: VEC2, VEC3, VEC4;
// for colours, VEC3 and VEC4 are both accepted and VEC3 gets alpha 1). Float components, or
// normalized unsigned byte / short when `normalized_ok`. Throws std::runtime_error naming
// `what` ("POSITION of mesh \"rock\" primitive 0") on anything wrong.
std::vector<float> read_float_accessor(const tinygltf::Model& model, int index, int components, bool normalized_ok,
                                       const std::string& what);

// Reads an index accessor (SCALAR, unsigned byte, short or int); every index must be below
// `vertex_count`.
std::vector<uint32_t> read_index_accessor(const tinygltf::Model& model, int index, uint64_t vertex_count,
                                          const std::string& what);

// The bytes of buffer view `index`, range-checked against its buffer.
const unsigned char* buffer_view_bytes(const tinygltf::Model& model, int index, size_t* size, const std::string& what);

} // namespace grass_sample
