// English names of the public enums, for messages: one copy for the core and every backend.
#pragma once

#include <grass/grass.h>

namespace grass {

// "geometry", "volume", "image" ("unknown" for any other value).
const char* tier_kind_name(grass_tier_kind kind);
// The call that makes a context of `backend`: "grass_create_context", "grass_gl_create_context", ...
const char* backend_creator(grass_backend backend);

} // namespace grass
