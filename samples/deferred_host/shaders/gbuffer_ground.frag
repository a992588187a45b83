#version 450
// grass-deferred's ground in its G-buffer (both halves): soil (scene.hpp's kSoil), facing up,
// rough, opaque and unoccluded, in grass's G-buffer encoding (scene.hpp's gbuffer_layout), and
// its velocity in grass's encoding (docs/integration.md, "Motion vectors": this frame's NDC
// minus the previous frame's, x 0.5; each half's clip y, so y up in GL and down in Vulkan, as
// grass's), b and a 1 to mark the ground (grass writes b 0 over it, velocity.hpp).
layout(location = 0) in vec4 v_clip;
layout(location = 1) in vec4 v_previous_clip;
layout(location = 0) out vec4 out_albedo;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_material;
layout(location = 3) out vec4 out_velocity;
void main() {
    out_albedo = vec4(0.09, 0.065, 0.035, 1.0); // soil
    out_normal = vec4(0.5, 1.0, 0.5, 1.0);      // up, encoded as grass encodes a UNORM normal
    out_material = vec4(1.0, 0.0, 1.0, 1.0);    // rough, opaque, unoccluded
    out_velocity = vec4((v_clip.xy / v_clip.w - v_previous_clip.xy / v_previous_clip.w) * 0.5, 1.0, 1.0);
}
