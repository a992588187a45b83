// C entry points for mesh fields (jahrmann2017 4): grass on a host's triangle mesh, scattered
// once at creation (mesh/mesh_field.hpp) and kept as a field the frame planner culls by patch.
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"
#include "mesh/mesh_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grass {
namespace {

using u64 = unsigned long long;

// How far a blade of `patch` reaches from its root, in metres: its height, and half again
// for a lean that tips it over (the patch's blades are at most that tall).
double blade_reach(const PatchData& patch, double patch_scale) {
    const double height = std::max(std::fabs(static_cast<double>(patch.bounds_max[1])),
                                   std::fabs(static_cast<double>(patch.bounds_min[1])));
    return 1.5 * height * patch_scale;
}

// A stride in bytes: 0 (packed: `packed` bytes) or at least that and a multiple of 4.
grass_result check_stride(grass_context* ctx, const char* fn, const char* name, uint32_t stride, uint32_t packed) {
    if (stride == 0 || (stride >= packed && stride % 4 == 0)) return GRASS_SUCCESS;
    return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                     "%s: %s is %u; it must be 0 (packed) or a multiple of 4 of at least %u bytes", fn, name, stride,
                     packed);
}

// The host's strided array as packed floats: `n` per vertex.
void copy_packed(const float* from, uint32_t stride, uint64_t count, int n, Vector<float>& to) {
    const uint64_t step = stride == 0 ? uint64_t(n) : stride / 4;
    to.resize(count * n);
    for (uint64_t k = 0; k < count; ++k)
        for (int i = 0; i < n; ++i) to[k * n + i] = from[k * step + i];
}

bool is_null(grass_map_id id) { return id.index == 0 && id.generation == 0 && id.owner == 0; }

// The map stack of a mesh field: density (GRASS_MESH_DENSITY_MAP) and colour, at the UVs.
grass_result validate_mesh_maps(grass_context* ctx, const char* fn, const grass_mesh_field_desc& d) {
    const grass_map_stack& m = d.maps;
    const grass_map_id unused[3] = {m.ambient, m.diffuse, m.height};
    static const char* const unused_names[3] = {"desc->maps.ambient", "desc->maps.diffuse", "desc->maps.height"};
    for (int k = 0; k < 3; ++k) {
        if (!is_null(unused[k])) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                             "%s: %s is set; a mesh field samples only maps.density and maps.color", fn,
                             unused_names[k]);
        }
    }
    for (int k = 0; k < 6; ++k) {
        if (m.cell_to_map[k] != 0.0) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                             "%s: desc->maps.cell_to_map[%d] is %g; a mesh field's maps are sampled at its UVs (all "
                             "zero)",
                             fn, k, m.cell_to_map[k]);
        }
    }
    const bool density_map = d.density_source == GRASS_MESH_DENSITY_MAP;
    if (density_map != !is_null(m.density)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                         "%s: desc->maps.density is %s and desc->density_source is %d; the density map is sampled "
                         "with GRASS_MESH_DENSITY_MAP (2) and only then",
                         fn, is_null(m.density) ? "none" : "set", static_cast<int>(d.density_source));
    }
    const grass_map_id ids[2] = {m.density, m.color};
    static const char* const names[2] = {"desc->maps.density", "desc->maps.color"};
    for (int k = 0; k < 2; ++k) {
        if (is_null(ids[k])) continue;
        GRASS_TRY(check_map_id(ctx, fn, names[k], ids[k]));
        if (!d.uvs) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                             "%s: %s is set and desc->uvs is NULL; maps are sampled at the mesh's UVs", fn, names[k]);
        }
        const uint32_t channels = ctx->maps.get(ids[k].index - 1)->channels;
        const uint32_t wanted = k == 1 ? 4 : 1;
        if (channels != wanted) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE, "%s: %s has %u channel(s); it needs %s",
                             fn, names[k], channels, wanted == 4 ? "an RGBA format" : "a single-channel (R) format");
        }
    }
    return GRASS_SUCCESS;
}

// Everything but the arrays' contents (build_mesh_surface reads those), before any is read.
grass_result validate_mesh_field_desc(grass_context* ctx, const char* fn, const grass_mesh_field_desc* desc) {
    GRASS_TRY(GRASS_CHECK_DESC(ctx, fn, desc, GRASS_STRUCT_TYPE_MESH_FIELD_DESC));
    const grass_mesh_field_desc& d = *desc;
    GRASS_TRY(check_patch_id(ctx, fn, "desc->patch", d.patch));
    GRASS_TRY(check_float_range(ctx, fn, "desc->patch_scale", d.patch_scale, 1e-4, 1e4));
    GRASS_TRY(check_not_null(ctx, fn, "desc->positions", d.positions));
    GRASS_TRY(check_not_null(ctx, fn, "desc->normals", d.normals));
    GRASS_TRY(check_not_null(ctx, fn, "desc->indices", d.indices));
    GRASS_TRY(check_stride(ctx, fn, "desc->position_stride", d.position_stride, 12));
    GRASS_TRY(check_stride(ctx, fn, "desc->normal_stride", d.normal_stride, 12));
    GRASS_TRY(check_stride(ctx, fn, "desc->uv_stride", d.uv_stride, 8));
    GRASS_TRY(check_stride(ctx, fn, "desc->vertex_density_stride", d.vertex_density_stride, 4));
    GRASS_TRY(check_mesh_counts(ctx, fn, d.vertex_count, d.index_count));
    for (int c = 12; c < 15; ++c) {
        if (std::fabs(d.transform[c]) > 1e12) { // NaN passes here and is refused by build_mesh_surface
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->transform[%d] (translation) is %g; it must be within +-1e12 m", fn, c,
                             d.transform[c]);
        }
    }
    GRASS_TRY(check_range_above(ctx, fn, "desc->density", d.density, 0.0, 1e5));
    const int64_t source = raw_enum(d.density_source);
    if (source < GRASS_MESH_DENSITY_UNIFORM || source > GRASS_MESH_DENSITY_MAP) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: desc->density_source is %lld; it must be GRASS_MESH_DENSITY_UNIFORM (0), _PER_VERTEX "
                         "(1) or _MAP (2)",
                         fn, static_cast<long long>(source));
    }
    if (source == GRASS_MESH_DENSITY_PER_VERTEX)
        GRASS_TRY(check_not_null(ctx, fn, "desc->vertex_density", d.vertex_density));
    const int64_t seeding = raw_enum(d.seeding);
    if (seeding != GRASS_MESH_SEEDING_SINGLE_BLADES && seeding != GRASS_MESH_SEEDING_TUFTS) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: desc->seeding is %lld; it must be GRASS_MESH_SEEDING_SINGLE_BLADES (0) or _TUFTS (1)", fn,
                         static_cast<long long>(seeding));
    }
    return validate_mesh_maps(ctx, fn, d);
}

// The per-vertex densities, finite and in [0, 1].
grass_result check_vertex_density(grass_context* ctx, const char* fn, const Vector<float>& density) {
    for (size_t k = 0; k < density.size(); ++k) {
        if (!(density[k] >= 0.0f && density[k] <= 1.0f)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->vertex_density[%llu] is %g; it must be in [0, 1]", fn, static_cast<u64>(k),
                             static_cast<double>(density[k]));
        }
    }
    return GRASS_SUCCESS;
}

// Scatters the mesh into a new MeshField (nothing of the context changes).
grass_result scatter_mesh_field(grass_context* ctx, const char* fn, const grass_mesh_field_desc& d, MeshField* out) {
    HostAllocator* host = &ctx->host;
    Vector<float> positions{StlAllocator<float>(host)}, normals{StlAllocator<float>(host)},
        uvs{StlAllocator<float>(host)}, density{StlAllocator<float>(host)};
    copy_packed(d.positions, d.position_stride, d.vertex_count, 3, positions);
    copy_packed(d.normals, d.normal_stride, d.vertex_count, 3, normals);
    if (d.uvs) copy_packed(d.uvs, d.uv_stride, d.vertex_count, 2, uvs);
    const bool per_vertex = d.density_source == GRASS_MESH_DENSITY_PER_VERTEX;
    if (per_vertex) {
        copy_packed(d.vertex_density, d.vertex_density_stride, d.vertex_count, 1, density);
        GRASS_TRY(check_vertex_density(ctx, fn, density));
    }
    MeshSurfaceDesc mesh;
    mesh.positions = positions.data();
    mesh.normals = normals.data();
    mesh.uvs = d.uvs ? uvs.data() : nullptr;
    mesh.indices = d.indices;
    mesh.vertex_count = d.vertex_count;
    mesh.index_count = d.index_count;
    std::memcpy(mesh.transform, d.transform, sizeof(mesh.transform));
    MeshSurface surface(host);
    GRASS_TRY(build_mesh_surface(ctx, fn, mesh, &surface));
    if (surface.degenerate_count() > 0) {
        ctx->warn(GRASS_MSG_MESH_FIELD, "%s: %u degenerate triangle(s) (zero area) skipped", fn,
                  surface.degenerate_count());
    }
    MeshScatterParams params;
    params.seeding = d.seeding == GRASS_MESH_SEEDING_TUFTS ? MeshSeeding::kTufts : MeshSeeding::kSingleBlades;
    params.density = d.density;
    params.patch_blades = d.patch_blades;
    params.tuft_min_distance = d.tuft_min_distance;
    params.tuft_radius = d.tuft_radius;
    params.blades_per_tuft = d.blades_per_tuft;
    params.seed = d.seed;
    const PatchData& patch = ctx->patches.get(d.patch.index - 1)->data;
    out->patch_scale = d.patch_scale;
    out->density_source = d.density_source;
    return build_mesh_field(ctx, fn, surface, params, per_vertex ? density.data() : nullptr,
                            blade_reach(patch, d.patch_scale), out);
}

grass_result create_mesh_field(grass_context* ctx, const grass_mesh_field_desc* desc, grass_field_id* out) {
    const char* fn = "grass_create_mesh_field";
    GRASS_TRY(check_not_null(ctx, fn, "out_field", out));
    if (ctx->in_frame) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                         "%s: cannot create a field between grass_begin_frame and grass_end_frame", fn);
    }
    GRASS_TRY(validate_mesh_field_desc(ctx, fn, desc));
    const grass_mesh_field_desc& d = *desc;
    MeshField* mesh = ctx->host.create<MeshField>(&ctx->host);
    Field* field = nullptr;
    try {
        const grass_result r = scatter_mesh_field(ctx, fn, d, mesh);
        if (r != GRASS_SUCCESS) {
            ctx->host.destroy(mesh);
            return r;
        }
        field = ctx->host.create<Field>();
    } catch (...) { // out of memory: nothing of this call is left
        ctx->host.destroy(mesh);
        throw;
    }
    field->mesh = mesh; // owned by the field from here on
    field->mesh_host = &ctx->host;
    field->patch_slot = d.patch.index - 1;
    if (!is_null(d.maps.density)) field->maps.map_slot[kMapDensity] = d.maps.density.index - 1;
    if (!is_null(d.maps.color)) field->maps.map_slot[kMapColor] = d.maps.color.index - 1;
    for (uint32_t r = 0; r < kMapRoleCount; ++r) {
        if (field->maps.map_slot[r] != kNoMap) field->maps.features |= 1u << r;
    }
    const FieldMaps maps = field->maps;
    const uint32_t slot = ctx->fields.insert(field); // destroys the field if the pool cannot grow
    grass_result r = GRASS_SUCCESS;
    try {
        r = ctx->backend->upload_field(slot, maps);
    } catch (...) {
        ctx->backend->release_field(slot);
        ctx->fields.erase(slot);
        throw;
    }
    if (r != GRASS_SUCCESS) {
        ctx->backend->release_field(slot);
        ctx->fields.erase(slot);
        return r;
    }
    ctx->patches.get(d.patch.index - 1)->field_users += 1;
    for (uint32_t map_slot : maps.map_slot) {
        if (map_slot != kNoMap) ctx->maps.get(map_slot)->field_users += 1;
    }
    out->index = slot + 1;
    out->generation = ctx->fields.generation(slot);
    out->owner = ctx->owner;
    if (ctx->backend->kind() != GRASS_BACKEND_NONE) { // planned, not drawn: say so, not silently
        ctx->warn(GRASS_MSG_MESH_FIELD,
                  "%s: the field is made and planned, but this backend does not draw mesh fields yet "
                  "(docs/mesh-fields.md, \"Known limits\")",
                  fn);
    }
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_mesh_field_desc grass_default_mesh_field_desc(void) {
    grass_mesh_field_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_MESH_FIELD_DESC;
    d.patch_scale = 0.25f;
    d.transform[0] = d.transform[5] = d.transform[10] = d.transform[15] = 1.0;
    d.density = 100.0f;
    d.tuft_min_distance = 0.2f;
    d.tuft_radius = 0.05f;
    d.blades_per_tuft = 8;
    d.patch_blades = 1024;
    d.seed = 1;
    return d;
}

GRASS_API grass_result grass_create_mesh_field(grass_context* context, const grass_mesh_field_desc* desc,
                                               grass_field_id* out_field) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_create_mesh_field", [&] {
        GRASS_TRY(grass::check_gpu_current(context, "grass_create_mesh_field"));
        return grass::create_mesh_field(context, desc, out_field);
    });
}

} // extern "C"
