#version 450
// grass-deferred's lighting pass (both halves): one triangle over the whole target.
#ifdef VULKAN
#define VERTEX_ID gl_VertexIndex
#else
#define VERTEX_ID gl_VertexID
#endif
void main() {
    vec2 p = vec2(VERTEX_ID == 1 ? 3.0 : -1.0, VERTEX_ID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
