// Draws the host's meshes (host_mesh.hpp) in a GL 4.5 context: camera-relative, Lambert +
// ambient under the view's sun, depth-tested and depth-writing into the bound framebuffer,
// so grass drawn after them is hidden behind them and stands in front of them. Used by the
// headless GL host; a windowed host (samples/viewer) makes one the same way:
//
//   grass_host::GlMeshDrawer meshes;
//   if (!meshes.init(loader, user, scene.meshes, &error)) ...   // GL context current
//   meshes.draw(view, reversed_z, false);                       // before grass_gl_render
//
// Like grass, it links no GL library: its calls go through the host's loader. It leaves
// no program, vertex array or uniform buffer bound and the depth test off.
#pragma once

#include "host_mesh.hpp"
#include "mesh_draw.hpp"

#include <grass/grass.h>

#include <memory>
#include <string>
#include <vector>

namespace grass_host {

class GlMeshDrawer final : public MovableMeshes {
public:
    // A GL entry point by name (eglGetProcAddress, glfwGetProcAddress, ...).
    using ProcLoader = void* (*)(void* user_data, const char* name);

    GlMeshDrawer();
    ~GlMeshDrawer() override; // the context that init used must be current
    GlMeshDrawer(const GlMeshDrawer&) = delete;
    GlMeshDrawer& operator=(const GlMeshDrawer&) = delete;

    // Compiles the shaders and uploads the meshes; false and *error when GL refuses.
    bool init(ProcLoader loader, void* user_data, const std::vector<HostMesh>& meshes, std::string* error);

    // Compiles the program that receives the host's shadows (shaders/cascade_shadows.glsl,
    // TargetDesc::host_shadows); false and *error when GL refuses. After init.
    bool init_receiving(std::string* error);

    // Draws every mesh with the depth test (GL_LESS, or GL_GREATER with reversed_z) and
    // depth writes on. encode_srgb: the target stores what the shader writes (no
    // GL_FRAMEBUFFER_SRGB conversion): the shader encodes. receive_shadows: with the program
    // of init_receiving, its map and block bound by the caller (GlShadowCascades).
    void draw(const grass_view_desc& view, bool reversed_z, bool encode_srgb, bool receive_shadows = false);

    // Moves mesh `index` (of init's list) to a new world origin: a host object that moves.
    void set_origin(size_t index, const double origin[3]) override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace grass_host
