/*
 * For the ABI hosts' GL part (C99): pins Mesa's GL driver once it is loaded, as the headless
 * hosts do (test_hosts/driver_residency.cpp). eglTerminate unloads it at exit, and
 * LeakSanitizer then reports its exit-time allocations from an "<unknown module>" that
 * tests/sanitizer/lsan.supp cannot name. Call after a GL context was made.
 */
#ifndef GRASS_ABI_KEEP_DRIVERS_RESIDENT_H
#define GRASS_ABI_KEEP_DRIVERS_RESIDENT_H

#include <dlfcn.h>
#include <link.h>
#include <string.h>

static int keep_driver_resident(struct dl_phdr_info* info, size_t size, void* user_data) {
    const char* path = info->dlpi_name;
    (void)size;
    (void)user_data;
    if (path && (strstr(path, "_dri.so") || strstr(path, "libgallium"))) {
        dlopen(path, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE); /* only pins what is loaded */
    }
    return 0;
}

static void keep_drivers_resident(void) { dl_iterate_phdr(keep_driver_resident, NULL); }

#endif
