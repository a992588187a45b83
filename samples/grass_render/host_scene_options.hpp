// grass-render's options for the host's own scene around grass (docs/engine-frames.md,
// "Shadows: grass in the host's shadow maps"): boxes and trees the host draws as meshes, and
// the host's cascaded sun shadows (TargetDesc::host_shadows), in which the meshes and grass
// cast and which the ground, the meshes and grass receive.
#pragma once

#include "cli.hpp"
#include "headless_host.hpp"

#include <string>
#include <vector>

namespace grass_sample {

struct HostSceneOptions {
    std::vector<std::string> boxes; // --box X0,Y0,Z0,X1,Y1,Z1
    std::vector<std::string> trees; // --tree X,Z,TRUNK,CROWN
    std::string shadows;            // --host-shadows SPLIT[,SPLIT...]
};

void add_host_scene_options(CLI::App& app, HostSceneOptions* o);
// The boxes and trees as host meshes, after `meshes`.
void add_host_meshes(const HostSceneOptions& o, std::vector<grass_host::HostMesh>* meshes);
// --host-shadows into target->host_shadows (a cascade per split distance).
void apply_host_shadows(const HostSceneOptions& o, grass_host::TargetDesc* target);

} // namespace grass_sample
