// libFuzzer target: grass_create_mesh_field (api/src/entry/api_mesh_field.cpp, mesh/) on a
// CPU-only context, then a frame planned around the field (plan/mesh_plan.cpp). The input
// decodes to a small mesh: positions within a few metres (or NaN, infinities, huge values),
// normals (zero ones too), UVs, per-vertex densities, indices (anything up to 0xffffffff:
// out of range, repeated corners for degenerate triangles), strides, and the desc's numbers
// at and past their edges; sometimes counts of 2^31 and more, which must be refused before
// the arrays (as long as the real ones) are read. A refusal is fine; a crash, a leak, a
// sanitizer report or an error without a message is not.
#include "fuzz_values.hpp"

#include <grass/grass.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

float coordinate(FuzzedDataProvider& in) {
    return in.ConsumeBool() ? grass_fuzz::hostile_float(in, -2.0, 2.0)
                            : static_cast<float>(in.ConsumeIntegralInRange<int>(-8, 8)) * 0.25f;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    grass_context* ctx = nullptr;
    grass_context_desc cd = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) std::abort();
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 16;
    grass_patch_id patch{};
    if (grass_create_patch(ctx, &pd, &patch) != GRASS_SUCCESS) std::abort();

    const uint32_t vertices = in.ConsumeIntegralInRange<uint32_t>(1, 24);
    const uint32_t stride_floats = in.ConsumeIntegralInRange<uint32_t>(9, 12); // pos, normal, uv, density, pad
    std::vector<float> v(size_t{vertices} * stride_floats);
    for (uint32_t k = 0; k < vertices; ++k) {
        float* p = &v[size_t{k} * stride_floats];
        for (int i = 0; i < 3; ++i) p[i] = coordinate(in);
        for (int i = 3; i < 6; ++i) p[i] = static_cast<float>(in.ConsumeIntegralInRange<int>(-1, 1));
        if (in.ConsumeBool()) p[3 + in.ConsumeIntegralInRange<int>(0, 2)] = grass_fuzz::hostile_float(in, -1.0, 1.0);
        p[6] = grass_fuzz::hostile_float(in, 0.0, 1.0);
        p[7] = grass_fuzz::hostile_float(in, 0.0, 1.0);
        p[8] = grass_fuzz::hostile_float(in, 0.0, 1.0);
    }
    const uint32_t triangles = in.ConsumeIntegralInRange<uint32_t>(1, 32);
    std::vector<uint32_t> indices(size_t{triangles} * 3);
    for (uint32_t& i : indices) i = in.ConsumeBool() ? grass_fuzz::hostile_u32(in, 0, vertices - 1) : 0;

    grass_mesh_field_desc d = grass_default_mesh_field_desc();
    d.patch = patch;
    d.positions = v.data();
    d.normals = v.data() + 3;
    d.uvs = in.ConsumeBool() ? v.data() + 6 : nullptr;
    d.vertex_density = v.data() + 8;
    d.position_stride = d.normal_stride = d.uv_stride = d.vertex_density_stride = stride_floats * 4;
    d.vertex_count = vertices;
    d.index_count = indices.size();
    d.indices = indices.data();
    // Counts past the limits: refused before any array is read.
    switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0:
        d.index_count = uint64_t{1} << 31;
        break;
    case 1:
        d.vertex_count = (uint64_t{1} << 31) + in.ConsumeIntegral<uint32_t>();
        break;
    case 2:
        d.index_count = ~uint64_t{0};
        break;
    default:
        break;
    }
    d.density = grass_fuzz::hostile_float(in, 0.5, 20.0);
    d.density_source = static_cast<grass_mesh_density_source>(in.ConsumeIntegralInRange<int>(0, 3));
    d.seeding = static_cast<grass_mesh_seeding>(in.ConsumeIntegralInRange<int>(0, 2));
    d.tuft_min_distance = grass_fuzz::hostile_float(in, 0.05, 1.0);
    d.tuft_radius = grass_fuzz::hostile_float(in, 0.0, 0.2);
    d.blades_per_tuft = grass_fuzz::hostile_u32(in, 1, 16);
    d.patch_blades = grass_fuzz::hostile_u32(in, 64, 256);
    d.patch_scale = grass_fuzz::hostile_float(in, 0.05, 1.0);
    if (in.ConsumeBool()) d.transform[in.ConsumeIntegralInRange<int>(0, 15)] = grass_fuzz::hostile_double(in, -4, 4);
    d.seed = in.ConsumeIntegral<uint32_t>();
    // Stay small: the scatter's blade count follows the area, which the transform can grow.
    for (int k = 0; k < 12; ++k) {
        if (d.transform[k] > 4.0 || d.transform[k] < -4.0) d.transform[k] = 1.0;
    }

    grass_field_id field{};
    const grass_result r = grass_create_mesh_field(ctx, &d, &field);
    if (r != GRASS_SUCCESS && grass_get_last_error(ctx)[0] == '\0') std::abort(); // refused without a message
    if (r == GRASS_SUCCESS) {
        grass_view_desc view = grass_default_view_desc();
        view.camera_position[0] = coordinate(in);
        view.camera_position[1] = 2.0;
        view.camera_position[2] = coordinate(in) - 6.0;
        grass_frame_desc frame = grass_default_frame_desc();
        uint32_t index = 0;
        if (grass_begin_host_frame(ctx, &frame) == GRASS_SUCCESS) {
            (void)grass_plan_view(ctx, &view, &index);
            (void)grass_end_frame(ctx);
        }
        if (grass_destroy_field(ctx, field) != GRASS_SUCCESS) std::abort();
    }
    grass_destroy_context(ctx);
    return 0;
}
