#version 450
// grass-deferred's ground in its G-buffer (both halves): soil (scene.hpp's kSoil), facing up,
// rough, opaque and unoccluded, in grass's G-buffer encoding (scene.hpp's gbuffer_layout).
layout(location = 0) out vec4 out_albedo;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_material;
void main() {
    out_albedo = vec4(0.09, 0.065, 0.035, 1.0); // soil
    out_normal = vec4(0.5, 1.0, 0.5, 1.0);      // up, encoded as grass encodes a UNORM normal
    out_material = vec4(1.0, 0.0, 1.0, 1.0);    // rough, opaque, unoccluded
}
