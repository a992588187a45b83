// How the blades of one grass type respond to wind, gravity and colliders (jahrmann2017
// 5.1): recovery stiffness, mass, wind response, collision strength and recovery time.
#pragma once

#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

grass_blade_mechanics default_blade_mechanics();

// Every value finite and in its documented range (grass.h); `name` names the argument.
grass_result validate_blade_mechanics(Log* log, const char* fn, const char* name, const grass_blade_mechanics& m);

} // namespace grass
