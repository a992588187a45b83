// A scene file's responsive-grass keys (docs/scene-format.md): "wind" (with its sources),
// "interaction", "colliders" and "patch.mechanics".
#pragma once

#include "responsive.hpp"

#include <nlohmann/json_fwd.hpp>

namespace grass_sample {

// Reads those keys of the scene file's top level `scene` over *out; throws std::runtime_error
// naming the key (as "colliders[1].centre.keyframes") and the value of anything it refuses.
void read_responsive(const nlohmann::json& scene, Responsive* out);

} // namespace grass_sample
