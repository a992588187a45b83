// A host's triangle mesh as grass scatters blades on it (jahrmann2017 4: grass on any 3D
// model): the host's arrays validated once, the degenerate triangles left out and counted,
// and the area of what is left, with a cumulative table that picks a triangle by its area.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/log.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// The host's mesh, borrowed for the call that reads it (the arrays are not copied).
struct MeshSurfaceDesc {
    const float* positions = nullptr; // 3 floats per vertex, mesh space
    const float* normals = nullptr;   // 3 floats per vertex, mesh space, not zero (need not be unit)
    const float* uvs = nullptr;       // 2 floats per vertex, or NULL for a mesh without UVs
    const uint32_t* indices = nullptr;
    uint64_t vertex_count = 0;                                               // 1 .. kMaxMeshVertices
    uint64_t index_count = 0;                                                // 3 .. kMaxMeshIndices, a multiple of 3
    double transform[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // mesh to world, column-major, affine
};

// Indices are 32-bit and counts are kept signed-safe: fewer than 2^31 of each.
constexpr uint64_t kMaxMeshIndices = (uint64_t{1} << 31) - 3; // the largest multiple of 3 below 2^31
constexpr uint64_t kMaxMeshVertices = (uint64_t{1} << 31) - 1;

class MeshSurface {
public:
    explicit MeshSurface(HostAllocator* host)
        : triangles_(StlAllocator<uint32_t>(host)), cumulative_area_(StlAllocator<double>(host)) {}

    const MeshSurfaceDesc& mesh() const { return mesh_; }
    bool has_uvs() const { return mesh_.uvs != nullptr; }
    // Triangles with an area, and how many of the host's were left out as degenerate.
    uint32_t triangle_count() const { return static_cast<uint32_t>(triangles_.size()); }
    uint32_t degenerate_count() const { return degenerate_count_; }
    // The host's triangle (index of its first index / 3) of kept triangle k.
    uint32_t host_triangle(uint32_t k) const { return triangles_[k]; }
    // Area in world units (square metres: the transform's scale included).
    double total_area() const { return total_area_; }
    // The kept triangle whose share of the cumulative area holds `a` in [0, total_area()).
    uint32_t triangle_at_area(double a) const;
    // The vertex indices of the host's triangle t.
    void corners(uint32_t host_triangle, uint32_t out[3]) const;
    // The transform's linear part applied to a mesh-space vector (world-linear, no translation).
    void to_world_linear(const double v[3], double out[3]) const;
    // Its inverse: a world-linear vector back to mesh space.
    void to_mesh_linear(const double v[3], double out[3]) const;

private:
    friend grass_result build_mesh_surface(Log* log, const char* fn, const MeshSurfaceDesc& desc, MeshSurface* out);
    MeshSurfaceDesc mesh_;
    Vector<uint32_t> triangles_;                      // host triangle of each kept triangle
    Vector<double> cumulative_area_;                  // inclusive running sum, one per kept triangle
    double linear_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // column-major 3x3 of the transform
    double inverse_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; // its inverse
    double total_area_ = 0;
    uint32_t degenerate_count_ = 0;
};

// desc->vertex_count in [1, kMaxMeshVertices] and desc->index_count a multiple of 3 in
// [3, kMaxMeshIndices], refused naming them (checked before any array is read).
grass_result check_mesh_counts(Log* log, const char* fn, uint64_t vertex_count, uint64_t index_count);

// Validates `desc` and fills `out` (built with the context's allocator, empty). Refused, with
// a message naming the argument and the value and `out` left as it was: a NULL array, a count
// of 0 or above the limits (checked before any array is read), an index count not a multiple
// of 3, an index not below vertex_count, a NaN or infinite position, normal or UV, a zero
// normal, a transform that is not finite, not affine or not invertible, and a mesh whose
// triangles are all degenerate. A triangle of zero area (repeated or collinear corners) is
// skipped and counted (degenerate_count), never drawn on.
grass_result build_mesh_surface(Log* log, const char* fn, const MeshSurfaceDesc& desc, MeshSurface* out);

} // namespace grass
