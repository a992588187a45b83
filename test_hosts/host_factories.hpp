// Private to the test hosts' library: one factory per backend.
#pragma once

#include "headless_host.hpp"

namespace grass_host {
std::unique_ptr<Host> create_gl_host(const TargetDesc& target, std::string* error);
std::unique_ptr<Host> create_vk_host(const TargetDesc& target, std::string* error);
} // namespace grass_host
