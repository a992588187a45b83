// The shader interface: what the C++ side and the shared GLSL (api/shaders/, bindings and
// blocks in blade_interface.glsl) agree on, for the core that plans draws and for both
// backends that bind and draw them. The map roles and their texture bindings, the feature
// bits that pick a shader variant, the bindings of responsive grass, and the vertices each
// tier's vertex shader makes from its vertex index. Nothing here is a backend's choice; the
// backend interface (what a backend implements) is api/src/context/backend.hpp, the uniform
// blocks a draw carries are in frame_plan.hpp.
#pragma once

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// The roles of a field's design maps (grass_map_stack). A shader variant samples the maps
// of the roles in its feature mask (bit = 1 << role) and no others; the texture bindings
// are those of api/shaders/blade_interface.glsl.
enum MapRole : uint32_t {
    kMapDensity = 0,
    kMapColor = 1,
    kMapAmbient = 2,
    kMapDiffuse = 3,
    kMapHeight = 4,
    kMapRoleCount = 5
};
constexpr uint32_t kMapBinding[kMapRoleCount] = {2, 6, 7, 8, 9};
// The map slot of a role without a map (FieldMaps, a field's wind map): no binding, and
// the role's bit is not in the feature mask.
constexpr uint32_t kNoMap = 0xffffffffu;

// Feature bits of a draw past the map roles (TierDraw::features, GRASS_FEATURES in the
// shaders): responsive grass. A draw without them runs the shader of still grass.
constexpr uint32_t kFeatureWind = 1u << 5;        // wind or gravity: blades bend, slices sway (wind.glsl)
constexpr uint32_t kFeatureInteraction = 1u << 6; // the interaction map is bound (interaction.glsl)
constexpr uint32_t kFeatureWindMap = 1u << 7;     // the field's wind map is bound (wind.glsl); with kFeatureWind
// Per-blade culling (jahrmann2017 6.2, blade_culling.glsl): geometry draws only.
constexpr uint32_t kFeatureBladeCulling = 1u << 8;
// The features whose shaders are the responsive variants (GRASS_RESPONSIVE): they read the
// patch's blade control points (kBladeCurvesBinding) and the vertices per blade (trample.w).
// (kFeatureWindMap comes with kFeatureWind.)
constexpr uint32_t kBladeCurveFeatures = kFeatureWind | kFeatureInteraction | kFeatureBladeCulling;
// The frame draws a debug view that changes the grass's colour (kDebugViewFlags): only then
// do the shaders hold that code (GRASS_DEBUG_VIEW). A branch on a Frame value is not free:
// where the rasteriser cannot tell that all its lanes take the same side (lavapipe reads the
// blocks lane by lane), it runs both, and the threshold view's share (tier_blade_opacity)
// cost every volume hit a second transition interval (docs/records/tier-cost.md).
constexpr uint32_t kFeatureDebugView = 1u << 9;
constexpr uint32_t kDebugViewFlags = GRASS_VIEW_FLAG_DEBUG_TIERS | GRASS_VIEW_FLAG_DEBUG_THRESHOLDS;
// A depth-only pass (GRASS_PASS_DEPTH, GRASS_DEPTH_PASS in the shaders): the shaders skip
// lighting and colour and keep the coverage test and depth of the colour pass. Set on every
// draw of a depth view's plan and no other, so a host without depth views never compiles it.
constexpr uint32_t kFeatureDepthPass = 1u << 10;
// A view that receives the host's shadow map (grass_shadow_receive_desc, GRASS_SHADOW_RECEIVE
// in the shaders): its variants declare the map and its block (host_shadows.glsl, behind
// the GRASS_HOST_SHADOWS define) and darken the sun term. Set on every draw of a receiving
// colour view's plan and no other.
constexpr uint32_t kFeatureShadowReceive = 1u << 11;
// A view that writes motion vectors (grass_view_motion_desc, GRASS_MOTION in the shaders):
// its variants declare the GrassMotion block and the velocity output (motion.glsl, behind
// the GRASS_VELOCITY define) and also pose the grass at the previous time. Set on every draw
// of such a colour view's plan and no other.
constexpr uint32_t kFeatureMotion = 1u << 12;
// A view lit by the host's lights (grass_view_lights_desc, GRASS_HOST_LIGHTS in the shaders):
// its variants declare the GrassLights block (host_lights.glsl) and add the lights, the
// specular and the ambient harmonics. Set on every draw of such a colour view's plan and no
// other.
constexpr uint32_t kFeatureHostLights = 1u << 13;
// A G-buffer view (GRASS_PASS_GBUFFER, GRASS_GBUFFER in the shaders): its variants write
// the surface (gbuffer.glsl) to the fixed output locations of kGBufferOutput instead of a lit
// colour, with the depth pass's coverage. Set on every draw of such a view's plan and no other.
constexpr uint32_t kFeatureGBuffer = 1u << 14;
// A responsive geometry draw whose instances' cells the blade window holds, every one, this
// frame (plan/blade_window.hpp; GRASS_BLADE_WINDOW in the shaders): its variant reads
// each blade's pose from the window and has no per-vertex pose code. Set by the core only
// for a backend that runs the window pass (Backend::runs_blade_window); a draw with any cell
// the window does not hold keeps the per-vertex variant.
constexpr uint32_t kFeatureBladeWindow = 1u << 15;
// The feature bits the blade window pass (blade_window.comp) is compiled or specialised with,
// in both backends: the design maps', wind, the interaction map and the wind map (all below
// kFeatureBladeCulling).
constexpr uint32_t kBladeWindowPassFeatures = kFeatureBladeCulling - 1;
// Every feature mask is below this (the variants a backend may compile).
constexpr uint32_t kFeatureMaskCount = kFeatureBladeWindow << 1;
// The fragment output location of each grass_gbuffer_semantic in the GRASS_GBUFFER variants
// (gbuffer.glsl): albedo takes the colour's, velocity motion.glsl's; the backend routes each
// location to the host's attachment of that semantic. kNoGBufferOutput: NONE writes nothing.
constexpr uint32_t kNoGBufferOutput = 0xffffffffu;
constexpr uint32_t kGBufferOutputs = 4;
constexpr uint32_t kGBufferOutput[5] = {kNoGBufferOutput, 0, 2, 3, 1}; // NONE, ALBEDO, NORMAL, MATERIAL, VELOCITY
// The debug boxes (GRASS_VIEW_FLAG_DEBUG_CELLS, debug_tiers.*) sample the height map alone.
constexpr uint32_t kDebugBoxFeatures = 1u << kMapHeight;
// Bindings of responsive grass in the draw shaders (Vulkan set 0): the interaction map's
// levels (sampler2D, RGBA32F, read with texelFetch) and the patch's blade control points
// (readonly std430 buffer `BladeCurves`: PatchData::blade_curves).
constexpr uint32_t kInteractionMapBinding[2] = {10, 11};
constexpr uint32_t kBladeCurvesBinding = 12;
// The field's wind map (grass_set_field_wind_map): an RGBA design map, read with texelFetch.
constexpr uint32_t kWindMapBinding = 13;

// The vertices per instance of the draws without vertex input of their own: the vertex
// shader makes its corner from the vertex index (gl_VertexIndex / gl_VertexID).
constexpr uint32_t kVolumeVertices = 36;          // a cuboid, 6 faces x 2 triangles (volume.vert)
constexpr uint32_t kImageVertices = 6;            // a horizontal quad, 2 triangles (image.vert)
constexpr uint32_t kImageVerticesWithSkirts = 30; // on a height map: the quad and 4 skirts (image.vert)
constexpr uint32_t kDebugBoxVertices = 6;         // a flat box on the ground, 2 triangles (debug_tiers.vert)

// The vertices per instance of a draw of tier `kind` with feature mask `features` (volume
// and image tiers; the geometry tier draws its patch's indices): the image tier on a height
// map draws skirts down the terrain's steps between cells.
constexpr uint32_t slice_tier_vertices(grass_tier_kind kind, uint32_t features) {
    return kind == GRASS_TIER_VOLUME               ? kVolumeVertices
           : (features & (1u << kMapHeight)) != 0u ? kImageVerticesWithSkirts
                                                   : kImageVertices;
}

// The maps a field samples: the map slot of each role (kNoMap: none) and the feature mask
// (the map bits of the shader variant its draws run).
struct FieldMaps {
    uint32_t map_slot[kMapRoleCount] = {kNoMap, kNoMap, kNoMap, kNoMap, kNoMap};
    uint32_t features = 0; // bit r set <=> map_slot[r] != kNoMap
};

} // namespace grass
