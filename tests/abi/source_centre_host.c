/*
 * A host's source written against the 0.5 development headers, which spelled the collider's
 * field grass_collider.centre (now center, as grass_lod_node.center always was). Compiled as
 * C11 against the current headers with GRASS_ENABLE_DEPRECATED (docs/migrating.md), the old
 * name is an alias of the same storage: what it writes, the library reads as center. ctest
 * abi_source_centre_host runs it; abi_source_centre_compiles checks that it warns with the
 * macro (C11 and C++) and is refused without it (tests/abi/source_centre_compiles.sh).
 */
#include "host_checks.h"

#include <grass/grass.h>

#include <stddef.h>

#if defined(__cplusplus)
#    define STATIC_ASSERT static_assert
#else
#    define STATIC_ASSERT _Static_assert
#endif

/* The alias changes neither the layout nor the size. */
STATIC_ASSERT(offsetof(grass_collider, centre) == offsetof(grass_collider, center), "one storage");
STATIC_ASSERT(offsetof(grass_collider, center) == 8 && offsetof(grass_collider, end) == 32, "0.5 layout");
STATIC_ASSERT(sizeof(grass_collider) == 72, "0.5 size");

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = NULL;
    grass_collider ball;
    const char* message;

    memset(&ball, 0, sizeof(ball));
    ball.shape = GRASS_COLLIDER_SPHERE;
    ball.radius = 0.3f;
    ball.centre[0] = 1.0; /* the development name */
    ball.centre[1] = 0.2;
    ball.centre[2] = 3.0;
    CHECK(ball.center[0] == 1.0 && ball.center[1] == 0.2 && ball.center[2] == 3.0);
    CHECK(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) == GRASS_SUCCESS);
    if (!ctx) return 1;
    CHECK(grass_set_colliders(ctx, &ball, 1) == GRASS_SUCCESS);
    /* Out of range through the old name: the library refuses it by its new name. */
    ball.centre[2] = -2e12;
    CHECK(grass_set_colliders(ctx, &ball, 1) == GRASS_ERROR_INVALID_ARGUMENT);
    message = grass_get_last_error(ctx);
    CHECK(message != NULL && strstr(message, "colliders[0].center[2]") != NULL);
    if (message) printf("source_centre_host: refused as expected: %s\n", message);
    grass_destroy_context(ctx);
    return checks_result("source_centre_host");
}
