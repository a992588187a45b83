// Private to the headless hosts. GPU drivers are unloaded when their API shuts down
// (eglTerminate, the Vulkan loader at vkDestroyInstance). Pinning them keeps leak checkers
// able to name the drivers' own allocations (tests/sanitizer/lsan.supp matches them by
// library) and spares each new host a reload of LLVM.
#pragma once

namespace grass_host {

// Pins every loaded shared object whose path contains one of `patterns` (NULL-terminated).
void keep_drivers_resident(const char* const* patterns);

} // namespace grass_host
