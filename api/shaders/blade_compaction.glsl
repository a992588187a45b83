// The compacted blades of a window draw (docs/responsive.md "Culled blades compacted",
// jahrmann2017 6.1-6.2): blade_compaction.comp writes, per geometry draw of a view that runs
// the window variant, one item per blade that the view draws (not culled, opacity above 0)
// and the draw's indirect arguments; the compacted window variant (GRASS_BLADE_COMPACT in
// blade.vert) draws one instance per item, reading the patch's vertices and the view's
// instances from storage. Compiled only there and in the compaction pass.

#ifdef VULKAN
#define GRASS_COMPACT_VERTICES_BINDING 16
#define GRASS_COMPACT_INSTANCES_BINDING 17
#define GRASS_COMPACT_ITEMS_BINDING 18
#else // GL: shader storage bindings 3-5 (gl_blade_compaction.cpp)
#define GRASS_COMPACT_VERTICES_BINDING 3
#define GRASS_COMPACT_INSTANCES_BINDING 4
#define GRASS_COMPACT_ITEMS_BINDING 5
#endif
#ifdef GRASS_BLADE_COMPACTION_PASS
#define GRASS_COMPACT_ITEMS_ACCESS writeonly
#else
#define GRASS_COMPACT_ITEMS_ACCESS readonly
#endif

// The patch's vertices (api/src/patch/patch_data.hpp BladeVertex: 12 words each, a blade's
// vertices after each other): position 0-2, normal 3-5, root and shape 6-9, colour 10
// (unorm8 x 4), threshold 11.
layout(std430, binding = GRASS_COMPACT_VERTICES_BINDING) readonly buffer CompactPatchVertices {
    float compact_vertex_words[];
};
// The view's instances (api/src/foundation/frame_plan.hpp TierInstance: three vec4 each).
layout(std430, binding = GRASS_COMPACT_INSTANCES_BINDING) readonly buffer CompactInstances {
    vec4 compact_instance_words[];
};
// The items: (instance, blade), the instance an index into the view's instances; a draw's
// items start at its indirect arguments' first instance.
layout(std430, binding = GRASS_COMPACT_ITEMS_BINDING) GRASS_COMPACT_ITEMS_ACCESS buffer CompactItems {
    uvec2 compact_items[];
};

const uint kCompactVertexWords = 12u;

// The vertices a blade of the draw's patch has (set by the backend in field.trample.w).
uint compact_vertices_per_blade() { return max(uint(field.trample.w + 0.5), 4u); }
