#include "driver_residency.hpp"

#include <dlfcn.h>
#include <link.h>

#include <cstring>

namespace grass_host {

void keep_drivers_resident(const char* const* patterns) {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* user) {
            const char* path = info->dlpi_name;
            if (!path || !*path) return 0;
            for (auto p = static_cast<const char* const*>(user); *p; ++p) {
                if (std::strstr(path, *p)) {
                    dlopen(path, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE); // only pins what is loaded
                    break;
                }
            }
            return 0;
        },
        const_cast<char**>(patterns));
}

} // namespace grass_host
