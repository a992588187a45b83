// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc): what a tier writes instead of
// its lit colour. Included only where GRASS_GBUFFER is defined (GL defines it with
// GRASS_FEATURES for the masks with kFeatureGBuffer; Vulkan compiles the GRASS_GBUFFER
// modules), so every other variant declares neither the block nor the outputs and its
// preprocessed text is what it was. Output locations (api/src/foundation/shader_interface.hpp
// kGBufferOutput): 0 the albedo (the colour's own out_color), 1 the velocity (motion.glsl),
// 2 the normal, 3 the material; the backend routes each to the host's attachment of that
// semantic, or to none (GL: GL_NONE; Vulkan rewrites the module: the output's Location moves
// to its attachment, an output the host did not ask for becomes a private variable,
// backend_vk/src/vk_gbuffer.cpp).
#if defined(VULKAN) && defined(GRASS_MULTIVIEW)
#error "a stereo (multiview) context draws no G-buffer views (grass_vk_gbuffer_target_desc is mono only)"
#endif

// The GrassGBuffer block (api/src/foundation/frame_plan.hpp GBufferUniforms): GL binding 5;
// Vulkan set 1, binding 3 (the view extras' blocks, backend_vk/src/vk_view_extras.hpp).
#ifdef VULKAN
layout(std140, set = 1, binding = 3) uniform GrassGBuffer {
#else
layout(std140, binding = 5) uniform GrassGBuffer {
#endif
    vec4 normal_encode; // x: scale, y: bias of the normal (0.5, 0.5 into a UNORM attachment)
} grass_gbuffer;

layout(location = 2) out vec4 out_gbuffer_normal;
layout(location = 3) out vec4 out_gbuffer_material;

// The material grass's own lighting implies (grass.h GRASS_GBUFFER_MATERIAL): Lambert's,
// without specular (roughness 1), and the share of a blade's back light its front lets through.
const float kGrassRoughness = 1.0;
const float kGrassTranslucency = 0.25;

// `albedo`: linear base colour; `world_normal`: unit, the side facing the camera; `ao`: what
// the ambient light is scaled by (the blades' occlusion times the ambient map).
void write_gbuffer(vec3 albedo, vec3 world_normal, float ao) {
    out_color = vec4(albedo, 1.0);
    out_gbuffer_normal = vec4(world_normal * grass_gbuffer.normal_encode.x + grass_gbuffer.normal_encode.y, 1.0);
    out_gbuffer_material = vec4(kGrassRoughness, kGrassTranslucency, ao, 1.0);
}

// A slice texel's normal as one vector (patch frame, unit): its `folded` components are
// magnitudes of lobes on both sides (lighting.glsl); each takes the side of `to_viewer`, and
// the whole the side that faces it, as the lobes lit there do.
vec3 gbuffer_slice_normal(vec3 n, vec3 folded, vec3 to_viewer) {
    vec3 side = vec3(to_viewer.x < 0.0 ? -1.0 : 1.0, to_viewer.y < 0.0 ? -1.0 : 1.0, to_viewer.z < 0.0 ? -1.0 : 1.0);
    vec3 m = mix(n, abs(n) * side, folded);
    if (dot(m, to_viewer) < 0.0) m = -m;
    return dot(m, m) > 1e-12 ? normalize(m) : to_viewer;
}
