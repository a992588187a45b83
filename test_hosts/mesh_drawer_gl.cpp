#include "mesh_drawer_gl.hpp"

#include "shadow_cascades_gl.hpp"

#include "gl_loader.hpp"
#include "host_shaders.hpp"
#include "mesh_draw.hpp"

#include <GL/glcorearb.h>

#include <algorithm>

namespace grass_host {

struct GlMeshDrawer::Impl : grass_bootstrap::GlFunctions {
    GLuint program = 0, receiving_program = 0, vao = 0, geometry = 0, uniforms = 0;
    struct Range {
        const HostMesh* mesh;
        size_t first_index; // in the geometry buffer's index part
        GLint base_vertex;
    };
    std::vector<HostMesh> meshes;
    std::vector<Range> ranges;
    size_t index_offset = 0; // bytes: where the indices begin in `geometry`
};

GlMeshDrawer::GlMeshDrawer() : impl_(std::make_unique<Impl>()) {}

GlMeshDrawer::~GlMeshDrawer() {
    Impl& g = *impl_;
    if (!g.DeleteProgram) return; // never initialised
    if (g.program) g.DeleteProgram(g.program);
    if (g.receiving_program) g.DeleteProgram(g.receiving_program);
    const GLuint buffers[2] = {g.geometry, g.uniforms};
    g.DeleteBuffers(2, buffers); // zero names are ignored
    if (g.vao) g.DeleteVertexArrays(1, &g.vao);
}

bool GlMeshDrawer::init(ProcLoader loader, void* user_data, const std::vector<HostMesh>& meshes, std::string* error) {
    std::string ignored;
    std::string* e = error ? error : &ignored;
    Impl& g = *impl_;
    if (!g.load(loader, user_data, e)) return false;
    g.program =
        grass_bootstrap::compile_program(g, grass_host_shaders::mesh_vert, grass_host_shaders::mesh_frag, "mesh", e);
    if (!g.program) return false;

    // One buffer: every mesh's vertices, then every mesh's indices.
    g.meshes = meshes;
    size_t vertex_floats = 0, indices = 0;
    for (const HostMesh& m : g.meshes) {
        g.ranges.push_back({&m, indices, GLint(vertex_floats / HostMesh::kFloatsPerVertex)});
        vertex_floats += m.vertices.size();
        indices += m.indices.size();
    }
    g.index_offset = vertex_floats * sizeof(float);
    const size_t bytes = g.index_offset + indices * sizeof(uint32_t);
    g.CreateBuffers(1, &g.geometry);
    g.NamedBufferStorage(g.geometry, GLsizeiptr(bytes ? bytes : 4), nullptr, GL_DYNAMIC_STORAGE_BIT);
    size_t v = 0, i = g.index_offset;
    for (const HostMesh& m : g.meshes) {
        g.NamedBufferSubData(g.geometry, GLintptr(v), GLsizeiptr(m.vertices.size() * sizeof(float)), m.vertices.data());
        g.NamedBufferSubData(g.geometry, GLintptr(i), GLsizeiptr(m.indices.size() * sizeof(uint32_t)),
                             m.indices.data());
        v += m.vertices.size() * sizeof(float);
        i += m.indices.size() * sizeof(uint32_t);
    }
    g.CreateBuffers(1, &g.uniforms);
    g.NamedBufferStorage(g.uniforms, sizeof(MeshDraw), nullptr, GL_DYNAMIC_STORAGE_BIT);
    g.CreateVertexArrays(1, &g.vao);
    g.VertexArrayVertexBuffer(g.vao, 0, g.geometry, 0, GLsizei(HostMesh::kFloatsPerVertex * sizeof(float)));
    g.VertexArrayElementBuffer(g.vao, g.geometry);
    for (GLuint a = 0; a < 2; ++a) {
        g.EnableVertexArrayAttrib(g.vao, a);
        g.VertexArrayAttribFormat(g.vao, a, 3, GL_FLOAT, GL_FALSE, GLuint(3 * a * sizeof(float)));
        g.VertexArrayAttribBinding(g.vao, a, 0);
    }
    return true;
}

bool GlMeshDrawer::init_receiving(std::string* error) {
    std::string ignored;
    Impl& g = *impl_;
    const std::string vert = with_define(grass_host_shaders::mesh_vert, "HOST_SHADOWS");
    const std::string frag = with_define(grass_host_shaders::mesh_frag, "HOST_SHADOWS");
    g.receiving_program =
        grass_bootstrap::compile_program(g, vert.c_str(), frag.c_str(), "mesh (shadows)", error ? error : &ignored);
    return g.receiving_program != 0;
}

void GlMeshDrawer::set_origin(size_t index, const double origin[3]) {
    if (index < impl_->meshes.size()) std::copy(origin, origin + 3, impl_->meshes[index].origin);
}

void GlMeshDrawer::draw(const grass_view_desc& view, bool reversed_z, bool encode_srgb, bool receive_shadows) {
    Impl& g = *impl_;
    const GLuint program = receive_shadows ? g.receiving_program : g.program;
    if (!program || g.ranges.empty()) return;
    g.UseProgram(program);
    g.BindVertexArray(g.vao);
    g.BindBufferBase(GL_UNIFORM_BUFFER, 0, g.uniforms);
    g.Enable(GL_DEPTH_TEST);
    g.DepthMask(GL_TRUE);
    g.DepthFunc(reversed_z ? GL_GREATER : GL_LESS);
    for (const Impl::Range& r : g.ranges) {
        const MeshDraw d = make_mesh_draw(view, *r.mesh, encode_srgb);
        g.NamedBufferSubData(g.uniforms, 0, sizeof(d), &d);
        const auto offset = static_cast<uintptr_t>(g.index_offset + r.first_index * sizeof(uint32_t));
        g.DrawElementsBaseVertex(GL_TRIANGLES, GLsizei(r.mesh->indices.size()), GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(offset), r.base_vertex);
    }
    g.Disable(GL_DEPTH_TEST);
    g.BindVertexArray(0);
    g.UseProgram(0);
}

} // namespace grass_host
