/* Compiled as C++11 with -Wall -Wextra -Werror -pedantic by ctest (header_compiles_as_cpp). */
#include <grass/grass.h>
#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

int grass_header_check(void);
int grass_header_check(void) {
    grass_patch_id id = {0, 0, 0};
    grass_view_desc view;
    view.type = GRASS_STRUCT_TYPE_VIEW_DESC;
    return (int)id.index + (int)view.type + (int)GRASS_HEADER_VERSION;
}
