#include "dynamics/dynamics_state.hpp"

#include "dynamics/interaction_map.hpp"
#include "dynamics/wind.hpp"

namespace grass {

DynamicsState::DynamicsState(HostAllocator* host)
    : wind(default_wind_desc()), colliders(StlAllocator<grass_collider>(host)),
      previous_colliders(StlAllocator<grass_collider>(host)), interaction(default_interaction_desc()),
      pending_colliders(StlAllocator<grass_collider>(host)), tile_rects(StlAllocator<TileRect>(host)),
      tile_fill(StlAllocator<uint32_t>(host)), collider_low(StlAllocator<float>(host)), window(host),
      window_used(StlAllocator<uint32_t>(host)) {}

} // namespace grass
