// The objects behind a host's patch and field ids, as the context keeps them in its pools
// and the frame planner reads them: a patch with its baked slice sets and blade mechanics,
// a field with its maps, tiers, quadtree and responsive settings.
#pragma once

#include "bake/baked_slices.hpp"
#include "dynamics/blade_mechanics.hpp"
#include "dynamics/wind_map.hpp"
#include "foundation/allocator.hpp"
#include "foundation/shader_interface.hpp"
#include "mesh/mesh_field.hpp"
#include "patch/patch_data.hpp"
#include "plan/blade_culling.hpp"
#include "plan/blade_tessellation.hpp"
#include "plan/lod_setup_types.hpp"
#include "plan/quadtree.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct Patch {
    explicit Patch(HostAllocator* h) : data(h), host(h), slice_sets(StlAllocator<SliceSet*>(h)) {}
    ~Patch() {
        for (SliceSet* s : slice_sets) host->destroy(s);
    }
    Patch(const Patch&) = delete;
    Patch& operator=(const Patch&) = delete;
    // The baked set with `slices_per_axis` (0 = the horizontal slice), or nullptr.
    const SliceSet* slices(uint32_t slices_per_axis) const {
        for (const SliceSet* s : slice_sets) {
            if (s->slices_per_axis == slices_per_axis) return s;
        }
        return nullptr;
    }
    PatchData data;
    HostAllocator* host;
    grass_patch_desc desc{};
    uint32_t field_users = 0;     // fields that use this patch
    Vector<SliceSet*> slice_sets; // baked on demand by the fields' tiers, uploaded once each
    // Responsive grass: how its blades respond (grass_set_blade_mechanics), and whether the
    // backend holds its blade curves (uploaded at the first responsive draw of the patch).
    grass_blade_mechanics mechanics = default_blade_mechanics();
    bool blade_curves_uploaded = false;
};

struct Field {
    Field() = default;
    ~Field() {
        if (mesh) mesh_host->destroy(mesh);
    }
    Field(const Field&) = delete;
    Field& operator=(const Field&) = delete;
    grass_field_desc desc{}; // pointers in it are cleared; maps are referenced below
    uint32_t patch_slot = 0;
    FieldMaps maps;                             // map slot per role (kNoMap: none) and the feature mask
    bool owns_density_map = false;              // maps.map_slot[kMapDensity] was made from desc.density_map
    double cell_to_map[6] = {0, 0, 0, 0, 0, 0}; // cell (x, z) -> map (u, v), lemme's configTf
    double height_scale = 0.0;                  // metres per height-map unit (0 without a height map)
    // Grass types (lemme 6.4.5): the first type is the field the host holds an id for; the
    // others are fields of their own, hidden behind it, made and destroyed with it.
    uint32_t parent = 0xffffffffu; // slot of the host's field for a hidden type, else none
    uint32_t children[GRASS_MAX_GRASS_TYPES - 1] = {};
    uint32_t child_count = 0;
    double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; // base transform's rotation, column-major
    double translation[3] = {0, 0, 0};
    LodSetup lod;                         // tiers and lod tests, copied from the desc
    QuadtreeShape tree;                   // implicit: nothing per node or cell
    LevelExtent extents[32];              // vertical extent of each level's nodes, in cells
    float bands[GRASS_MAX_TIERS][4] = {}; // per tier: its distance band (begin, end, in, out) for the transitions
    double overhang = 0.0;                // how far blade tips may leave their cell, in cells
    FieldWindMap wind_map;                // responsive grass: the host's wind map (grass_set_field_wind_map)
    BladeCulling culling;                 // per-blade culling of its geometry tiers (grass_set_blade_culling)
    BladeTessellation tessellation;       // dynamic tessellation of its geometry tiers (grass_set_blade_tessellation)
    // A mesh field (grass_create_mesh_field): its blades, owned; nullptr for a grid field,
    // whose desc, lod, tree and the grid's members above are then unused.
    MeshField* mesh = nullptr;
    HostAllocator* mesh_host = nullptr;
};

} // namespace grass
